//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The examples' one way to draw a figure: write a gnuplot script into the
// output directory and run gnuplot there (paths in the script are relative to
// it).  Without gnuplot the data files are still written; the caller says so.
#ifndef SPINSLIDE_EXAMPLES_GNUPLOT_HPP
#define SPINSLIDE_EXAMPLES_GNUPLOT_HPP

#include <cstdio>
#include <cstdlib>
#include <string>

namespace spinslide_examples {

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
