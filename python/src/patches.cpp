//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// Flat patches (docs/patches.md): the class PolygonPatch (the library's
// polygon_patch<double>), and the friction wrench and the dissipation of
// arrays of planar twists.
#include "arrays.hpp"
#include "bindings.hpp"

#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/patch_dissipation.hpp>
#include <spinslide/values/polygon_patch.hpp>

#include <pybind11/stl.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace spinslide_python {

namespace {

using patch = spinslide::polygon_patch<double>;
using vertex = std::array<double, 2>;

// An (n, 2) array-like of vertices (ValueError for another shape; the
// library checks the rest: the count, finiteness, convexity...).
std::vector<vertex> vertices_of(py::handle x, const char* what) {
  const contiguous a = contiguous::ensure(as_array(x, what));
  if (a.ndim() != 2 || a.shape(1) != 2)
    throw py::value_error(std::string(what) + " must be an (n, 2) array of points");
  std::vector<vertex> v(static_cast<std::size_t>(a.shape(0)));
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = {a.data()[2 * i], a.data()[2 * i + 1]};
  return v;
}

// One point (x, y) (ValueError for another shape).
vertex point_of(py::handle x, const char* what) {
  const contiguous a = contiguous::ensure(as_array(x, what));
  if (a.ndim() != 1 || a.shape(0) != 2)
    throw py::value_error(std::string(what) + " must be a point (x, y)");
  return {a.data()[0], a.data()[1]};
}

std::optional<spinslide::centre_of_pressure<double>> centre_of(py::handle x) {
  if (x.is_none()) return std::nullopt;
  return spinslide::centre_of_pressure<double>{point_of(x, "centre_of_pressure")};
}

patch make_patch(py::handle vertices, py::handle centre) {
  const std::vector<vertex> v = vertices_of(vertices, "vertices");
  const auto c = centre_of(centre);
  return c ? patch(v, *c) : patch(v);
}

patch make_segment(const vertex& from, const vertex& to, py::handle centre) {
  const auto c = centre_of(centre);
  return c ? patch::segment(from, to, *c) : patch::segment(from, to);
}

std::string repr(const patch& p) {
  static const char* shapes[] = {"area", "line", "point"};
  const auto str = [](double x) { return std::string(py::str(py::float_(x))); };
  return std::string("PolygonPatch(shape=") + shapes[static_cast<int>(p.shape())] +
         ", loaded_vertices=" + std::to_string(p.loaded_vertices().size()) + ", centre=(" +
         str(p.centre()[0]) + ", " + str(p.centre()[1]) + "), radius=" + str(p.radius()) + ")";
}

// The twists' inputs, broadcast: velocity (..., 2) and spin (...).
broadcast twists(py::handle velocity, py::handle spin) {
  return broadcast_inputs({{velocity, 1}, {spin, 0}}, {"velocity", "spin"});
}

spinslide::planar_twist<double> twist_at(const broadcast& in, std::size_t i) {
  const double *v = in.arrays[0].data(), *w = in.arrays[1].data();
  return {{v[2 * i], v[2 * i + 1]}, w[i]};
}

py::tuple wrench(const patch& p, py::handle velocity, py::handle spin) {
  const broadcast in = twists(velocity, spin);
  py::array_t<double> force(with(in.shape, {2})), torque(in.shape);
  double *f = force.mutable_data(), *t = torque.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < in.count; ++i) {
      const auto r = spinslide::friction_wrench(p, twist_at(in, i));
      f[2 * i] = r.force[0];
      f[2 * i + 1] = r.force[1];
      t[i] = r.torque;
    }
  }
  return py::make_tuple(force, finish(torque, in.shape.empty()));
}

py::tuple dissipation(const patch& p, py::handle velocity, py::handle spin) {
  const broadcast in = twists(velocity, spin);
  py::array_t<double> value(in.shape), gradient(with(in.shape, {3})),
      hessian(with(in.shape, {3, 3}));
  double *d = value.mutable_data(), *g = gradient.mutable_data(), *h = hessian.mutable_data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < in.count; ++i) {
      const auto r = spinslide::friction_dissipation(p, twist_at(in, i));
      d[i] = r.value;
      for (std::size_t j = 0; j < 3; ++j) {
        g[3 * i + j] = r.gradient[j];
        for (std::size_t k = 0; k < 3; ++k) h[9 * i + 3 * j + k] = r.hessian[j][k];
      }
    }
  }
  return py::make_tuple(finish(value, in.shape.empty()), gradient, hessian);
}

void bind_patch_class(py::module_& m) {
  py::enum_<spinslide::patch_shape>(m, "PatchShape", "What carries a patch's load.")
      .value("area", spinslide::patch_shape::area, "a polygon (3 or more loaded vertices)")
      .value("line", spinslide::patch_shape::line, "a segment with a linear line pressure")
      .value("point", spinslide::patch_shape::point, "a point: point friction");
  py::class_<patch>(
      m, "PolygonPatch",
      "A flat contact patch: a convex polygon under a uniform pressure, or under the linear "
      "pressure with a given centre of pressure (the no-tension pressure max(0, α + β·x) with "
      "the same resultant and centre beyond the kern).  A centre on an edge makes a line "
      "patch, on a vertex a point patch.  Lengths in any unit; the load is per unit μN.")
      .def(py::init(&make_patch), py::arg("vertices"), py::arg("centre_of_pressure") = py::none(),
           "PolygonPatch(vertices, centre_of_pressure=None): vertices an (n, 2) array-like of a "
           "convex polygon (n >= 3, either orientation), centre_of_pressure a point (x, y) inside "
           "it or None (uniform pressure).  A bad outline or centre raises ValueError naming the "
           "problem.")
      .def_static("segment", &make_segment, py::arg("a"), py::arg("b"),
                  py::arg("centre_of_pressure") = py::none(),
                  "The line patch from a to b (a box on its edge): uniform, or linear with its "
                  "centre of pressure on the segment (triangular beyond its middle third).")
      .def_static(
          "point", [](py::handle x) { return patch::point(point_of(x, "x")); }, py::arg("x"),
          "Point friction at x.")
      .def_property_readonly("shape", &patch::shape, "area, line or point (a PatchShape)")
      .def_property_readonly(
          "loaded_vertices",
          [](const patch& p) {
            const auto& v = p.loaded_vertices();
            py::array_t<double> a(std::vector<py::ssize_t>{static_cast<py::ssize_t>(v.size()), 2});
            for (std::size_t i = 0; i < v.size(); ++i) {
              a.mutable_data()[2 * i] = v[i][0];
              a.mutable_data()[2 * i + 1] = v[i][1];
            }
            return a;
          },
          "the loaded region's vertices, (k, 2), counter-clockwise (2 for a line patch, 1 for a "
          "point): the polygon, or the part that stays in contact where the pressure lifts off")
      .def_property_readonly(
          "centre", [](const patch& p) { return vector_array(p.centre()); },
          "the centre of pressure")
      .def_property_readonly("radius", &patch::radius,
                             "ℓ: the largest distance of a vertex of the outline from the origin")
      .def_property_readonly("loaded_radius", &patch::loaded_radius,
                             "the largest distance of a loaded vertex from the pressure origin")
      .def_property_readonly(
          "pressure_origin", [](const patch& p) { return vector_array(p.pressure_origin()); },
          "z₀, the loaded vertices' mean")
      .def_property_readonly("pressure_at_origin", &patch::pressure_at_origin, "p(z₀)")
      .def_property_readonly(
          "pressure_gradient", [](const patch& p) { return vector_array(p.pressure_gradient()); },
          "β = ∇p (along the segment for a line patch)")
      .def_property_readonly("thin", &patch::thin,
                             "True for a loaded area longer than 4 times its width (its wrench "
                             "is summed over slabs)")
      .def(
          "pressure",
          [](const patch& p, py::handle x) {
            const broadcast in = broadcast_inputs({{x, 1}}, {"x"});
            py::array_t<double> out(in.shape);
            for (std::size_t i = 0; i < in.count; ++i)
              out.mutable_data()[i] =
                  p.pressure({in.arrays[0].data()[2 * i], in.arrays[0].data()[2 * i + 1]});
            return finish(out, in.shape.empty());
          },
          py::arg("x"),
          "The pressure p₀ + β·(x − z₀) at points x (..., 2) of the loaded region, per unit "
          "area (per unit length for a line patch); it is negative outside the loaded region, "
          "where the patch carries nothing.")
      .def("__repr__", &repr);
}

}  // namespace

void bind_patches(py::module_& m) {
  bind_patch_class(m);
  m.def("_friction_wrench", &wrench, py::arg("patch"), py::arg("velocity"), py::arg("spin"),
        "The exact friction wrench of the patch moving with the planar twists (velocity "
        "(..., 2) of the patch origin, spin (...) counter-clockwise; broadcast): (force (..., 2), "
        "torque (...)) per unit μN, the torque about the patch origin in the vertices' length "
        "unit.  A zero twist (v = 0 and ω = 0) or a non-finite component raises ValueError.");
  m.def("_friction_dissipation", &dissipation, py::arg("patch"), py::arg("velocity"),
        py::arg("spin"),
        "The dissipation D = ∬ p |u| dA per unit μN of the twists (as friction_wrench), its "
        "gradient ∂D/∂(v_x, v_y, ω) = −(F_x, F_y, τ) (..., 3) and its Hessian (..., 3, 3) (+inf "
        "in every entry where it diverges: a line or point patch pivoting about one of its "
        "points): (value, gradient, hessian).");
}

}  // namespace spinslide_python
