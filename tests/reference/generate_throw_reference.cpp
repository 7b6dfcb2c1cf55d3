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
#include "csv.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using big = boost::multiprecision::cpp_bin_float_100;

struct ft {
  big force, torque;
};

big pi() { return boost::math::constants::pi<big>(); }

// Uniform disk, docs/theory.md §2: k = min(ε, 1/ε), m = k², y = 1 − m.
ft disk(const big& e) {
  if (e == 1) return {8 / (3 * pi()), 8 / (9 * pi())};
  const bool inside = e < 1;
  const big k = inside ? e : big(1 / e);
  const big m = k * k, y = (1 - k) * (1 + k);
  const big K = boost::math::ellint_1(k), E = boost::math::ellint_2(k);
  if (inside)
    return {4 * ((1 + m) * E - y * K) / (3 * pi() * k), 4 * ((4 - 2 * m) * E - y * K) / (9 * pi())};
  return {4 * ((1 + m) * E - y * K) / (3 * pi() * m),
          4 * ((4 * m - 2) * E + y * (2 - 3 * m) * K) / (9 * pi() * k * k * k)};
}

// Ring of radius 1 (R3).
ft ring(const big& e) {
  if (e == 1) return {2 / pi(), 2 / pi()};
  const bool inside = e < 1;
  const big k = inside ? e : big(1 / e);
  const big y = (1 - k) * (1 + k);
  const big K = boost::math::ellint_1(k), E = boost::math::ellint_2(k);
  if (inside) return {2 * (E - y * K) / (pi() * e), 2 * E / pi()};
  return {2 * E / pi(), 2 * e * (E - y * K) / pi()};
}

// Hertz (E1), (E2) and Boussinesq (B2), (B1).
ft hertz(const big& e) {
  const big e2 = e * e;
  if (e <= 1) return {3 * pi() * e * (4 - e2) / 32, 3 * pi() * (8 - 8 * e2 + 3 * e2 * e2) / 128};
  const big A = asin(1 / e), w = sqrt((e - 1) * (e + 1));
  return {3 * ((4 * e - e2 * e) * A + w * (e2 + 2) / e) / 16,
          3 * ((3 * e2 * e2 - 8 * e2 + 8) * A + 3 * w * (2 - e2)) / 64};
}

ft boussinesq(const big& e) {
  const big e2 = e * e;
  if (e <= 1) return {pi() * e / 4, pi() * (2 - e2) / 8};
  const big A = asin(1 / e), w = sqrt((e - 1) * (e + 1));
  return {(e * A + w / e) / 2, ((2 - e2) * A + w) / 4};
}

// 3/4 on the ring, 1/4 as a uniform disk of radius a = 1/8: the scaled disk
// has 𝓕(ε/a) and a𝓣(ε/a) (docs/theory.md §6, `scaled`).
ft ring_and_core(const big& e) {
  const big a = big(1) / 8;
  const ft r = ring(e), d = disk(e / a);
  return {(3 * r.force + d.force) / 4, (3 * r.torque + a * d.torque) / 4};
}

// The paper's CD: the annulus 1/8 ≤ r ≤ 1, the unit disk less the disk of
// radius b = 1/8, each uniform (docs/theory.md (A1)): 𝓕 = (𝓕_D(ε) − b²𝓕_D(ε/b))/(1 − b²),
// 𝓣 = (𝓣_D(ε) − b³𝓣_D(ε/b))/(1 − b²).  Singular at ε = b and ε = 1.
ft cd_annulus(const big& e) {
  const big b = big(1) / 8;
  const ft outer = disk(e), hole = disk(e / b);
  const big area = (1 - b) * (1 + b);
  return {(outer.force - b * b * hole.force) / area,
          (outer.torque - b * b * b * hole.torque) / area};
}

// The synthetic flows of --validate: f = ε − γ𝓕/𝓣 prescribed, so 𝓕 = (𝓣/γ)(ε − f),
// and 𝓣 = T constant: t* = γω0/T and θ* = γω0²/(2T) exactly, s* exactly for the
// linear flows; or 𝓣 = T + T₁(ε − ε₀) with f linear (linear_torque): t*, s*, θ*
// as series (validate()), a check of the tail's 𝓣 = 𝓣(ε₀).
const big synthetic_torque = big(7) / 10, torque_slope = big(1) / 10;
const big linear_zero = big(4) / 5, linear_rate = big(13) / 10, quadratic_b = big(1) / 2;

long evaluations = 0;  // of f, for the progress report

enum class load {
  disk,
  hertz,
  boussinesq,
  ring_and_core,
  cd_annulus,
  linear,
  linear_torque,
  quadratic,
  spin_linear
};

struct flow {
  load kind;
  big gamma;

  [[nodiscard]] ft at(const big& e) const {
    switch (kind) {
      case load::disk:
        return disk(e);
      case load::hertz:
        return hertz(e);
      case load::boussinesq:
        return boussinesq(e);
      case load::ring_and_core:
        return ring_and_core(e);
      case load::cd_annulus:
        return cd_annulus(e);
      default:
        break;
    }
    const big torque = kind == load::linear_torque
                           ? big(synthetic_torque + torque_slope * (e - linear_zero))
                           : synthetic_torque;
    return {torque * (e - synthetic_rate(e)) / gamma, torque};
  }
  // The prescribed f of the synthetic flows.
  [[nodiscard]] big synthetic_rate(const big& e) const {
    const big d = e - linear_zero;
    if (kind == load::linear || kind == load::linear_torque) return -linear_rate * d;
    if (kind == load::quadratic) return -linear_rate * d + quadratic_b * d * d;
    return -e / 2;  // spin_linear: ε → 0 with κ = 1/2
  }
  [[nodiscard]] big rate(const big& e) const {  // f(ε)
    ++evaluations;
    const ft v = at(e);
    return e - gamma * v.force / v.torque;
  }
  // Points where 𝓕 or 𝓣 is not analytic.
  [[nodiscard]] std::vector<big> breaks() const {
    if (kind == load::ring_and_core || kind == load::cd_annulus) return {big(1) / 8, big(1)};
    if (kind == load::disk || kind == load::hertz || kind == load::boussinesq) return {big(1)};
    return {};
  }
};

// The attractor the flow from ε_i reaches: march in the direction of the flow
// by factors 1.0625 until f changes sign, then TOMS 748 to full precision.
// 0 if ε falls below 1e-30 (pure spinning); sliding ends are not supported.
big attractor(const flow& fl, const big& ei) {
  const big fi = fl.rate(ei);
  if (abs(fi) < big("1e-90")) return ei;
  const bool down = fi < 0;
  const big factor("1.0625");
  big a = ei, fa = fi;
  for (int i = 0; i < 4000; ++i) {
    big b = down ? big(a / factor) : big(a * factor);
    if (down && b < big("1e-30")) return 0;
    if (!down && b > big("1e30")) throw std::runtime_error("the flow runs to pure sliding");
    const big fb = fl.rate(b);
    if (fb == 0) return b;
    if ((fb < 0) != (fa < 0)) {
      boost::uintmax_t iters = 500;
      auto f = [&](const big& e) { return fl.rate(e); };
      const auto r =
          down ? boost::math::tools::toms748_solve(
                     f, b, a, fb, fa,
                     boost::math::tools::eps_tolerance<big>(std::numeric_limits<big>::digits - 4),
                     iters)
               : boost::math::tools::toms748_solve(
                     f, a, b, fa, fb,
                     boost::math::tools::eps_tolerance<big>(std::numeric_limits<big>::digits - 4),
                     iters);
      return (r.first + r.second) / 2;
    }
    a = b;
    fa = fb;
  }
  throw std::runtime_error("no attractor found");
}

// Gauss–Legendre rule of n points on [−1, 1] (Newton on the three-term
// recurrence, in big), and its indefinite-integration matrix
// M[j][l] = ∫_{τ_j}^{1} ℓ_l(τ) dτ (ℓ_l the Lagrange basis of the nodes), from the
// Legendre expansion of the interpolant: ∫_τ^1 P_0 = 1 − τ,
// ∫_τ^1 P_k = (P_{k−1}(τ) − P_{k+1}(τ))/(2k + 1).
struct legendre_rule {
  std::vector<big> node, weight;
  std::vector<std::vector<big>> upper;  // M
  std::vector<std::vector<big>> basis;  // P_k(τ_l)

  explicit legendre_rule(std::size_t n) : node(n), weight(n), upper(n, std::vector<big>(n)) {
    for (std::size_t j = 0; j < n; ++j) {
      big t = cos(pi() * (j + big(3) / 4) / (n + big(1) / 2));
      for (int it = 0; it < 100; ++it) {
        const auto p = legendre(n, t);
        const big d = p.first / p.second;
        t -= d;
        if (abs(d) < big("1e-105")) break;
      }
      const auto p = legendre(n, t);
      node[j] = t;
      weight[j] = 2 / ((1 - t * t) * p.second * p.second);
    }
    for (std::size_t j = 0; j < n; ++j) basis.push_back(values(n, node[j]));
    for (std::size_t j = 0; j < n; ++j) {
      std::vector<big> P = values(n + 1, node[j]);  // P_0 … P_n at τ_j
      for (std::size_t l = 0; l < n; ++l) {
        std::vector<big> Q = values(n, node[l]);
        big m = (1 - node[j]) * Q[0] / 2;
        for (std::size_t k = 1; k < n; ++k)
          m += Q[k] * (P[k - 1] - P[k + 1]) / 2;  // (2k+1)/2 · (…)/(2k+1)
        upper[j][l] = weight[l] * m;
      }
    }
  }
  // P_0 … P_n at t.
  static std::vector<big> values(std::size_t n, const big& t) {
    std::vector<big> P(n + 1);
    P[0] = 1;
    if (n > 0) P[1] = t;
    for (std::size_t k = 1; k < n; ++k)
      P[k + 1] = ((2 * k + 1) * t * P[k] - k * P[k - 1]) / (k + 1);
    return P;
  }
  // P_n(t) and P_n′(t).
  static std::pair<big, big> legendre(std::size_t n, const big& t) {
    const std::vector<big> P = values(n, t);
    return {P[n], n * (t * P[n] - P[n - 1]) / (t * t - 1)};
  }
};

struct route {
  std::size_t points;  // Gauss–Legendre points per panel
  big width;           // the largest panel in u
  big tolerance;       // of the panels' last Legendre coefficients, relative
  big narrowest;       // panels are not bisected below this width
  big cut, cut_zero;   // δ_c for ε₀ > 0 and for ε₀ = 0
};
const route route_a{40, big(1), big("1e-40"), big("1e-40"), big("1e-45"), big("1e-22")};
const route route_b{30, big(1) / 2, big("1e-38"), big("1e-36"), big("1e-40"), big("1e-20")};

const legendre_rule& rule(std::size_t n) {
  static const legendre_rule a(route_a.points), b(route_b.points);
  return n == route_a.points ? a : b;
}

struct result {
  big end, time, distance, angle;
};

class throw_integral {
 public:
  throw_integral(const flow& fl, const route& r, const big& ei) : fl_(fl), r_(r), ei_(ei) {
    end_ = attractor(fl, ei);
    scale_ = end_ > 0 ? end_ : big(1);
    sign_ = ei > end_ ? 1 : -1;
    cut_ = log(end_ > 0 ? r.cut : r.cut_zero);
  }

  // Panels from u_i down to u_c; x(u_i) = 0 and x carried down panel by panel.
  result run() {
    const big distance = abs(ei_ - end_) / scale_;
    const big ui = distance > 0 ? big(log(distance)) : cut_;
    big x = 0;
    if (ui > cut_) {
      std::vector<big> ends{cut_, ui}, breaks{};
      for (const big& b : fl_.breaks()) {
        const big d = (b - end_) * sign_ / scale_;
        if (d > exp(cut_) && d < distance) breaks.push_back(log(d));
      }
      ends.insert(ends.end(), breaks.begin(), breaks.end());
      std::sort(ends.begin(), ends.end());
      std::vector<std::pair<big, big>> panels;
      for (std::size_t j = ends.size() - 1; j-- > 0;) split(ends[j], ends[j + 1], panels);
      for (const auto& p : panels) x = panel(p.first, p.second, x);
    }
    add_tail(x);
    return {end_, fl_.gamma * time_, fl_.gamma * distance_, fl_.gamma * angle_};
  }

 private:
  // [a, b] into panels no wider than the route's width, from the top down.
  void split(const big& a, const big& b, std::vector<std::pair<big, big>>& out) const {
    if (b - a > r_.width) {
      const big mid = (a + b) / 2;
      split(mid, b, out);
      split(a, mid, out);
      return;
    }
    out.emplace_back(a, b);
  }

  // One panel [a, b] with x(b) = xb: adds its part of the three integrals and
  // returns x(a).  x at the nodes is the indefinite integral of the
  // interpolant of φ (the inner quadrature), then the outer Gauss–Legendre sum.
  // A panel whose φ or 𝓣 is not resolved (the last two Legendre coefficients
  // of the interpolant above the route's tolerance times the largest) is
  // bisected, down to the route's narrowest width (only next to a break, where
  // the singular part is then negligible).
  big panel(const big& a, const big& b, const big& xb) {
    const legendre_rule& q = rule(r_.points);
    const std::size_t n = q.node.size();
    const big half = (b - a) / 2;
    std::vector<big> phi(n), eps(n), torque(n);
    for (std::size_t l = 0; l < n; ++l) {
      const big u = a + half * (q.node[l] + 1);
      const big d = sign_ * scale_ * exp(u);
      eps[l] = end_ + d;
      const ft v = fl_.at(eps[l]);
      ++evaluations;
      phi[l] = -d / (eps[l] - fl_.gamma * v.force / v.torque);
      torque[l] = v.torque;
    }
    if (b - a > r_.narrowest && !(resolved(q, phi) && resolved(q, torque))) {
      const big mid = (a + b) / 2;
      return panel(a, mid, panel(mid, b, xb));
    }
    big xa = xb;
    for (std::size_t j = 0; j < n; ++j) {
      big x = xb;
      for (std::size_t l = 0; l < n; ++l) x += half * q.upper[j][l] * phi[l];
      xa += half * q.weight[j] * phi[j];
      const big e1 = exp(-x), w = half * q.weight[j] * phi[j] / torque[j];
      time_ += w * e1;
      angle_ += w * e1 * e1;
      distance_ += w * eps[j] * e1 * e1;
    }
    return xa;
  }

  // Whether the interpolant's two highest Legendre coefficients are below the
  // tolerance times the largest.
  [[nodiscard]] bool resolved(const legendre_rule& q, const std::vector<big>& y) const {
    const std::size_t n = q.node.size();
    big largest = 0, last = 0;
    for (std::size_t k = 0; k < n; ++k) {
      big c = 0;
      for (std::size_t l = 0; l < n; ++l) c += q.weight[l] * y[l] * q.basis[l][k];
      c = abs(c * (2 * k + 1) / 2);
      if (c > largest) largest = c;
      if (k + 2 >= n && c > last) last = c;
    }
    return last <= r_.tolerance * largest;
  }

  // The part beyond u_c, where ε = ε₀ to O(δ_c): ∫_{x_c}^∞ of the integrands
  // with 𝓣 = 𝓣(ε_c) (for ε₀ = 0, ε = ε_c e^{−κ(x − x_c)} in s*, κ = −f(ε_c)/ε_c).
  void add_tail(const big& xc) {
    const big ec = end_ > 0 ? end_ : big(exp(cut_));
    const big torque = fl_.at(ec).torque;
    const big e1 = exp(-xc), e2 = e1 * e1;
    time_ += e1 / torque;
    angle_ += e2 / (2 * torque);
    if (end_ > 0) {
      distance_ += end_ * e2 / (2 * torque);
    } else {
      const big kappa = -fl_.rate(ec) / ec;
      distance_ += ec * e2 / ((2 + kappa) * torque);
    }
  }

  flow fl_;
  route r_;
  big ei_, end_, scale_, cut_;
  int sign_;
  big time_ = 0, distance_ = 0, angle_ = 0;
};

// A throw with ω0 = 1 (the results scale as ω0, ω0², ω0²).
result unit_throw(const flow& fl, const route& r, const big& ei) {
  return throw_integral(fl, r, ei).run();
}

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

big rel(const big& a, const big& b) { return b == 0 ? abs(a) : big(abs(a / b - 1)); }

// The closed forms above against the quadrature tables of 𝓕 and 𝓣 beside this
// file (the disk's area integrals, 64 digits; Hertz's and Boussinesq's ring
// kernel, 40 digits), for 1e-3 ≤ ε ≤ 1e3: the number of failures.
int closed_forms_against_tables() {
  std::vector<std::vector<std::string>> disk_rows, elastic_rows;
  if (!spinslide_reference::read_csv_rows(SPINSLIDE_DISK_REFERENCE, "eps_hex", disk_rows) ||
      !spinslide_reference::read_csv_rows(SPINSLIDE_ELASTIC_REFERENCE, "", elastic_rows))
    return 1;
  big worst_disk = 0, worst_elastic = 0;
  auto note = [](big& worst, const ft& v, const std::string& f, const std::string& t) {
    const big d = std::max(abs(v.force / big(f) - 1), abs(v.torque / big(t) - 1));
    if (d > worst) worst = d;
  };
  const double lo = 1e-3, hi = 1e3;
  for (const auto& c : disk_rows) {
    const double e = std::strtod(c.at(0).c_str(), nullptr);
    if (e >= lo && e <= hi) note(worst_disk, disk(big(e)), c.at(3), c.at(4));
  }
  for (const auto& c : elastic_rows) {
    const double e = std::strtod(c.at(1).c_str(), nullptr);
    if (e < lo || e > hi) continue;
    note(worst_elastic, c.at(0) == "hertz" ? hertz(big(e)) : boussinesq(big(e)), c.at(2), c.at(3));
  }
  std::printf("closed forms against disk_reference.csv: largest relative difference %s\n",
              worst_disk.str(3, std::ios_base::scientific).c_str());
  std::printf("closed forms against elastic_reference.csv: largest relative difference %s\n",
              worst_elastic.str(3, std::ios_base::scientific).c_str());
  return (worst_disk < big("1e-45") ? 0 : 1) + (worst_elastic < big("1e-38") ? 0 : 1);
}

// Synthetic flows with exact answers, both routes.
int validate() {
  int failures = 0;
  auto check = [&](const char* what, const big& got, const big& exact) {
    const big e = rel(got, exact);
    const bool ok = e < big("1e-38");
    failures += ok ? 0 : 1;
    std::printf("%-40s rel. error %s %s\n", what, e.str(3, std::ios_base::scientific).c_str(),
                ok ? "" : "FAIL");
  };
  const big gamma = big(1) / 2, T = synthetic_torque;
  for (const route* r : {&route_a, &route_b}) {
    const char* name = r == &route_b ? "B" : "A";
    std::printf("route %s\n", name);
    for (const char* start : {"0.05", "3", "0.81"}) {
      const big ei(start);
      const result lin = unit_throw(flow{load::linear, gamma}, *r, ei);
      std::printf(" linear flow, eps0 = 4/5, eps_i = %s:\n", start);
      check("  time", lin.time, gamma / T);
      check("  angle", lin.angle, gamma / (2 * T));
      check("  distance", lin.distance,
            gamma / T * (linear_zero / 2 + (ei - linear_zero) / (linear_rate + 2)));
      check("  eps_final", lin.end, linear_zero);
    }
    for (const char* start : {"0.05", "3"}) {
      // 1/𝓣 = Σ (−q)^n e^{−nλx}/T with q = T₁(ε_i − ε₀)/T, integrated term by term.
      const big ei(start), delta = ei - linear_zero, q = -torque_slope * delta / T;
      big t = 0, s = 0, th = 0, term = 1;
      for (int n = 0; abs(term) > big("1e-110"); ++n, term *= q) {
        t += term / (1 + n * linear_rate);
        th += term / (2 + n * linear_rate);
        s += term * (linear_zero / (2 + n * linear_rate) + delta / (2 + (n + 1) * linear_rate));
      }
      const result v = unit_throw(flow{load::linear_torque, gamma}, *r, ei);
      std::printf(" linear flow, torque 7/10 + (eps - 4/5)/10, eps_i = %s:\n", start);
      check("  time", v.time, gamma * t / T);
      check("  angle", v.angle, gamma * th / T);
      check("  distance", v.distance, gamma * s / T);
    }
    for (const char* start : {"0.05", "3", "0.81"}) {
      const big ei(start);
      const result q = unit_throw(flow{load::quadratic, gamma}, *r, ei);
      std::printf(" quadratic flow, eps0 = 4/5, eps_i = %s:\n", start);
      check("  time", q.time, gamma / T);
      check("  angle", q.angle, gamma / (2 * T));
    }
    for (const char* start : {"0.01", "1", "100"}) {
      const big ei(start);
      const result z = unit_throw(flow{load::spin_linear, gamma}, *r, ei);
      std::printf(" flow to pure spinning, kappa = 1/2, eps_i = %s:\n", start);
      check("  time", z.time, gamma / T);
      check("  angle", z.angle, gamma / (2 * T));
      check("  distance", z.distance, gamma / T * ei / (2 + big(1) / 2));
    }
  }
  failures += closed_forms_against_tables();
  std::printf("%d failures\n", failures);
  return failures == 0 ? 0 : 1;
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
