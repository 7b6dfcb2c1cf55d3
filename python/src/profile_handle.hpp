//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The Python profiles (docs/python.md).  A Python profile object holds a
// profile_handle: the library's run-time handle spinslide::contact_profile,
// which holds its named models by value, so that every algorithm runs on the
// concrete type (the same instantiation, and so the same numbers, as C++
// code gets), and the profiles that are built at run time (a weighted sum of
// a Python list, a pressure given as a Python callable, a table of either)
// as a spinslide::erased_profile.
#ifndef SPINSLIDE_PYTHON_PROFILE_HANDLE_HPP
#define SPINSLIDE_PYTHON_PROFILE_HANDLE_HPP

#include <spinslide/spinslide.hpp>

#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace spinslide_python {

// What a Python profile object holds: the profile, in the library's run-time
// handle (spinslide::contact_profile: the named models by value, every other
// as a spinslide::erased_profile), and how Python spells it.
struct profile_handle {
  spinslide::contact_profile<double> profile{spinslide::uniform_disk<>()};
  std::string repr;
};

// f(profile) on the concrete profile.
template <class F>
decltype(auto) visit(const profile_handle& p, F&& f) {
  return p.profile.visit(std::forward<F>(f));
}

// The profile as an erased_profile (for parts of sums and tables).
inline spinslide::erased_profile<> erase(const profile_handle& p) {
  return p.profile.visit([](const auto& q) -> spinslide::erased_profile<> {
    using Q = std::decay_t<decltype(q)>;
    if constexpr (std::is_same<Q, spinslide::erased_profile<>>::value)
      return q;
    else
      return spinslide::erased_profile<>(q);
  });
}

}  // namespace spinslide_python

#endif  // SPINSLIDE_PYTHON_PROFILE_HANDLE_HPP
