//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The profile classes (UniformDisk, Annulus, Ring, Hertz, Boussinesq,
// WeightedSum, RadialProfile, Tabulated), their values and moments, and the
// coupling curve.
#include "arrays.hpp"
#include "bindings.hpp"
#include "profile_handle.hpp"
#include "runtime_profiles.hpp"

#include <spinslide/values/coupling.hpp>

#include <pybind11/stl.h>

#include <boost/math/differentiation/finite_difference.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace spinslide_python {

namespace {

struct uniform_disk_py : profile_handle {};
struct annulus_py : profile_handle {};
struct ring_py : profile_handle {};
struct hertz_py : profile_handle {};
struct boussinesq_py : profile_handle {};
struct weighted_sum_py : profile_handle {};
struct radial_profile_py : profile_handle {};
struct tabulated_py : profile_handle {};
struct scaled_py : profile_handle {};

template <class Handle, class Profile>
Handle make(Profile p, const std::string& repr) {
  Handle h;
  h.profile = std::move(p);
  h.repr = repr;
  return h;
}

// x as Python writes it (the shortest repr that reads back).
std::string number(double x) { return py::repr(py::float_(x)); }

// float32 in: the float64 result rounded to float32 (the profiles compute in
// float64); otherwise the float64 result.
py::object like_input(const py::array& eps, py::object result) {
  if (!is_float32(eps)) return result;
  if (py::isinstance<py::tuple>(result)) {
    py::tuple t = result;
    py::tuple out(t.size());
    for (std::size_t k = 0; k < t.size(); ++k) out[k] = t[k].attr("astype")("float32");
    return py::object(std::move(out));
  }
  return result.attr("astype")("float32");
}

template <class P>
constexpr bool has_closed_slope() {
  return spinslide::detail::has_member_force_derivative<P>::value ||
         std::is_same<P, spinslide::uniform_disk<>>::value;
}

// 𝓕′(ε) of a profile without a closed-form derivative (the annulus, the
// ring, sums, scaled and radial profiles): Boost's eighth-order central
// difference (finite_difference_derivative) of 𝓕(e^u) in u = ln ε, so that
// its step is relative to ε.  Its step (about 0.036 in u) shrinks near a
// singular ratio (detail::singular_ratios: 1 and the edges of the load),
// where 𝓕 is not smooth, so that the stencil stays well on one side.  At a
// singular ratio itself, the mean of the two sides 1e-7 away in u (𝓕′ is
// continuous there for a load with a density, and logarithmically infinite
// for a ring).  ε = 0: ⟨1/r⟩/2 (exact); ε = ∞: 0.  Accuracy: docs/python.md.
template <class P>
double numerical_slope(const P& p, double eps) {
  if (eps == 0) return p.mean_inverse_radius() / 2;
  if (std::isinf(eps)) return 0.0;
  (void)p.force(eps);  // a bad ε is reported as by the other methods
  const double u0 = std::log(eps);
  const auto singular = spinslide::detail::singular_ratios(p);
  double distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < singular.size(); ++i)
    distance = std::min(distance, std::fabs(u0 - std::log(singular[i])));
  // d𝓕/du at u, by Boost on s ↦ 𝓕(exp(u + scale·s)) at s = 0; for ε > 1,
  // where 𝓕 → 1 and its differences cancel, −ε times d𝓣/du (𝓣′ = −ε𝓕′, and
  // 𝓣 → ⟨r²⟩/(2ε) keeps its relative accuracy).
  const bool by_torque = eps > 1;
  auto slope_in_u = [&p, by_torque](double u, double scale) {
    auto f = [&p, u, scale, by_torque](double s) {
      const double e = std::exp(u + scale * s);
      return by_torque ? p.torque(e) : p.force(e);
    };
    const double d =
        boost::math::differentiation::finite_difference_derivative<decltype(f), double, 8>(f, 0.0) /
        scale;
    return by_torque ? -d / std::exp(u) : d;
  };
  const double step = std::pow(551.25 * std::numeric_limits<double>::epsilon(), 1.0 / 9);
  if (distance == 0) {
    const double side = 1e-7, scale = side / (40 * step);
    return (slope_in_u(u0 - side, scale) / std::exp(u0 - side) +
            slope_in_u(u0 + side, scale) / std::exp(u0 + side)) /
           2;
  }
  // The stencil, ±4 steps, spans a tenth of the distance to a singular ratio.
  return slope_in_u(u0, std::min(1.0, distance / (40 * step))) / eps;
}

template <class P>
double slope(const P& p, double eps) {
  if constexpr (std::is_same<P, spinslide::uniform_disk<>>::value) {
    (void)p;
    return spinslide::force_derivative(eps);
  } else if constexpr (has_closed_slope<P>()) {
    return p.force_derivative(eps);
  } else {
    return numerical_slope(p, eps);
  }
}

// f(profile, eps) over an array of ratios, in float64.
template <std::size_t N, class F>
py::object over_ratios(const profile_handle& h, py::handle eps, F f) {
  // The input read once: its dtype decides the output's.
  const py::array ratios = as_array(eps, "eps");
  auto body = [&h, f](const double* in, std::size_t n, std::array<double*, N> out) {
    visit(h, [&](const auto& p) {
      for (std::size_t i = 0; i < n; ++i) f(p, in[i], out, i);
    });
  };
  return like_input(ratios, map_typed<double, N>(ratios, body));
}

const char* const eps_doc =
    "\n\neps: the ratio ε = v/(aω) ≥ 0, any array-like (broadcast as numpy does); a scalar "
    "gives a scalar, float32 stays float32.  NaN or a negative ratio raises ValueError.";

void bind_profile_methods(py::class_<profile_handle>& c) {
  c.def(
      "force",
      [](const profile_handle& h, py::handle eps) {
        return over_ratios<1>(h, eps, [](const auto& p, double e, auto out, std::size_t i) {
          out[0][i] = p.force(e);
        });
      },
      py::arg("eps"), (std::string("𝓕(ε): the friction force in units of μN.") + eps_doc).c_str());
  c.def(
      "torque",
      [](const profile_handle& h, py::handle eps) {
        return over_ratios<1>(h, eps, [](const auto& p, double e, auto out, std::size_t i) {
          out[0][i] = p.torque(e);
        });
      },
      py::arg("eps"),
      (std::string("𝓣(ε): the friction torque in units of μNa (a: the contact radius).") + eps_doc)
          .c_str());
  c.def(
      "force_torque",
      [](const profile_handle& h, py::handle eps) {
        return over_ratios<2>(h, eps, [](const auto& p, double e, auto out, std::size_t i) {
          const auto ft = p.force_torque(e);
          out[0][i] = ft.force;
          out[1][i] = ft.torque;
        });
      },
      py::arg("eps"), (std::string("(𝓕(ε), 𝓣(ε)) from one evaluation.") + eps_doc).c_str());
  c.def(
      "force_derivative",
      [](const profile_handle& h, py::handle eps) {
        return over_ratios<1>(h, eps, [](const auto& p, double e, auto out, std::size_t i) {
          out[0][i] = slope(p, e);
        });
      },
      py::arg("eps"),
      (std::string("𝓕′(ε) = d𝓕/dε: the closed form for UniformDisk, Hertz, Boussinesq and "
                   "Tabulated (within 16 ulp); for the other profiles an eighth-order central "
                   "difference in ln ε (docs/python.md, \"Derivatives\").") +
       eps_doc)
          .c_str());
  c.def(
      "torque_derivative",
      [](const profile_handle& h, py::handle eps) {
        return over_ratios<1>(h, eps, [](const auto& p, double e, auto out, std::size_t i) {
          out[0][i] = std::isinf(e) ? 0.0 : -e * slope(p, e);
        });
      },
      py::arg("eps"),
      (std::string("𝓣′(ε) = −ε𝓕′(ε) (every profile obeys it; 𝓕′ as force_derivative).") + eps_doc)
          .c_str());
  c.def(
      "mean_radius",
      [](const profile_handle& h) {
        return visit(h, [](const auto& p) { return p.mean_radius(); });
      },
      "⟨r⟩ = 𝓣(0): the load-weighted mean radius, in units of the contact radius.");
  c.def(
      "mean_inverse_radius",
      [](const profile_handle& h) {
        return visit(h, [](const auto& p) { return p.mean_inverse_radius(); });
      },
      "⟨1/r⟩ = 2𝓕′(0) (may be inf).");
  c.def(
      "mean_square_radius",
      [](const profile_handle& h) {
        return visit(h, [](const auto& p) { return p.mean_square_radius(); });
      },
      "⟨r²⟩ = 2 lim ε𝓣(ε) as ε → ∞.");
  c.def("__repr__", [](const profile_handle& h) { return h.repr; });
}

void bind_profile_classes(py::module_& m) {
  using namespace spinslide;
  py::class_<uniform_disk_py, profile_handle>(m, "UniformDisk",
                                              "Uniform pressure on the disk: the paper's profile.")
      .def(py::init([] { return make<uniform_disk_py>(uniform_disk<>(), "UniformDisk()"); }));
  py::class_<annulus_py, profile_handle>(
      m, "Annulus", "Uniform pressure on the annulus b ≤ r ≤ 1 (the paper's CD: b = 0.125).")
      .def(py::init([](double b) {
             return make<annulus_py>(annulus<>(b), "Annulus(" + number(b) + ")");
           }),
           py::arg("inner_ratio"), "inner_ratio: b, 0 ≤ b < 1 (else ValueError).");
  py::class_<ring_py, profile_handle>(m, "Ring", "All the load on one circle r = radius.")
      .def(py::init([](double radius) {
             const std::string repr = "Ring(" + number(radius) + ")";
             if (radius == 1) return make<ring_py>(ring<>(), repr);
             return make<ring_py>(spinslide::erased_profile<>(scaled<ring<>>(ring<>(), radius)),
                                  repr);
           }),
           py::arg("radius") = 1.0,
           "radius: the circle's radius in units of the contact radius, in (0, 1] (else "
           "ValueError).");
  py::class_<hertz_py, profile_handle>(m, "Hertz",
                                       "p ∝ √(1 − r²): an elastic sphere's contact (closed forms).")
      .def(py::init([] { return make<hertz_py>(hertz<>(), "Hertz()"); }));
  py::class_<boussinesq_py, profile_handle>(
      m, "Boussinesq", "p ∝ 1/√(1 − r²): a rigid flat punch on an elastic body (closed forms).")
      .def(py::init([] { return make<boussinesq_py>(boussinesq<>(), "Boussinesq()"); }));
  py::class_<weighted_sum_py, profile_handle>(
      m, "WeightedSum",
      "A load-weighted sum: fraction wᵢ of the load is distributed as profile i (the weights "
      "are normalised).")
      .def(py::init([](const std::vector<std::pair<double, const profile_handle*>>& parts) {
             std::vector<double> w;
             std::vector<spinslide::erased_profile<>> p;
             std::string repr = "WeightedSum([";
             for (const auto& [weight, part] : parts) {
               if (part == nullptr) throw py::type_error("spinslide.WeightedSum: a part is None");
               w.push_back(weight);
               p.push_back(erase(*part));
               repr += (w.size() > 1 ? ", (" : "(") + number(weight) + ", " + part->repr + ")";
             }
             return make<weighted_sum_py>(
                 spinslide::erased_profile<>(runtime_weighted_sum(std::move(w), std::move(p))),
                 repr + "])");
           }),
           py::arg("parts"),
           "parts: a list of (weight, profile); each weight finite and ≥ 0, one > 0 (else "
           "ValueError).");
  py::class_<radial_profile_py, profile_handle>(
      m, "RadialProfile",
      "Any axisymmetric pressure p(r) on inner_ratio ≤ r ≤ 1, given as a Python callable; "
      "its values by quadrature (each evaluation calls p a few hundred times: tabulate it for "
      "speed).")
      .def(py::init([](py::function pressure, double inner_ratio) {
             return make<radial_profile_py>(
                 spinslide::erased_profile<>(radial_profile<double, python_pressure>(
                     python_pressure(std::move(pressure)), inner_ratio)),
                 "RadialProfile(<pressure>, inner_ratio=" + number(inner_ratio) + ")");
           }),
           py::arg("pressure"), py::arg("inner_ratio") = 0.0,
           "pressure: p(r) ≥ 0, finite except for integrable singularities at the ends; "
           "inner_ratio: b, 0 ≤ b < 1.");
  py::class_<scaled_py, profile_handle>(
      m, "Scaled",
      "A profile shrunk to the radius `radius` of the contact (0 < radius ≤ 1): its load on "
      "r ≤ radius, as the part of a weighted sum (a core under a ring, say).")
      .def(py::init([](const profile_handle& p, double radius) {
             return make<scaled_py>(
                 spinslide::erased_profile<>(scaled<spinslide::erased_profile<>>(erase(p), radius)),
                 "Scaled(" + p.repr + ", " + number(radius) + ")");
           }),
           py::arg("profile"), py::arg("radius"));
  py::class_<tabulated_py, profile_handle>(
      m, "Tabulated",
      "Any profile tabulated once (piecewise Chebyshev, 1e-13 relative by default): about the "
      "cost of the uniform disk per evaluation, whatever the profile.")
      .def(py::init([](const profile_handle& p, double tolerance) {
             auto table =
                 visit(p, [tolerance](const auto& q) { return tabulated_profile<>(q, tolerance); });
             return make<tabulated_py>(std::move(table), "Tabulated(" + p.repr + ", tolerance=" +
                                                             number(tolerance) + ")");
           }),
           py::arg("profile"), py::arg("tolerance") = 1e-13);
}

void bind_coupling(py::module_& m) {
  auto inverse = [&m](const char* name, const char* argument, const char* help, auto f) {
    m.def(
        name,
        [f, argument](const profile_handle& h, py::handle x) {
          return map_doubles<1>(
              x, argument, [&h, f](const double* in, std::size_t n, std::array<double*, 1> out) {
                visit(h, [&](const auto& p) {
                  for (std::size_t i = 0; i < n; ++i) out[0][i] = f(p, in[i]);
                });
              });
        },
        py::arg("profile"), py::arg(argument), help);
  };
  inverse("ratio_from_force", "force",
          "ε(𝓕): the ratio at which the profile's friction force is `force` (0 ≤ force < 1, "
          "else ValueError); array-like.",
          [](const auto& p, double f) { return spinslide::ratio_from_force(p, f); });
  inverse("torque_at_force", "force",
          "𝓣(𝓕): the exact limit curve, the largest torque that acts together with friction "
          "force `force` (0 ≤ force < 1); array-like.",
          [](const auto& p, double f) { return spinslide::torque_at_force(p, f); });
  inverse("ratio_from_torque", "torque",
          "ε(𝓣): the ratio at which the profile's friction torque is `torque` "
          "(0 < torque ≤ ⟨r⟩); array-like.",
          [](const auto& p, double t) { return spinslide::ratio_from_torque(p, t); });
  inverse("force_at_torque", "torque",
          "𝓕(𝓣): the limit curve read the other way (0 < torque ≤ ⟨r⟩); array-like.",
          [](const auto& p, double t) { return spinslide::force_at_torque(p, t); });
}

}  // namespace

void bind_profiles(py::module_& m) {
  py::class_<profile_handle> base(
      m, "Profile",
      "A friction profile: how the normal load is spread over the contact disk.  Its 𝓕(ε) "
      "and 𝓣(ε) are the friction force and torque in units of μN and μNa.");
  bind_profile_methods(base);
  bind_profile_classes(m);
  bind_coupling(m);
}

}  // namespace spinslide_python
