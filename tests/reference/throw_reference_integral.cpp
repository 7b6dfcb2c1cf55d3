//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// generate_throw_reference: the stop time, distance and angle of a throw by
// nested quadrature in u = ln|ε − ε₀| (Gauss–Legendre panels, the inner
// integral by the rule's integration matrix, and the tail beyond the cut);
// generate_throw_reference.cpp says how and why.
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

#include "throw_reference.hpp"

namespace throw_reference {

namespace {

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

const legendre_rule& rule(std::size_t n) {
  static const legendre_rule a(route_a.points), b(route_b.points);
  return n == route_a.points ? a : b;
}

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

}  // namespace

// A throw with ω0 = 1 (the results scale as ω0, ω0², ω0²).
result unit_throw(const flow& fl, const route& r, const big& ei) {
  return throw_integral(fl, r, ei).run();
}

}  // namespace throw_reference
