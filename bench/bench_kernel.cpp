// Kernel benchmark: error against run time for the tangent-sphere solvers.
//
// For each solver variant and input set, over quadruples built around a
// known sphere: median and max tangency residual of the solution nearest the
// known sphere, the fraction of quadruples where the known sphere is not
// returned (within 1e-6 relative), and nanoseconds per solve (median of
// repeated timed passes over the whole set). Prints a Markdown table.
//
// usage: bench_kernel [quadruples per set] [timed passes]
#include "reinforce_tangent_sphere.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace reinforce;

namespace {

struct Case {
  Sphere in[4];
  Sphere known;
};

Vec3 random_unit(std::mt19937_64 &rng)
{
  std::normal_distribution<double> g;
  Vec3 v{g(rng), g(rng), g(rng)};
  return (1.0 / norm(v)) * v;
}

Case around(const Sphere &s, const Vec3 dir[4], const double radius[4])
{
  Case c;
  c.known = s;
  for (int i = 0; i < 4; ++i)
    c.in[i] = {s.c + ((s.r + radius[i]) / norm(dir[i])) * dir[i], radius[i]};
  return c;
}

// Spread directions (pairwise angle > 20 degrees), radii ratio <= 3.
std::vector<Case> well_conditioned(int n, std::mt19937_64 &rng)
{
  std::uniform_real_distribution<double> u(1.0, 3.0);
  std::vector<Case> out;
  while (static_cast<int>(out.size()) < n) {
    Vec3 dir[4];
    for (Vec3 &d : dir) d = random_unit(rng);
    bool spread = true;
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j) spread = spread && dot(dir[i], dir[j]) < std::cos(0.35);
    if (!spread) continue;
    const double radius[4] = {u(rng), u(rng), u(rng), u(rng)};
    out.push_back(around({{u(rng), u(rng), u(rng)}, u(rng)}, dir, radius));
  }
  return out;
}

// The stiff families of docs/design.md ("The kernel"), in equal shares: radius ratio
// 1e3 (both ways), nearly coplanar centres, clustered directions (nearly
// collinear inverted centres), offset 1e6, radii 1e-6.
const char *const kFamilies[6] = {
    "neighbours 1e3 x larger", "sphere 1e3 x larger", "nearly coplanar centres",
    "clustered directions",    "offset 1e6",          "radii 1e-6"};

// family < 0: all families in turn; else that family only.
std::vector<Case> stiff(int n, std::mt19937_64 &rng, int family = -1)
{
  std::uniform_real_distribution<double> u(1.0, 3.0), s(-1, 1);
  std::vector<Case> out;
  for (int k = 0; static_cast<int>(out.size()) < n; ++k) {
    Vec3 dir[4];
    for (Vec3 &d : dir) d = random_unit(rng);
    double radius[4] = {u(rng), u(rng), u(rng), u(rng)};
    Sphere known{{u(rng), u(rng), u(rng)}, u(rng)};
    switch (family < 0 ? k % 6 : family) {
    case 0:
      for (double &r : radius) r *= 1e3;
      break;
    case 1:
      known.r *= 1e3;
      break;
    case 2:
      for (Vec3 &d : dir) d.z = 1e-7 * s(rng);
      break;
    case 3: {
      const Vec3 axis = random_unit(rng);
      for (Vec3 &d : dir) d = axis + 0.05 * random_unit(rng);
      break;
    }
    case 4:
      known.c = known.c + Vec3{1e6, -1e6, 1e6};
      break;
    case 5:
      for (double &r : radius) r *= 1e-6;
      known.r *= 1e-6;
      known.c = 1e-6 * known.c;
      break;
    }
    out.push_back(around(known, dir, radius));
  }
  return out;
}

struct Variant {
  const char *name;
  int (*solve)(const Sphere[4], Sphere[2], int);
  int newton_steps;
};

struct Row {
  double median_residual, max_residual, failures, ns;
};

Row measure(const Variant &v, const std::vector<Case> &cases, int passes)
{
  std::vector<double> residuals;
  int failed = 0;
  for (const Case &c : cases) {
    Sphere out[2];
    const int n = v.solve(c.in, out, v.newton_steps);
    double best = INFINITY, res = INFINITY;
    for (int k = 0; k < n; ++k) {
      const double miss =
          (norm(out[k].c - c.known.c) + std::fabs(out[k].r - c.known.r)) / c.known.r;
      if (miss < best) {
        best = miss;
        res = tangency_residual(c.in, out[k]);
      }
    }
    if (best > 1e-6) {
      ++failed;
    } else {
      residuals.push_back(res);
    }
  }
  std::vector<double> times;
  volatile double sink = 0;
  for (int p = 0; p < passes; ++p) {
    const auto t0 = std::chrono::steady_clock::now();
    for (const Case &c : cases) {
      Sphere out[2];
      sink = sink + v.solve(c.in, out, v.newton_steps);
    }
    const auto t1 = std::chrono::steady_clock::now();
    times.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() / cases.size());
  }
  std::sort(times.begin(), times.end());
  std::sort(residuals.begin(), residuals.end());
  Row row{};
  row.median_residual = residuals.empty() ? NAN : residuals[residuals.size() / 2];
  row.max_residual = residuals.empty() ? NAN : residuals.back();
  row.failures = static_cast<double>(failed) / cases.size();
  row.ns = times[times.size() / 2];
  return row;
}

}    // namespace

int main(int argc, char **argv)
{
  const int n = argc > 1 ? std::atoi(argv[1]) : 100000;
  const int passes = argc > 2 ? std::atoi(argv[2]) : 7;
  if (n <= 0 || passes <= 0) {
    std::fprintf(stderr, "usage: bench_kernel [quadruples per set > 0] [timed passes > 0]\n");
    return 2;
  }
  std::mt19937_64 rng(2026);
  const std::vector<Case> sets[2] = {well_conditioned(n, rng), stiff(n, rng)};
  const char *set_names[2] = {"well-conditioned", "stiff"};
  const Variant variants[] = {
      {"inversion", tangent_spheres_inversion, 0},
      {"inversion + 1 Newton", tangent_spheres_inversion, 1},
      {"inversion + 2 Newton", tangent_spheres_inversion, 2},
      {"algebraic", tangent_spheres_algebraic, 0},
      {"algebraic + 1 Newton", tangent_spheres_algebraic, 1},
  };
  std::printf("| set | solver | median residual | max residual | failures | ns/solve |\n");
  std::printf("|---|---|---|---|---|---|\n");
  for (int s = 0; s < 2; ++s)
    for (const Variant &v : variants) {
      const Row r = measure(v, sets[s], passes);
      std::printf("| %s | %s | %.1e | %.1e | %.4f%% | %.0f |\n", set_names[s], v.name,
                  r.median_residual, r.max_residual, 100 * r.failures, r.ns);
    }
  std::printf("\nStiff families alone (failures / max residual):\n\n| family |");
  for (const Variant &v : variants) std::printf(" %s |", v.name);
  std::printf("\n|---|---|---|---|---|---|\n");
  for (int f = 0; f < 6; ++f) {
    const std::vector<Case> cases = stiff(n / 6, rng, f);
    std::printf("| %s |", kFamilies[f]);
    for (const Variant &v : variants) {
      const Row r = measure(v, cases, 1);
      std::printf(" %.2f%% / %.0e |", 100 * r.failures, r.max_residual);
    }
    std::printf("\n");
  }
  std::printf("\n%d quadruples per set, median of %d timed passes; residual = max_i "
              "| |c - c_i| - (r + r_i) | / r of the solution nearest the known sphere; "
              "failure = known sphere not returned within 1e-6.\n",
              n, passes);
  return 0;
}
