//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Generates tests/reference/throw_reference.csv: the stop time t*, distance
// s* and angle θ* of throws (profile, γ, v0*, ω0*) in the paper's
// dimensionless units, by nested quadrature in the ratio ε = v*/ω*, in
// cpp_bin_float_100, with nothing of spinslide:
//
//   dv*/dt* = −𝓕(ε),  dω*/dt* = −𝓣(ε)/γ;  with x = −ln(ω*/ω0*),
//   dε/dx = f(ε) = ε − γ𝓕/𝓣,   dt*/dx = γω*/𝓣,   so
//   t* = γω0 ∫₀^∞ e^{−x}/𝓣 dx,  s* = γω0² ∫₀^∞ ε e^{−2x}/𝓣 dx,  θ* = γω0² ∫₀^∞ e^{−2x}/𝓣 dx
//
// (docs/theory.md §8–9).  The flow takes ε monotonically from ε_i = v0/ω0 to
// the attractor ε₀ (a zero of f, or 0 for pure spinning), reached as x → ∞,
// where e^{−x} decays like a power of |ε − ε₀|.  The integration variable is
// u = ln(|ε − ε₀|/s) (s = ε₀, or 1 if ε₀ = 0), ε = ε₀ + σ s e^u, in which
// dx = φ(u) du with φ = −(ε − ε₀)/f(ε) → 1/|f′(ε₀)| as u → −∞: smooth and
// bounded, no endpoint singularity.  Then
//
//   x(u) = ∫_u^{u_i} φ du′                                  (inner quadrature)
//   t* = γω0 [∫_{u_c}^{u_i} e^{−x} φ/𝓣 du + e^{−x_c}/𝓣(ε₀)]     (outer quadrature + tail)
//
// and likewise s*, θ* (tails ε₀e^{−2x_c}/(2𝓣(ε₀)) and e^{−2x_c}/(2𝓣(ε₀))).
// The cut u_c = ln 1e-45 (1e-22 for ε₀ = 0, where the tail's relative error
// is O(ε_c²) and the closed forms lose digits at small ε) makes the tail's
// relative error O(δ_c); f is evaluated in 100 digits so that its rounding
// near the zero, 1e-100/δ relative, stays far below the 35 digits kept.
//
// Quadrature: the u-range is split where ε crosses a point where 𝓕, 𝓣 are not
// analytic (ε = 1; and 1/8, the core's rim, for the two-attractor load), and
// cut into Gauss–Legendre panels of width ≤ 1, walked from u_i down.  On each
// panel φ and 𝓣 are sampled at the n nodes; x at the nodes is x at the
// panel's top plus the exact integral of the degree n−1 interpolant of φ (the
// inner quadrature, a spectral integration matrix), x at its bottom the
// Gauss–Legendre sum of φ; the outer sums use the same nodes.  A panel whose
// interpolants of φ or 𝓣 have their last two Legendre coefficients above a
// tolerance (relative to the largest) is bisected, down to a narrowest width
// (only next to a break, where the singular part of 𝓕, 𝓣 — (ε − 1) ln|ε − 1|
// for the ring, |ε − 1|^(3/2) for Boussinesq, weaker for the others — is
// negligible on so short a panel).  With a narrowest width of 1e-10 instead of
// 1e-40 the two routes differed by up to 3e-29 (the ring) and 3e-35
// (Boussinesq) on throws starting at or next to ε = 1.
//
// 𝓕, 𝓣 are the closed forms of docs/theory.md, evaluated here from scratch:
// uniform disk §2 (the paper's forms with the corrected torque for ε > 1,
// K and E from Boost ellint_1/ellint_2), Hertz (E1)/(E2), Boussinesq
// (B2)/(B1), and a two-attractor load: 3/4 of the load on the rim (ring,
// (R3)) and 1/4 as a uniform disk of radius 1/8 at the centre, whose flow has
// a repelling zero ε₁, an attractor ε₂ and an attracting ε = 0.
//
// Two routes: A (the table): n = 40, coefficient tolerance 1e-40, narrowest
// panel 1e-40, δ_c = 1e-45 (1e-22 for ε₀ = 0); B: n = 30, panels ≤ 1/2,
// tolerance 1e-38, narrowest 1e-36, δ_c = 1e-40 (1e-20).
//   generate_throw_reference             > tests/reference/throw_reference.csv
//   generate_throw_reference --validate  synthetic flows with exact answers, and
//                                        the closed forms against the 𝓕, 𝓣 tables
//   generate_throw_reference --compare FILE [STRIDE]
//                                        route B on every STRIDE-th row of FILE
// Progress on stderr.
//
// The program's parts: throw_reference.hpp (what they share),
// throw_reference_loads.cpp (the closed forms and the attractor),
// throw_reference_integral.cpp (the quadrature), throw_reference_validate.cpp
// (--validate), and this file (the table and --compare).
#include "csv.hpp"
#include "throw_reference.hpp"

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace throw_reference;

struct throw_spec {
  const char* profile;
  load kind;
  double gamma, v0, omega0;
};

result compute(const throw_spec& s, const route& r) {
  const flow fl{s.kind, big(s.gamma)};
  const big w = s.omega0;
  const result u = unit_throw(fl, r, big(s.v0) / w);
  return {u.end, u.time * w, u.distance * w * w, u.angle * w * w};
}

std::string digits(const big& x) { return x.str(40, std::ios_base::scientific); }

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The table's throws: each (profile, γ) with ε_i = 10^(k/3), k = −6 … 6,
// the attractor ε₀ (rounded to double), and 1 ± 2^−20; ω0 cycles 1, 2.5, 0.75.
std::vector<throw_spec> table_throws() {
  struct family {
    const char* name;
    load kind;
    std::vector<double> gammas;
  };
  const std::vector<family> families{{"uniform_disk", load::disk, {0.3, 0.5, 0.6}},
                                     {"hertz", load::hertz, {0.25, 0.4}},
                                     {"boussinesq", load::boussinesq, {0.4, 0.5, 0.8}},
                                     {"cd_annulus", load::cd_annulus, {0.5}}};
  const double omegas[] = {1.0, 2.5, 0.75};
  std::vector<throw_spec> out;
  int n = 0;
  auto add = [&](const char* name, load kind, double g, double eps) {
    const double w = omegas[n++ % 3];
    out.push_back({name, kind, g, eps * w, w});
  };
  for (const family& f : families) {
    for (double g : f.gammas) {
      for (int k = -6; k <= 6; k += 2) add(f.name, f.kind, g, std::pow(10.0, k / 3.0));
      const big e0 = attractor(flow{f.kind, big(g)}, big(1));
      add(f.name, f.kind, g, static_cast<double>(e0));
      add(f.name, f.kind, g, 1 - std::ldexp(1.0, -20));
      add(f.name, f.kind, g, 1 + std::ldexp(1.0, -20));
      if (f.kind == load::cd_annulus) {  // beside the inner edge ε = b
        add(f.name, f.kind, g, 0.125 * (1 - std::ldexp(1.0, -20)));
        add(f.name, f.kind, g, 0.125 * (1 + std::ldexp(1.0, -20)));
      }
    }
  }
  // Two attractors (0 and ε₂) and a repeller ε₁ at γ = 1/2.
  for (double eps : {0.01, 0.1, 0.3, 1.0, 10.0, 100.0})
    add("ring_and_core", load::ring_and_core, 0.5, eps);
  return out;
}

void print_row(const throw_spec& s, const result& r) {
  std::printf("%s,%a,%a,%a,%.17g,%s,%s,%s,%s\n", s.profile, s.gamma, s.v0, s.omega0,
              s.v0 / s.omega0, digits(r.end).c_str(), digits(r.time).c_str(),
              digits(r.distance).c_str(), digits(r.angle).c_str());
  std::fflush(stdout);
}

int generate() {
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<throw_spec> throws = table_throws();
  std::printf(
      "# spinslide reference: stop time, distance and angle of throws in the paper's\n"
      "# dimensionless units, by nested quadrature in u = ln|eps - eps0|\n"
      "# (Gauss-Legendre panels of 40 points, cpp_bin_float_100; tail cut at\n"
      "# |eps - eps0| = 1e-45 eps0, or 1e-22 for eps0 = 0).\n"
      "# generated by tests/reference/generate_throw_reference.cpp; 40 digits printed,\n"
      "# 35+ correct\n"
      "# (see docs/accuracy.md).  ring_and_core: 3/4 of the load on the rim, 1/4 a uniform disk\n"
      "# of radius 1/8 at the centre.  cd_annulus: uniform on 1/8 <= r <= 1 (the paper's CD).\n"
      "# columns: profile, gamma, v0, omega0 (exact, hex), eps_initial (v0/omega0, decimal),\n"
      "#          eps_final (0: pure spinning), time, distance, angle\n"
      "profile,gamma,v0,omega0,eps_initial,eps_final,time,distance,angle\n");
  for (std::size_t i = 0; i < throws.size(); ++i) {
    print_row(throws[i], compute(throws[i], route_a));
    std::fprintf(stderr, "%zu/%zu %s gamma=%g eps=%g: %ld evaluations of f (%.0f s)\n", i + 1,
                 throws.size(), throws[i].profile, throws[i].gamma, throws[i].v0 / throws[i].omega0,
                 evaluations, seconds_since(t0));
    evaluations = 0;
  }
  std::printf("# %zu throws in %.0f s of CPU time (one core)\n", throws.size(),
              static_cast<double>(std::clock()) / CLOCKS_PER_SEC);
  return 0;
}

load load_of(const std::string& name) {
  if (name == "uniform_disk") return load::disk;
  if (name == "hertz") return load::hertz;
  if (name == "boussinesq") return load::boussinesq;
  if (name == "ring_and_core") return load::ring_and_core;
  if (name == "cd_annulus") return load::cd_annulus;
  throw std::runtime_error("unknown profile " + name);
}

// Route B on every stride-th row of a table: the largest relative differences.
int compare(const std::string& path, std::size_t stride) {
  std::vector<std::vector<std::string>> rows;
  if (!spinslide_reference::read_csv_rows(path, "profile", rows)) return 2;
  big worst[4] = {0, 0, 0, 0};
  const auto t0 = std::chrono::steady_clock::now();
  for (std::size_t i = 0; i < rows.size(); i += stride) {
    const auto& c = rows[i];
    const throw_spec s{c.at(0).c_str(), load_of(c.at(0)), std::strtod(c.at(1).c_str(), nullptr),
                       std::strtod(c.at(2).c_str(), nullptr),
                       std::strtod(c.at(3).c_str(), nullptr)};
    const result r = compute(s, route_b);
    const big d[4] = {abs(r.end - big(c.at(5))), rel(r.time, big(c.at(6))),
                      rel(r.distance, big(c.at(7))), rel(r.angle, big(c.at(8)))};
    for (int k = 0; k < 4; ++k)
      if (d[k] > worst[k]) worst[k] = d[k];
    std::printf("%s gamma=%g eps=%s: |d eps0| %s, rel. d time %s distance %s angle %s (%.0f s)\n",
                s.profile, s.gamma, c.at(4).c_str(), d[0].str(3, std::ios_base::scientific).c_str(),
                d[1].str(3, std::ios_base::scientific).c_str(),
                d[2].str(3, std::ios_base::scientific).c_str(),
                d[3].str(3, std::ios_base::scientific).c_str(), seconds_since(t0));
    std::fflush(stdout);
  }
  std::printf("largest: |d eps0| %s, rel. d time %s, distance %s, angle %s\n",
              worst[0].str(3, std::ios_base::scientific).c_str(),
              worst[1].str(3, std::ios_base::scientific).c_str(),
              worst[2].str(3, std::ios_base::scientific).c_str(),
              worst[3].str(3, std::ios_base::scientific).c_str());
  const bool ok = worst[1] < big("1e-35") && worst[2] < big("1e-35") && worst[3] < big("1e-35");
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "--validate") return validate();
    if (mode == "--compare" && argc > 2)
      return compare(argv[2], argc > 3 ? std::strtoul(argv[3], nullptr, 10) : 1);
    if (!mode.empty()) {
      std::fprintf(stderr, "usage: %s [--validate | --compare FILE [STRIDE]]\n", argv[0]);
      return 2;
    }
    return generate();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "generate_throw_reference: %s\n", e.what());
    return 2;
  }
}
