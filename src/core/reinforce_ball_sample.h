// The volume fraction of a ball inside a body, sampled at fixed points:
// the share of a target inside the bars (the relocation's displaced
// targets, the regrowth's volume balance).
#pragma once

#include "reinforce_vec3.h"

#include <vector>

namespace reinforce {

inline double ball_volume(double r)
{
  return 4.0 / 3.0 * 3.14159265358979323846 * r * r * r;
}

// Fixed sample points of the unit ball (a cubic lattice, 9 per axis, 389
// points): the volume fraction of a target inside the bars to about 1 %.
inline const std::vector<Vec3> &unit_ball_points()
{
  static const std::vector<Vec3> points = [] {
    std::vector<Vec3> p;
    const int n = 9;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          const Vec3 u{(2 * i + 1.0) / n - 1, (2 * j + 1.0) / n - 1, (2 * k + 1.0) / n - 1};
          if (norm2(u) <= 1) p.push_back(u);
        }
    return p;
  }();
  return points;
}

// The share of the sample points of ball (x, r) for which inside(point) is
// true: 0 to 1, in steps of 1/389.
template <class Inside> double ball_fraction(Vec3 x, double r, Inside inside)
{
  const std::vector<Vec3> &points = unit_ball_points();
  std::size_t in = 0;
  for (const Vec3 &u : points)
    if (inside(x + r * u)) ++in;
  return static_cast<double>(in) / points.size();
}

}    // namespace reinforce
