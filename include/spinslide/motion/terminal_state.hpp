//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file terminal_state.hpp
/// How a throw ends: the terminal regime and the limit of the ratio ε
/// (docs/theory.md §8), as terminal_motion (terminal.hpp) reports it and a
/// throw's stop_result (motion_types.hpp) carries it.  Its own header
/// (issue 28), so that the results of a throw need not include the flow's
/// analysis.

#ifndef SPINSLIDE_MOTION_TERMINAL_STATE_HPP
#define SPINSLIDE_MOTION_TERMINAL_STATE_HPP

namespace spinslide {

/// How the ratio ε behaves as the motion stops.  Sliding and spinning always
/// end at the same instant; the regime says which of them dominates on the way.
enum class terminal_regime {
  pure_sliding,          ///< ε → ∞: the spin dies relatively faster
  sliding_and_spinning,  ///< ε → ε₀, a finite attracting zero of f
  pure_spinning          ///< ε → 0: the sliding dies relatively faster
};

/// The terminal regime and the limit of ε: ε₀, +∞ or 0.
template <class Real>
struct terminal_state {
  using value_type = Real;  ///< the floating type
  terminal_regime regime;   ///< how ε behaves as the motion stops
  Real ratio;               ///< the limit of ε: ε₀, +∞ (pure sliding) or 0 (pure spinning)
};

}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_TERMINAL_STATE_HPP
