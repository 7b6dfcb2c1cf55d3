//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Misuse of stop_results (batch_throws.hpp) must not compile.  Compiled by
// tests/compile_fail/check.cmake once per MISUSE: 0 is the correct call (it
// must compile, so that the failures below are not an include path), and
// every other value must fail, with the message the test expects.
#include <spinslide/motion/batch_throws.hpp>
#include <spinslide/values/profile.hpp>

#include <list>
#include <vector>

int main() {
  const spinslide::uniform_disk<> disk;
#if MISUSE == 0
  const std::vector<spinslide::throw_start<double>> starts = {{1, 1}};
  return spinslide::stop_results(disk, 0.5, starts).size() == 1 ? 0 : 1;
#elif MISUSE == 1
  // Plain numbers: which is v0 and which ω0?
  const std::vector<double> speeds = {1, 1};
  return static_cast<int>(spinslide::stop_results(disk, 0.5, speeds).size());
#elif MISUSE == 2
  // A raw pointer and a count.
  const spinslide::throw_start<double> starts[] = {{1, 1}};
  const spinslide::throw_start<double>* p = starts;
  return static_cast<int>(spinslide::stop_results(disk, 0.5, p, 1).size());
#elif MISUSE == 3
  // A range without random access.
  const std::list<spinslide::throw_start<double>> starts = {{1, 1}};
  return static_cast<int>(spinslide::stop_results(disk, 0.5, starts).size());
#elif MISUSE == 4
  // Starts of another floating type than the profile's.
  const std::vector<spinslide::throw_start<float>> starts = {{1, 1}};
  return static_cast<int>(spinslide::stop_results(disk, 0.5, starts).size());
#endif
}
