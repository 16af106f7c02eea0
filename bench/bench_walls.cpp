// Walls benchmark: the cost of Boundaries::admits against a cylinder mould
// meshed as an STL mesher does it (long slivers spanning its height, a fan
// of thin triangles for its floor), the walls of a LIGGGHTS scene.
//
// Two kinds of query, each timed over the whole set (median of repeated
// passes): the relaxation's, a sphere inside the mould moved by a small
// step (a FIRE step), and the relocation's, a sphere moved from one place
// of the mould to another. Prints nanoseconds per query, those of the
// index's lookup alone (Boundaries::triangles_tested), the triangles one
// query looks at, and how many were admitted.
//
// usage: bench_walls [segments] [queries] [timed passes]
#include "reinforce_boundaries.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace reinforce;

namespace {

struct Query {
  Vec3 from, c;
  double r;
};

// An open-topped cylinder about the z axis through (cx, cy), from z = 0 to
// `height`: per segment, its side rectangle as two triangles and one
// triangle of the floor's fan.
std::vector<Triangle> mould(double cx, double cy, double radius, double height, int segments)
{
  std::vector<Triangle> tris;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < segments; ++i) {
    const double a0 = 2 * pi * i / segments, a1 = 2 * pi * (i + 1) / segments;
    const Vec3 p0{cx + radius * std::cos(a0), cy + radius * std::sin(a0), 0};
    const Vec3 p1{cx + radius * std::cos(a1), cy + radius * std::sin(a1), 0};
    const Vec3 up{0, 0, height};
    tris.push_back({p0, p1, p1 + up});
    tris.push_back({p0, p1 + up, p0 + up});
    tris.push_back({{cx, cy, 0}, p1, p0});
  }
  return tris;
}

template <class Gen> Vec3 inside(Gen &gen, double cx, double cy, double radius, double height)
{
  std::uniform_real_distribution<double> u(-1, 1), z(0, height);
  for (;;) {
    const double x = u(gen), y = u(gen);
    if (x * x + y * y <= 1) return {cx + radius * x, cy + radius * y, z(gen)};
  }
}

template <class Gen> Vec3 direction(Gen &gen)
{
  std::normal_distribution<double> g;
  const Vec3 v{g(gen), g(gen), g(gen)};
  return (1 / norm(v)) * v;
}

// Nanoseconds per query of f (median of `passes` passes); the sum of what
// f returned in the last pass.
template <class F>
double time_queries(const std::vector<Query> &queries, int passes, F &&f, std::size_t *sum)
{
  std::vector<double> ns;
  for (int p = 0; p < passes; ++p) {
    std::size_t total = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (const Query &q : queries) total += f(q);
    const auto t1 = std::chrono::steady_clock::now();
    ns.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / queries.size());
    *sum = total;
  }
  std::sort(ns.begin(), ns.end());
  return ns[ns.size() / 2];
}

}    // namespace

int main(int argc, char **argv)
{
  const int segments = argc > 1 ? std::atoi(argv[1]) : 64;
  const int count = argc > 2 ? std::atoi(argv[2]) : 200000;
  const int passes = argc > 3 ? std::atoi(argv[3]) : 5;
  if (segments < 3 || count < 1 || passes < 1) {
    std::fprintf(stderr, "usage: bench_walls [segments >= 3] [queries] [timed passes]\n");
    return 2;
  }
  // The scene of the LIGGGHTS mould test: radius 0.05 m, height 0.1 m,
  // spheres of radius 4 to 8 mm.
  const double cx = 0.06, cy = 0.06, radius = 0.05, height = 0.1;
  Boundaries walls;
  for (const Triangle &t : mould(cx, cy, radius, height, segments)) walls.add(t);
  std::mt19937_64 gen(12345);
  std::uniform_real_distribution<double> rad(0.004, 0.008);
  std::vector<Query> step, jump;
  for (int i = 0; i < count; ++i) {
    const double r = rad(gen);
    const Vec3 c = inside(gen, cx, cy, radius, height);
    step.push_back({c, c + (0.05 * r) * direction(gen), r});
    jump.push_back({inside(gen, cx, cy, radius, height), c, r});
  }
  std::printf("mould: %d segments, %zu triangles; %d queries, median of %d passes\n", segments,
              walls.size(), count, passes);
  std::printf("| query | ns per admits | ns per index lookup | triangles looked at (mean) | "
              "admitted |\n|---|---|---|---|---|\n");
  for (const auto &kind : {std::make_pair("step (0.05 r)", &step), std::make_pair("jump", &jump)}) {
    std::size_t admitted = 0, looked = 0;
    const double ns = time_queries(
        *kind.second, passes, [&](const Query &q) { return walls.admits(q.from, q.c, q.r, 1e-6); },
        &admitted);
    // The index alone: the triangles a query would test, none tested.
    const double lookup = time_queries(
        *kind.second, passes,
        [&](const Query &q) { return walls.triangles_tested(q.from, q.c, q.r); }, &looked);
    std::printf("| %s | %.0f | %.0f | %.1f | %zu of %d |\n", kind.first, ns, lookup,
                static_cast<double>(looked) / count, admitted, count);
  }
  return 0;
}
