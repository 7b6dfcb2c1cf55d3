//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The parts of the extension module spinslide._core, one translation unit
// each (they compile in parallel).
#ifndef SPINSLIDE_PYTHON_BINDINGS_HPP
#define SPINSLIDE_PYTHON_BINDINGS_HPP

#include <pybind11/pybind11.h>

namespace spinslide_python {

void bind_values(pybind11::module_& m);    // values.cpp: the disk's 𝓕, 𝓣, derivatives, ε₀
void bind_profiles(pybind11::module_& m);  // profiles.cpp: the profile classes, coupling
void bind_dynamics(pybind11::module_& m);  // dynamics.cpp: terminal motion, throws, batches
void bind_contact(pybind11::module_& m);   // contact.cpp: the limit-set projection, laws
void bind_patches(pybind11::module_& m);   // patches.cpp: flat patches, their wrench, dissipation
void bind_plates(pybind11::module_& m);    // plates.cpp: a flat plate thrown on a plane

}  // namespace spinslide_python

#endif  // SPINSLIDE_PYTHON_BINDINGS_HPP
