//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// paper: the figures and numbers of Farkas, Bartels, Unger & Wolf (2003),
// computed.
//
//   paper [OUTPUT_DIR]
//
// Writes into OUTPUT_DIR (default: the current directory), with a progress
// line per figure:
//   fig1_velocity.csv/.png     Fig. 1(b-d): the relative velocity field on the
//                              disk at eps = 0.2, 1 and 5
//   fig2_force_torque.csv/.png Fig. 2: (a) F and T against eps; (b) T(F)
//   fig3_trajectories.csv/.png Fig. 3: (a) omega*-v* and (b) eps-v* trajectories
//                              of the paper's disk (gamma = 1/2) from 16 throws
//   fig4_flow.csv/.png         Fig. 4: f(eps) = eps - F/(2T) with its
//                              asymptotes eps/4 and -eps
// and prints every number the paper states beside the computed value.  The
// PNG files need gnuplot (Debian: gnuplot-nox); without it only the CSV files
// are written.
//   fig5_experiment.png        Fig. 5: the simulated CD experiment, the
//                              measured T/F against eps (no mu needed) and
//                              F and T over the theory curves
//                              (examples/cd_experiment, docs/experiment.md)
#include <spinslide/spinslide.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_2.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../cd_experiment/cd_experiment.hpp"
#include "../dense_times.hpp"
#include "../gnuplot.hpp"

namespace {

const double pi = boost::math::constants::pi<double>();

struct output {
  std::string dir;
  FILE* open(const std::string& name) const {
    return spinslide_examples::open_output(dir + "/" + name, "paper");
  }
  void figure(const std::string& stem, const std::string& what, const std::string& script) const {
    const bool png = spinslide_examples::plot(dir, stem + ".gp", script);
    std::printf("%-22s %s: %s.csv%s\n", (stem + ":").c_str(), what.c_str(), stem.c_str(),
                png ? (", " + stem + ".png").c_str() : " (no gnuplot: no PNG)");
    std::fflush(stdout);
  }
};

const char* png_header =
    "set terminal pngcairo size 1200,450 font ',11'\nset datafile separator ','\n";

// Fig. 1(b-d): the velocity of the table relative to the disk's surface,
// eps e_v + e_omega x r = (eps - y, x) in units of R omega (theory.md §1).
void figure1(const output& out) {
  FILE* f = out.open("fig1_velocity.csv");
  if (!f) return;
  std::fprintf(f, "panel,eps,x,y,ux,uy\n");
  const double eps_values[] = {0.2, 1.0, 5.0};
  for (int k = 0; k < 3; ++k) {
    const double e = eps_values[k];
    // Arrows scaled so that the longest is 0.11 (a grid step is 0.125).
    const double longest = std::hypot(e + 1, 1.0);
    for (int i = -8; i <= 8; ++i)
      for (int j = -8; j <= 8; ++j) {
        const double x = i / 8.0, y = j / 8.0;
        if (x * x + y * y > 1) continue;
        std::fprintf(f, "%d,%g,%g,%g,%.6g,%.6g\n", k, e, x, y, 0.11 * (e - y) / longest,
                     0.11 * x / longest);
      }
    std::fprintf(f, "\n\n");
  }
  std::fclose(f);
  std::string script = png_header;
  script +=
      "set output 'fig1_velocity.png'\nset multiplot layout 1,3 title "
      "'Fig. 1(b-d): the relative velocity field on the disk (v along x, spin about z)'\n"
      "set size ratio -1\nset xrange [-1.15:1.15]\nset yrange [-1.15:1.15]\nunset key\n"
      "set object 1 circle at 0,0 size 1 fs empty lc rgb 'gray'\n";
  const char* titles[] = {"{/Symbol e} = 0.2", "{/Symbol e} = 1", "{/Symbol e} = 5"};
  for (int k = 0; k < 3; ++k)
    script += std::string("set title '") + titles[k] + "'\nplot 'fig1_velocity.csv' index " +
              std::to_string(k) +
              " using 3:4:5:6 with vectors head size 0.03,20 lc rgb '#1f77b4'\n";
  script += "unset multiplot\n";
  out.figure("fig1_velocity", "Fig. 1(b-d), velocity fields at eps = 0.2, 1, 5", script);
}

// Fig. 2: F and T against eps, and the coupling curve T(F).
void figure2(const output& out) {
  FILE* f = out.open("fig2_force_torque.csv");
  if (!f) return;
  std::fprintf(f, "eps,F,T\n");
  for (int i = 0; i <= 500; ++i) {  // (a): eps in [0, 5]
    const double e = i / 100.0;
    const auto ft = spinslide::force_torque(e);
    std::fprintf(f, "%.6g,%.17g,%.17g\n", e, ft.force, ft.torque);
  }
  std::fprintf(f, "\n\n");
  for (int i = 0; i <= 800; ++i) {  // (b): eps log-spaced over [1e-4, 1e4], the whole curve
    const double e = std::pow(10.0, -4 + i / 100.0);
    const auto ft = spinslide::force_torque(e);
    std::fprintf(f, "%.6g,%.17g,%.17g\n", e, ft.force, ft.torque);
  }
  std::fclose(f);
  std::string script = png_header;
  script +=
      "set output 'fig2_force_torque.png'\nset multiplot layout 1,2\nset grid\n"
      "set title '(a) friction force and torque'\nset xlabel '{/Symbol e} = v/(R{/Symbol w})'\n"
      "set key right center\n"
      "plot 'fig2_force_torque.csv' index 0 using 1:2 with lines lw 2 title 'F({/Symbol e})', "
      "'' index 0 using 1:3 with lines lw 2 dt 2 title 'T({/Symbol e})'\n"
      "set title '(b) the coupling: possible (F, T) pairs'\nset xlabel 'F'\nset ylabel 'T'\n"
      "set xrange [0:1]\nset yrange [0:0.7]\nunset key\n"
      "plot 'fig2_force_torque.csv' index 1 using 2:3 with lines lw 2\n"
      "unset multiplot\n";
  out.figure("fig2_force_torque", "Fig. 2, F(eps), T(eps) and T(F)", script);
}

// Fig. 3: trajectories of the paper's disk from throws on a quarter circle,
// each sampled densely (spinslide::trajectory at 600 times: half evenly in t,
// half evenly in log(t_stop − t) down to 1e-9 of the stop, where ε still
// moves), so that every curve is smooth at the figure's size (issue 31; the
// integrator's own steps, about 9 per throw, drew visible corners).
void figure3(const output& out) {
  FILE* f = out.open("fig3_trajectories.csv");
  if (!f) return;
  std::fprintf(f, "throw,t,v,omega,eps\n");
  int n = 0;
  const spinslide::uniform_disk<> disk;
  for (int i = 0; i < 16; ++i) {
    const double a = (i + 0.5) / 16 * pi / 2;  // the direction of (v0*, omega0*)
    const double v0 = std::cos(a), w0 = std::sin(a);
    const double stop = spinslide::simulate_throw(disk, 0.5, v0, w0).time;
    for (const auto& s : spinslide::trajectory(
             disk, 0.5, v0, w0, spinslide_examples::times_towards_stop(stop, stop, 300, 300)))
      std::fprintf(f, "%d,%.9g,%.9g,%.9g,%.9g\n", i, s.time, s.speed, s.spin, s.ratio);
    std::fprintf(f, "\n\n");
    ++n;
  }
  std::fclose(f);
  std::string script = png_header;
  script +=
      "set output 'fig3_trajectories.png'\nset multiplot layout 1,2\nset grid\nunset key\n"
      "set title '(a) trajectories in the (v*, {/Symbol w}*) plane'\n"
      "set xlabel 'v*'\nset ylabel '{/Symbol w}*'\nset size ratio -1\n"
      "plot for [i=0:" +
      std::to_string(n - 1) +
      "] 'fig3_trajectories.csv' index i using 3:4 with lines lw 1.5\n"
      "set size noratio\nset title '(b) {/Symbol e} tends to {/Symbol e}_0 = 0.653 as "
      "the disk stops'\n"
      "set xlabel 'v*'\nset ylabel '{/Symbol e} = v*/{/Symbol w}*'\nset logscale y\n"
      "set yrange [0.01:100]\n"
      "plot for [i=0:" +
      std::to_string(n - 1) +
      "] 'fig3_trajectories.csv' index i using 3:5 with lines lw 1.5, 0.653 dt 2 lc "
      "rgb 'black'\nunset multiplot\n";
  out.figure("fig3_trajectories", "Fig. 3, 16 throws of the paper's disk", script);
}

// Fig. 4: the flow of eps, f = eps - F/(2T), with its asymptotes.
void figure4(const output& out) {
  FILE* f = out.open("fig4_flow.csv");
  if (!f) return;
  std::fprintf(f, "eps,f\n");
  for (int i = 0; i <= 300; ++i) {
    const double e = i / 100.0;
    std::fprintf(f, "%.6g,%.17g\n", e, spinslide::ratio_flow(spinslide::uniform_disk<>(), e, 0.5));
  }
  std::fclose(f);
  const std::string script =
      "set terminal pngcairo size 800,500 font ',11'\nset datafile separator ','\n"
      "set output 'fig4_flow.png'\nset grid\nset key left bottom\n"
      "set title 'Fig. 4: f({/Symbol e}) = {/Symbol e} - F/(2T), zero at {/Symbol e}_0 = 0.653'\n"
      "set xlabel '{/Symbol e}'\nset ylabel 'f'\nset xrange [0:3]\nset yrange [-3.2:0.4]\n"
      "plot 'fig4_flow.csv' using 1:2 with lines lw 2 title 'f({/Symbol e})', "
      "x/4 dt 2 title '{/Symbol e}/4', -x dt 3 title '-{/Symbol e}', 0 lc rgb 'black' notitle\n";
  out.figure("fig4_flow", "Fig. 4, f(eps) and its asymptotes", script);
}

// Fig. 5: the CD experiment, simulated and analysed (docs/experiment.md).
void figure5(const output& out) {
  std::printf("fig5_experiment:       Fig. 5, the CD experiment (60 simulated throws):\n");
  const auto frames = cd_experiment::simulate(60, 2003);
  cd_experiment::write_frames(out.dir + "/cd_frames.csv", frames);
  cd_experiment::analyse(cd_experiment::read_frames(out.dir + "/cd_frames.csv"), out.dir, true);
  std::fflush(stdout);
}

// The paper's printed torque for eps >= 1, which lacks a factor eps^2
// (docs/theory.md §3).
double printed_torque(double e) {
  const double k = 1 / e, K = boost::math::ellint_1(k), E = boost::math::ellint_2(k);
  return 4 * ((4 - 2 * e * e) * E + (2 * e * e - 5 + 3 / (e * e)) * K) / (9 * e * pi);
}

void numbers() {
  std::printf("\nEvery number the paper states, computed (double):\n\n");
  std::printf("| claim | paper | computed | exact, or reference |\n| --- | --- | --- | --- |\n");
  auto row = [](const char* claim, const char* paper, double computed, const char* exact) {
    std::printf("| %s | %s | %.17g | %s |\n", claim, paper, computed, exact);
  };
  row("F(1)", "8/(3 pi)", spinslide::force(1.0), "0.84882636315677512410");
  row("F'(1)", "4/(3 pi)", spinslide::force_derivative(1.0), "0.42441318157838756205");
  row("T(1)", "8/(9 pi)", spinslide::torque(1.0), "0.28294212105225837470");
  row("T'(1)", "-4/(3 pi)", spinslide::torque_derivative(1.0), "-0.42441318157838756205");
  row("F(0)", "0", spinslide::force(0.0), "0");
  row("F(eps), eps -> inf", "1", spinslide::force(1e300), "1");
  row("T(0)", "2/3", spinslide::torque(0.0), "0.66666666666666666667");
  row("T(eps), eps -> inf", "0", spinslide::torque(1e300), "2.5e-301 = 1/(4 eps)");
  row("eps0", "~0.653", spinslide::terminal_ratio(), "0.65300178920559763899");
  const spinslide::uniform_disk<> disk;
  row("f(eps)/eps, eps -> 0", "1/4", spinslide::ratio_flow(disk, 1e-6, 0.5) / 1e-6, "0.25");
  row("f(eps)/eps, eps -> inf", "-1", spinslide::ratio_flow(disk, 1e6, 0.5) / 1e6, "-1");
  // The CD's 1.5 cm hole in R = 6 cm: "deviation from the full disk not significant".
  const spinslide::annulus<> cd(0.125);
  double dF = 0, dT = 0;
  for (int i = 0; i <= 800; ++i) {
    const double e = std::pow(10.0, -4 + i / 100.0);
    dF = std::fmax(dF, std::fabs(cd.force(e) - spinslide::force(e)));
    dT = std::fmax(dT, std::fabs(cd.torque(e) - spinslide::torque(e)));
  }
  row("CD hole: max over eps of abs(F_CD - F)", "not significant", dF,
      "bound from (A1): b^2/(1-b^2) = 0.0159");
  row("CD hole: max over eps of abs(T_CD - T)", "not significant", dT,
      "at eps = 0 by (A1): 2b^2/(3(1+b)) = 0.00926");
  row("printed T(3) (eps >= 1 branch)", "(formula)", printed_torque(3.0),
      "area integral: 0.084130 (printed form lacks eps^2)");
  row("T(3)", "", spinslide::torque(3.0), "0.084130");
}

}  // namespace

int main(int argc, char** argv) {
  const output out{argc > 1 ? argv[1] : "."};
  std::error_code error;
  std::filesystem::create_directories(out.dir, error);
  if (error) {
    std::fprintf(stderr, "paper: cannot create %s: %s\n", out.dir.c_str(), error.message().c_str());
    return 1;
  }
  std::printf("Farkas, Bartels, Unger & Wolf (2003), computed by spinslide; output in %s\n\n",
              out.dir.c_str());
  figure1(out);
  figure2(out);
  figure3(out);
  figure4(out);
  figure5(out);
  numbers();
  return 0;
}
