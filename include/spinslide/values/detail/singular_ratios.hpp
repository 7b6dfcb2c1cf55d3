//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The ratios ε at which a profile's 𝓕 and 𝓣 are not smooth.  Where the
// pressure's support has an edge at radius r_e, the point r = ε of the
// contact's velocity field (the instantaneous centre of rotation) crosses
// that edge at ε = r_e, and 𝓕″ and 𝓣″ diverge logarithmically there (for the
// uniform disk at ε = 1, where K(k) diverges; for an annulus b ≤ r ≤ 1 also at
// ε = b; docs/theory.md §9).  A high-order integrator over ε loses its order on
// a step across such a point, so the stop integrator takes them as
// breakpoints.
//
// The profile concept does not ask for them: a profile may say where they are
// by a member singular_ratios() returning a ratio_list; otherwise the edge of
// the unit disk, ε = 1, is assumed (right for every profile supported up to
// r = 1; an extra breakpoint only costs a panel).
#ifndef SPINSLIDE_VALUES_DETAIL_SINGULAR_RATIOS_HPP
#define SPINSLIDE_VALUES_DETAIL_SINGULAR_RATIOS_HPP

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace spinslide {
namespace detail {

/// At most `capacity` finite ratios ε > 0, ascending and distinct; a ratio
/// beyond the capacity is dropped (it then only costs the integrator order).
template <class Real>
class ratio_list {
 public:
  static constexpr std::size_t capacity = 8;

  ratio_list() = default;
  /// The single ratio `eps`.
  explicit ratio_list(Real eps) { add(eps); }

  /// Adds `eps` in order, unless it is not finite and > 0 or already present.
  void add(Real eps) {
    using std::isfinite;
    if (!(eps > 0) || !isfinite(eps) || size_ == capacity) return;
    std::size_t i = 0;
    while (i < size_ && ratios_[i] < eps) ++i;
    if (i < size_ && ratios_[i] == eps) return;
    for (std::size_t j = size_; j > i; --j) ratios_[j] = ratios_[j - 1];
    ratios_[i] = eps;
    ++size_;
  }
  /// Adds every ratio of `other`, each multiplied by `factor`.
  void add_scaled(const ratio_list& other, Real factor) {
    for (std::size_t i = 0; i < other.size(); ++i) add(other[i] * factor);
  }

  std::size_t size() const { return size_; }
  Real operator[](std::size_t i) const { return ratios_[i]; }

 private:
  std::array<Real, capacity> ratios_{};
  std::size_t size_ = 0;
};

template <class P, class = void>
struct has_member_singular_ratios : std::false_type {};
template <class P>
struct has_member_singular_ratios<P,
                                  std::void_t<decltype(std::declval<const P&>().singular_ratios())>>
    : std::true_type {};

/// The ratios where P's 𝓕 and 𝓣 are singular: its member singular_ratios(),
/// else {1}.
template <class P>
ratio_list<typename P::value_type> singular_ratios(const P& p) {
  if constexpr (has_member_singular_ratios<P>::value) {
    return p.singular_ratios();
  } else {
    return ratio_list<typename P::value_type>(typename P::value_type(1));
  }
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_VALUES_DETAIL_SINGULAR_RATIOS_HPP
