//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)

/// \file engines/pair_friction.hpp
/// Where pair_friction was before it moved into the core (issue 27): include
/// <spinslide/pair_friction.hpp> instead.  Kept for one release.
#ifndef SPINSLIDE_ENGINES_PAIR_FRICTION_HPP
#define SPINSLIDE_ENGINES_PAIR_FRICTION_HPP

#include <spinslide/pair_friction.hpp>

#endif  // SPINSLIDE_ENGINES_PAIR_FRICTION_HPP
