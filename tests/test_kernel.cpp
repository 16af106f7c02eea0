// Kernel tests: spheres tangent to four spheres. Each test states the
// tolerance it asserts and why.
#include "reinforce_tangent_sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace reinforce;

namespace {

using Solver = int (*)(const Sphere[4], Sphere[2], int);

// Four spheres around a known sphere s, touching it at the given directions.
void around(const Sphere &s, const Vec3 dir[4], const double radius[4], Sphere in[4])
{
  for (int i = 0; i < 4; ++i)
    in[i] = {s.c + ((s.r + radius[i]) / norm(dir[i])) * dir[i], radius[i]};
}

// Distance from the known sphere to the nearest returned one, relative to r.
double miss(const Sphere &known, const Sphere *out, int n)
{
  double best = INFINITY;
  for (int k = 0; k < n; ++k)
    best = std::min(best, (norm(out[k].c - known.c) + std::fabs(out[k].r - known.r)) / known.r);
  return best;
}

void expect_clean(const Sphere in[4], const Sphere *out, int n)
{
  ASSERT_GE(n, 0);
  ASSERT_LE(n, 2);
  for (int k = 0; k < n; ++k) {
    EXPECT_TRUE(is_finite(out[k].c));
    EXPECT_TRUE(std::isfinite(out[k].r));
    EXPECT_GT(out[k].r, 0);
    EXPECT_LE(tangency_residual(in, out[k]), kAcceptResidual);
  }
}

Vec3 random_unit(std::mt19937_64 &rng)
{
  std::normal_distribution<double> g;
  Vec3 v{g(rng), g(rng), g(rng)};
  return (1.0 / norm(v)) * v;
}

// Draws n random directions into dir; true when they are spread: every
// pairwise angle above 20 degrees (well-conditioned neighbours).
bool spread_directions(std::mt19937_64 &rng, Vec3 *dir, int n)
{
  for (int i = 0; i < n; ++i) dir[i] = random_unit(rng);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      if (!(dot(dir[i], dir[j]) < std::cos(0.35))) return false;
  return true;
}

// Regular tetrahedron with edge e, centred at the origin.
void tetrahedron(double e, double radius, Sphere in[4])
{
  const double a = e / (2 * std::sqrt(2.0));
  const Vec3 v[4] = {{a, a, a}, {a, -a, -a}, {-a, a, -a}, {-a, -a, a}};
  for (int i = 0; i < 4; ++i) in[i] = {v[i], radius};
}

}    // namespace

// Equal touching spheres on a regular tetrahedron: the one external solution
// sits at the centroid with r = e*sqrt(6)/4 - r_i. Tolerance 1e-13: a
// well-conditioned case, exact up to a few roundings.
TEST(Kernel, RegularTetrahedronEqualRadii)
{
  for (double edge : {2.0, 1.8, 2.5}) {    // touching, overlapping, apart
    Sphere in[4], out[2];
    tetrahedron(edge, 1.0, in);
    const double expected = edge * std::sqrt(6.0) / 4 - 1.0;
    for (Solver solve : {Solver(tangent_spheres_inversion), Solver(tangent_spheres_algebraic)}) {
      const int n = solve(in, out, 0);
      expect_clean(in, out, n);
      ASSERT_EQ(n, 1) << "edge " << edge;
      EXPECT_NEAR(out[0].r, expected, 1e-13);
      EXPECT_LT(norm(out[0].c), 1e-13);
    }
  }
}

// Four points (radius 0): the tangent sphere is the circumsphere.
TEST(Kernel, PointsGiveCircumsphere)
{
  Sphere in[4], out[2];
  tetrahedron(2.0, 0.0, in);
  const int n = tangent_spheres_inversion(in, out, 0);
  ASSERT_EQ(n, 1);
  EXPECT_NEAR(out[0].r, 2.0 * std::sqrt(6.0) / 4, 1e-13);
}

// Randomized property: build four spheres around a chosen one; the kernel
// must give it back. Well-conditioned draws (directions spread, radius ratio
// <= 3): residual <= 1e-12 relative with one Newton step, and the raw
// inversion within 1e-8 (it amplifies rounding by the condition of the
// triangle of inverted centres: 5e-10 was seen once in 20000 draws). A draw is well-conditioned
// when the smallest angle between directions is > 20 degrees.
TEST(Kernel, RecoversKnownSphereRandomized)
{
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> unif(1.0, 3.0);
  int tried = 0, missed_raw = 0, missed_polished = 0;
  double worst_polished = 0;
  while (tried < 20000) {
    Vec3 dir[4];
    if (!spread_directions(rng, dir, 4)) continue;
    ++tried;
    const double radius[4] = {unif(rng), unif(rng), unif(rng), unif(rng)};
    const Sphere known{{unif(rng), -unif(rng), unif(rng)}, unif(rng)};
    Sphere in[4], out[2];
    around(known, dir, radius, in);
    int n = tangent_spheres_inversion(in, out, 0);
    expect_clean(in, out, n);
    if (miss(known, out, n) > 1e-8) ++missed_raw;
    n = tangent_spheres_inversion(in, out, 1);
    expect_clean(in, out, n);
    const double m = miss(known, out, n);
    if (m > 1e-9) {
      ++missed_polished;
    } else {
      for (int k = 0; k < n; ++k)
        if ((norm(out[k].c - known.c) + std::fabs(out[k].r - known.r)) / known.r <= 1e-9)
          worst_polished = std::max(worst_polished, tangency_residual(in, out[k]));
    }
  }
  EXPECT_EQ(missed_raw, 0);
  EXPECT_EQ(missed_polished, 0);
  EXPECT_LE(worst_polished, 1e-12);
}

// The algebraic reference on the same kind of draws, as a check of the
// reference itself.
TEST(Kernel, AlgebraicReferenceRecoversKnownSphere)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unif(0.5, 2.0);
  for (int t = 0; t < 2000; ++t) {
    Vec3 dir[4] = {{1, 0.1, 0.2}, {-0.5, 0.9, 0.1}, {-0.4, -0.8, 0.3}, {0.1, 0.1, -1}};
    for (Vec3 &d : dir) d = d + 0.3 * random_unit(rng);
    const double radius[4] = {unif(rng), unif(rng), unif(rng), unif(rng)};
    const Sphere known{{0, 0, 0}, unif(rng)};
    Sphere in[4], out[2];
    around(known, dir, radius, in);
    const int n = tangent_spheres_algebraic(in, out, 0);
    expect_clean(in, out, n);
    EXPECT_LE(miss(known, out, n), 1e-10);
  }
}

// Radius ratios up to 1e3, both ways: a small sphere among big ones and a
// big one among small ones. Relative residual <= 1e-12 after polish.
TEST(Kernel, RadiusRatioThousand)
{
  const Vec3 dir[4] = {{1, 0.2, 0.1}, {-0.6, 0.8, 0.2}, {-0.5, -0.7, 0.4}, {0.1, 0.1, -1}};
  for (double big : {1e3, 1e-3}) {
    const Sphere known{{0.3, -0.2, 0.1}, 1.0};
    const double radius[4] = {big, 0.7 * big, 1.3 * big, big};
    Sphere in[4], out[2];
    around(known, dir, radius, in);
    const int n = tangent_spheres_inversion(in, out, 1);
    expect_clean(in, out, n);
    EXPECT_LE(miss(known, out, n), 1e-9) << "ratio " << big;
    for (int k = 0; k < n; ++k) EXPECT_LE(tangency_residual(in, out[k]), 1e-12);
  }
}

// Offset 1e6 from the origin with radii ~1: the answer cannot be stored
// better than 1e6 * 2.2e-16 = 2.2e-10 absolute, so the relative tolerance is
// 1e-9; at the origin the same case gives 1e-12.
TEST(Kernel, FarFromOrigin)
{
  const Vec3 dir[4] = {{1, 0.2, 0.1}, {-0.6, 0.8, 0.2}, {-0.5, -0.7, 0.4}, {0.1, 0.1, -1}};
  const double radius[4] = {1.0, 1.5, 0.8, 1.2};
  for (double offset : {0.0, 1e6, -1e6}) {
    const Sphere known{{offset + 0.1, offset - 0.3, offset + 0.2}, 0.9};
    Sphere in[4], out[2];
    around(known, dir, radius, in);
    for (int steps : {0, 1}) {
      const int n = tangent_spheres_inversion(in, out, steps);
      expect_clean(in, out, n);
      const double tol = offset == 0 ? 1e-12 : 1e-9;
      EXPECT_LE(miss(known, out, n), tol) << "offset " << offset << " steps " << steps;
    }
  }
}

// SI units of fine powders: radii of 1e-6 m. The local frame is scaled, so
// the relative accuracy is that of a unit scene: 1e-12.
TEST(Kernel, MicroRadii)
{
  const Vec3 dir[4] = {{1, 0.2, 0.1}, {-0.6, 0.8, 0.2}, {-0.5, -0.7, 0.4}, {0.1, 0.1, -1}};
  const double s = 1e-6;
  const double radius[4] = {1.0 * s, 1.5 * s, 0.8 * s, 1.2 * s};
  const Sphere known{{2e-5, -1e-5, 3e-6}, 0.9 * s};
  Sphere in[4], out[2];
  around(known, dir, radius, in);
  for (Solver solve : {Solver(tangent_spheres_inversion), Solver(tangent_spheres_algebraic)}) {
    const int n = solve(in, out, 1);
    expect_clean(in, out, n);
    EXPECT_LE(miss(known, out, n), 1e-12);
  }
}

// Centres nearly coplanar (the known sphere touches four spheres around its
// equator, tilted by delta): the algebraic system becomes singular and the
// two mirror solutions merge into a double root. The inversion still finds
// the sphere: a double root loses half the digits, so the tolerance is 1e-6
// (sqrt of the unit roundoff times a margin).
TEST(Kernel, NearlyCoplanarCentres)
{
  for (double delta : {1e-3, 1e-6, 1e-9, 0.0}) {
    const Vec3 dir[4] = {{1, 0, delta}, {0, 1, -delta}, {-1, 0.1, delta}, {0.1, -1, -delta}};
    const double radius[4] = {1.0, 1.2, 0.9, 1.1};
    const Sphere known{{0, 0, 0}, 0.5};
    Sphere in[4], out[2];
    around(known, dir, radius, in);
    int n = tangent_spheres_inversion(in, out, 1);
    expect_clean(in, out, n);
    EXPECT_LE(miss(known, out, n), 1e-6) << "delta " << delta;
    n = tangent_spheres_algebraic(in, out, 1);
    expect_clean(in, out, n);    // may lose the case, never returns garbage
    if (delta == 0.0) {
      EXPECT_EQ(n, 0);
    }
  }
}

// Inverted centres (nearly) collinear: build the inverted picture directly,
// three inverted spheres on a line through nothing special, then map back.
// On the line exactly there is no isolated solution; near it the answer is
// ill-conditioned. Whatever is returned must be a true solution.
TEST(Kernel, NearlyCollinearInvertedCentres)
{
  for (double eps : {1e-2, 1e-5, 1e-8, 1e-12, 0.0}) {
    const double m = 0.5;
    const Vec3 q[3] = {{1, 0.5, 0.2}, {2, 0.5 + eps, 0.2}, {3, 0.5, 0.2 - eps}};
    const double sigma[3] = {0.1, 0.15, 0.05};
    Sphere in[4];
    in[0] = {{0, 0, 0}, m};
    for (int j = 0; j < 3; ++j) {
      const double power = norm2(q[j]) - sigma[j] * sigma[j];
      in[j + 1] = {(1.0 / power) * q[j], sigma[j] / power + m};
    }
    Sphere out[2];
    int n = tangent_spheres_inversion(in, out, 1);
    expect_clean(in, out, n);
    if (eps == 0.0) {
      EXPECT_EQ(n, 0);
    }
    n = tangent_spheres_algebraic(in, out, 1);
    expect_clean(in, out, n);
  }
}

// Equal spheres with cocircular centres: the inverted centres are exactly
// collinear and the centres coplanar: both methods must say "none".
TEST(Kernel, CocircularEqualSpheresHaveNoIsolatedSolution)
{
  Sphere in[4], out[2];
  for (int i = 0; i < 4; ++i) {
    const double a = 0.4 + 1.3 * i;
    in[i] = {{std::cos(a), std::sin(a), 0}, 0.2};
  }
  EXPECT_EQ(tangent_spheres_inversion(in, out, 1), 0);
  EXPECT_EQ(tangent_spheres_algebraic(in, out, 1), 0);
}

// Overlapping input spheres: the neighbours overlap each other by up to 30%
// of their radius, the known sphere still touches each once.
TEST(Kernel, OverlappingInputSpheres)
{
  const Vec3 dir[4] = {{1, 0.3, 0.1}, {0.6, 0.8, 0.2}, {0.5, -0.7, 0.4}, {0.9, 0.1, -0.5}};
  const double radius[4] = {1.0, 1.2, 0.9, 1.1};
  const Sphere known{{0, 0, 0}, 0.6};
  Sphere in[4], out[2];
  around(known, dir, radius, in);
  ASSERT_LT(norm(in[0].c - in[1].c), in[0].r + in[1].r);    // they do overlap
  const int n = tangent_spheres_inversion(in, out, 1);
  expect_clean(in, out, n);
  EXPECT_LE(miss(known, out, n), 1e-12);
}

// Degenerate and invalid inputs: no solution, never NaN or infinity.
TEST(Kernel, DegenerateInputsGiveNothing)
{
  Sphere out[2];
  const double nan = std::nan(""), inf = INFINITY;
  const Sphere cases[][4] = {
      {{{0, 0, 0}, 1}, {{0, 0, 0}, 1}, {{0, 0, 0}, 1}, {{0, 0, 0}, 1}},        // all equal
      {{{0, 0, 0}, 1}, {{1, 0, 0}, 1}, {{2, 0, 0}, 1}, {{3, 0, 0}, 1}},        // collinear
      {{{0, 0, 0}, 1}, {{1, 0, 0}, 1}, {{0, 1, 0}, 1}, {{0, 0, nan}, 1}},      // NaN
      {{{0, 0, 0}, 1}, {{1, 0, 0}, 1}, {{0, 1, 0}, 1}, {{0, 0, inf}, 1}},      // infinity
      {{{0, 0, 0}, 1}, {{1, 0, 0}, -1}, {{0, 1, 0}, 1}, {{0, 0, 1}, 1}},       // negative radius
      {{{0, 0, 0}, 0.1}, {{0.2, 0, 0}, 5}, {{0, 3, 0}, 1}, {{0, 0, 3}, 1}},    // one inside another
      {{{0, 0, 0}, 1e300}, {{1, 0, 0}, 1e300}, {{0, 1, 0}, 1e300}, {{0, 0, 1}, 1e300}},
  };
  for (const auto &in : cases) {
    for (Solver solve : {Solver(tangent_spheres_inversion), Solver(tangent_spheres_algebraic)}) {
      for (int steps : {0, 2}) {
        const int n = solve(in, out, steps);
        expect_clean(in, out, n);
      }
    }
  }
  EXPECT_EQ(tangent_spheres_inversion(cases[0], out, 0), 0);
  EXPECT_EQ(tangent_spheres_inversion(cases[1], out, 0), 0);
  EXPECT_EQ(tangent_spheres_inversion(cases[2], out, 0), 0);
  EXPECT_EQ(tangent_spheres_inversion(cases[5], out, 0), 0);
}

// Polish: from a perturbed start Newton converges back to the tangent
// sphere (quadratically: two steps reach 1e-13 from 1e-3).
TEST(Kernel, NewtonPolishConverges)
{
  Sphere in[4];
  tetrahedron(2.0, 1.0, in);
  Sphere s{{1e-3, -2e-3, 1e-3}, 2.0 * std::sqrt(6.0) / 4 - 1.0 + 1e-3};
  const double before = tangency_residual(in, s);
  ASSERT_TRUE(polish_tangent_sphere(in, s, 3));
  EXPECT_LT(tangency_residual(in, s), 1e-13);
  EXPECT_GT(before, 1e-3);
  Sphere bad{{0, 0, 0}, -1};
  EXPECT_FALSE(polish_tangent_sphere(in, bad, 2));
}

// Found by fuzz_kernel: coordinates near 1e76 with radii near 1e-57. A
// solution exact in the local frame is not representable globally; the
// kernel must return nothing rather than a sphere that misses the contract.
TEST(Kernel, FuzzRegressionUnrepresentableAnswer)
{
  const double v[16] = {1.2239892642988364e-250,
                        1.3979718782083983e-76,
                        -2.877778643224362e+76,
                        1.398043286095289e-76,
                        3.697842578956727e-57,
                        2.62978563937385e-52,
                        5.229550245763785e+67,
                        5.22520243651314e-310,
                        5.4808986009239014e-222,
                        6.011840146654814e-67,
                        2.1219649296e-314,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0};
  Sphere in[4], out[2];
  for (int s = 0; s < 4; ++s) in[s] = {{v[4 * s], v[4 * s + 1], v[4 * s + 2]}, v[4 * s + 3]};
  for (Solver solve : {Solver(tangent_spheres_inversion), Solver(tangent_spheres_algebraic)})
    for (int steps : {0, 1}) expect_clean(in, out, solve(in, out, steps));
}

// One million random quadruples of every kind (random centres in a cube,
// radii spanning six decades, a quarter of them nearly coplanar and a
// quarter with touching pairs): every solution returned meets the contract.
TEST(Kernel, MillionRandomQuadruplesMeetTheContract)
{
  std::mt19937_64 rng(1234567);
  std::uniform_real_distribution<double> pos(-1, 1), decade(-3, 3);
  long solutions = 0;
  for (int t = 0; t < 1000000; ++t) {
    Sphere in[4];
    for (Sphere &s : in) s = {{pos(rng), pos(rng), pos(rng)}, 0.1 * std::pow(10.0, decade(rng))};
    if (t % 4 == 1)
      for (Sphere &s : in) s.c.z *= 1e-9;
    if (t % 4 == 2)
      in[1].c = in[0].c + ((in[0].r + in[1].r) / norm(in[1].c - in[0].c)) * (in[1].c - in[0].c);
    Sphere out[2];
    const int n = tangent_spheres_inversion(in, out, 1);
    solutions += n;
    for (int k = 0; k < n; ++k) {
      ASSERT_TRUE(is_finite(out[k].c) && std::isfinite(out[k].r) && out[k].r > 0) << "case " << t;
      ASSERT_LE(tangency_residual(in, out[k]), kAcceptResidual) << "case " << t;
    }
  }
  EXPECT_GT(solutions, 100000);    // the test exercises solutions, not only rejections
}

// A sphere of given radius tangent to three: random known spheres with three
// neighbours touching them are recovered (tolerance 1e-9 of r: the contract
// of centres_tangent_to_three, well above the rounding of a few operations
// on scaled coordinates), from micro to large scales and far from the
// origin; the second solution is tangent too.
TEST(Kernel, ThreeTangentRecoversKnownSphere)
{
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unif(1.0, 3.0);
  int tried = 0, missed = 0;
  for (double scale : {1e-9, 1.0, 1e6})
    for (double offset : {0.0, 1e3}) {
      for (int draw = 0; draw < 3000; ++draw) {
        Vec3 dir[3];
        // Not nearly collinear centres: directions well apart.
        if (!spread_directions(rng, dir, 3)) continue;
        ++tried;
        const Sphere known{scale * Vec3{unif(rng) + offset, -unif(rng), unif(rng)},
                           scale * unif(rng)};
        Sphere in[3];
        for (int i = 0; i < 3; ++i) {
          const double ri = scale * unif(rng);
          in[i] = {known.c + (known.r + ri) * dir[i], ri};
        }
        Vec3 out[2];
        const int n = centres_tangent_to_three(in, known.r, out);
        double best = INFINITY;
        for (int k = 0; k < n; ++k) {
          ASSERT_TRUE(is_finite(out[k]));
          for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(norm(out[k] - in[i].c), in[i].r + known.r, 1e-9 * (in[i].r + known.r));
          best = std::min(best, norm(out[k] - known.c) / known.r);
        }
        if (!(best <= 1e-9)) ++missed;
      }
    }
  EXPECT_GT(tried, 5000);
  EXPECT_EQ(missed, 0);
}

// Degenerate and extreme inputs give nothing, never NaN or infinity:
// coincident or collinear centres, spheres too far apart, NaN, infinity,
// negative or zero radii, coordinates whose differences overflow.
TEST(Kernel, ThreeTangentDegenerateInputsGiveNothing)
{
  const double nan = std::nan(""), inf = INFINITY;
  struct Case {
    Sphere in[3];
    double r;
  };
  const Case cases[] = {
      {{{{0, 0, 0}, 1}, {{0, 0, 0}, 1}, {{0, 0, 0}, 1}}, 1},        // coincident
      {{{{0, 0, 0}, 1}, {{1, 0, 0}, 1}, {{2, 0, 0}, 1}}, 1},        // collinear
      {{{{0, 0, 0}, 1}, {{100, 0, 0}, 1}, {{0, 100, 0}, 1}}, 1},    // too far apart
      {{{{0, 0, 0}, 1}, {{2, 0, 0}, 1}, {{0, 2, nan}, 1}}, 1},      // NaN
      {{{{0, 0, 0}, 1}, {{2, 0, 0}, 1}, {{0, 2, inf}, 1}}, 1},      // infinity
      {{{{0, 0, 0}, 1}, {{2, 0, 0}, -1}, {{0, 2, 0}, 1}}, 1},       // negative radius
      {{{{0, 0, 0}, 1}, {{2, 0, 0}, 1}, {{0, 2, 0}, 1}}, 0},        // zero radius asked
      {{{{0, 0, 0}, 1}, {{2, 0, 0}, 1}, {{0, 2, 0}, 1}}, -1},       // negative radius asked
      {{{{0, 0, 0}, 1}, {{2, 0, 0}, 1}, {{0, 2, 0}, 1}}, nan},      // NaN radius asked
      {{{{-1e308, 0, 0}, 1}, {{1e308, 0, 0}, 1}, {{0, 1e308, 0}, 1}}, 1},    // overflow
  };
  for (const Case &c : cases) {
    Vec3 out[2] = {{nan, nan, nan}, {nan, nan, nan}};
    EXPECT_EQ(centres_tangent_to_three(c.in, c.r, out), 0);
  }
  // Touching at one point only: one solution (the two coincide).
  const Sphere touch[3] = {{{0, 0, 0}, 1}, {{4, 0, 0}, 1}, {{2, 2, 0}, 1}};
  Vec3 out[2];
  const int n = centres_tangent_to_three(touch, 1, out);
  ASSERT_EQ(n, 1);
  EXPECT_NEAR(norm(out[0] - Vec3{2, 0, 0}), 0, 1e-12);
}

// The pre-polish filter: accepting everything changes nothing (bit for bit);
// each solution it sees is within kAcceptResidual r of the polished one it
// becomes (the slack callers allow for); what it rejects is not returned,
// and the rest is returned as without it. Random well-posed groups around a
// known sphere, radii over three decades.
TEST(Kernel, PrePolishFilterOnlyDropsWhatItRejects)
{
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> unif(0, 1);
  int checked = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Sphere known{{unif(rng) * 100, unif(rng) * 100, unif(rng) * 100},
                       std::pow(10.0, -1 + 2 * unif(rng))};
    Vec3 dir[4];
    double radius[4];
    for (int i = 0; i < 4; ++i) {
      dir[i] = random_unit(rng);
      radius[i] = known.r * std::pow(10.0, -0.5 + unif(rng));
    }
    Sphere in[4];
    around(known, dir, radius, in);
    Sphere plain[2], all[2], some[2];
    const int n = tangent_spheres_inversion(in, plain, 2);
    std::vector<Sphere> seen;
    const int n_all = tangent_spheres_inversion(in, all, 2, [&](const Sphere &s) {
      seen.push_back(s);
      return true;
    });
    ASSERT_EQ(n_all, n);
    for (int k = 0; k < n; ++k) {
      EXPECT_EQ(all[k].r, plain[k].r);
      EXPECT_EQ(all[k].c.x, plain[k].c.x);
      EXPECT_EQ(all[k].c.y, plain[k].c.y);
      EXPECT_EQ(all[k].c.z, plain[k].c.z);
      double nearest = INFINITY;
      for (const Sphere &s : seen)
        nearest = std::min(nearest, norm(s.c - all[k].c) + std::fabs(s.r - all[k].r));
      EXPECT_LE(nearest, kAcceptResidual * all[k].r);
    }
    // Keep only solutions larger than the known sphere (the other one, if any).
    const int n_some = tangent_spheres_inversion(
        in, some, 2, [&](const Sphere &s) { return s.r > known.r * 1.001; });
    int expected = 0;
    for (int k = 0; k < n; ++k)
      if (plain[k].r > known.r * 1.001) {
        ASSERT_LT(expected, n_some);
        EXPECT_EQ(some[expected].r, plain[k].r);
        ++expected;
      }
    EXPECT_EQ(n_some, expected);
    checked += n;
  }
  EXPECT_GT(checked, 2000);
}
