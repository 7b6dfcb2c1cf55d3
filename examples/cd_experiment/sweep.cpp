//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// cd_sweep: the CD experiment's analysis over many seeds (docs/experiment.md,
// "Calibration over seeds", quotes its output).  Each seed is one simulated
// experiment of 60 throws; the sweep reports, per band of the measured ε, the
// spread of each throw's two estimates of μ around the true μ(n) and of their
// z-scores with the propagated sd, and, per estimator of μ(n) = a + b n, the
// spread of â and b̂ and the distribution of their z-scores.
//
//   cd_sweep [--seeds N] [--first S] [--threads T] [--fit-frames K]
//            [--evaluate-at I] [--noise-scale X] [--no-window-correction]
//            [--correction-iterations K]
//
// --noise-scale 0 films without tracking noise: what is left is the
// analysis's own (discretisation) bias.  Progress goes to stderr.
#include "cd_experiment.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using namespace cd_experiment;

namespace {

struct sweep_options {
  int seeds = 400, throws = 60, threads = 2;
  unsigned first = 1;
  double noise_scale = 1;
  analysis_options analysis;
};

// The estimators compared: the authors' equal weights and the inverse-
// covariance weights, each on both estimates, the force's only and the
// torque's only.
struct estimator {
  const char* name;
  bool corrected, weighted;
  estimates use;
};
const estimator estimators[] = {
    {"the authors': uncorrected, equal weights, both", false, false, estimates::both},
    {"uncorrected, equal weights, force", false, false, estimates::force},
    {"uncorrected, equal weights, torque", false, false, estimates::torque},
    {"uncorrected, weighted, both", false, true, estimates::both},
    {"corrected, equal weights, both", true, false, estimates::both},
    {"corrected, weighted, both (the analysis)", true, true, estimates::both},
    {"corrected, weighted, force", true, true, estimates::force},
    {"corrected, weighted, torque", true, true, estimates::torque},
};
constexpr std::size_t n_estimators = sizeof(estimators) / sizeof(estimators[0]);

// One throw's estimates relative to the truth: (μ̂ − μ)/μ and (μ̂ − μ)/sd.
struct throw_result {
  double eps, rel_force, rel_torque, z_force, z_torque, ratio_z;
};

struct seed_result {
  std::vector<mu_fit> fits;
  std::vector<throw_result> raw_throws, throws;  // without and with the window correction
  ratio_summary ratio;
  noise_estimate noise;
};

std::vector<throw_result> per_throw(const std::vector<measured>& m, const noise_estimate& noise) {
  std::vector<throw_result> out;
  for (const auto& r : m) {
    const double mu = true_a + true_b * r.n;
    const pair_covariance c = covariance(r, noise, mu);
    const ratio_point p = ratio_test_point(r, noise);
    out.push_back({r.eps, r.mu_from_force / mu - 1, r.mu_from_torque / mu - 1,
                   (r.mu_from_force - mu) / std::sqrt(c.ff),
                   (r.mu_from_torque - mu) / std::sqrt(c.tt), p.d / std::sqrt(p.var_d)});
  }
  return out;
}

seed_result run_seed(unsigned seed, const sweep_options& opt) {
  const film_noise noise = {tracking_noise.position * opt.noise_scale,
                            tracking_noise.angle * opt.noise_scale};
  const throws_t frames = simulate(opt.throws, seed, noise);
  const std::vector<measured> raw = measure(frames, opt.analysis, /*quiet=*/true);
  const std::vector<measured> m = measure_corrected(frames, opt.analysis, /*quiet=*/true);
  seed_result out;
  for (const estimator& e : estimators) {
    const std::vector<measured>& data = e.corrected ? m : raw;
    out.fits.push_back(e.weighted ? weighted_fit(data, e.use) : pooled_fit(data, e.use));
  }
  out.noise = pooled_noise(m);
  out.ratio = ratio_test(m, out.noise);
  out.raw_throws = per_throw(raw, pooled_noise(raw));
  out.throws = per_throw(m, out.noise);
  return out;
}

// Mean and sd of a sample.
struct moments {
  double n = 0, sum = 0, sum2 = 0;
  void add(double x) { n += 1, sum += x, sum2 += x * x; }
  double mean() const { return sum / n; }
  double sd() const { return std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1))); }
};

void print_bands(const std::vector<seed_result>& results, bool corrected) {
  const double edges[] = {0, 0.5, 0.8, 2, 1e300};
  std::printf(
      "\nper throw, %s, by the measured eps: (mu_hat - mu)/mu, mean and sd,\n"
      "and the sd of z = (mu_hat - mu)/sd_propagated (1 if the weights are right)\n",
      corrected ? "window-corrected" : "uncorrected (as the authors measured)");
  std::printf(
      "| eps band | throws | force: mean | sd | sd(z) | torque: mean | sd | sd(z) |"
      " T/F: sd(z) |\n|---|---|---|---|---|---|---|---|---|\n");
  for (int k = 0; k < 4; ++k) {
    moments f, t, zf, zt, zr;
    for (const auto& s : results)
      for (const auto& r : corrected ? s.throws : s.raw_throws)
        if (r.eps >= edges[k] && r.eps < edges[k + 1]) {
          f.add(r.rel_force), t.add(r.rel_torque), zf.add(r.z_force), zt.add(r.z_torque);
          zr.add(r.ratio_z);
        }
    std::printf("| %.1f-%s | %.0f | %+.4f | %.4f | %.2f | %+.4f | %.4f | %.2f | %.2f |\n", edges[k],
                k == 3 ? "inf" : std::to_string(edges[k + 1]).substr(0, 3).c_str(), f.n, f.mean(),
                f.sd(), zf.sd(), t.mean(), t.sd(), zt.sd(), zr.sd());
  }
}

void print_estimators(const std::vector<seed_result>& results) {
  std::printf("\nestimators of mu(n) = a + b n over the seeds (z = (estimate - truth)/its se)\n");
  std::printf(
      "| estimator | mean a - 0.202 | sd of a | mean se_a | sd z_a | |z_a|>2 | |z_a|>3 |"
      " mean b - 0.00053 | sd of b | sd z_b | |z_b|>3 |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t e = 0; e < n_estimators; ++e) {
    moments a, sea, za, b, zb;
    double za2 = 0, za3 = 0, zb3 = 0;
    for (const auto& s : results) {
      const mu_fit& f = s.fits[e];
      a.add(f.a), sea.add(f.se_a), za.add((f.a - true_a) / f.se_a);
      b.add(f.b), zb.add((f.b - true_b) / f.se_b);
      za2 += std::fabs(f.a - true_a) > 2 * f.se_a;
      za3 += std::fabs(f.a - true_a) > 3 * f.se_a;
      zb3 += std::fabs(f.b - true_b) > 3 * f.se_b;
    }
    const double n = a.n;
    std::printf(
        "| %s | %+.5f | %.5f | %.5f | %.2f | %.1f %% | %.2f %% | %+.7f | %.7f | %.2f |"
        " %.2f %% |\n",
        estimators[e].name, a.mean() - true_a, a.sd(), sea.mean(), za.sd(), 100 * za2 / n,
        100 * za3 / n, b.mean() - true_b, b.sd(), zb.sd(), 100 * zb3 / n);
  }
}

void print_summary(const std::vector<seed_result>& results) {
  moments s, zs, pos, ang;
  double low_p = 0;
  for (const auto& r : results) {
    s.add(r.ratio.s), zs.add((r.ratio.s - 1) / r.ratio.se_s);
    low_p += r.ratio.p_value < 0.01;
    pos.add(std::sqrt(r.noise.position_var)), ang.add(std::sqrt(r.noise.angle_var));
  }
  std::printf(
      "\nmu-free test (T/F against eps): s mean %.4f, sd %.4f, sd of (s - 1)/se %.2f; "
      "chi2 p < 0.01 in %.1f %% of seeds\n",
      s.mean(), s.sd(), zs.sd(), 100 * low_p / s.n);
  std::printf("tracking noise from the residuals: %.4f mm (sd %.4f), %.5f rad (sd %.5f)\n",
              1e3 * pos.mean(), 1e3 * pos.sd(), ang.mean(), ang.sd());
}

sweep_options parse(int argc, char** argv) {
  sweep_options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error("missing value after " + a);
      return argv[++i];
    };
    if (a == "--seeds")
      o.seeds = std::stoi(value());
    else if (a == "--first")
      o.first = static_cast<unsigned>(std::stoul(value()));
    else if (a == "--threads")
      o.threads = std::max(1, std::stoi(value()));
    else if (a == "--fit-frames")
      o.analysis.fit_frames = std::stoi(value());
    else if (a == "--evaluate-at")
      o.analysis.evaluate_at = std::stoi(value());
    else if (a == "--noise-scale")
      o.noise_scale = std::stod(value());
    else if (a == "--no-window-correction")
      o.analysis.window_correction = false;
    else if (a == "--correction-iterations")
      o.analysis.correction_iterations = std::stoi(value());
    else
      throw std::runtime_error("unknown argument " + a);
  }
  if (o.seeds < 2) throw std::runtime_error("--seeds must be at least 2");
  if (o.analysis.fit_frames < 4) throw std::runtime_error("--fit-frames must be at least 4");
  if (o.analysis.evaluate_at >= o.analysis.fit_frames)
    throw std::runtime_error("--evaluate-at must be below --fit-frames");
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const sweep_options opt = parse(argc, argv);
    std::printf(
        "cd_sweep: seeds %u-%u, %d throws each; fits over %d frames, evaluated at frame "
        "%d; tracking noise x %g; window correction %s\n",
        opt.first, opt.first + static_cast<unsigned>(opt.seeds) - 1, opt.throws,
        opt.analysis.fit_frames,
        opt.analysis.evaluate_at < 0 ? opt.analysis.fit_frames / 2 : opt.analysis.evaluate_at,
        opt.noise_scale, opt.analysis.window_correction ? "on" : "off");
    std::vector<seed_result> results(static_cast<std::size_t>(opt.seeds));
    std::atomic<int> done{0};
    auto work = [&](int worker) {
      for (int k = worker; k < opt.seeds; k += opt.threads) {
        results[static_cast<std::size_t>(k)] = run_seed(opt.first + static_cast<unsigned>(k), opt);
        const int d = ++done;
        if (d % 50 == 0 || d == opt.seeds)
          std::fprintf(stderr, "cd_sweep: %d/%d seeds\n", d, opt.seeds);
      }
    };
    std::vector<std::thread> pool;
    pool.reserve(static_cast<std::size_t>(opt.threads));
    for (int w = 0; w < opt.threads; ++w) pool.emplace_back(work, w);
    for (auto& th : pool) th.join();
    print_bands(results, false);
    if (opt.analysis.window_correction) print_bands(results, true);
    print_estimators(results);
    print_summary(results);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "cd_sweep: %s\n", e.what());
    return 2;
  }
}
