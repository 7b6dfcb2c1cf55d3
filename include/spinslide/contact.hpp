//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file contact.hpp
/// The contact: the contact law for simulators, the coupled limit set and its
/// projection (for round profiles and flat patches), the impulse,
/// spring-history and trial-cap laws, one coupled
/// pair (`pair_friction`), the joint solve of many pairs and the adapters'
/// reports (include/spinslide/contact/).  Includes the values it builds on.
/// The engine adapters are not here: engines/\<engine\>/ (docs/engines.md).

#ifndef SPINSLIDE_CONTACT_HPP
#define SPINSLIDE_CONTACT_HPP

#include <spinslide/base/friction_result.hpp>
#include <spinslide/contact/contact_inputs.hpp>
#include <spinslide/contact/contact_law.hpp>
#include <spinslide/contact/contact_patch.hpp>
#include <spinslide/contact/impulse_friction.hpp>
#include <spinslide/contact/joint_pairs.hpp>
#include <spinslide/contact/limit_set.hpp>
#include <spinslide/contact/pair_friction.hpp>
#include <spinslide/contact/pair_report.hpp>
#include <spinslide/contact/patch_impulse.hpp>
#include <spinslide/contact/patch_limit_set.hpp>
#include <spinslide/contact/patch_result.hpp>
#include <spinslide/contact/patch_trial_cap.hpp>
#include <spinslide/contact/planar_metric.hpp>
#include <spinslide/contact/spring_friction.hpp>
#include <spinslide/contact/trial_cap.hpp>

#endif  // SPINSLIDE_CONTACT_HPP
