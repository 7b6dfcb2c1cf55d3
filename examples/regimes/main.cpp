//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// regimes: how a sliding, spinning body's motion ends, over the inertia ratio
// γ = I/(mR²), for every built-in profile (docs/theory.md §8).
//
//   regimes [OUTPUT_DIR]
//
// For each profile it prints the window (W) ⟨r²⟩/2 < γ < 2⟨r⟩/⟨1/r⟩ from the
// profile's moments, the γ at which the scan of terminal_motion sees the
// regime change (they must agree), and ε₀ at a few γ; it writes regimes.csv
// (the scan: γ and ε₀ per profile; 0 = pure spinning, inf = pure sliding),
// regimes_curves.csv (the figure's curves, sampled densely towards the
// window's edges) and, with gnuplot, regimes.png: ε₀ against γ, one curve
// per profile, each running from ∞ at its window's lower edge to 0 at its
// upper edge.
#include <spinslide/spinslide.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "../gnuplot.hpp"

namespace {

struct column {
  std::string name;
  double lower, upper;        // the window (W)
  std::vector<double> ratio;  // ε₀ at each γ of the scan (0 or inf outside)
  double observed_lower = NAN, observed_upper = NAN;
};

template <class Profile>
column scan(const std::string& name, const Profile& p, const std::vector<double>& gammas) {
  column c{name, p.mean_square_radius() / 2, 2 * p.mean_radius() / p.mean_inverse_radius(), {}};
  spinslide::terminal_regime previous = spinslide::terminal_regime::pure_sliding;
  for (std::size_t i = 0; i < gammas.size(); ++i) {
    const auto t = spinslide::terminal_motion(p, gammas[i]);
    c.ratio.push_back(t.ratio);
    // The first γ of the scan in the new regime.
    if (i > 0 && t.regime != previous) {
      if (t.regime == spinslide::terminal_regime::sliding_and_spinning)
        c.observed_lower = gammas[i];
      if (t.regime == spinslide::terminal_regime::pure_spinning) c.observed_upper = gammas[i];
    }
    previous = t.regime;
  }
  std::fprintf(stderr, "  %s\n", name.c_str());
  return c;
}

// ε₀ of `p` inside its window (lower, upper), for the figure: 601 values
// of γ spaced evenly in the middle and geometrically towards both edges (to
// 5e-7 of the window's width), where ε₀ runs off to ∞ and to 0 (issue 31:
// the shared grid of the scan drew those plunges as a few long segments);
// only the points inside the plotted range 1e-2 ≤ ε₀ ≤ 1e2 are written.
template <class Profile>
void write_curve(FILE* f, const std::string& name, const Profile& p, double lower, double upper) {
  std::fprintf(f, "# %s\n", name.c_str());
  const int n = 300;
  for (int k = -n; k <= n; ++k) {
    const double t = double(k) / n;
    const double u = 0.5 * (1 + (t < 0 ? -1 : 1) * (1 - std::pow(10.0, -6 * std::fabs(t))));
    const double gamma = lower + (upper - lower) * u;
    const double eps0 = spinslide::terminal_motion(p, gamma).ratio;
    if (eps0 >= 1e-2 && eps0 <= 1e2) std::fprintf(f, "%.12g,%.12g\n", gamma, eps0);
  }
  std::fprintf(f, "\n\n");
}

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  // γ log-spaced over [0.1, 3], 600 points.
  std::vector<double> gammas;
  for (int i = 0; i < 600; ++i) gammas.push_back(0.1 * std::pow(30.0, i / 599.0));
  std::fprintf(stderr, "scanning %zu values of gamma per profile:\n", gammas.size());
  std::vector<column> cols;
  cols.push_back(scan("uniform disk", spinslide::uniform_disk<>(), gammas));
  cols.push_back(scan("CD annulus b = 0.125", spinslide::annulus<>(0.125), gammas));
  cols.push_back(scan("annulus b = 0.8", spinslide::annulus<>(0.8), gammas));
  cols.push_back(scan("Hertz", spinslide::hertz<>(), gammas));
  cols.push_back(scan("Boussinesq", spinslide::boussinesq<>(), gammas));
  cols.push_back(scan("ring", spinslide::ring<>(), gammas));

  std::printf(
      "The window (W) <r^2>/2 < gamma < 2<r>/<1/r> of a finite eps0, and where the scan\n"
      "of %zu log-spaced gamma in [0.1, 3] sees the regime change (first gamma after):\n\n",
      gammas.size());
  std::printf("| profile | window (W) | scan: eps0 finite from | scan: pure spinning from |\n");
  std::printf("| --- | --- | ---: | ---: |\n");
  for (const auto& c : cols)
    std::printf("| %s | %.6f < gamma < %.6f | %.6f | %.6f |\n", c.name.c_str(), c.lower, c.upper,
                c.observed_lower, c.observed_upper);

  std::printf("\neps0 at gamma = 1/2 (the paper's disk: 0.653001789205598):\n");
  std::printf("  uniform disk: %.15f\n",
              spinslide::terminal_motion(spinslide::uniform_disk<>(), 0.5).ratio);
  std::printf("  Boussinesq:   %.15f (exactly 1: F(1) = pi/4, T(1) = pi/8, theory.md (B1))\n",
              spinslide::terminal_motion(spinslide::boussinesq<>(), 0.5).ratio);
  std::printf("  CD annulus at its own gamma = (1 + b^2)/2: %.15f\n",
              spinslide::terminal_motion(spinslide::annulus<>(0.125), 0.5078125).ratio);

  const std::string csv = dir + "/regimes.csv";
  FILE* f = spinslide_examples::open_output(csv, "regimes");
  if (!f) return 1;
  std::fprintf(f, "gamma");
  for (const auto& c : cols) std::fprintf(f, ",%s", c.name.c_str());
  std::fprintf(f, "\n");
  for (std::size_t i = 0; i < gammas.size(); ++i) {
    std::fprintf(f, "%.9g", gammas[i]);
    for (const auto& c : cols) std::fprintf(f, ",%.12g", c.ratio[i]);
    std::fprintf(f, "\n");
  }
  std::fclose(f);
  std::printf("\nwrote %s\n", csv.c_str());

  const std::string curves = dir + "/regimes_curves.csv";
  FILE* g = spinslide_examples::open_output(curves, "regimes");
  if (!g) return 1;
  std::fprintf(g, "gamma,eps0\n");
  write_curve(g, cols[0].name, spinslide::uniform_disk<>(), cols[0].lower, cols[0].upper);
  write_curve(g, cols[1].name, spinslide::annulus<>(0.125), cols[1].lower, cols[1].upper);
  write_curve(g, cols[2].name, spinslide::annulus<>(0.8), cols[2].lower, cols[2].upper);
  write_curve(g, cols[3].name, spinslide::hertz<>(), cols[3].lower, cols[3].upper);
  write_curve(g, cols[4].name, spinslide::boussinesq<>(), cols[4].lower, cols[4].upper);
  write_curve(g, cols[5].name, spinslide::ring<>(), cols[5].lower, cols[5].upper);
  std::fclose(g);
  std::printf("wrote %s (the figure's curves)\n", curves.c_str());

  std::string script =
      "set terminal pngcairo size 900,600 font ',11'\n"
      "set output 'regimes.png'\n"
      "set datafile separator ','\n"
      "set logscale xy\n"
      "set xrange [0.1:3]\nset yrange [1e-2:1e2]\n"
      "set xlabel 'inertia ratio {/Symbol g} = I/(mR^2)'\n"
      "set ylabel 'terminal ratio {/Symbol e}_0 = v/(R{/Symbol w}) at the stop'\n"
      "set title \"How the motion ends: {/Symbol e}_0 -> {/Symbol \\245} (pure sliding) at the "
      "left "
      "of each profile's window,\\n-> 0 (pure spinning) at its right; dotted: the paper's disk, "
      "{/Symbol g} = 1/2\"\n"
      "set key outside right\nset grid\n"
      "set arrow from 0.5,1e-2 to 0.5,1e2 nohead dt 3 lc rgb 'gray'\n"
      "plot ";
  for (std::size_t k = 0; k < cols.size(); ++k)
    script += (k ? ", " : "") + std::string("'regimes_curves.csv' index ") + std::to_string(k) +
              " using 1:2 with lines lw 2 title '" + cols[k].name + "'";
  script += "\n";
  if (spinslide_examples::plot(dir, "regimes.gp", script))
    std::printf("wrote %s/regimes.png\n", dir.c_str());
  else
    std::printf("gnuplot not found or failed: no PNG (install gnuplot-nox); the CSV is written\n");
  return 0;
}
