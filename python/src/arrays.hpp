//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// numpy in, numpy out, as a ufunc does: any array-like of ratios (or
// other reals), the result of its shape; float32 stays float32, every other
// type is computed in float64; a scalar (a Python number, a numpy scalar
// or a 0-d array) gives a numpy scalar.  The loop runs without the GIL.
#ifndef SPINSLIDE_PYTHON_ARRAYS_HPP
#define SPINSLIDE_PYTHON_ARRAYS_HPP

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace spinslide_python {

namespace py = pybind11;

// x as an array (TypeError naming `what` if it is not numbers).
inline py::array as_array(py::handle x, const char* what) {
  py::module_ np = py::module_::import("numpy");
  py::array a = np.attr("asarray")(x);
  const char kind = a.dtype().kind();
  if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
    throw py::type_error(std::string(what) + " must be a real number or an array of real numbers");
  return a;
}

inline bool is_float32(const py::array& a) { return a.dtype().is(py::dtype::of<float>()); }

// Element i of each of N outputs; as a scalar where the input was one.
template <class Real, std::size_t N, class Body>
py::object map_typed(const py::array& any, Body& body) {
  using array = py::array_t<Real, py::array::c_style | py::array::forcecast>;
  const array in = array::ensure(any);
  const std::vector<py::ssize_t> shape(in.shape(), in.shape() + in.ndim());
  std::array<array, N> out;
  std::array<Real*, N> dst{};
  for (std::size_t k = 0; k < N; ++k) {
    out[k] = array(shape);
    dst[k] = out[k].mutable_data();
  }
  const Real* src = in.data();
  const std::size_t n = static_cast<std::size_t>(in.size());
  {
    py::gil_scoped_release release;
    body(src, n, dst);
  }
  auto finish = [&](array& a) -> py::object {
    if (in.ndim() == 0) return a[py::tuple()];
    return std::move(a);
  };
  if constexpr (N == 1) {
    return finish(out[0]);
  } else {
    py::tuple t(N);
    for (std::size_t k = 0; k < N; ++k) t[k] = finish(out[k]);
    return py::object(std::move(t));
  }
}

// body(const Real* in, std::size_t n, std::array<Real*, N> out), a generic
// lambda, for Real = float or double.
template <std::size_t N, class Body>
py::object map_reals(py::handle x, const char* what, Body body) {
  const py::array a = as_array(x, what);
  if (is_float32(a)) return map_typed<float, N>(a, body);
  return map_typed<double, N>(a, body);
}

// As map_reals, always in float64 (the profiles' type).
template <std::size_t N, class Body>
py::object map_doubles(py::handle x, const char* what, Body body) {
  return map_typed<double, N>(as_array(x, what), body);
}

}  // namespace spinslide_python

#endif  // SPINSLIDE_PYTHON_ARRAYS_HPP
