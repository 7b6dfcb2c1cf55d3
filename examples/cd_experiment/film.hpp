//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The simulated CD experiment and its film (cd_experiment.hpp has the whole
// story): the CD's constants, N hand-thrown throws filmed at 25 frames/s with
// tracking noise, and the frames' CSV format, written and read.
#ifndef SPINSLIDE_EXAMPLES_CD_FILM_HPP
#define SPINSLIDE_EXAMPLES_CD_FILM_HPP

#include <spinslide/spinslide.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace cd_experiment {

inline const double R = 0.06, hole = 0.125, gamma_cd = (1 + hole * hole) / 2, g = 9.81;
inline const double fps = 25;
inline const int default_fit_frames = 7;

// The tracking noise of the simulated film: the sd of each coordinate of the
// centre (m) and of the angle (rad) in every frame.
struct film_noise {
  double position, angle;
};
inline const film_noise tracking_noise = {0.5e-3, 0.01};
inline const double true_a = 0.202, true_b = 0.00053;

struct frame {
  double t, x, y, theta;
};
using throws_t = std::map<int, std::vector<frame>>;

// The frame times of a throw that stops at `stop` (s): k/fps up to the
// first frame at or after the stop (at rest).
inline std::vector<double> frame_times(double stop) {
  std::vector<double> t;
  for (int k = 0;; ++k) {
    t.push_back(k / fps);
    if (t.back() >= stop) return t;
  }
}

// Simulates and films N throws.  The motion is spinslide::trajectory's,
// sampled at the frame times in the paper's units (it steps through the
// stop exactly and gives the rest state after it), converted to SI.
inline throws_t simulate(int n_throws, unsigned seed, film_noise noise_sd = tracking_noise) {
  const spinslide::annulus<> cd(hole);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> speed(0.4, 1.2), spin(5, 30), angle(0, 6.283185307179586);
  std::normal_distribution<double> noise(0, 1);
  throws_t out;
  for (int n = 1; n <= n_throws; ++n) {
    const double mu = true_a + true_b * n;
    const double v0 = speed(rng), w0 = spin(rng), direction = angle(rng), theta0 = angle(rng);
    const spinslide::si_motion<spinslide::annulus<>> units(cd, R, mu, g, gamma_cd);
    const auto stop = spinslide::simulate_throw_si(
        cd, spinslide::disk_radius{R}, spinslide::friction_coefficient{mu}, spinslide::gravity{g},
        gamma_cd, spinslide::initial_speed{v0}, spinslide::initial_spin{w0});
    const std::vector<double> t = frame_times(stop.time);
    std::vector<double> t_scaled;
    t_scaled.reserve(t.size());
    for (const double tk : t) t_scaled.push_back(tk / units.time_unit());
    const auto motion = spinslide::trajectory(cd, gamma_cd, v0 / units.velocity_unit(),
                                              w0 / units.spin_unit(), t_scaled);
    std::vector<frame>& frames = out[n];
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double s = motion[k].distance * units.distance_unit();
      const double th = motion[k].angle * units.angle_unit();
      frames.push_back({t[k], s * std::cos(direction) + noise_sd.position * noise(rng),
                        s * std::sin(direction) + noise_sd.position * noise(rng),
                        theta0 + th + noise_sd.angle * noise(rng)});
    }
  }
  return out;
}

inline void write_frames(const std::string& path, const throws_t& throws) {
  std::ofstream f(path);
  f << "throw,t,x,y,theta\n";
  f.precision(10);
  for (const auto& [n, frames] : throws)
    for (const frame& fr : frames)
      f << n << ',' << fr.t << ',' << fr.x << ',' << fr.y << ',' << fr.theta << '\n';
}

inline throws_t read_frames(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  std::string line;
  std::getline(f, line);
  if (line.rfind("throw,t,x,y,theta", 0) != 0)
    throw std::runtime_error(path + ": the first line must be the header throw,t,x,y,theta");
  throws_t out;
  int row = 1;
  while (std::getline(f, line)) {
    ++row;
    if (line.empty()) continue;
    std::istringstream in(line);
    int n;
    frame fr;
    char c1, c2, c3, c4;
    if (!(in >> n >> c1 >> fr.t >> c2 >> fr.x >> c3 >> fr.y >> c4 >> fr.theta) || c1 != ',' ||
        c2 != ',' || c3 != ',' || c4 != ',')
      throw std::runtime_error(path + ", line " + std::to_string(row) +
                               ": expected throw,t,x,y,theta (five numbers)");
    auto& frames = out[n];
    if (!frames.empty() && !(fr.t > frames.back().t))
      throw std::runtime_error(path + ", line " + std::to_string(row) + ": times must increase");
    frames.push_back(fr);
  }
  if (out.empty()) throw std::runtime_error(path + ": no frames");
  return out;
}

}  // namespace cd_experiment

#endif  // SPINSLIDE_EXAMPLES_CD_FILM_HPP
