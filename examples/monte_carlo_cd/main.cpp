//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// monte_carlo_cd: how well could the paper's CD experiment resolve the growth
// of the friction coefficient, μ(n) = 0.202 + 0.00053 n, from where and when
// each throw stops?  Many repetitions of the 60-throw experiment, thrown with
// spinslide::stop_results (batch_throws.hpp) over all cores.
//
//   monte_carlo_cd [--throws N] [--method table|integrate] [--threads T] [--seed S]
//
// N throws (default 10⁶; the fits use the whole experiments of 60) of the CD of
// examples/cd_experiment (annulus b = 0.125, γ = (1 + b²)/2, R = 6 cm):
// throw i is throw n = i mod 60 + 1 of experiment i / 60, with μ = μ(n) and
// a hand throw v0 ∈ U[0.4, 1.2] m/s, ω0 ∈ U[5, 30] rad/s.
//
// The physics used: at given v0 and ω0 the stop time and distance scale as
// 1/μ exactly (the equations of motion in the paper's units, docs/theory.md:
// t = t₁/μ and s = s₁/μ, with t₁, s₁ those of μ = 1).  So one throw measures
//   μ̂ = s₁(v̂0, ω̂0)/ŝ   (from the stop distance)  and   μ̂ = t₁(v̂0, ω̂0)/t̂   (from the stop time),
// and each experiment fits μ̂ = a + b n by least squares over its 60 throws.
// The measurement errors are the film's (cd_experiment's tracking noise):
// - the stop distance: release and rest positions each with 0.5 mm per
//   coordinate, so 0.71 mm along the line;
// - the stop time: between the last moving frame and the first frame at rest
//   (25 frames/s), taken at the middle of that interval;
// - v0 and ω0: the slope at release of a parabola fitted to the first 7
//   frames, with the noise that fit propagates (its window bias, which
//   docs/experiment.md removes, is left out here).
// The truth is computed with the tabulated throw (--method table, the default;
// within 4e-14 of the integration in time, 1e-9 in distance) or with
// simulate_throw (--method integrate); the analysis's s₁ and t₁ always with the
// table.  A check on the first 2000 throws compares the two, and recovers μ
// exactly from noise-free measurements.
//
// stderr shows a progress bar when it is a terminal, and a line every few
// seconds otherwise.
#include <spinslide/motion/batch_throws.hpp>
#include <spinslide/values/profile.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#if defined(_WIN32)
#include <io.h>
#define SPINSLIDE_ISATTY(f) _isatty(_fileno(f))
#else
#include <unistd.h>
#define SPINSLIDE_ISATTY(f) isatty(fileno(f))
#endif

#include "../cd_experiment/cd_experiment.hpp"

namespace {

using cd_experiment::g;
using cd_experiment::R;
using profile = spinslide::annulus<>;
using starts_t = std::vector<spinslide::throw_start<double>>;
const int per_experiment = 60;

struct options {
  long throws = 1000000;
  std::string method = "table";
  unsigned threads = 0;
  unsigned seed = 2003;
};

options parse(int argc, char** argv) {
  options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (i + 1 >= argc) throw std::runtime_error("missing value after " + a);
    const std::string v = argv[++i];
    if (a == "--throws")
      o.throws = std::stol(v);
    else if (a == "--method")
      o.method = v;
    else if (a == "--threads")
      o.threads = static_cast<unsigned>(std::stoul(v));
    else if (a == "--seed")
      o.seed = static_cast<unsigned>(std::stoul(v));
    else
      throw std::runtime_error("unknown option " + a);
  }
  if (o.throws < per_experiment) throw std::runtime_error("--throws must be at least 60");
  if (o.method != "table" && o.method != "integrate")
    throw std::runtime_error("--method must be table or integrate");
  return o;
}

// The progress of one batch on stderr: a bar on a terminal, otherwise a line
// every 5 s (a log file gets no carriage returns).
spinslide::batch_options with_progress(unsigned threads, const char* what) {
  spinslide::batch_options b;
  b.threads = threads;
  const bool terminal = SPINSLIDE_ISATTY(stderr) != 0;
  b.progress_interval = std::chrono::milliseconds(terminal ? 100 : 5000);
  const auto start = std::chrono::steady_clock::now();
  b.progress = [terminal, what, start](std::size_t done, std::size_t total) {
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double f = total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
    if (terminal) {
      const int width = 40, filled = static_cast<int>(f * width);
      std::fprintf(stderr, "\r%-10s [%s%s] %3.0f%% %zu/%zu %.1f s", what,
                   std::string(static_cast<std::size_t>(filled), '#').c_str(),
                   std::string(static_cast<std::size_t>(width - filled), '.').c_str(), 100 * f,
                   done, total, seconds);
      if (done == total) std::fputc('\n', stderr);
    } else {
      std::fprintf(stderr, "%s: %zu of %zu throws (%.0f%%), %.1f s\n", what, done, total, 100 * f,
                   seconds);
    }
  };
  return b;
}

// Stop times (s) and distances (m) of throws given in the paper's units.
struct stops {
  std::vector<double> time, distance;
};

stops stop_of(const starts_t& in, const spinslide::tabulated_throw<profile>& table,
              const std::string& method, const spinslide::batch_options& b) {
  stops out;
  out.time.reserve(in.size());
  out.distance.reserve(in.size());
  if (method == "table") {
    for (const auto& r : spinslide::stop_results(table, in, b)) {
      out.time.push_back(r.time);
      out.distance.push_back(r.distance);
    }
  } else {
    const profile cd(cd_experiment::hole);
    for (const auto& r : spinslide::stop_results(cd, cd_experiment::gamma_cd, in, b)) {
      out.time.push_back(r.time);
      out.distance.push_back(r.distance);
    }
  }
  return out;
}

// The dimensionless start of a throw (v0 m/s, ω0 rad/s) on a surface with μ.
spinslide::throw_start<double> start(double v0, double w0, double mu) {
  const spinslide::si_units<double> u{R, mu, g};
  return {v0 / u.velocity_unit(), w0 / u.spin_unit()};
}

// The standard deviation of the slope at release of a parabola fitted to the
// first 7 frames, per unit noise.
double release_slope_sd() {
  std::vector<double> t;
  t.reserve(cd_experiment::default_fit_frames);
  for (int k = 0; k < cd_experiment::default_fit_frames; ++k) t.push_back(k / cd_experiment::fps);
  return std::sqrt(cd_experiment::design(t, 0).slope_var);
}

// Least-squares line y = a + b n over n = 1..60.
struct line {
  double a, b;
};
line fit_line(const double* y) {
  double sn = 0, sy = 0, snn = 0, sny = 0;
  for (int k = 0; k < per_experiment; ++k) {
    const double n = k + 1;
    sn += n, sy += y[k], snn += n * n, sny += n * y[k];
  }
  const double b = (per_experiment * sny - sn * sy) / (per_experiment * snn - sn * sn);
  return {(sy - b * sn) / per_experiment, b};
}

struct spread {
  double mean, sd;
};
spread spread_of(const std::vector<double>& x) {
  double m = 0, q = 0;
  for (const double v : x) m += v;
  m /= static_cast<double>(x.size());
  for (const double v : x) q += (v - m) * (v - m);
  return {m, std::sqrt(q / static_cast<double>(x.size() - 1))};
}

// The fits of every experiment to the per-throw estimates mu_hat, and their spread.
void report(const char* what, const std::vector<double>& mu_hat) {
  std::vector<double> a, b;
  for (std::size_t e = 0; e + per_experiment <= mu_hat.size(); e += per_experiment) {
    const line l = fit_line(&mu_hat[e]);
    a.push_back(l.a);
    b.push_back(l.b);
  }
  const spread sa = spread_of(a), sb = spread_of(b);
  const double se_b = sb.sd / std::sqrt(static_cast<double>(b.size()));
  std::printf(
      "%-14s a = %.5f (sd %.5f),  b = %.6f (sd %.6f; mean - truth = %+.1f se),  "
      "b/sd(b) = %.1f\n",
      what, sa.mean, sa.sd, sb.mean, sb.sd, (sb.mean - cd_experiment::true_b) / se_b,
      cd_experiment::true_b / sb.sd);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) try {
  const options o = parse(argc, argv);
  const auto t0 = std::chrono::steady_clock::now();
  const auto n = static_cast<std::size_t>(o.throws);
  const profile cd(cd_experiment::hole);
  const spinslide::tabulated_throw<profile> table(cd, cd_experiment::gamma_cd);
  std::printf("%zu throws (%zu whole experiments of %d), method %s; table built in %.2f s\n", n,
              n / per_experiment, per_experiment, o.method.c_str(), seconds_since(t0));

  // The throws and their true stops.
  std::mt19937_64 rng(o.seed);
  std::uniform_real_distribution<double> speed(0.4, 1.2), spin(5, 30);
  std::vector<double> mu(n), v0(n), w0(n);
  starts_t truth_in(n);
  for (std::size_t i = 0; i < n; ++i) {
    mu[i] = cd_experiment::true_a + cd_experiment::true_b * static_cast<double>(i % 60 + 1);
    v0[i] = speed(rng);
    w0[i] = spin(rng);
    truth_in[i] = start(v0[i], w0[i], mu[i]);
  }
  const auto t1 = std::chrono::steady_clock::now();
  const stops truth = stop_of(truth_in, table, o.method, with_progress(o.threads, "throws"));
  const double throw_seconds = seconds_since(t1);
  const double time_scale = std::sqrt(R / g);

  // The film's measurements, and the stops of μ = 1 at the measured start.
  const auto noise = cd_experiment::tracking_noise;
  const double sd_v = noise.position * release_slope_sd(), sd_w = noise.angle * release_slope_sd();
  std::normal_distribution<double> normal(0, 1);
  std::vector<double> s_hat(n), t_hat(n);
  starts_t model_in(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = truth.time[i] * time_scale, s = truth.distance[i] * mu[i] * R;
    t_hat[i] = (std::ceil(t * cd_experiment::fps) - 0.5) / cd_experiment::fps;
    s_hat[i] = s + std::sqrt(2.0) * noise.position * normal(rng);
    model_in[i] = start(v0[i] + sd_v * normal(rng), w0[i] + sd_w * normal(rng), 1);
  }
  const stops model = stop_of(model_in, table, "table", with_progress(o.threads, "analysis"));
  std::vector<double> mu_s(n), mu_t(n);
  for (std::size_t i = 0; i < n; ++i) {
    mu_s[i] = model.distance[i] * R / s_hat[i];
    mu_t[i] = model.time[i] * time_scale / t_hat[i];
  }

  std::printf(
      "measurement errors: stop distance %.2f mm, stop time %.1f ms (one frame, "
      "uniform), v0 %.1f mm/s, omega0 %.3f rad/s\n",
      std::sqrt(2.0) * noise.position * 1e3, 1e3 / cd_experiment::fps / std::sqrt(12.0), sd_v * 1e3,
      sd_w);
  std::vector<double> s_true(n);
  for (std::size_t i = 0; i < n; ++i) s_true[i] = truth.distance[i] * mu[i] * R;
  const spread ss = spread_of(s_true);
  std::printf(
      "stop distance over the hand throws: mean %.1f cm, sd %.1f cm; mu(60)/mu(1) = %.4f "
      "(the same throw stops that much shorter)\n",
      100 * ss.mean, 100 * ss.sd,
      (cd_experiment::true_a + 60 * cd_experiment::true_b) /
          (cd_experiment::true_a + cd_experiment::true_b));
  std::vector<double> rel_s(n), rel_t(n);
  for (std::size_t i = 0; i < n; ++i)
    rel_s[i] = mu_s[i] / mu[i] - 1, rel_t[i] = mu_t[i] / mu[i] - 1;
  std::printf("one throw's mu: from the distance %.2f %% sd, from the time %.2f %% sd\n",
              100 * spread_of(rel_s).sd, 100 * spread_of(rel_t).sd);
  std::printf("fits of mu(n) = a + b n over each experiment (truth a = %.5f, b = %.6f):\n",
              cd_experiment::true_a, cd_experiment::true_b);
  report("from distance", mu_s);
  report("from time", mu_t);

  // Checks on the first throws: the table against the integration, and the
  // 1/μ scaling from noise-free measurements.
  const std::size_t k = std::min<std::size_t>(n, 2000);
  const starts_t first(truth_in.begin(), truth_in.begin() + static_cast<long>(k));
  spinslide::batch_options quiet;
  quiet.threads = o.threads;
  const stops integrated = stop_of(first, table, "integrate", quiet);
  const stops tabulated = stop_of(first, table, "table", quiet);
  starts_t exact_in(k);
  for (std::size_t i = 0; i < k; ++i) exact_in[i] = start(v0[i], w0[i], 1);
  const stops exact = stop_of(exact_in, table, "table", quiet);
  double table_error = 0, scaling_error = 0;
  for (std::size_t i = 0; i < k; ++i) {
    table_error = std::max({table_error, std::fabs(tabulated.time[i] / integrated.time[i] - 1),
                            std::fabs(tabulated.distance[i] / integrated.distance[i] - 1)});
    // μ = t₁/t = s₁/s from the integrated true stop and the table's stop at
    // μ = 1: in the paper's units t*₁/t* and s*₁/(μ s*) (t = t*√(R/g), s = μR s*).
    const double from_time = exact.time[i] / integrated.time[i];
    const double from_distance = exact.distance[i] / (integrated.distance[i] * mu[i]);
    scaling_error = std::max(
        {scaling_error, std::fabs(from_time / mu[i] - 1), std::fabs(from_distance / mu[i] - 1)});
  }
  std::printf("check on %zu throws: table vs integration %.1e; noise-free mu recovered to %.1e\n",
              k, table_error, scaling_error);
  std::printf("%zu throws in %.2f s (%.3g throws/s), %.2f s in all\n", n, throw_seconds,
              static_cast<double>(n) / throw_seconds, seconds_since(t0));
  const bool pass = table_error < 1e-8 && scaling_error < 1e-8;
  std::printf("checks: %s\n", pass ? "PASS" : "FAIL");
  return pass ? 0 : 1;
} catch (const std::exception& e) {
  std::fprintf(stderr, "monte_carlo_cd: %s\n", e.what());
  return 2;
}
