//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Reading and writing the components of users' vector types, for the contact
// law (contact_law.hpp): operator[] or members x, y, z.
#ifndef SPINSLIDE_BASE_DETAIL_VECTOR_ACCESS_HPP
#define SPINSLIDE_BASE_DETAIL_VECTOR_ACCESS_HPP

#include <array>
#include <tuple>
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

template <class V, class = void>
struct has_members_xy : std::false_type {};
template <class V>
struct has_members_xy<V,
                      std::void_t<decltype(std::declval<V&>().x), decltype(std::declval<V&>().y)>>
    : std::true_type {};
template <class V, class = void>
struct has_member_z : std::false_type {};
template <class V>
struct has_member_z<V, std::void_t<decltype(std::declval<V&>().z)>> : std::true_type {};

// True if V is a vector type the contact law can read and return with N
// components: a class with operator[] or members x, y (and z for N = 3).  A
// pointer or a C array is not (its size is unknown, and a result cannot be
// returned in one): the contact law static_asserts this, so that a raw
// pointer such as MuJoCo's mjtNum* does not compile instead of writing
// through a null "vector".
template <class V, int N>
constexpr bool is_vector() {
  if constexpr (std::is_pointer<V>::value || std::is_array<V>::value || !std::is_class<V>::value) {
    return false;
  } else {
    return has_subscript<V>::value ||
           (has_members_xy<V>::value && (N == 2 || has_member_z<V>::value));
  }
}

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

template <class V, class = void>
struct has_tuple_size : std::false_type {};
template <class V>
struct has_tuple_size<V, std::void_t<decltype(std::tuple_size<V>::value)>> : std::true_type {};

// How many components a vector type holds, where its type says: its
// std::tuple_size (std::array), 3 with a member z, else 2 (a class with
// operator[] and no std::tuple_size, read as a tangent-plane 2-vector).
template <class V>
constexpr int components() {
  if constexpr (has_tuple_size<V>::value) {
    return static_cast<int>(std::tuple_size<V>::value);
  } else if constexpr (has_member_z<V>::value) {
    return 3;
  } else {
    return 2;
  }
}

// The first N (2 or 3) components of v as a 3-vector of Real (z = 0 for N = 2).
template <int N, class Real, class V>
std::array<Real, 3> read(const V& v) {
  static_assert(N == 2 || N == 3, "read: 2 or 3 components");
  if constexpr (N == 3) {
    return {static_cast<Real>(get<0>(v)), static_cast<Real>(get<1>(v)),
            static_cast<Real>(get<2>(v))};
  } else {
    return {static_cast<Real>(get<0>(v)), static_cast<Real>(get<1>(v)), Real(0)};
  }
}

// The first N (2 or 3) components of x into v.
template <int N, class V, class Real>
void write(V& v, const std::array<Real, 3>& x) {
  static_assert(N == 2 || N == 3, "write: 2 or 3 components");
  set<0>(v, x[0]);
  set<1>(v, x[1]);
  if constexpr (N == 3) set<2>(v, x[2]);
}

}  // namespace detail
}  // namespace spinslide

#endif  // SPINSLIDE_BASE_DETAIL_VECTOR_ACCESS_HPP
