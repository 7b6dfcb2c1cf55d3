//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file spinslide.hpp
/// Umbrella header: includes every public spinslide header.

#ifndef SPINSLIDE_SPINSLIDE_HPP
#define SPINSLIDE_SPINSLIDE_HPP

#include <spinslide/approximations.hpp>
#include <spinslide/batch_throws.hpp>
#include <spinslide/contact.hpp>
#include <spinslide/contact_inputs.hpp>
#include <spinslide/coupling.hpp>
#include <spinslide/cylinder.hpp>
#include <spinslide/disk.hpp>
#include <spinslide/dynamics.hpp>
#include <spinslide/equations_of_motion.hpp>
#include <spinslide/impulse_friction.hpp>
#include <spinslide/limit_set.hpp>
#include <spinslide/pair_friction.hpp>
#include <spinslide/pair_report.hpp>
#include <spinslide/planar_metric.hpp>
#include <spinslide/profile.hpp>
#include <spinslide/profile_base.hpp>
#include <spinslide/profile_concept.hpp>
#include <spinslide/projection_results.hpp>
#include <spinslide/spring_friction.hpp>
#include <spinslide/tabulated.hpp>
#include <spinslide/tabulated_throw.hpp>
#include <spinslide/terminal.hpp>
#include <spinslide/throw_inputs.hpp>
#include <spinslide/trial_cap.hpp>

#endif  // SPINSLIDE_SPINSLIDE_HPP
