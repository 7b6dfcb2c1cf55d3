//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file spinslide.hpp
/// Umbrella header: includes every public spinslide header of the core, through
/// the umbrellas of its three parts (values.hpp, motion.hpp, contact.hpp).
/// The engine adapters are not in it (engines/\<engine\>/, docs/engines.md).

#ifndef SPINSLIDE_SPINSLIDE_HPP
#define SPINSLIDE_SPINSLIDE_HPP

#include <spinslide/contact.hpp>
#include <spinslide/motion.hpp>
#include <spinslide/values.hpp>

#endif  // SPINSLIDE_SPINSLIDE_HPP
