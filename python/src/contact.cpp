//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The contact: the projection onto the coupled limit set, and the impulse
// and spring-history laws, for one contact or for arrays of contacts (a
// numpy simulator calls them once per step for all its contacts); for a
// round profile, and for a flat patch (with the inverse map of its limit
// surface).
#include "arrays.hpp"
#include "bindings.hpp"
#include "profile_handle.hpp"

#include <spinslide/contact/impulse_friction.hpp>
#include <spinslide/contact/limit_set.hpp>
#include <spinslide/contact/patch_impulse.hpp>
#include <spinslide/contact/patch_limit_set.hpp>
#include <spinslide/contact/spring_friction.hpp>

#include <array>
#include <string>
#include <type_traits>
#include <vector>

namespace spinslide_python {

namespace {

// What a projection or a law step returns for each contact: the force (a
// magnitude, or a 2-vector for the laws), the torque, whether it sticks and
// the slip's ratio.
class friction_outputs {
 public:
  friction_outputs(const std::vector<py::ssize_t>& shape, bool vector_force)
      : force_(vector_force ? with(shape, {2}) : shape),
        torque_(shape),
        ratio_(shape),
        sticking_(shape),
        scalar_(shape.empty()),
        f_(force_.mutable_data()),
        t_(torque_.mutable_data()),
        e_(ratio_.mutable_data()),
        s_(sticking_.mutable_data()) {}

  // Contact i's result (writes only: safe without the GIL).
  template <class Result>
  void set(std::size_t i, const Result& r) {
    if constexpr (std::is_arithmetic<decltype(r.force)>::value) {
      f_[i] = r.force;
    } else {
      f_[2 * i] = r.force[0];
      f_[2 * i + 1] = r.force[1];
    }
    t_[i] = r.torque;
    s_[i] = r.sticking;
    e_[i] = r.ratio;
  }

  py::dict to_dict() {
    py::dict out;
    out["force"] = force_.ndim() > torque_.ndim() ? py::object(force_) : finish(force_, scalar_);
    out["torque"] = finish(torque_, scalar_);
    out["sticking"] = finish(sticking_, scalar_);
    out["ratio"] = finish(ratio_, scalar_);
    return out;
  }

 private:
  py::array_t<double> force_, torque_, ratio_;
  py::array_t<bool> sticking_;
  bool scalar_;
  double *f_, *t_, *e_;
  bool* s_;
};

// The 3×3 matrix at element i of a broadcast (..., 3, 3) input, as a metric
// (its checks: std::domain_error, ValueError in Python).
spinslide::planar_metric<double> metric_at(const contiguous& m, std::size_t i) {
  const double* mi = m.data() + 9 * i;
  return spinslide::planar_metric<double>(
      {{{mi[0], mi[1], mi[2]}, {mi[3], mi[4], mi[5]}, {mi[6], mi[7], mi[8]}}});
}

// A patch's result adds its slip, a twist: (..., 2) and (...).
class patch_outputs : public friction_outputs {
 public:
  explicit patch_outputs(const std::vector<py::ssize_t>& shape)
      : friction_outputs(shape, true),
        velocity_(with(shape, {2})),
        spin_(shape),
        scalar_(shape.empty()),
        v_(velocity_.mutable_data()),
        w_(spin_.mutable_data()) {}

  template <class Result>
  void set(std::size_t i, const Result& r) {
    friction_outputs::set(i, r);
    v_[2 * i] = r.slip.velocity[0];
    v_[2 * i + 1] = r.slip.velocity[1];
    w_[i] = r.slip.omega;
  }

  py::dict to_dict() {
    py::dict out = friction_outputs::to_dict();
    out["slip_velocity"] = velocity_;
    out["slip_spin"] = finish(spin_, scalar_);
    return out;
  }

 private:
  py::array_t<double> velocity_, spin_;
  bool scalar_;
  double *v_, *w_;
};

spinslide::planar_twist<double> twist_at(const contiguous& v, const contiguous& w, std::size_t i) {
  return {{v.data()[2 * i], v.data()[2 * i + 1]}, w.data()[i]};
}

py::dict project_patch(const spinslide::polygon_patch<double>& patch, py::handle force,
                       py::handle torque, py::handle metric, py::handle start_velocity,
                       py::handle start_spin) {
  const broadcast in =
      broadcast_inputs({{force, 1}, {torque, 0}, {metric, 2}, {start_velocity, 1}, {start_spin, 0}},
                       {"force", "torque", "metric", "start_velocity", "start_spin"});
  patch_outputs out(in.shape);
  const double *f = in.arrays[0].data(), *t = in.arrays[1].data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < in.count; ++i) {
      const spinslide::planar_wrench<double> point{{f[2 * i], f[2 * i + 1]}, t[i]};
      out.set(i, spinslide::project_to_limit_set(patch, point, metric_at(in.arrays[2], i),
                                                 twist_at(in.arrays[3], in.arrays[4], i)));
    }
  }
  return out.to_dict();
}

py::dict surface_twist(const spinslide::polygon_patch<double>& patch, py::handle force,
                       py::handle torque) {
  const broadcast in = broadcast_inputs({{force, 1}, {torque, 0}}, {"force", "torque"});
  py::array_t<double> velocity(with(in.shape, {2})), spin(in.shape), gauge(in.shape);
  double *v = velocity.mutable_data(), *w = spin.mutable_data(), *g = gauge.mutable_data();
  const double *f = in.arrays[0].data(), *t = in.arrays[1].data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < in.count; ++i) {
      const auto r = spinslide::limit_surface_twist(
          patch, spinslide::planar_wrench<double>{{f[2 * i], f[2 * i + 1]}, t[i]});
      v[2 * i] = r.twist.velocity[0];
      v[2 * i + 1] = r.twist.velocity[1];
      w[i] = r.twist.omega;
      g[i] = r.gauge;
    }
  }
  const bool scalar = in.shape.empty();
  py::dict out;
  out["velocity"] = velocity;
  out["spin"] = finish(spin, scalar);
  out["gauge"] = finish(gauge, scalar);
  return out;
}

py::dict patch_impulse(const spinslide::polygon_patch<double>& patch, py::handle velocity,
                       py::handle spin, py::handle inverse_mass, py::handle normal_impulse,
                       py::handle mu, py::handle start_velocity, py::handle start_spin) {
  const broadcast in = broadcast_inputs({{velocity, 1},
                                         {spin, 0},
                                         {inverse_mass, 2},
                                         {normal_impulse, 0},
                                         {mu, 0},
                                         {start_velocity, 1},
                                         {start_spin, 0}},
                                        {"velocity", "spin", "inverse_mass", "normal_impulse",
                                         "friction_coefficient", "start_velocity", "start_spin"});
  patch_outputs out(in.shape);
  const double *v = in.arrays[0].data(), *w = in.arrays[1].data(), *n = in.arrays[3].data(),
               *u = in.arrays[4].data();
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < in.count; ++i) {
      const spinslide::patch_impulse_contact<double> c{
          spinslide::normal_impulse<double>{n[i]}, spinslide::friction_coefficient<double>{u[i]}};
      out.set(i, spinslide::impulse_friction(patch, std::array<double, 2>{v[2 * i], v[2 * i + 1]},
                                             w[i], metric_at(in.arrays[2], i), c,
                                             twist_at(in.arrays[5], in.arrays[6], i)));
    }
  }
  return out.to_dict();
}

py::dict project(const profile_handle& h, py::handle force, py::handle torque,
                 py::handle torque_weight) {
  const broadcast in = broadcast_inputs({{force, 0}, {torque, 0}, {torque_weight, 0}},
                                        {"force", "torque", "torque_weight"});
  friction_outputs out(in.shape, false);
  const double *x = in.arrays[0].data(), *y = in.arrays[1].data(), *w = in.arrays[2].data();
  {
    py::gil_scoped_release release;
    visit(h, [&](const auto& p) {
      for (std::size_t i = 0; i < in.count; ++i)
        out.set(i, spinslide::project_to_limit_set(p, x[i], y[i], w[i]));
    });
  }
  return out.to_dict();
}

py::dict impulse(const profile_handle& h, py::handle velocity, py::handle spin,
                 py::handle inverse_mass, py::handle radius, py::handle normal_impulse,
                 py::handle mu, py::handle start) {
  const broadcast in = broadcast_inputs({{velocity, 1},
                                         {spin, 0},
                                         {inverse_mass, 2},
                                         {radius, 0},
                                         {normal_impulse, 0},
                                         {mu, 0},
                                         {start, 0}},
                                        {"velocity", "spin", "inverse_mass", "radius",
                                         "normal_impulse", "friction_coefficient", "start_ratio"});
  friction_outputs out(in.shape, true);
  const double *v = in.arrays[0].data(), *w = in.arrays[1].data(), *a = in.arrays[3].data(),
               *n = in.arrays[4].data(), *u = in.arrays[5].data(), *s0 = in.arrays[6].data();
  {
    py::gil_scoped_release release;
    visit(h, [&](const auto& p) {
      for (std::size_t i = 0; i < in.count; ++i) {
        const spinslide::planar_metric<double> metric = metric_at(in.arrays[2], i);
        const spinslide::impulse_contact<double> c{spinslide::patch_radius<double>{a[i]},
                                                   spinslide::normal_impulse<double>{n[i]},
                                                   spinslide::friction_coefficient<double>{u[i]}};
        out.set(i,
                spinslide::impulse_friction(p, std::array<double, 2>{v[2 * i], v[2 * i + 1]}, w[i],
                                            metric, c, spinslide::curve_point<double>{s0[i]}));
      }
    });
  }
  return out.to_dict();
}

py::dict spring(const profile_handle& h, py::handle displacement, py::handle twist,
                py::handle curve_ratio, py::handle d_displacement, py::handle d_twist,
                py::handle kt, py::handle kw, py::handle radius, py::handle normal, py::handle mu) {
  const broadcast in =
      broadcast_inputs({{displacement, 1},
                        {twist, 0},
                        {curve_ratio, 0},
                        {d_displacement, 1},
                        {d_twist, 0},
                        {kt, 0},
                        {kw, 0},
                        {radius, 0},
                        {normal, 0},
                        {mu, 0}},
                       {"displacement", "twist", "curve_ratio", "displacement_increment",
                        "twist_increment", "tangential_stiffness", "twisting_stiffness", "radius",
                        "normal_force", "friction_coefficient"});
  friction_outputs out(in.shape, true);
  py::array_t<double> xi(with(in.shape, {2})), phi(in.shape), ce(in.shape);
  std::array<const double*, 10> p_in{};
  for (std::size_t k = 0; k < 10; ++k) p_in[k] = in.arrays[k].data();
  double *xo = xi.mutable_data(), *po = phi.mutable_data(), *co = ce.mutable_data();
  {
    py::gil_scoped_release release;
    visit(h, [&](const auto& p) {
      for (std::size_t i = 0; i < in.count; ++i) {
        spinslide::spring_history<std::array<double, 2>, double> history{
            {p_in[0][2 * i], p_in[0][2 * i + 1]},
            p_in[1][i],
            spinslide::curve_point<double>{p_in[2][i]}};
        const spinslide::spring_stiffness<double> springs{
            spinslide::tangential_stiffness<double>{p_in[5][i]},
            spinslide::twisting_stiffness<double>{p_in[6][i]}};
        const spinslide::force_contact<double> c{
            spinslide::patch_radius<double>{p_in[7][i]},
            spinslide::normal_force<double>{p_in[8][i]},
            spinslide::friction_coefficient<double>{p_in[9][i]}};
        const auto r = spinslide::spring_history_friction(
            p, history, std::array<double, 2>{p_in[3][2 * i], p_in[3][2 * i + 1]}, p_in[4][i],
            springs, c);
        out.set(i, r);
        xo[2 * i] = history.displacement[0];
        xo[2 * i + 1] = history.displacement[1];
        po[i] = history.twist;
        co[i] = history.curve.ratio;
      }
    });
  }
  const bool scalar = in.shape.empty();
  py::dict result = out.to_dict();
  result["displacement"] = std::move(xi);
  result["twist"] = finish(phi, scalar);
  result["curve_ratio"] = finish(ce, scalar);
  return result;
}

}  // namespace

void bind_contact(py::module_& m) {
  m.def("_project_to_limit_set", &project, py::arg("profile"), py::arg("force"), py::arg("torque"),
        py::arg("torque_weight"));
  m.def("_impulse_friction", &impulse, py::arg("profile"), py::arg("velocity"), py::arg("spin"),
        py::arg("inverse_mass"), py::arg("radius"), py::arg("normal_impulse"),
        py::arg("friction_coefficient"), py::arg("start_ratio"));
  m.def("_project_patch_to_limit_set", &project_patch, py::arg("patch"), py::arg("force"),
        py::arg("torque"), py::arg("metric"), py::arg("start_velocity"), py::arg("start_spin"));
  m.def("_limit_surface_twist", &surface_twist, py::arg("patch"), py::arg("force"),
        py::arg("torque"));
  m.def("_patch_impulse_friction", &patch_impulse, py::arg("patch"), py::arg("velocity"),
        py::arg("spin"), py::arg("inverse_mass"), py::arg("normal_impulse"),
        py::arg("friction_coefficient"), py::arg("start_velocity"), py::arg("start_spin"));
  m.def("_spring_history_friction", &spring, py::arg("profile"), py::arg("displacement"),
        py::arg("twist"), py::arg("curve_ratio"), py::arg("displacement_increment"),
        py::arg("twist_increment"), py::arg("tangential_stiffness"), py::arg("twisting_stiffness"),
        py::arg("radius"), py::arg("normal_force"), py::arg("friction_coefficient"));
}

}  // namespace spinslide_python
