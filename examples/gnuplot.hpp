//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The examples' output helpers.  One way to draw a figure: write a gnuplot
// script into the output directory and run gnuplot there (paths in the script
// are relative to it).  Without gnuplot the data files are still written; the
// caller says so.
#ifndef SPINSLIDE_EXAMPLES_GNUPLOT_HPP
#define SPINSLIDE_EXAMPLES_GNUPLOT_HPP

#include <cstdio>
#include <cstdlib>
#include <string>

namespace spinslide_examples {

// Opens `path` for writing; on failure says so on stderr, naming `program`,
// and returns null.
inline FILE* open_output(const std::string& path, const char* program) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) std::fprintf(stderr, "%s: cannot write %s\n", program, path.c_str());
  return f;
}

// Writes `script` to dir/name and runs it with gnuplot in dir; true if a
// figure was made.
inline bool plot(const std::string& dir, const std::string& name, const std::string& script) {
  const std::string path = dir + "/" + name;
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return false;
  std::fputs(script.c_str(), f);
  std::fclose(f);
  const std::string run =
      "command -v gnuplot >/dev/null 2>&1 && cd '" + dir + "' && gnuplot '" + name + "'";
  return std::system(run.c_str()) == 0;
}

}  // namespace spinslide_examples

#endif  // SPINSLIDE_EXAMPLES_GNUPLOT_HPP
