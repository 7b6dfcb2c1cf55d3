//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//  (See accompanying file LICENSE or copy at http://www.boost.org/LICENSE_1_0.txt)
//
// spinslide.force, torque, force_torque and the derivatives: the paper's
// uniformly pressed disk, over any array of ratios.
#include "arrays.hpp"
#include "bindings.hpp"

#include <spinslide/motion/terminal.hpp>
#include <spinslide/values/disk.hpp>

namespace spinslide_python {

namespace {

const char* const ratio_doc_tail = R"(

eps is the ratio ε = v/(Rω) of sliding speed to rim speed, ε ≥ 0 (0: pure
spinning; inf: pure sliding); any array-like, broadcast as numpy does.
float32 in gives float32 out, everything else float64; a scalar gives a
scalar.  Accuracy: within 4 ulp of the exact value everywhere (docs/accuracy.md).
NaN or a negative ratio raises ValueError.  The GIL is released over arrays.)";

std::string doc(const char* head) { return std::string(head) + ratio_doc_tail; }

template <class F>
void bind_unary(py::module_& m, const char* name, const char* head, F f) {
  m.def(
      name,
      [f](py::handle eps) {
        return map_reals<1>(eps, "eps", [f](const auto* in, std::size_t n, auto out) {
          for (std::size_t i = 0; i < n; ++i) out[0][i] = f(in[i]);
        });
      },
      py::arg("eps"), doc(head).c_str());
}

}  // namespace

void bind_values(py::module_& m) {
  bind_unary(m, "force",
             "𝓕(ε): the friction force of a sliding, spinning uniformly pressed disk, "
             "in units of μN.",
             [](auto e) { return spinslide::force(e); });
  bind_unary(m, "torque",
             "𝓣(ε): the friction torque of a sliding, spinning uniformly pressed "
             "disk, in units of μNR.",
             [](auto e) { return spinslide::torque(e); });
  bind_unary(m, "force_derivative", "𝓕′(ε) = d𝓕/dε of the uniformly pressed disk.",
             [](auto e) { return spinslide::force_derivative(e); });
  bind_unary(m, "torque_derivative", "𝓣′(ε) = d𝓣/dε = −ε𝓕′(ε) of the uniformly pressed disk.",
             [](auto e) { return spinslide::torque_derivative(e); });
  m.def(
      "force_torque",
      [](py::handle eps) {
        return map_reals<2>(eps, "eps", [](const auto* in, std::size_t n, auto out) {
          spinslide::force_torque_batch(in, n, out[0], out[1]);
        });
      },
      py::arg("eps"),
      doc("(𝓕(ε), 𝓣(ε)) of the uniformly pressed disk from one evaluation: a tuple of two "
          "arrays (or scalars), force in units of μN and torque in units of μNR; the fastest "
          "way to get both.")
          .c_str());
  // The benchmark's baseline (python/benchmarks/bench_python.py): the C++
  // batch on caller-owned float64 buffers, without numpy's conversions.
  m.def(
      "_force_torque_batch_into",
      [](const py::array_t<double, py::array::c_style>& eps,
         py::array_t<double, py::array::c_style>& f, py::array_t<double, py::array::c_style>& t) {
        if (f.size() < eps.size() || t.size() < eps.size())
          throw py::value_error("_force_torque_batch_into: the outputs are shorter than eps");
        const double* in = eps.data();
        double *fo = f.mutable_data(), *to = t.mutable_data();
        const auto n = static_cast<std::size_t>(eps.size());
        py::gil_scoped_release release;
        spinslide::force_torque_batch(in, n, fo, to);
      },
      py::arg("eps"), py::arg("force"), py::arg("torque"));
  m.def(
      "terminal_ratio", [] { return spinslide::terminal_ratio<double>(); },
      "ε₀ = 0.65300178920559763898…: the ratio at which a uniformly pressed disk with inertia "
      "ratio γ = I/(mR²) = 1/2 stops, sliding and spinning ending together (the paper's "
      "terminal ratio); within 1 ulp.");
}

}  // namespace spinslide_python
