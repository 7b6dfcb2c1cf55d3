//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The dynamics: the terminal regime and the flow's zeros, throws (one, SI,
// sampled, and batches on every core).
#include "arrays.hpp"
#include "bindings.hpp"
#include "profile_handle.hpp"

#include <spinslide/motion/batch_throws.hpp>
#include <spinslide/motion/dynamics.hpp>
#include <spinslide/motion/terminal.hpp>

#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <optional>
#include <vector>

namespace spinslide_python {

namespace {

using spinslide::motion_sample;
using spinslide::stop_result;
using spinslide::terminal_regime;
using spinslide::terminal_state;

// The samples of a throw as numpy arrays, one per quantity.
py::dict samples_to_arrays(const std::vector<motion_sample<double>>& s) {
  const auto n = static_cast<py::ssize_t>(s.size());
  py::array_t<double> t(n), v(n), w(n), e(n), d(n), a(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    const auto& x = s[static_cast<std::size_t>(i)];
    t.mutable_at(i) = x.time;
    v.mutable_at(i) = x.speed;
    w.mutable_at(i) = x.spin;
    e.mutable_at(i) = x.ratio;
    d.mutable_at(i) = x.distance;
    a.mutable_at(i) = x.angle;
  }
  py::dict out;
  out["time"] = t;
  out["speed"] = v;
  out["spin"] = w;
  out["ratio"] = e;
  out["distance"] = d;
  out["angle"] = a;
  return out;
}

// One throw's result, and its trajectory if asked (a dict of arrays).
struct throw_result {
  stop_result<double> stop;
  py::object trajectory = py::none();
};

void bind_terminal(py::module_& m) {
  py::enum_<terminal_regime>(m, "TerminalRegime", "How the ratio ε behaves as the motion stops.")
      .value("pure_sliding", terminal_regime::pure_sliding, "ε → ∞: the spin ends first")
      .value("sliding_and_spinning", terminal_regime::sliding_and_spinning,
             "ε → ε₀: both end together")
      .value("pure_spinning", terminal_regime::pure_spinning, "ε → 0: the sliding ends first");
  py::class_<terminal_state<double>>(m, "TerminalState",
                                     "The terminal regime and the limit of ε at the stop.")
      .def_readonly("regime", &terminal_state<double>::regime)
      .def_readonly("ratio", &terminal_state<double>::ratio, "ε₀, inf or 0")
      .def("__repr__", [](const terminal_state<double>& s) {
        return "TerminalState(regime=" + std::string(py::str(py::cast(s.regime))) +
               ", ratio=" + std::string(py::str(py::float_(s.ratio))) + ")";
      });
  py::class_<spinslide::ratio_flow_zero<double>>(m, "RatioFlowZero",
                                                 "A zero ε₀ of the flow f(ε) = ε − γ𝓕/𝓣.")
      .def_readonly("ratio", &spinslide::ratio_flow_zero<double>::ratio)
      .def_readonly("attracting", &spinslide::ratio_flow_zero<double>::attracting)
      .def("__repr__", [](const spinslide::ratio_flow_zero<double>& z) {
        return "RatioFlowZero(ratio=" + std::string(py::str(py::float_(z.ratio))) +
               ", attracting=" + (z.attracting ? "True" : "False") + ")";
      });
  m.def(
      "terminal_motion",
      [](const profile_handle& h, double gamma, std::optional<double> initial) {
        py::gil_scoped_release release;
        return visit(h, [&](const auto& p) {
          return initial ? spinslide::terminal_motion(p, gamma, *initial)
                         : spinslide::terminal_motion(p, gamma);
        });
      },
      py::arg("profile"), py::arg("inertia_ratio"), py::arg("initial_ratio") = py::none(),
      "The terminal regime of a body with this profile and inertia ratio γ = I/(ma²) that "
      "starts sliding and spinning; with initial_ratio ε_i = v0/(aω0), the regime reached "
      "from it (needed where the flow has several attractors: otherwise ValueError).");
  m.def(
      "ratio_flow_zeros",
      [](const profile_handle& h, double gamma) {
        py::gil_scoped_release release;
        return visit(h, [&](const auto& p) { return spinslide::ratio_flow_zeros(p, gamma); });
      },
      py::arg("profile"), py::arg("inertia_ratio"),
      "Every zero of the flow f(ε) = ε − γ𝓕/𝓣 at which f changes sign, ascending, each with "
      "whether it attracts.");
  m.def(
      "terminal_window",
      [](const profile_handle& h) {
        const auto w = visit(h, [](const auto& p) { return spinslide::terminal_window(p); });
        return py::make_tuple(w.lower, w.upper);
      },
      py::arg("profile"),
      "(lower, upper): the inertia ratios ⟨r²⟩/2 < γ < 2⟨r⟩/⟨1/r⟩ for which every motion ends "
      "sliding and spinning with a finite ε₀.");
}

void bind_throws(py::module_& m) {
  py::class_<throw_result>(
      m, "StopResult",
      "A throw's stop: its time, distance, angle and terminal regime, and the trajectory "
      "where simulate_throw was asked for it.")
      .def_property_readonly(
          "time", [](const throw_result& r) { return r.stop.time; }, "the stop time (t* or s)")
      .def_property_readonly(
          "distance", [](const throw_result& r) { return r.stop.distance; },
          "the distance slid (s* or m)")
      .def_property_readonly(
          "angle", [](const throw_result& r) { return r.stop.angle; },
          "the angle turned (θ* or rad)")
      .def_property_readonly(
          "terminal", [](const throw_result& r) { return r.stop.terminal; },
          "the terminal regime and the limit of ε")
      .def_readonly("trajectory", &throw_result::trajectory,
                    "None, or (trajectory=True) a dict of arrays time, speed, spin, ratio, "
                    "distance, angle at the integrator's steps and the stop")
      .def("__repr__", [](const throw_result& r) {
        return "StopResult(time=" + std::string(py::str(py::float_(r.stop.time))) +
               ", distance=" + std::string(py::str(py::float_(r.stop.distance))) +
               ", angle=" + std::string(py::str(py::float_(r.stop.angle))) + ")";
      });
  m.def(
      "simulate_throw",
      [](const profile_handle& h, double gamma, double v0, double w0, bool keep) {
        std::vector<motion_sample<double>> steps;
        throw_result r;
        {
          py::gil_scoped_release release;
          r.stop = visit(h, [&](const auto& p) {
            if (!keep) return spinslide::simulate_throw(p, gamma, v0, w0);
            return spinslide::simulate_throw(
                p, gamma, v0, w0, [&steps](const motion_sample<double>& s) { steps.push_back(s); });
          });
        }
        if (keep) r.trajectory = samples_to_arrays(steps);
        return r;
      },
      py::arg("profile"), py::arg("inertia_ratio"), py::arg("v0"), py::arg("omega0"),
      py::arg("trajectory") = false,
      "The exact throw of a body with this profile and inertia ratio γ = I/(ma²) from the "
      "dimensionless speed v0* = v/(μ√(ga)) and spin ω0* = ω√(a/g)/μ (both ≥ 0): its stop "
      "time, distance, angle and terminal regime (dimensionless, t* = t√(g/a)).  For a "
      "smooth trajectory at chosen times use spinslide.trajectory.");
  m.def(
      "stop_time",
      [](const profile_handle& h, double gamma, double v0, double w0) {
        py::gil_scoped_release release;
        return visit(h, [&](const auto& p) { return spinslide::stop_time(p, gamma, v0, w0); });
      },
      py::arg("profile"), py::arg("inertia_ratio"), py::arg("v0"), py::arg("omega0"),
      "The dimensionless stop time t* of a throw (simulate_throw(...).time, without the rest).");
  m.def(
      "trajectory",
      [](const profile_handle& h, double gamma, double v0, double w0, std::vector<double> times) {
        std::vector<motion_sample<double>> s;
        {
          py::gil_scoped_release release;
          s = visit(h,
                    [&](const auto& p) { return spinslide::trajectory(p, gamma, v0, w0, times); });
        }
        return samples_to_arrays(s);
      },
      py::arg("profile"), py::arg("inertia_ratio"), py::arg("v0"), py::arg("omega0"),
      py::arg("times"),
      "The throw sampled at `times` (dimensionless, ascending, ≥ 0; at or after the stop the "
      "rest state): a dict of arrays time, speed, spin, ratio, distance, angle.");
  m.def(
      "simulate_throw_si",
      [](const profile_handle& h, double radius, double mu, double g, double gamma, double v0,
         double w0) {
        throw_result r;
        py::gil_scoped_release release;
        r.stop = visit(h, [&](const auto& p) {
          return spinslide::simulate_throw_si(
              p, spinslide::disk_radius<double>(radius),
              spinslide::friction_coefficient<double>(mu), spinslide::gravity<double>(g), gamma,
              spinslide::initial_speed<double>(v0), spinslide::initial_spin<double>(w0));
        });
        return r;
      },
      py::arg("profile"), py::kw_only(), py::arg("radius"), py::arg("friction_coefficient"),
      py::arg("gravity"), py::arg("inertia_ratio"), py::arg("v0"), py::arg("omega0"),
      "A throw in SI units (keyword arguments, so that none can be swapped): contact radius "
      "[m], μ, gravity [m/s²], γ = I/(ma²), speed v0 [m/s] and spin ω0 [rad/s] (both ≥ 0).  "
      "Returns the stop time [s], distance [m] and angle [rad].");
}

// stop_results over the broadcast starts; progress(done, total) is called
// with the GIL, from the calling thread, about every 0.1 s (it may raise,
// which ends the batch; so does Ctrl-C).
py::dict batch(const profile_handle& h, double gamma, py::handle v0, py::handle w0,
               unsigned threads, py::object progress) {
  py::module_ np = py::module_::import("numpy");
  py::tuple both = np.attr("broadcast_arrays")(as_array(v0, "v0"), as_array(w0, "omega0"));
  using array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const array v = array::ensure(both[0]), w = array::ensure(both[1]);
  std::vector<spinslide::throw_start<double>> starts(static_cast<std::size_t>(v.size()));
  for (std::size_t i = 0; i < starts.size(); ++i) starts[i] = {v.data()[i], w.data()[i]};
  spinslide::batch_options options;
  options.threads = threads;
  options.progress = [&progress](std::size_t done, std::size_t total) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (!progress.is_none()) progress(done, total);
  };
  std::vector<stop_result<double>> r;
  {
    py::gil_scoped_release release;
    r = visit(h, [&](const auto& p) { return spinslide::stop_results(p, gamma, starts, options); });
  }
  const std::vector<py::ssize_t> shape(v.shape(), v.shape() + v.ndim());
  array t(shape), d(shape), a(shape), e(shape);
  for (std::size_t i = 0; i < r.size(); ++i) {
    t.mutable_data()[i] = r[i].time;
    d.mutable_data()[i] = r[i].distance;
    a.mutable_data()[i] = r[i].angle;
    e.mutable_data()[i] = r[i].terminal.ratio;
  }
  py::dict out;
  out["time"] = t;
  out["distance"] = d;
  out["angle"] = a;
  out["terminal_ratio"] = e;
  return out;
}

}  // namespace

void bind_dynamics(py::module_& m) {
  bind_terminal(m);
  bind_throws(m);
  m.def("_stop_results", &batch, py::arg("profile"), py::arg("inertia_ratio"), py::arg("v0"),
        py::arg("omega0"), py::arg("threads"), py::arg("progress"),
        "stop_results' compiled part (spinslide.stop_results wraps it).");
}

}  // namespace spinslide_python
