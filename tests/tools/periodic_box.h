// What the scene tools share: the box with its periodic images, the cells
// around a point in a cell grid over it and the random numbers
// (grow_packing, scene_quality), and the spheres of a --bar (make_scene,
// grow_packing). Header-only so that each tool stays one standalone C++17
// file to build (tests/tools/README.md); kept in one place so that the
// packings and the measures of them agree, and so do the two tools' bars.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tools {

constexpr double kFourThirdsPi = 4.1887902047863905;

// splitmix64: portable, deterministic uniform doubles in [0, 1).
struct Rng {
  std::uint64_t s;
  explicit Rng(std::uint64_t seed) : s(seed * 0x9E3779B97F4A7C15ULL + 12345) {}
  std::uint64_t next()
  {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }
  double uniform() { return (next() >> 11) * (1.0 / 9007199254740992.0); }
  // A point uniform in the unit ball, by rejection from the cube.
  void in_unit_ball(double q[3])
  {
    do {
      for (int k = 0; k < 3; ++k) q[k] = 2 * uniform() - 1;
    } while (q[0] * q[0] + q[1] * q[1] + q[2] * q[2] > 1);
  }
};

// An orthogonal box, each dimension walled or periodic.
struct PeriodicBox {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  bool periodic[3] = {false, false, false};
  double len(int k) const { return hi[k] - lo[k]; }
  // a - b, the nearest image along periodic dimensions.
  void delta(const double *a, const double *b, double *d) const
  {
    for (int k = 0; k < 3; ++k) {
      d[k] = a[k] - b[k];
      if (periodic[k]) d[k] -= len(k) * std::round(d[k] / len(k));
    }
  }
  // x into [lo, hi) along periodic dimensions.
  void wrap(double *x) const
  {
    for (int k = 0; k < 3; ++k)
      if (periodic[k]) {
        x[k] -= len(k) * std::floor((x[k] - lo[k]) / len(k));
        if (x[k] >= hi[k]) x[k] = lo[k];
      }
  }
};

// Calls f(cell index) for each cell of an n[0] x n[1] x n[2] grid over box
// within `reach` cells of cell c (per dimension), through the periodic
// boundaries; a periodic dimension with fewer than 2 reach + 1 cells is
// visited once whole, so no cell comes twice.
template <class F>
void for_cells_around(const PeriodicBox &box, const int n[3], const int c[3], int reach, F &&f)
{
  int lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = c[k] - reach;
    hi[k] = c[k] + reach;
    if (!box.periodic[k]) {
      lo[k] = std::max(lo[k], 0);
      hi[k] = std::min(hi[k], n[k] - 1);
    } else if (hi[k] - lo[k] + 1 >= n[k]) {
      lo[k] = 0;
      hi[k] = n[k] - 1;
    }
  }
  for (int a = lo[0]; a <= hi[0]; ++a)
    for (int b = lo[1]; b <= hi[1]; ++b)
      for (int d = lo[2]; d <= hi[2]; ++d) {
        const int ia = ((a % n[0]) + n[0]) % n[0], ib = ((b % n[1]) + n[1]) % n[1],
                  id = ((d % n[2]) + n[2]) % n[2];
        f((ia * n[1] + ib) * n[2] + id);
      }
}

// Calls f(centre) for each sphere of a bar b = {X0, Y0, Z0, X1, Y1, Z1, R,
// STEP}: about STEP apart from X0 to X1, both ends included.
template <class F> void for_bar_centres(const std::vector<double> &b, F &&f)
{
  const double len =
      std::sqrt(std::pow(b[3] - b[0], 2) + std::pow(b[4] - b[1], 2) + std::pow(b[5] - b[2], 2));
  const int n = std::max(1, static_cast<int>(std::round(len / b[7])));
  for (int s = 0; s <= n; ++s) {
    const double t = static_cast<double>(s) / n;
    const double p[3] = {b[0] + t * (b[3] - b[0]), b[1] + t * (b[4] - b[1]),
                         b[2] + t * (b[5] - b[2])};
    f(p);
  }
}

}    // namespace tools
