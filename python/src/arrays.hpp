//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// numpy in, numpy out, as a ufunc does: any array-like of ratios (or
// other reals), the result of its shape; float32 stays float32, every other
// type is computed in float64; a scalar (a Python number, a numpy scalar
// or a 0-d array) gives a numpy scalar.  The loop runs without the GIL.
// The contact and patch functions broadcast several inputs, each with its
// own trailing (vector or matrix) dimensions, in float64 (broadcast_inputs).
#ifndef SPINSLIDE_PYTHON_ARRAYS_HPP
#define SPINSLIDE_PYTHON_ARRAYS_HPP

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <initializer_list>
#include <string>
#include <utility>
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

using contiguous = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The inputs broadcast together, each with `trailing` fixed trailing
// dimensions (1: a vector of 2, 2: a 3×3 matrix; any other size is a
// ValueError naming the input), as contiguous float64.
struct broadcast {
  std::vector<contiguous> arrays;
  std::vector<py::ssize_t> shape;  // the contacts' shape (without the trailing dimensions)
  std::size_t count = 1;
};

inline broadcast broadcast_inputs(const std::vector<std::pair<py::handle, int>>& inputs,
                                  const std::vector<const char*>& names) {
  // Each array's leading (contact) dimensions, broadcast together.
  py::module_ np = py::module_::import("numpy");
  std::vector<py::array> arrays;
  py::list leading;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    py::array a = as_array(inputs[k].first, names[k]);
    const int trailing = inputs[k].second;
    const py::ssize_t size = trailing == 1 ? 2 : 3;
    bool fits = a.ndim() >= trailing;
    for (int i = 1; fits && i <= trailing; ++i) fits = a.shape(a.ndim() - i) == size;
    if (!fits)
      throw py::value_error(std::string(names[k]) + " must have " + std::to_string(trailing) +
                            " trailing dimension(s) (a vector is (..., 2), a matrix (..., 3, 3))");
    arrays.push_back(a);
    py::list s;
    for (py::ssize_t i = 0; i < a.ndim() - trailing; ++i) s.append(a.shape(i));
    leading.append(py::tuple(s));
  }
  const py::tuple shape = np.attr("broadcast_shapes")(*leading);
  broadcast out;
  for (const auto& d : shape) out.shape.push_back(d.cast<py::ssize_t>());
  for (const auto n : out.shape) out.count *= static_cast<std::size_t>(n);
  for (std::size_t k = 0; k < arrays.size(); ++k) {
    py::list full(shape);
    for (py::ssize_t i = arrays[k].ndim() - inputs[k].second; i < arrays[k].ndim(); ++i)
      full.append(arrays[k].shape(i));
    out.arrays.push_back(contiguous::ensure(
        np.attr("ascontiguousarray")(np.attr("broadcast_to")(arrays[k], py::tuple(full)))));
  }
  return out;
}

inline std::vector<py::ssize_t> with(std::vector<py::ssize_t> shape,
                                     std::initializer_list<py::ssize_t> t) {
  shape.insert(shape.end(), t);
  return shape;
}

// A 2-vector (a point, a force) as a numpy array of shape (2,).
inline py::array_t<double> vector_array(const std::array<double, 2>& x) {
  py::array_t<double> a(2);
  a.mutable_at(0) = x[0];
  a.mutable_at(1) = x[1];
  return a;
}

// A result array (or a scalar where the contacts' shape is ()).
inline py::object finish(py::array a, bool scalar) {
  if (scalar) return a[py::tuple()];
  return py::object(std::move(a));
}

}  // namespace spinslide_python

#endif  // SPINSLIDE_PYTHON_ARRAYS_HPP
