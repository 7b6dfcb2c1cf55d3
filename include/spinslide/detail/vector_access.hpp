//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Reading and writing the components of users' vector types, for the contact
// law (contact.hpp): operator[] or members x, y, z.
#ifndef SPINSLIDE_DETAIL_VECTOR_ACCESS_HPP
#define SPINSLIDE_DETAIL_VECTOR_ACCESS_HPP

#include <type_traits>
#include <utility>

namespace spinslide {
namespace detail {

// Component access for users' vector types: operator[] (std::array, Eigen,
// most math libraries) or public members x, y, z (Box2D, glm, plain structs).
template <class V, class = void>
struct has_subscript : std::false_type {};
template <class V>
struct has_subscript<V, std::void_t<decltype(std::declval<V&>()[0])>> : std::true_type {};

template <int I, class V>
decltype(auto) component(V& v) {
  if constexpr (has_subscript<V>::value) {
    return (v[I]);
  } else if constexpr (I == 0) {
    return (v.x);
  } else if constexpr (I == 1) {
    return (v.y);
  } else {
    return (v.z);
  }
}
template <int I, class V>
auto get(const V& v) {
  return component<I>(v);  // V deduced const: reads through the const accessors
}
template <int I, class V, class Real>
void set(V& v, Real value) {
  using C = std::remove_reference_t<decltype(component<I>(v))>;
  component<I>(v) = static_cast<C>(value);
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_DETAIL_VECTOR_ACCESS_HPP
