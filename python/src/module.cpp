//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// spinslide._core: the compiled part of the Python package (python/spinslide
// re-exports it with the pure-Python helpers).
#include "bindings.hpp"

#include <stdexcept>

// The package's version, VERSION's at the repository root: CMake
// (python/CMakeLists.txt) and setup.py define it.
#ifndef SPINSLIDE_VERSION
#error "spinslide._core: compile with -DSPINSLIDE_VERSION=\"<the VERSION file's version>\""
#endif

PYBIND11_MODULE(_core, m) {
  m.doc() =
      "Coupled sliding and spinning friction (Coulomb-Contensou), exact: the compiled core of "
      "the spinslide package.  Import spinslide, not this module.";
  // The library's bad-argument errors are std::domain_error (ValueError in
  // Python, by pybind11's own translation); its message names the function,
  // the argument and the rule.
  m.attr("__version__") = SPINSLIDE_VERSION;
  spinslide_python::bind_values(m);
  spinslide_python::bind_profiles(m);
  spinslide_python::bind_dynamics(m);
  spinslide_python::bind_contact(m);
  spinslide_python::bind_patches(m);
  spinslide_python::bind_plates(m);
}
