//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Reads the reference tables of tests/reference (disk_reference.csv,
// profile_reference.csv, terminal_ratio.txt): lines of comma-separated cells,
// '#' comment lines, and at most one header line of column names.  No quoting:
// the tables have none.  Standard library only, so that the generators, which
// do not link spinslide, include it too; the tests and the accuracy report
// read the tables through it.
#ifndef SPINSLIDE_TESTS_REFERENCE_CSV_HPP
#define SPINSLIDE_TESTS_REFERENCE_CSV_HPP

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace spinslide_reference {

// The cells of one line, split at every comma (a trailing empty cell is
// dropped, as std::getline does).
inline std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(cell);
  return cells;
}

// The data rows of the file at `path`, each split into cells: every line but
// the empty ones, the '#' comments and, if `first_column` is given, the header
// (the line whose first cell is `first_column`).  Throws std::runtime_error if
// the file cannot be opened.
inline std::vector<std::vector<std::string>> read_csv_rows(const std::string& path,
                                                           const std::string& first_column = "") {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells = split_csv(line);
    if (!first_column.empty() && !cells.empty() && cells[0] == first_column) continue;
    rows.push_back(std::move(cells));
  }
  return rows;
}

// read_csv_rows for a command-line tool: false, with the reason on stderr,
// where read_csv_rows would throw.
inline bool read_csv_rows(const std::string& path, const std::string& first_column,
                          std::vector<std::vector<std::string>>& rows) {
  try {
    rows = read_csv_rows(path, first_column);
    return true;
  } catch (const std::runtime_error& e) {
    std::cerr << e.what() << '\n';
    return false;
  }
}

}  // namespace spinslide_reference

#endif  // SPINSLIDE_TESTS_REFERENCE_CSV_HPP
