//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file values.hpp
/// The values: 𝓕(ε), 𝓣(ε) of the paper's disk and of every pressure profile,
/// the coupling curve and its inverses, the tilted cylinder, and today's
/// engine models for comparison (include/spinslide/values/).

#ifndef SPINSLIDE_VALUES_HPP
#define SPINSLIDE_VALUES_HPP

#include <spinslide/base/friction_result.hpp>
#include <spinslide/base/named_inputs.hpp>
#include <spinslide/values/approximations.hpp>
#include <spinslide/values/contact_profile.hpp>
#include <spinslide/values/coupling.hpp>
#include <spinslide/values/cylinder.hpp>
#include <spinslide/values/disk.hpp>
#include <spinslide/values/erased_profile.hpp>
#include <spinslide/values/force_torque_result.hpp>
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/patch_dissipation.hpp>
#include <spinslide/values/polygon_patch.hpp>
#include <spinslide/values/profile.hpp>
#include <spinslide/values/profile_base.hpp>
#include <spinslide/values/profile_concept.hpp>
#include <spinslide/values/radial_profile.hpp>
#include <spinslide/values/tabulated.hpp>

#endif  // SPINSLIDE_VALUES_HPP
