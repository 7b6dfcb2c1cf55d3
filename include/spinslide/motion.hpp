//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion.hpp
/// The motion: the equations of motion (odeint systems), the integration of a
/// throw through its stop, the terminal ratio and regime, tabulated and batched
/// throws, a flat plate thrown to its stop (include/spinslide/motion/).
/// Includes the values it builds on.

#ifndef SPINSLIDE_MOTION_HPP
#define SPINSLIDE_MOTION_HPP

#include <spinslide/motion/batch_throws.hpp>
#include <spinslide/motion/dynamics.hpp>
#include <spinslide/motion/equations_of_motion.hpp>
#include <spinslide/motion/motion_types.hpp>
#include <spinslide/motion/plate_motion.hpp>
#include <spinslide/motion/plate_terminal.hpp>
#include <spinslide/motion/plate_throw.hpp>
#include <spinslide/motion/tabulated_throw.hpp>
#include <spinslide/motion/terminal.hpp>
#include <spinslide/motion/terminal_state.hpp>
#include <spinslide/motion/throw_inputs.hpp>

#endif  // SPINSLIDE_MOTION_HPP
