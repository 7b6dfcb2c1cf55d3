//  Copyright (c) 2026 the spinslide developers.
//  Distributed under the Boost Software License, Version 1.0.
//
// The exact limit surface of flat patches against the Howe–Cutkosky
// ellipsoid (docs/patches.md, "The limit surface"), the model planar
// manipulation uses for a patch's friction: (|F|/F_max)² + (τ/τ_max)² = 1,
// with the exact largest force F_max = μN (pure translation) and the exact
// largest moment τ_max (pure rotation about the centre of pressure).
//
// For each patch (uniform pressure, origin at its centre) the wrench of every
// twist direction is a point w of the exact surface; the ellipsoid's point
// in w's direction is w/e, e = √((|F|/F_max)² + (τ/τ_max)²), and the
// deviation 1 − e is how far inside the ellipsoid the exact surface lies,
// relative to the ellipsoid's radius there.  Prints the largest deviation of
// each patch and the twist where it occurs; the paper's disk, from its
// closed forms 𝓕(ε), 𝓣(ε), is the check of the measure: a regular 512-gon
// must agree with it.  Writes limit_surface.csv and (with gnuplot)
// limit_surface.png: the surface's sections of the square (slip along a side
// and along a diagonal) and of the sole (slip along its length and across),
// beside the ellipsoid.
//   ./build/release/examples/limit_surface [output-directory]
#include <spinslide/values/friction_wrench.hpp>
#include <spinslide/values/polygon_patch.hpp>
#include <spinslide/values/profile.hpp>

#include <boost/math/constants/constants.hpp>

#include "../gnuplot.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace {

using spinslide::planar_twist;
using spinslide::polygon_patch;
using vertex = std::array<double, 2>;

std::vector<vertex> rectangle(double length, double width) {
  return {{-length / 2, -width / 2},
          {length / 2, -width / 2},
          {length / 2, width / 2},
          {-length / 2, width / 2}};
}
std::vector<vertex> regular(int n, double radius) {
  const double pi = boost::math::constants::pi<double>();
  std::vector<vertex> v;
  for (int k = 0; k < n; ++k)
    v.push_back({radius * std::cos(2 * pi * k / n), radius * std::sin(2 * pi * k / n)});
  return v;
}
// An equilateral triangle with its centroid at the origin.
std::vector<vertex> triangle(double side) {
  const double h = side * std::sqrt(3.0) / 2;
  return {{-side / 2, -h / 3}, {side / 2, -h / 3}, {0, 2 * h / 3}};
}

struct named_patch {
  const char* name;
  std::vector<vertex> outline;
};

// The twist of direction (θ, φ): the slip v = ρ sin θ (cos φ, sin φ), the
// spin cos θ, so that ε = v/(ρω) = tan θ with ρ the patch's size.
planar_twist<double> twist_at(double theta, double phi, double size) {
  const double v = size * std::sin(theta);
  return {{v * std::cos(phi), v * std::sin(phi)}, std::cos(theta)};
}

struct worst_point {
  double deviation = 0, theta = 0, phi = 0;
};

// 1 − e at the wrench of a twist (see the file's comment).
double deviation(const spinslide::planar_wrench<double>& w, double torque_max) {
  const double f = std::hypot(w.force[0], w.force[1]), t = w.torque / torque_max;
  return 1 - std::sqrt(f * f + t * t);
}

// The largest deviation over twist directions: θ on a grid in [0, π/2]
// (ω ≥ 0 suffices: the surface is symmetric about the origin, w(−t) =
// −w(t)) and φ in [0, 2π), refined around the grid's worst point.
worst_point largest_deviation(const polygon_patch<double>& p, double torque_max, double size) {
  const double pi = boost::math::constants::pi<double>();
  worst_point worst;
  auto probe = [&](double theta, double phi) {
    const double d =
        deviation(spinslide::friction_wrench(p, twist_at(theta, phi, size)), torque_max);
    if (d > worst.deviation) worst = {d, theta, phi};
  };
  const int n_theta = 120, n_phi = 96;
  for (int i = 1; i < n_theta; ++i)
    for (int j = 0; j < n_phi; ++j) probe(pi / 2 * i / n_theta, 2 * pi * j / n_phi);
  for (double step = pi / 2 / n_theta; step > 1e-7; step /= 4) {
    const worst_point at = worst;
    for (int i = -4; i <= 4; ++i)
      for (int j = -4; j <= 4; ++j) probe(at.theta + i * step / 4, at.phi + j * step / 4);
  }
  return worst;
}

// The disk's deviation from its closed forms: 1 − √(𝓕² + (𝓣/⟨r⟩)²), ⟨r⟩ = 2/3.
worst_point disk_deviation() {
  const spinslide::uniform_disk<double> disk;
  worst_point worst;
  for (int i = 1; i < 100000; ++i) {
    const double theta = boost::math::constants::half_pi<double>() * i / 100000;
    const auto ft = disk.force_torque(std::tan(theta));
    const double t = ft.torque / disk.mean_radius();
    const double d = 1 - std::sqrt(ft.force * ft.force + t * t);
    if (d > worst.deviation) worst = {d, theta, 0};
  }
  return worst;
}

// τ_max: the torque of a pure spin about the centre.
double largest_torque(const polygon_patch<double>& p) {
  return std::fabs(spinslide::friction_wrench(p, planar_twist<double>{{0, 0}, 1}).torque);
}

// The sections at the slip directions φ of one patch, as (|F|, |τ|/τ_max) rows.
void write_sections(FILE* out, const char* name, const polygon_patch<double>& p, double size,
                    const std::array<double, 2>& phis) {
  const double tmax = largest_torque(p);
  for (const double phi : phis) {
    std::fprintf(out, "# %s phi=%g\n", name, phi);
    for (int i = 0; i <= 400; ++i) {
      const double theta = boost::math::constants::half_pi<double>() * i / 400;
      const auto w = spinslide::friction_wrench(p, twist_at(theta, phi, size));
      std::fprintf(out, "%.9g %.9g\n", std::hypot(w.force[0], w.force[1]),
                   std::fabs(w.torque) / tmax);
    }
    std::fprintf(out, "\n\n");
  }
}

const char* const script = R"(set terminal pngcairo size 1100,520 font ',11'
set output 'limit_surface.png'
set multiplot layout 1,2
set size ratio -1
set xrange [0:1.05]
set yrange [0:1.05]
set xlabel '|F| / F_{max}'
set ylabel '{/Symbol t} / {/Symbol t}_{max}'
set key bottom left
set samples 200
set parametric
set trange [0:pi/2]
set title 'square'
plot cos(t), sin(t) w l lw 2 dt 2 lc rgb 'black' t 'Howe–Cutkosky ellipsoid', \
     'limit_surface.csv' i 0 u 1:2 w l lw 2 t 'exact, slip along a side', \
     'limit_surface.csv' i 1 u 1:2 w l lw 2 t 'exact, slip along a diagonal'
set title 'sole 0.22 × 0.10 m'
plot cos(t), sin(t) w l lw 2 dt 2 lc rgb 'black' t 'Howe–Cutkosky ellipsoid', \
     'limit_surface.csv' i 2 u 1:2 w l lw 2 t 'exact, slip along the length', \
     'limit_surface.csv' i 3 u 1:2 w l lw 2 t 'exact, slip across'
unset multiplot
)";

}  // namespace

int main(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : ".";
  const double pi = boost::math::constants::pi<double>();
  const std::vector<named_patch> patches = {
      {"disk (regular 512-gon)", regular(512, 1.0)}, {"square", rectangle(1.0, 1.0)},
      {"equilateral triangle", triangle(1.0)},       {"regular hexagon", regular(6, 1.0)},
      {"sole 0.22 x 0.10", rectangle(0.22, 0.10)},   {"rectangle 2.75 : 1", rectangle(2.75, 1.0)},
      {"strip 200 : 1", rectangle(200.0, 1.0)}};
  const worst_point disk = disk_deviation();
  std::printf("largest deviation of the exact limit surface inside the Howe-Cutkosky ellipsoid\n");
  std::printf(
      "(at the twist of slip v along phi and spin w, eps = v/(l w), l the largest\n"
      " distance of a vertex from the centre)\n");
  std::printf("%-24s %10s %10s %10s\n", "patch", "deviation", "eps", "phi (deg)");
  std::printf("%-24s %9.3f%% %10.4f %10s\n", "disk (closed forms)", 100 * disk.deviation,
              std::tan(disk.theta), "any");
  for (const auto& np : patches) {
    const polygon_patch<double> p(np.outline);
    double size = 0;
    for (const auto& v : np.outline) size = std::fmax(size, std::hypot(v[0], v[1]));
    const worst_point w = largest_deviation(p, largest_torque(p), size);
    std::printf("%-24s %9.3f%% %10.4f %10.2f\n", np.name, 100 * w.deviation, std::tan(w.theta),
                std::fmod(w.phi * 180 / pi + 360, 360.0));
  }
  FILE* out = spinslide_examples::open_output(dir + "/limit_surface.csv", "limit_surface");
  if (!out) return 1;
  write_sections(out, "square", polygon_patch<double>(rectangle(1.0, 1.0)), std::sqrt(0.5),
                 {0.0, pi / 4});
  write_sections(out, "sole", polygon_patch<double>(rectangle(0.22, 0.10)), std::hypot(0.11, 0.05),
                 {0.0, pi / 2});
  std::fclose(out);
  if (!spinslide_examples::plot(dir, "limit_surface.gp", script))
    std::printf("(no gnuplot: limit_surface.csv written, no figure)\n");
  return 0;
}
