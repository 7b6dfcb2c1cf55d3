//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
/// \file motion/detail/panel_width_controller.hpp
/// The step-size control of the integration to the stop (docs/theory.md §9;
/// motion/detail/stop_integrator.hpp): the width of the next panel, in the path's
/// parameter s and in u, from the error of the last one.

#ifndef SPINSLIDE_MOTION_DETAIL_PANEL_WIDTH_CONTROLLER_HPP
#define SPINSLIDE_MOTION_DETAIL_PANEL_WIDTH_CONTROLLER_HPP

#include <algorithm>
#include <cmath>

namespace spinslide {
namespace detail {

/// The widths of the next panel in s and in u.  A panel whose error is above
/// the tolerance is rejected unless its width is already at the rounding of
/// where it starts; the next width is the last one times 0.9(tol/err)^{1/8}
/// (the panels converge at about that order), kept within [0.1, 0.5] after a
/// rejection and within [0.5, 4] after an acceptance.
class panel_width_controller {
 public:
  /// Where panels are measured: in the path's parameter s, or in u.
  enum class variable { s, u };

  explicit panel_width_controller(double tolerance) : tolerance_(tolerance) {}

  double tolerance() const { return tolerance_; }
  double width(variable in) const { return in == variable::u ? width_u_ : width_s_; }
  /// A new leg: its first width in s (the width in u carries on).
  void restart(double width_in_s) { width_s_ = width_in_s; }

  /// Whether the panel of width h, starting at `start` (s or u), with the
  /// given error is accepted; sets the next width either way.
  bool accept(variable in, double h, double error, double start) {
    double& width = in == variable::u ? width_u_ : width_s_;
    const double factor = error > 0 ? 0.9 * std::pow(tolerance_ / error, 0.125) : 4;
    if (error > tolerance_ && h > 1e-9 * (1 + start)) {
      width = h * (std::max)(0.1, (std::min)(0.5, factor));
      return false;
    }
    width = h * (std::max)(0.5, (std::min)(4.0, factor));
    return true;
  }

 private:
  double tolerance_;
  double width_s_ = 1;
  double width_u_ = 1;
};

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_MOTION_DETAIL_PANEL_WIDTH_CONTROLLER_HPP
