//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// The profiles that Python builds at run time: a weighted sum of a list
// (C++'s weighted_sum takes its parts as template arguments) and a radial
// profile whose pressure is a Python callable.
#ifndef SPINSLIDE_PYTHON_RUNTIME_PROFILES_HPP
#define SPINSLIDE_PYTHON_RUNTIME_PROFILES_HPP

#include "profile_handle.hpp"

#include <pybind11/pybind11.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace spinslide_python {

using spinslide::force_torque_result;
using ratio_list = spinslide::detail::ratio_list<double>;

// weighted_sum over a list: the same normalisation (one function,
// detail::normalise_weights) and the same order of summation, so that it
// gives weighted_sum's numbers bit for bit.
class runtime_weighted_sum : public spinslide::profile_base<runtime_weighted_sum, double,
                                                            boost::math::policies::policy<>> {
 public:
  runtime_weighted_sum(std::vector<double> weights, std::vector<spinslide::erased_profile<>> parts)
      : parts_(std::move(parts)), w_(std::move(weights)) {
    if (parts_.empty())
      throw std::domain_error("spinslide.WeightedSum: the list of (weight, profile) is empty");
    spinslide::detail::normalise_weights<boost::math::policies::policy<>>(
        w_, "spinslide.WeightedSum(parts)");
  }
  const std::vector<double>& weights() const { return w_; }
  double mean_radius() const {
    return sum([](const spinslide::erased_profile<>& p) { return p.mean_radius(); });
  }
  double mean_inverse_radius() const {
    return sum([](const spinslide::erased_profile<>& p) { return p.mean_inverse_radius(); });
  }
  double mean_square_radius() const {
    return sum([](const spinslide::erased_profile<>& p) { return p.mean_square_radius(); });
  }
  ratio_list singular_ratios() const {
    ratio_list r;
    for (std::size_t i = 0; i < parts_.size(); ++i)
      if (w_[i] > 0) r.add_scaled(parts_[i].singular_ratios(), 1.0);
    return r;
  }

 private:
  friend class spinslide::profile_base<runtime_weighted_sum, double,
                                       boost::math::policies::policy<>>;
  static constexpr const char* name = "spinslide.WeightedSum";
  // Σ wᵢ𝓕ᵢ and Σ wᵢ𝓣ᵢ in the order of the parts, each part evaluated once,
  // without allocating (the terms of each sum are added in weighted_sum's
  // order, so the results are its own).
  force_torque_result<double> general(double eps) const {
    force_torque_result<double> r{0, 0};
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const auto ft = parts_[i].force_torque(eps);
      r.force += w_[i] * ft.force;
      r.torque += w_[i] * ft.torque;
    }
    return r;
  }
  template <class F>
  double sum(F f) const {
    double s = 0;
    for (std::size_t i = 0; i < parts_.size(); ++i) s += w_[i] * f(parts_[i]);
    return s;
  }

  std::vector<spinslide::erased_profile<>> parts_;
  std::vector<double> w_;
};

// A Python thread state kept for the life of a thread that Python did not
// start (stop_results' workers).  Without it each call of the pressure from
// such a thread creates and destroys one: 15 µs a call instead of 0.35 µs
// (measured: a RadialProfile throw in stop_results was 45 times slower than
// in simulate_throw).  Made on the thread's first call (without the GIL),
// released at its exit (the batch joins its workers with the GIL released).
class foreign_thread_state {
 public:
  foreign_thread_state() {
    if (PyGILState_GetThisThreadState() != nullptr) return;  // a Python thread
    state_ = PyGILState_Ensure();
    saved_ = PyEval_SaveThread();
  }
  ~foreign_thread_state() {
    if (saved_ == nullptr) return;
    PyEval_RestoreThread(saved_);
    PyGILState_Release(state_);
  }
  foreign_thread_state(const foreign_thread_state&) = delete;
  foreign_thread_state& operator=(const foreign_thread_state&) = delete;

 private:
  PyGILState_STATE state_{};
  PyThreadState* saved_ = nullptr;
};

// A Python callable p(r) as radial_profile's pressure.  Copies share it and
// are safe without the GIL (the library copies profiles on any thread); a
// call takes the GIL.  What the callable raises, or a result that is not a
// number, becomes a std::domain_error with its message (a ValueError in
// Python).
class python_pressure {
 public:
  explicit python_pressure(pybind11::function f)
      : f_(new pybind11::function(std::move(f)), [](pybind11::function* p) {
          pybind11::gil_scoped_acquire gil;
          delete p;
        }) {}
  double operator()(double r) const {
    static thread_local const foreign_thread_state keep;
    pybind11::gil_scoped_acquire gil;
    try {
      return (*f_)(r).cast<double>();
    } catch (pybind11::error_already_set& e) {
      throw std::domain_error(std::string("spinslide.RadialProfile: the pressure raised: ") +
                              e.what());
    } catch (const pybind11::cast_error&) {
      throw std::domain_error(
          "spinslide.RadialProfile: the pressure returned a non-number at r = " +
          std::to_string(r));
    }
  }

 private:
  std::shared_ptr<pybind11::function> f_;
};

}  // namespace spinslide_python

#endif  // SPINSLIDE_PYTHON_RUNTIME_PROFILES_HPP
