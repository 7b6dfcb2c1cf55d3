//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// A flat plate thrown on a plane (docs/plate_dynamics.md): throw_plate, its
// path as numpy arrays, and plate_terminal_points.
#include "arrays.hpp"
#include "bindings.hpp"

#include <pybind11/stl.h>

#include <spinslide/motion/plate_motion.hpp>
#include <spinslide/motion/plate_terminal.hpp>
#include <spinslide/motion/plate_throw.hpp>

#include <array>
#include <string>
#include <vector>

namespace spinslide_python {

namespace {

using result = spinslide::plate_throw_result<double>;

// The path's samples, one array per quantity.
py::dict path_arrays(const std::vector<spinslide::plate_sample<double>>& s) {
  const auto n = static_cast<py::ssize_t>(s.size());
  py::array_t<double> t(n), x(std::vector<py::ssize_t>{n, 2}), a(n),
      v(std::vector<py::ssize_t>{n, 2}), w(n);
  for (std::size_t i = 0; i < s.size(); ++i) {
    t.mutable_data()[i] = s[i].time;
    x.mutable_data()[2 * i] = s[i].position[0];
    x.mutable_data()[2 * i + 1] = s[i].position[1];
    a.mutable_data()[i] = s[i].angle;
    v.mutable_data()[2 * i] = s[i].velocity[0];
    v.mutable_data()[2 * i + 1] = s[i].velocity[1];
    w.mutable_data()[i] = s[i].omega;
  }
  py::dict out;
  out["time"] = t;
  out["position"] = x;
  out["angle"] = a;
  out["velocity"] = v;
  out["spin"] = w;
  return out;
}

result throw_it(const spinslide::polygon_patch<double>& face, double k, double mu, double g,
                py::handle velocity, double spin, double angle) {
  const contiguous u = contiguous::ensure(as_array(velocity, "velocity"));
  if (u.ndim() != 1 || u.shape(0) != 2)
    throw py::value_error("velocity must be a vector (u_x, u_y)");
  const spinslide::plate_motion<double> plate(face, spinslide::gyration_radius<double>{k},
                                              spinslide::friction_coefficient<double>{mu},
                                              spinslide::gravity<double>{g});
  const spinslide::planar_twist<double> start{{u.data()[0], u.data()[1]}, spin};
  py::gil_scoped_release release;
  return spinslide::throw_plate(plate, start, angle);
}

}  // namespace

void bind_plates(py::module_& m) {
  using ending = spinslide::plate_ending<double>;
  py::class_<ending>(m, "PlateEnding",
                     "How a plate's throw ends: the limits of the ratio ε = |u|/(ℓ|ω|) and of "
                     "the slip's direction in the body frame as it stops.")
      .def_readonly("ratio", &ending::ratio,
                    "ε at the stop: inf for pure sliding, 0 for pure "
                    "spinning")
      .def_readonly("direction", &ending::direction,
                    "the angle of u in the body frame (NaN for pure spinning)")
      .def_readonly("spin_sense", &ending::spin_sense,
                    "the sign of ω at the stop (0 for pure "
                    "sliding)")
      .def_readonly("converged", &ending::converged,
                    "False if the direction still moved at the end of its integration")
      .def("__repr__", [](const ending& e) {
        return "PlateEnding(ratio=" + std::string(py::str(py::float_(e.ratio))) +
               ", direction=" + std::string(py::str(py::float_(e.direction))) +
               ", spin_sense=" + std::to_string(e.spin_sense) + ")";
      });
  py::class_<result>(m, "PlateThrow", "A plate's throw to its stop (throw_plate).")
      .def_readonly("time", &result::time, "the stop time")
      .def_readonly("distance", &result::distance, "the length of the centre's path")
      .def_property_readonly(
          "displacement", [](const result& r) { return vector_array(r.displacement); },
          "the centre's displacement, world frame")
      .def_readonly("rotation", &result::rotation, "the total turn θ_end − θ₀ (signed)")
      .def_readonly("terminal", &result::terminal, "the limits at the stop (PlateEnding)")
      .def_readonly("reached_stop", &result::reached_stop,
                    "False if the step limit ended the integration first (then inexact)")
      .def_property_readonly(
          "path", [](const result& r) { return path_arrays(r.path); },
          "a dict of arrays at every accepted step and the stop: time, position (n, 2), angle, "
          "velocity (n, 2, body frame) and spin")
      .def("__repr__", [](const result& r) {
        return "PlateThrow(time=" + std::string(py::str(py::float_(r.time))) +
               ", distance=" + std::string(py::str(py::float_(r.distance))) +
               ", rotation=" + std::string(py::str(py::float_(r.rotation))) + ")";
      });
  using fixed = spinslide::plate_fixed_point<double>;
  py::class_<fixed>(m, "PlateFixedPoint",
                    "A fixed point of a plate's direction flow, with ω > 0 (its mirror with "
                    "ω < 0 is the same point with the slip reversed).")
      .def_readonly("ratio", &fixed::ratio, "ε* = |u|/(ℓω), ℓ = patch.radius")
      .def_readonly("direction", &fixed::direction,
                    "φ*, the slip's angle in the body frame (0 at ε* = 0)")
      .def_property_readonly(
          "exponents", [](const fixed& f) { return vector_array(f.exponents); },
          "λ₁ ≤ λ₂: the direction's deviation ∝ (time left)^λ")
      .def_readonly("stable", &fixed::stable,
                    "both exponents > 0: the throws that reach it end here")
      .def_property_readonly(
          "twist",
          [](const fixed& f) {
            py::array_t<double> a(3);
            for (py::ssize_t i = 0; i < 3; ++i) a.mutable_at(i) = f.twist[std::size_t(i)];
            return a;
          },
          "n = (u, kω)/|(u, kω)|")
      .def("__repr__", [](const fixed& f) {
        return "PlateFixedPoint(ratio=" + std::string(py::str(py::float_(f.ratio))) +
               ", direction=" + std::string(py::str(py::float_(f.direction))) +
               ", stable=" + (f.stable ? "True" : "False") + ")";
      });
  m.def(
      "plate_terminal_points",
      [](const spinslide::polygon_patch<double>& face, double k) {
        py::gil_scoped_release release;
        return spinslide::plate_terminal_points(face, spinslide::gyration_radius<double>{k});
      },
      py::arg("patch"), py::arg("gyration_radius"),
      "The fixed points with ω > 0 of the direction flow of a plate with this contact face "
      "(an area patch) and radius of gyration k, where (F, τ/k) is antiparallel to (u, kω): "
      "how its throws can end (docs/plate_dynamics.md).  A list of PlateFixedPoint.  k not "
      "finite and > 0 raises ValueError.");
  m.def("throw_plate", &throw_it, py::arg("patch"), py::kw_only(), py::arg("gyration_radius"),
        py::arg("friction_coefficient"), py::arg("gravity"), py::arg("velocity"), py::arg("spin"),
        py::arg("angle") = 0.0,
        "A flat plate with contact face `patch` (its centre of mass above the patch origin, "
        "its normal load mg), radius of gyration k = √(I/m), friction μ and gravity g, thrown "
        "from the world origin with the body-frame velocity (u_x, u_y) of its centre, the spin "
        "ω and the orientation θ₀ (keyword arguments: lengths in the patch's unit, time in "
        "g's): integrated through its exact stop.  Returns a PlateThrow.  k, μ, g not finite "
        "and > 0, a zero or non-finite twist raise ValueError.");
}

}  // namespace spinslide_python
