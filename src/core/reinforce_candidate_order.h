// The candidates of one target and the order in which groups of them are
// tried: an order that does not depend on where the spheres sit in a
// process's view, so every process count tries the same groups
// (docs/design.md, "The relocation engine").
#pragma once

#include "reinforce_tangent_sphere.h"
#include "reinforce_vec3.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace reinforce {

// A candidate neighbour: its surface gap to the target, its atom ID and
// its index in the scene.
struct Candidate {
  double gap;
  std::int64_t id;
  int index;
  bool operator<(const Candidate &o) const
  {
    if (gap != o.gap) return gap < o.gap;
    if (id != o.id) return id < o.id;
    return index < o.index;
  }
};

// A fixed order of spheres that does not depend on where they sit in a
// process's view: by id, then position (periodic images of one atom).
inline bool same_order_everywhere(std::int64_t ida, Vec3 a, std::int64_t idb, Vec3 b)
{
  if (ida != idb) return ida < idb;
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

// The smallest n with C(n, 4) >= tries: the colex enumeration of the first
// `tries` groups of four uses only the n nearest candidates.
inline std::size_t candidates_needed(int tries)
{
  double groups = 0;
  std::size_t n = 4;
  for (;; ++n) {
    groups = static_cast<double>(n) * (n - 1) * (n - 2) * (n - 3) / 24;
    if (groups >= tries) return n;
  }
}

// The smallest n with C(n, 3) >= tries.
inline std::size_t candidates_needed_for_triples(int tries)
{
  std::size_t n = 3;
  while (static_cast<double>(n) * (n - 1) * (n - 2) / 6 < tries) ++n;
  return n;
}

// Calls f(a, b, c) for the triples of [0, n) in colex order (all triples of
// the k nearest before any using the (k+1)-th), at most `limit` of them or
// until f returns true.
template <class F> void for_each_triple(int n, int limit, F &&f)
{
  int done = 0;
  for (int c = 2; c < n; ++c)
    for (int b = 1; b < c; ++b)
      for (int a = 0; a < b; ++a) {
        if (done++ >= limit || f(a, b, c)) return;
      }
}

// Calls f(a, b, c, d) for the groups of four of [0, n) in colex order (all
// groups of the k nearest before any group using the (k+1)-th), at most
// `limit` groups or until f returns true.
template <class F> void for_each_group(int n, int limit, F &&f)
{
  int done = 0;
  for (int d = 3; d < n; ++d)
    for (int c = 2; c < d; ++c)
      for (int b = 1; b < c; ++b)
        for (int a = 0; a < b; ++a) {
          if (done++ >= limit || f(a, b, c, d)) return;
        }
}

// Surface gaps between the first n candidates, pair by pair (row-major,
// n x n): the groups and triples reuse each pair many times.
template <class SphereOf>
std::vector<double> pair_gaps(const std::vector<Candidate> &near, std::size_t n,
                              SphereOf &&sphere_of)
{
  std::vector<double> gap(n * n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Sphere a = sphere_of(near[i].index), b = sphere_of(near[j].index);
      gap[i * n + j] = gap[j * n + i] = norm(a.c - b.c) - a.r - b.r;
    }
  return gap;
}

}    // namespace reinforce
