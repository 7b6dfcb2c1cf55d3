//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// Generates tests/reference/patch_reference.csv: the friction wrench of a
// flat patch (values/friction_wrench.hpp) straight from the DEFINING AREA
// INTEGRALS, in cpp_bin_float_50,
//   F = −∬ p û dA,   τ = −∬ p (x × û) dA,   û = u/|u|,  u = v + ω ẑ × x,
// with no closed form anywhere (spinslide sums elementary edge terms and the
// far field's contour integrals instead):
//  - the pressure: uniform, or p = (α + β·x)₊ with ∬ p = 1 and ∬ p x = e,
//    solved here by Newton with a finite-difference Jacobian on moments
//    computed by Gauss quadrature of the clipped polygon's triangles;
//  - the wrench in polar coordinates about the instantaneous centre c =
//    ẑ × v/ω: the polygon as the signed triangles (c, A, B) of its edges,
//    each ∫dθ ∫₀^ρ(θ) f ρ dρ, f the raw integrand evaluated from (v, ω) at
//    x = c + ρ e(θ) (Gauss in ρ, where f ρ is a polynomial; tanh_sinh in θ),
//    so that the kink of |u| at c sits at the triangles' common vertex; for
//    a centre beyond 8 sizes, where those triangles would be huge and cancel,
//    30 × 30 Gauss points on the patch's own triangles (the integrand is
//    analytic there);
//  - ω = 0: û = v̂ everywhere, F = −v̂ and τ = −(∬ p x) × v̂.
//   ./build/wrench/tests/generate_patch_reference > tests/reference/patch_reference.csv
// (a few minutes; the rows are tests/reference/patch_cases.hpp's).
#include "csv.hpp"
#include "patch_cases.hpp"

#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using big = boost::multiprecision::cpp_bin_float_50;
using pt = std::array<big, 2>;

big cross(const pt& a, const pt& b) { return a[0] * b[1] - a[1] * b[0]; }
pt sub(const pt& a, const pt& b) { return {a[0] - b[0], a[1] - b[1]}; }

std::vector<pt> to_big(const std::vector<patch_cases::point>& v) {
  std::vector<pt> out;
  out.reserve(v.size());
  for (const auto& p : v) out.push_back({big(p[0]), big(p[1])});
  return out;
}

// The pressure (α + β·x)₊ on its loaded polygon.
struct pressure {
  big alpha;
  pt beta;
  std::vector<pt> loaded;
  big at(const pt& x) const { return alpha + beta[0] * x[0] + beta[1] * x[1]; }
};

std::vector<pt> clip(const std::vector<pt>& poly, const big& alpha, const pt& beta) {
  std::vector<pt> out;
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const pt& a = poly[i];
    const pt& b = poly[(i + 1) % n];
    const big fa = alpha + beta[0] * a[0] + beta[1] * a[1];
    const big fb = alpha + beta[0] * b[0] + beta[1] * b[1];
    if (fa >= 0) out.push_back(a);
    if ((fa > 0 && fb < 0) || (fa < 0 && fb > 0)) {
      const big t = fa / (fa - fb);
      out.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
  }
  return out;
}

// ∬ g over a polygon, g polynomial of degree ≤ 3: the triangles (v0, vi, vi+1)
// mapped from the square (Duffy), 4 × 4 Gauss points (exact to degree 7 in each).
template <class G>
big polygon_integral(const std::vector<pt>& poly, G g) {
  using rule = boost::math::quadrature::gauss<big, 7>;
  big sum = 0;
  for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
    const pt e1 = sub(poly[i], poly[0]), e2 = sub(poly[i + 1], poly[0]);
    const big jac = cross(e1, e2);
    const big s = rule::integrate([&](const big& x) {
      const big u = (x + 1) / 2;
      return rule::integrate([&](const big& y) {
        const big w = (y + 1) / 2;
        // (u, w) in the square → (u, u w) in the triangle, Jacobian u.
        const pt p{poly[0][0] + u * (1 - w) * e1[0] + u * w * e2[0],
                   poly[0][1] + u * (1 - w) * e1[1] + u * w * e2[1]};
        return big(g(p) * u / 4);
      });
    });
    sum += s * jac;
  }
  return sum;
}

// The residual (∬ p − 1, ∬ p x − e) of θ = (α, β).
std::array<big, 3> residual(const std::vector<pt>& poly, const pt& e, const std::array<big, 3>& t) {
  const pressure p{t[0], {t[1], t[2]}, clip(poly, t[0], {t[1], t[2]})};
  return {polygon_integral(p.loaded, [&](const pt& x) { return p.at(x); }) - 1,
          polygon_integral(p.loaded, [&](const pt& x) { return big(p.at(x) * x[0]); }) - e[0],
          polygon_integral(p.loaded, [&](const pt& x) { return big(p.at(x) * x[1]); }) - e[1]};
}

bool solve3(std::array<std::array<big, 3>, 3> m, std::array<big, 3> b, std::array<big, 3>& x) {
  for (std::size_t c = 0; c < 3; ++c) {
    std::size_t piv = c;
    for (std::size_t r = c + 1; r < 3; ++r)
      if (abs(m[r][c]) > abs(m[piv][c])) piv = r;
    std::swap(m[c], m[piv]);
    std::swap(b[c], b[piv]);
    if (m[c][c] == 0) return false;
    for (std::size_t r = c + 1; r < 3; ++r) {
      const big f = m[r][c] / m[c][c];
      for (std::size_t k = c; k < 3; ++k) m[r][k] -= f * m[c][k];
      b[r] -= f * b[c];
    }
  }
  for (std::size_t c = 3; c-- > 0;) {
    big s = b[c];
    for (std::size_t k = c + 1; k < 3; ++k) s -= m[c][k] * x[k];
    x[c] = s / m[c][c];
  }
  return true;
}

// Newton with a central-difference Jacobian, from the uniform pressure.
pressure solve_pressure(const std::vector<pt>& poly, const pt& e) {
  const big area = polygon_integral(poly, [](const pt&) { return big(1); });
  std::array<big, 3> t{1 / area, 0, 0};
  for (int it = 0; it < 60; ++it) {
    const auto r = residual(poly, e, t);
    if (abs(r[0]) + abs(r[1]) + abs(r[2]) < big(1e-46)) break;
    std::array<std::array<big, 3>, 3> jac;
    const big h = big(1e-22) * (abs(t[0]) + abs(t[1]) + abs(t[2]));
    for (std::size_t k = 0; k < 3; ++k) {
      auto tp = t, tm = t;
      tp[k] += h;
      tm[k] -= h;
      const auto rp = residual(poly, e, tp), rm = residual(poly, e, tm);
      for (std::size_t i = 0; i < 3; ++i) jac[i][k] = (rp[i] - rm[i]) / (2 * h);
    }
    std::array<big, 3> step{};
    if (!solve3(jac, {-r[0], -r[1], -r[2]}, step)) break;
    // Halve the step while it empties the loaded region or raises the residual.
    big lam = 1;
    for (int k = 0; k < 40; ++k, lam /= 2) {
      const std::array<big, 3> tt{t[0] + lam * step[0], t[1] + lam * step[1], t[2] + lam * step[2]};
      if (clip(poly, tt[0], {tt[1], tt[2]}).size() < 3) continue;
      const auto rt = residual(poly, e, tt);
      if (abs(rt[0]) + abs(rt[1]) + abs(rt[2]) < abs(r[0]) + abs(r[1]) + abs(r[2])) {
        t = tt;
        break;
      }
    }
  }
  return {t[0], {t[1], t[2]}, clip(poly, t[0], {t[1], t[2]})};
}

struct wrench {
  big fx, fy, tau;
};

// One signed triangle (c, A, B) in polar coordinates about c.
wrench triangle_about_centre(const pressure& p, const pt& c, const pt& A, const pt& B,
                             const big& vx, const big& vy, const big& omega) {
  using boost::multiprecision::atan2;
  const pt a = sub(A, c), b = sub(B, c), d = sub(b, a);
  const big h = cross(a, d);  // |AB| times the distance of c from the line AB
  if (abs(h) < big(1e-45)) return {0, 0, 0};
  const big theta_a = atan2(a[1], a[0]);
  const big sweep = atan2(cross(a, b), a[0] * b[0] + a[1] * b[1]);
  static boost::math::quadrature::tanh_sinh<big> ts;
  using inner = boost::math::quadrature::gauss<big, 7>;
  auto component = [&](int k) {
    auto f = [&](const big& s) {
      const big th = theta_a + s * sweep;
      const pt e{cos(th), sin(th)};
      const big rmax = h / cross(e, d);
      return big(inner::integrate([&](const big& y) {
                   const big rho = rmax * (y + 1) / 2;
                   const pt x{c[0] + rho * e[0], c[1] + rho * e[1]};
                   const big ux = vx - omega * x[1], uy = vy + omega * x[0];
                   const big speed = sqrt(ux * ux + uy * uy);
                   const big w = p.at(x) * rho * rmax / 2;
                   if (k == 0) return big(-w * ux / speed);
                   if (k == 1) return big(-w * uy / speed);
                   return big(-w * (x[0] * uy - x[1] * ux) / speed);
                 }) *
                 sweep);
    };
    return big(ts.integrate(f, big(0), big(1), big(1e-45)));
  };
  return {component(0), component(1), component(2)};
}

// The wrench by 30 × 30 Gauss points on each triangle of the fan from the
// first vertex (Duffy), of the raw integrand: for a centre far outside the
// patch (> 8 sizes) the integrand is analytic on it and Gauss converges like
// (2R)^−60; there the polar triangles about c would be huge and cancel.
wrench direct_wrench(const pressure& p, const big& vx, const big& vy, const big& omega) {
  using rule = boost::math::quadrature::gauss<big, 30>;
  const std::vector<pt>& v = p.loaded;
  wrench w{0, 0, 0};
  for (std::size_t i = 1; i + 1 < v.size(); ++i) {
    const pt e1 = sub(v[i], v[0]), e2 = sub(v[i + 1], v[0]);
    const big jac = cross(e1, e2);
    for (int k = 0; k < 3; ++k) {
      const big s = rule::integrate([&](const big& a) {
        const big u = (a + 1) / 2;
        return rule::integrate([&](const big& b) {
          const big t = (b + 1) / 2;
          const pt x{v[0][0] + u * (1 - t) * e1[0] + u * t * e2[0],
                     v[0][1] + u * (1 - t) * e1[1] + u * t * e2[1]};
          const big ux = vx - omega * x[1], uy = vy + omega * x[0];
          const big f = -p.at(x) * u / 4 / sqrt(ux * ux + uy * uy);
          if (k == 0) return big(f * ux);
          if (k == 1) return big(f * uy);
          return big(f * (x[0] * uy - x[1] * ux));
        });
      });
      (k == 0 ? w.fx : k == 1 ? w.fy : w.tau) += s * jac;
    }
  }
  return w;
}

// The wrench about the instantaneous centre c: the signed polar triangles.
wrench polar_wrench(const pressure& p, const big& vx, const big& vy, const big& omega) {
  wrench w{0, 0, 0};
  const pt c{-vy / omega, vx / omega};
  const std::size_t n = p.loaded.size();
  for (std::size_t i = 0; i < n; ++i) {
    const wrench t = triangle_about_centre(p, c, p.loaded[i], p.loaded[(i + 1) % n], vx, vy, omega);
    w.fx += t.fx;
    w.fy += t.fy;
    w.tau += t.tau;
  }
  return w;
}

// The distance of the instantaneous centre from the loaded vertices' mean,
// in units of their largest distance from it (+∞ for ω = 0).
big centre_ratio(const pressure& p, const big& vx, const big& vy, const big& omega) {
  pt m{0, 0};
  for (const auto& x : p.loaded) {
    m[0] += x[0] / big(p.loaded.size());
    m[1] += x[1] / big(p.loaded.size());
  }
  big size = 0;
  for (const auto& x : p.loaded)
    size = std::max(size, big(sqrt(pow(x[0] - m[0], 2) + pow(x[1] - m[1], 2))));
  const big cx = -vy / omega - m[0], cy = vx / omega - m[1];
  return sqrt(cx * cx + cy * cy) / size;
}

wrench reference_wrench(const pressure& p, const big& vx, const big& vy, const big& omega) {
  if (omega == 0) {
    const big speed = sqrt(vx * vx + vy * vy);
    const big ex = polygon_integral(p.loaded, [&](const pt& x) { return big(p.at(x) * x[0]); });
    const big ey = polygon_integral(p.loaded, [&](const pt& x) { return big(p.at(x) * x[1]); });
    return {-vx / speed, -vy / speed, -(ex * vy - ey * vx) / speed};
  }
  return centre_ratio(p, vx, vy, omega) > 8 ? direct_wrench(p, vx, vy, omega)
                                            : polar_wrench(p, vx, vy, omega);
}

// One row's reference; `lifted` says whether the pressure lifts off.
wrench row_wrench(const patch_cases::input& row, bool& lifted) {
  const std::vector<pt> poly = to_big(patch_cases::outline(row.shape));
  pressure p;
  if (row.pressure == "uniform") {
    p = {1 / polygon_integral(poly, [](const pt&) { return big(1); }), {0, 0}, poly};
  } else {
    p = solve_pressure(poly, {big(row.centre[0]), big(row.centre[1])});
  }
  lifted = p.loaded.size() != poly.size() ||
           polygon_integral(p.loaded, [](const pt&) { return big(1); }) <
               polygon_integral(
                   poly, [](const pt&) { return big(1); }) *
                   (1 - big(1e-30));
  return reference_wrench(p, big(row.vx), big(row.vy), big(row.omega));
}

// --compare FILE STRIDE: every STRIDE-th row again, against FILE, to 1e-35;
// and every row's pressure lifts off exactly when it is "no_tension".
int compare(const char* path, std::size_t stride) {
  const auto rows = spinslide_reference::read_csv_rows(path, "shape");
  const auto inputs = patch_cases::inputs();
  if (rows.size() != inputs.size()) {
    std::printf("%zu rows, but patch_cases has %zu\n", rows.size(), inputs.size());
    return 1;
  }
  int bad = 0;
  for (std::size_t i = 0; i < rows.size(); i += stride) {
    bool lifted = false;
    const wrench w = row_wrench(inputs[i], lifted);
    const big e = std::max(
        {abs(w.fx - big(rows[i][8])), abs(w.fy - big(rows[i][9])), abs(w.tau - big(rows[i][10]))});
    bool ok = e < big(1e-35) && lifted == (inputs[i].pressure == "no_tension");
    // Where both apply (8 to 100 sizes), the polar and the direct quadrature agree.
    const patch_cases::input& in = inputs[i];
    if (in.omega != 0) {
      const std::vector<pt> poly = to_big(patch_cases::outline(in.shape));
      const pressure p =
          in.pressure == "uniform"
              ? pressure{1 / polygon_integral(poly, [](const pt&) { return big(1); }), {0, 0}, poly}
              : solve_pressure(poly, {big(in.centre[0]), big(in.centre[1])});
      const big r = centre_ratio(p, big(in.vx), big(in.vy), big(in.omega));
      if (r > 8 && r < 100) {
        const wrench a = polar_wrench(p, big(in.vx), big(in.vy), big(in.omega));
        const wrench b = direct_wrench(p, big(in.vx), big(in.vy), big(in.omega));
        const big d = std::max({abs(a.fx - b.fx), abs(a.fy - b.fy), abs(a.tau - b.tau)});
        std::printf("  polar - direct %.2e\n", static_cast<double>(d));
        ok = ok && d < big(1e-35);
      }
    }
    bad += ok ? 0 : 1;
    std::printf("row %zu %s %s %s: %.2e%s\n", i, inputs[i].shape.c_str(),
                inputs[i].pressure.c_str(), inputs[i].where.c_str(), static_cast<double>(e),
                ok ? "" : "  MISMATCH");
  }
  return bad == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc == 4 && std::string(argv[1]) == "--compare")
    return compare(argv[2], static_cast<std::size_t>(std::stoul(argv[3])));
  std::printf("# GENERATED by tests/reference/generate_patch_reference.cpp: the friction wrench\n");
  std::printf(
      "# of a flat patch per unit mu N from its defining area integral (cpp_bin_float_50)\n");
  std::printf("shape,pressure,centre_x,centre_y,where,vx,vy,omega,force_x,force_y,torque\n");
  for (const auto& row : patch_cases::inputs()) {
    bool lifted = false;
    const wrench w = row_wrench(row, lifted);
    if (lifted != (row.pressure == "no_tension"))
      std::fprintf(stderr, "%s %s: the pressure %s\n", row.shape.c_str(), row.pressure.c_str(),
                   lifted ? "lifts off" : "does not lift off");
    std::printf("%s,%s,%.17g,%.17g,%s,%.17g,%.17g,%.17g,%s,%s,%s\n", row.shape.c_str(),
                row.pressure.c_str(), row.centre[0], row.centre[1], row.where.c_str(), row.vx,
                row.vy, row.omega, w.fx.str(40).c_str(), w.fy.str(40).c_str(),
                w.tau.str(40).c_str());
    std::fflush(stdout);
  }
} catch (const std::exception& e) {
  std::fprintf(stderr, "generate_patch_reference: %s\n", e.what());
  return 1;
}
