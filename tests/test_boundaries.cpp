// Walls a relocated sphere must not cross (reinforce_boundaries.h): planes,
// cylinders and triangles, against independent brute force. Each test
// states the tolerance it asserts and why; degenerate and extreme inputs
// are covered, and no NaN or infinity may come out of finite inputs.
#include "reinforce_boundaries.h"
#include "tools/vec3.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <unistd.h>
#include <vector>

using namespace reinforce;

namespace {

constexpr double kTol = 1e-6;    // the fix's default `tol`

// ---------------------------------------------------------------------------
// Independent references, in long double (vector arithmetic shared with
// check_scene only: tools/vec3.h), sharing no code with
// reinforce_boundaries.cpp (none of its formulas either: Gram systems and signed
// volumes where it uses projections and cross products with the normal).

using LD = long double;
using V = tools::Vec<LD>;
V ld(Vec3 a)
{
  return {a.x, a.y, a.z};
}

LD ref_segment(V x, V a, V b)
{
  const V ab = b - a;
  const LD len2 = dot(ab, ab);
  LD t = len2 > 0 ? dot(x - a, ab) / len2 : 0;
  if (t < 0) t = 0;
  if (t > 1) t = 1;
  return norm(x - (a + t * ab));
}

// Exact distance to the triangle: the foot of x from the 2x2 Gram system
// when it lies inside, else the nearest of the three edges.
LD ref_triangle(Vec3 xd, const Triangle &t)
{
  const V x = ld(xd), a = ld(t.a), b = ld(t.b), c = ld(t.c);
  const V e0 = b - a, e1 = c - a, d = x - a;
  const LD g00 = dot(e0, e0), g01 = dot(e0, e1), g11 = dot(e1, e1);
  const LD det = g00 * g11 - g01 * g01;
  LD best = std::min({ref_segment(x, a, b), ref_segment(x, b, c), ref_segment(x, c, a)});
  if (det > 1e-30L * g00 * g11) {
    const LD r0 = dot(d, e0), r1 = dot(d, e1);
    const LD s = (g11 * r0 - g01 * r1) / det, u = (g00 * r1 - g01 * r0) / det;
    if (s >= 0 && u >= 0 && s + u <= 1) best = std::min(best, norm(d - s * e0 - u * e1));
  }
  return best;
}

// Minimum of a convex function on [lo, hi] by golden sections (and the
// ends, where a minimum on the boundary is).
template <class F> LD golden_min(F &&f, LD lo, LD hi)
{
  const LD g = (std::sqrt(5.0L) - 1) / 2;
  LD best = std::min(f(lo), f(hi));
  LD x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  LD f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 90; ++i) {
    if (f1 < f2) {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - g * (hi - lo), f1 = f(x1);
    } else {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + g * (hi - lo), f2 = f(x2);
    }
  }
  return std::min({best, f1, f2});
}

// The distance as the minimum of a convex function over the triangle's
// barycentric coordinates (any triangle, degenerate too): the value of a
// point of the triangle, so never below the true distance, and above it by
// no more than the search's resolution (about 1e-15 of the edges).
LD convex_search_triangle(Vec3 xd, const Triangle &t)
{
  const V x = ld(xd), a = ld(t.a), e0 = ld(t.b) - ld(t.a), e1 = ld(t.c) - ld(t.a);
  auto at = [&](LD u, LD v) { return norm(x - (a + u * e0 + v * e1)); };
  return golden_min([&](LD u) { return golden_min([&](LD v) { return at(u, v); }, 0, 1 - u); }, 0,
                    1);
}

// The minimum over an n x n barycentric grid of the triangle. Every point of
// the triangle is within max_edge / n of a sample.
double sampled_triangle(Vec3 x, const Triangle &t, int n)
{
  const V xl = ld(x), a = ld(t.a), e0 = ld(t.b) - ld(t.a), e1 = ld(t.c) - ld(t.a);
  LD best = INFINITY;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const V p = a + (LD(i) / n) * e0 + (LD(j) / n) * e1;
      const V d = xl - p;
      best = std::min(best, dot(d, d));
    }
  return static_cast<double>(std::sqrt(best));
}

double max_edge(const Triangle &t)
{
  return std::max({norm(t.b - t.a), norm(t.c - t.b), norm(t.a - t.c)});
}

// Whether [p, q] crosses the triangle, from signed volumes (the line meets
// the triangle when the three volumes of pq with its edges agree in sign).
// `borderline` is set when a volume or an end's height is within 1e-9
// (relative) of zero near the triangle: rounding may decide such a case.
// Segments in the plane, and degenerate triangles, never meet (as in
// reinforce_boundaries.h: the distance test holds those).
bool ref_crosses(Vec3 pd, Vec3 qd, const Triangle &t, bool *borderline)
{
  const V p = ld(pd), q = ld(qd), a = ld(t.a), b = ld(t.b), c = ld(t.c);
  const V n = cross(b - a, c - a);
  const LD nn = norm(n);
  if (nn == 0) return false;
  const LD size = std::max({norm(b - a), norm(c - a), norm(c - b)});
  const LD hp = dot(p - a, n) / nn, hq = dot(q - a, n) / nn;
  const LD eps = 1e-9L * size;
  if ((std::fabs(hp) < eps && ref_triangle(pd, t) < 1e-6 * size) ||
      (std::fabs(hq) < eps && ref_triangle(qd, t) < 1e-6 * size))
    *borderline = true;
  if ((hp > 0 && hq > 0) || (hp < 0 && hq < 0)) return false;
  if (hp == hq) return false;
  const V pq = q - p;
  const LD u = dot(pq, cross(c - p, b - p)), v = dot(pq, cross(a - p, c - p)),
           w = dot(pq, cross(b - p, a - p));
  const LD scale = norm(pq) * nn;
  if (std::fabs(u) < 1e-9L * scale || std::fabs(v) < 1e-9L * scale || std::fabs(w) < 1e-9L * scale)
    *borderline = true;
  return (u >= 0 && v >= 0 && w >= 0) || (u <= 0 && v <= 0 && w <= 0);
}

LD ref_plane_height(Vec3 x, const Plane &p)
{
  return dot(ld(x) - ld(p.point), ld(p.normal)) / norm(ld(p.normal));
}

// x about the cylinder's axis: a x (x - point) / |a|, the part of x - point
// across the axis turned a quarter (same length).
V ref_across(Vec3 x, const Cylinder &y)
{
  return (1 / norm(ld(y.axis))) * cross(ld(y.axis), ld(x) - ld(y.point));
}

LD ref_axis_distance(Vec3 x, const Cylinder &y)
{
  return norm(ref_across(x, y));
}

// Closest approach to the axis of the path from -> c.
LD ref_path_axis_distance(Vec3 from, Vec3 c, const Cylinder &y)
{
  return ref_segment({0, 0, 0}, ref_across(from, y), ref_across(c, y));
}

struct Walls {
  std::vector<Plane> planes;
  std::vector<Cylinder> cylinders;
  std::vector<Triangle> triangles;
  std::string name;

  Boundaries build() const
  {
    Boundaries b;
    for (const Plane &p : planes) EXPECT_TRUE(b.add(p));
    for (const Cylinder &c : cylinders) EXPECT_TRUE(b.add(c));
    for (const Triangle &t : triangles) EXPECT_TRUE(b.add(t));
    EXPECT_EQ(b.size(), planes.size() + cylinders.size() + triangles.size());
    return b;
  }
};

enum class Verdict { Admitted, Refused, Unsure };

// The rule of reinforce_boundaries.h, checked wall by wall with the references above.
// Unsure when a quantity that decides it is within 1e-9 of its threshold.
Verdict ref_admits(const Walls &w, Vec3 from, Vec3 c, double r, double tol)
{
  if (!is_finite(from) || !is_finite(c) || !std::isfinite(r) || !(r >= 0)) return Verdict::Refused;
  const LD clear = r * (1 - LD(tol)), eps = 1e-9L;
  bool sure_refused = false, unsure = false, refused = false;
  auto check = [&](bool fails, bool borderline) {
    if (fails && !borderline) sure_refused = true;
    if (borderline) unsure = true;
    if (fails) refused = true;
  };
  for (const Plane &p : w.planes) {
    const LD before = ref_plane_height(from, p), after = ref_plane_height(c, p);
    check((before >= 0) != (after >= 0) || std::fabs(after) < clear,
          std::fabs(before) < eps || std::fabs(after) < eps ||
              std::fabs(std::fabs(after) - clear) < eps);
  }
  for (const Cylinder &y : w.cylinders) {
    const LD before = ref_axis_distance(from, y) - y.radius,
             after = ref_axis_distance(c, y) - y.radius;
    check((before >= 0) != (after >= 0) || std::fabs(after) < clear,
          std::fabs(before) < eps || std::fabs(after) < eps ||
              std::fabs(std::fabs(after) - clear) < eps);
    if (before >= 0 && after >= 0) {
      const LD pass = ref_path_axis_distance(from, c, y) - y.radius;
      check(pass < 0, std::fabs(pass) < eps);
    }
  }
  for (const Triangle &t : w.triangles) {
    const LD d = ref_triangle(c, t);
    check(d < clear, std::fabs(d - clear) < eps);
    bool borderline = false;
    const bool crosses = ref_crosses(from, c, t, &borderline);
    check(crosses, borderline);
  }
  if (sure_refused) return Verdict::Refused;
  if (unsure) return Verdict::Unsure;
  return refused ? Verdict::Refused : Verdict::Admitted;
}

LD ref_distance(const Walls &w, Vec3 x)
{
  LD best = INFINITY;
  for (const Plane &p : w.planes) best = std::min(best, std::fabs(ref_plane_height(x, p)));
  for (const Cylinder &y : w.cylinders)
    best = std::min(best, std::fabs(ref_axis_distance(x, y) - y.radius));
  for (const Triangle &t : w.triangles) best = std::min(best, ref_triangle(x, t));
  return best;
}

// ---------------------------------------------------------------------------
// Random inputs (fixed seeds).

struct Random {
  std::mt19937_64 gen;
  explicit Random(unsigned seed) : gen(seed) {}
  double uniform(double lo, double hi)
  {
    return std::uniform_real_distribution<double>(lo, hi)(gen);
  }
  Vec3 in_box(double h) { return {uniform(-h, h), uniform(-h, h), uniform(-h, h)}; }
  Vec3 direction()
  {
    for (;;) {
      const Vec3 v = in_box(1);
      const double n = norm(v);
      if (n > 0.1 && n <= 1) return (1 / n) * v;
    }
  }
};

// A triangle of one of several shapes: any, a sliver (one short height), a
// needle (one short edge), a very obtuse one.
Triangle random_triangle(Random &rng, int kind)
{
  const Vec3 a = rng.in_box(1), b = rng.in_box(1);
  switch (kind % 4) {
  case 1: {    // sliver: c near the line ab
    const double h = std::pow(10.0, rng.uniform(-13, -3));
    return {a, b, a + rng.uniform(-0.5, 1.5) * (b - a) + h * rng.direction()};
  }
  case 2:    // needle: c near a
    return {a, b, a + std::pow(10.0, rng.uniform(-10, -2)) * rng.direction()};
  case 3:    // obtuse: c near the middle of ab, a little off it
    return {a, b, 0.5 * (a + b) + 0.05 * rng.direction()};
  default:
    return {a, b, rng.in_box(1)};
  }
}

// A point near the triangle: above its interior, beyond an edge or a
// vertex, in its plane, or anywhere.
Vec3 random_point_near(Random &rng, const Triangle &t, int kind)
{
  const double s = max_edge(t);
  double u = rng.uniform(0, 1), v = rng.uniform(0, 1);
  if (u + v > 1) u = 1 - u, v = 1 - v;
  const Vec3 on = t.a + u * (t.b - t.a) + v * (t.c - t.a);
  const Vec3 n = cross(t.b - t.a, t.c - t.a);
  const Vec3 up = norm(n) > 0 ? (1 / norm(n)) * n : rng.direction();
  switch (kind % 5) {
  case 0:
    return on + rng.uniform(-1, 1) * s * up;
  case 1:
    return on;    // in the plane (up to rounding), on the triangle
  case 2:
    return on + std::pow(10.0, rng.uniform(-9, 0)) * s * rng.direction();
  case 3:
    return t.a + rng.uniform(0, 0.5) * s * rng.direction();
  default:
    return rng.in_box(2);
  }
}

// A sphere of `sub` subdivisions of an octahedron (8 * 4^sub triangles)
// about `centre`, its vertices moved off the sphere a little.
std::vector<Triangle> ball_mesh(Vec3 centre, double radius, int sub, Random &rng)
{
  std::vector<Triangle> tris;
  const Vec3 ax[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (int i : {0, 1})
    for (int j : {2, 3})
      for (int k : {4, 5}) tris.push_back({ax[i], ax[j], ax[k]});
  auto mid = [](Vec3 p, Vec3 q) {
    const Vec3 m = 0.5 * (p + q);
    return (1 / norm(m)) * m;
  };
  for (int s = 0; s < sub; ++s) {
    std::vector<Triangle> next;
    for (const Triangle &t : tris) {
      const Vec3 ab = mid(t.a, t.b), bc = mid(t.b, t.c), ca = mid(t.c, t.a);
      next.push_back({t.a, ab, ca});
      next.push_back({ab, t.b, bc});
      next.push_back({ca, bc, t.c});
      next.push_back({ab, bc, ca});
    }
    tris.swap(next);
  }
  for (Triangle &t : tris) {
    for (Vec3 *p : {&t.a, &t.b, &t.c}) *p = centre + (radius * (1 + rng.uniform(-0.03, 0.03))) * *p;
  }
  return tris;
}

// A square of side 2 * half about `centre` (at height z), as two
// triangles sharing the diagonal (-half, -half) - (half, half).
std::vector<Triangle> square(double half, double z, Vec3 centre = {0, 0, 0})
{
  const Vec3 p00 = centre + Vec3{-half, -half, z}, p10 = centre + Vec3{half, -half, z},
             p11 = centre + Vec3{half, half, z}, p01 = centre + Vec3{-half, half, z};
  return {{p00, p10, p11}, {p00, p11, p01}};
}

// The mixed set of walls: two planes, two cylinders (one thin), a mesh of
// 512 small triangles (a bumpy ball), a few degenerate triangles, and a floor
// of two very large triangles (which the index keeps apart).
Walls mixed_walls(Random &rng)
{
  Walls w;
  w.name = "mixed";
  w.planes.push_back({{0, 0, -0.9}, {0, 0, 1}});
  w.planes.push_back({{0.6, 0.1, 0}, {1, 2, -0.5}});
  w.cylinders.push_back({{0.4, 0.5, 0}, {0.3, -0.2, 1}, 0.2});
  w.cylinders.push_back({{0, -0.6, 0.3}, {1, 0, 0.1}, 0.02});
  w.triangles = ball_mesh({-0.4, 0.3, 0.2}, 0.35, 3, rng);
  // Degenerate: a segment (two equal vertices), a collinear triple, a point.
  w.triangles.push_back({{0.1, -0.2, 0.5}, {0.1, -0.2, 0.5}, {0.3, -0.1, 0.55}});
  w.triangles.push_back({{-0.5, -0.25, -0.3}, {-0.25, -0.25, -0.3}, {0, -0.25, -0.3}});
  w.triangles.push_back({{0.2, 0.2, -0.2}, {0.2, 0.2, -0.2}, {0.2, 0.2, -0.2}});
  for (const Triangle &t : square(60, -0.5)) w.triangles.push_back(t);
  return w;
}

// Random spheres and moves for a set of walls about the unit box, with
// many near the walls: near the mesh, near the far corners of a large
// floor, near the thin cylinder, and long moves through the mesh.
struct Move {
  Vec3 from, c;
  double r, tol;
};

std::vector<Move> random_moves(Random &rng, int count)
{
  std::vector<Move> moves;
  const double tols[] = {kTol, kTol, 1e-10, 0.1};
  for (int i = 0; i < count; ++i) {
    Move m;
    m.r = std::pow(10.0, rng.uniform(-2.5, -0.7));
    m.tol = tols[i % 4];
    switch (i % 6) {
    case 0:
    case 1:
      m.c = rng.in_box(1.2);
      break;
    case 2:    // about the ball mesh's surface
      m.c = Vec3{-0.4, 0.3, 0.2} + (0.35 + rng.uniform(-1.5, 1.5) * m.r) * rng.direction();
      break;
    case 3:    // near the large floor, anywhere on it (far corners too)
      m.c = {rng.uniform(-62, 62), rng.uniform(-62, 62), -0.5 + rng.uniform(-2, 2) * m.r};
      break;
    case 4:    // near the thin cylinder
      m.c = Vec3{rng.uniform(-1, 1), -0.6, 0.3} + rng.uniform(0, 0.1) * rng.direction();
      break;
    default: {    // a long move across the ball mesh, through it or past it
      const Vec3 centre{-0.4, 0.3, 0.2}, d = rng.direction();
      m.c = centre + 0.6 * d + rng.in_box(0.4);
      m.from = centre - rng.uniform(0.2, 0.7) * d + rng.in_box(0.4);
      moves.push_back(m);
      continue;
    }
    }
    m.from = m.c + rng.uniform(0, 2 * m.r + 0.05) * rng.direction();
    moves.push_back(m);
  }
  return moves;
}

std::string describe(Vec3 x)
{
  char buf[100];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g, %.17g)", x.x, x.y, x.z);
  return buf;
}

std::string describe(Vec3 x, const Triangle &t)
{
  return "point " + describe(x) + " triangle " + describe(t.a) + " " + describe(t.b) + " " +
         describe(t.c);
}

std::string describe(const Move &m)
{
  char buf[300];
  std::snprintf(buf, sizeof buf,
                "from (%.17g, %.17g, %.17g) to (%.17g, %.17g, %.17g) r %.17g tol %g", m.from.x,
                m.from.y, m.from.z, m.c.x, m.c.y, m.c.z, m.r, m.tol);
  return buf;
}

// The sets of walls the brute-force comparisons run on.
std::vector<Walls> wall_sets()
{
  Random rng(20240611);
  std::vector<Walls> sets;
  sets.push_back(mixed_walls(rng));
  {    // the mesh and its large floor only (no plane or cylinder hides a miss)
    Walls w = mixed_walls(rng);
    w.name = "mesh and floor";
    w.planes.clear();
    w.cylinders.clear();
    sets.push_back(w);
  }
  {    // the large floor alone (no small triangle: the index has no typical size)
    Walls w;
    w.name = "floor alone";
    w.triangles = square(60, -0.5);
    sets.push_back(w);
  }
  {    // more than one in ten large: all of them in the index's grid
    Walls w;
    w.name = "many large";
    w.triangles = ball_mesh({0.3, -0.2, 0.1}, 0.3, 2, rng);
    for (int i = 0; i < 40; ++i) {
      const Vec3 a = rng.in_box(1.2);
      w.triangles.push_back({a, a + 0.8 * rng.direction(), a + 0.8 * rng.direction()});
    }
    sets.push_back(w);
  }
  {    // a mesh with large triangles 3 and 5 times its typical size
    Walls w;
    w.name = "medium large";
    w.triangles = ball_mesh({0.3, -0.2, 0.1}, 0.3, 3, rng);
    const double typical = 0.03;    // the bounding radius of its triangles
    for (double f : {2.0, 3.5, 4.0, 4.5, 6.0})
      for (const Triangle &t : square(f * typical, rng.uniform(-0.8, 0.8), rng.in_box(0.5)))
        w.triangles.push_back(t);
    sets.push_back(w);
  }
  return sets;
}

}    // namespace

// ===========================================================================
// distance_to_triangle

// Against a 200 x 200 barycentric sampling of the triangle: the exact
// distance is never above the sampled minimum (every sample is a point of
// the triangle) by more than rounding, and below it by at most the sampling
// error max_edge / 200. Against a convex search over the triangle (a
// second, tight brute force): equal within 1e-12 of the scene (rounding of
// coordinates of size ~2: a few 1e-16; the search: ~1e-15). Any triangle,
// thin needles and very obtuse ones; slivers are the next test.
TEST(BoundariesTriangleDistance, MatchesSamplingAndConvexSearch)
{
  Random rng(7);
  const int n = 200;
  int count = 0;
  for (int k = 0; k < 64; ++k) {
    const int kind = k % 4;    // slivers (kind 1): sampling only
    const Triangle t = random_triangle(rng, kind);
    const double bound = max_edge(t) / n;
    for (int i = 0; i < 25; ++i) {
      const Vec3 x = random_point_near(rng, t, i);
      const double d = distance_to_triangle(x, t);
      ASSERT_TRUE(std::isfinite(d)) << describe(x, t);
      ASSERT_GE(d, 0);
      const double sampled = sampled_triangle(x, t, n);
      const double rounding = 1e-13 * (1 + norm(x) + max_edge(t));
      EXPECT_LE(d, sampled + rounding) << describe(x, t);
      EXPECT_GE(d, sampled - bound - rounding) << describe(x, t);
      ++count;
      if (kind == 1) continue;
      const double searched = static_cast<double>(convex_search_triangle(x, t));
      EXPECT_NEAR(d, searched, 1e-12) << describe(x, t);
      // The reference of the brute-force tests below (it is not used on
      // slivers, where its Gram system is ill-conditioned).
      EXPECT_NEAR(searched, static_cast<double>(ref_triangle(x, t)), 1e-12) << describe(x, t);
    }
  }
  EXPECT_EQ(count, 64 * 25);
}

// Slivers: three vertices spread over ~1 but nearly collinear (height
// 1e-13 .. 1e-3 above the line). Against the convex search, on both sides
// (above the truth would admit an overlap, below it refuses a sphere that
// only touches), within the header's bound: 1e-12 of the scene plus the
// long-double rounding of a sliver's normal, 2e-18 L |x - a| / h (L the
// longest edge, h the height). One failure each, with the worst input.
TEST(BoundariesTriangleDistance, SliversWithinTheStatedTolerance)
{
  Random rng(8);
  double over = 0, under = 0;
  std::string worst_over, worst_under;
  for (int k = 0; k < 200; ++k) {
    const Triangle t = random_triangle(rng, 1);
    for (int i = 0; i < 10; ++i) {
      const Vec3 x = random_point_near(rng, t, i);
      const double d = distance_to_triangle(x, t);
      ASSERT_TRUE(std::isfinite(d)) << describe(x, t);
      const double searched = static_cast<double>(convex_search_triangle(x, t));
      const double edge = max_edge(t);
      const double height = norm(cross(t.b - t.a, t.c - t.a)) / edge;
      const double bound = 1e-12 + 2e-18 * edge * norm(x - t.a) / height;
      char buf[160];
      std::snprintf(buf, sizeof buf, ": distance %.17g, convex search %.17g, bound %.3g", d,
                    searched, bound);
      // Measured against each case's bound: over and under are multiples of it.
      if ((d - searched) / bound > over)
        over = (d - searched) / bound, worst_over = describe(x, t) + buf;
      if ((searched - d) / bound > under)
        under = (searched - d) / bound, worst_under = describe(x, t) + buf;
    }
  }
  EXPECT_LE(over, 1) << "above the truth by " << over << " bounds: " << worst_over;
  EXPECT_LE(under, 1) << "below the truth by " << under << " bounds: " << worst_under;
}

TEST(BoundariesTriangleDistance, KnownValues)
{
  const Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const double e = 1e-15;    // a few roundings of values of size ~1
  EXPECT_NEAR(distance_to_triangle({0.25, 0.25, 2}, t), 2, e);                 // above the interior
  EXPECT_NEAR(distance_to_triangle({0.25, 0.25, -3}, t), 3, e);                // below it
  EXPECT_NEAR(distance_to_triangle({0.2, 0.3, 0}, t), 0, e);                   // on it
  EXPECT_NEAR(distance_to_triangle({0.5, -1, 0.5}, t), std::sqrt(1.25), e);    // beyond ab
  EXPECT_NEAR(distance_to_triangle({-2, 0.5, 0}, t), 2, e);              // beyond ca, in the plane
  EXPECT_NEAR(distance_to_triangle({1, 1, 0}, t), std::sqrt(0.5), e);    // beyond bc
  EXPECT_NEAR(distance_to_triangle({1, 1, 1}, t), std::sqrt(1.5), e);
  EXPECT_NEAR(distance_to_triangle({-1, -1, 1}, t), std::sqrt(3.0), e);    // beyond vertex a
  EXPECT_NEAR(distance_to_triangle({3, -1, 0}, t), std::sqrt(5.0), e);     // beyond vertex b
  EXPECT_NEAR(distance_to_triangle({0, 2, -1}, t), std::sqrt(2.0), e);     // beyond vertex c
  EXPECT_EQ(distance_to_triangle({1, 0, 0}, t), 0);                        // on a vertex
  EXPECT_EQ(distance_to_triangle({0, 0, 0}, t), 0);
  // The same, whatever the order (and so the orientation) of the vertices.
  const Triangle u{t.c, t.b, t.a};
  EXPECT_NEAR(distance_to_triangle({0.25, 0.25, 2}, u), 2, e);
  EXPECT_NEAR(distance_to_triangle({-1, -1, 1}, u), std::sqrt(3.0), e);
}

// A degenerate triangle is the segment or point it spans: its distance is
// the distance to that segment or point (exact to rounding, 1e-15).
TEST(BoundariesTriangleDistance, DegenerateTriangles)
{
  const double e = 1e-15;
  // Two equal vertices: the segment [0, (2, 0, 0)].
  for (const Triangle &t :
       {Triangle{{0, 0, 0}, {0, 0, 0}, {2, 0, 0}}, Triangle{{0, 0, 0}, {2, 0, 0}, {0, 0, 0}},
        Triangle{{2, 0, 0}, {0, 0, 0}, {0, 0, 0}}}) {
    EXPECT_NEAR(distance_to_triangle({1, 1, 0}, t), 1, e);
    EXPECT_NEAR(distance_to_triangle({1, 0, -0.5}, t), 0.5, e);
    EXPECT_NEAR(distance_to_triangle({3, 0, 0}, t), 1, e);
    EXPECT_NEAR(distance_to_triangle({-1, 1, 0}, t), std::sqrt(2.0), e);
    EXPECT_EQ(distance_to_triangle({0.5, 0, 0}, t), 0);
  }
  // Three collinear vertices, the middle one last: the segment [0, 3].
  for (const Triangle &t :
       {Triangle{{0, 0, 0}, {3, 0, 0}, {1, 0, 0}}, Triangle{{1, 0, 0}, {0, 0, 0}, {3, 0, 0}}}) {
    EXPECT_NEAR(distance_to_triangle({2, 1, 0}, t), 1, e);
    EXPECT_NEAR(distance_to_triangle({2.5, 0, 2}, t), 2, e);
    EXPECT_NEAR(distance_to_triangle({4, 0, 0}, t), 1, e);
    EXPECT_NEAR(distance_to_triangle({-1, 0, 1}, t), std::sqrt(2.0), e);
  }
  // Collinear along a slanted line, not exactly representable: within
  // rounding of the segment from (0.1, 0.2, 0.3) to (0.7, 0.8, 0.9).
  {
    const Vec3 a{0.1, 0.2, 0.3}, d{0.2, 0.2, 0.2};
    const Triangle t{a, a + 3.0 * d, a + 1.0 * d};
    const Vec3 x{0.5, 0.2, 0.9};
    EXPECT_NEAR(distance_to_triangle(x, t),
                static_cast<double>(ref_segment(ld(x), ld(a), ld(a + 3.0 * d))), 1e-14);
  }
  // All three equal: a point.
  const Triangle p{{1, 2, 3}, {1, 2, 3}, {1, 2, 3}};
  EXPECT_NEAR(distance_to_triangle({1, 2, 5}, p), 2, e);
  EXPECT_NEAR(distance_to_triangle({4, 6, 3}, p), 5, e);
  EXPECT_EQ(distance_to_triangle({1, 2, 3}, p), 0);
  // Slivers about the threshold where the triangle is taken as its edges
  // (height 1e-12 of the edge): within their height (and rounding) of the
  // exact distance, whichever way they are taken.
  for (double h : {1e-6, 1e-10, 1e-11, 1e-12, 1e-13, 1e-15, 1e-300}) {
    const Triangle s{{0, 0, 0}, {1, 0, 0}, {0.5, h, 0}};
    for (const Vec3 &x : {Vec3{0.5, 0, 1}, Vec3{0.5, h / 2, 0}, Vec3{0.3, -1, 0}, Vec3{2, 0, 0},
                          Vec3{0.25, 0.25 * h, 1e-14}}) {
      const double d = distance_to_triangle(x, s);
      ASSERT_TRUE(std::isfinite(d)) << h;
      EXPECT_NEAR(d, static_cast<double>(convex_search_triangle(x, s)), h + 1e-15) << h;
    }
  }
}

// Scaled by s, the distance scales by s: relative 1e-12 (rounding, a few
// 1e-16 relative, with room for the convex search of the unit case), and it
// stays finite. Beyond 1e8 and 1e-8 (the brief) the scales the products of
// three coordinates allow (their squares reach 1e+-300 near 1e+-75).
TEST(BoundariesTriangleDistance, ScaledInputsScaleTheDistance)
{
  Random rng(11);
  for (int k = 0; k < 20; ++k) {
    const Triangle t = random_triangle(rng, k % 4 == 1 ? 0 : k);    // slivers: above
    for (int i = 0; i < 10; ++i) {
      const Vec3 x = random_point_near(rng, t, i);
      const double d1 = distance_to_triangle(x, t);
      for (double s : {1e8, 1e-8, 1e30, 1e-30, 1e60, 1e-60}) {
        const Triangle ts{s * t.a, s * t.b, s * t.c};
        const double ds = distance_to_triangle(s * x, ts);
        ASSERT_TRUE(std::isfinite(ds)) << s;
        // The degenerate test is relative: a sliver is taken the same way at
        // every scale, up to the rounding of its height.
        EXPECT_NEAR(ds / s, d1, 1e-12 * (1 + norm(x)))
            << "scale " << s << " " << describe(x, t) << " search "
            << static_cast<double>(convex_search_triangle(x, t));
      }
    }
  }
  // A unit triangle far from the origin (coordinates 1e8, exact in
  // binary): the differences of coordinates are exact, the distance is as
  // at the origin up to 1e-15 of 1e8 (the header's relative bound).
  const double o = 1e8;
  const Triangle t{{o, o, o}, {o + 1, o, o}, {o, o + 1, o}};
  EXPECT_NEAR(distance_to_triangle({o + 0.25, o + 0.25, o + 2}, t), 2, 1e-7);
  EXPECT_NEAR(distance_to_triangle({o - 1, o - 1, o + 1}, t), std::sqrt(3.0), 1e-7);
  EXPECT_NEAR(distance_to_triangle({o + 1, o + 1, o}, t), std::sqrt(0.5), 1e-7);
  // Tiny triangle, large distance and the reverse.
  const Triangle tiny{{0, 0, 0}, {1e-8, 0, 0}, {0, 1e-8, 0}};
  EXPECT_NEAR(distance_to_triangle({0, 0, 1e8}, tiny), 1e8, 1e-7);
  EXPECT_NEAR(distance_to_triangle({2.5e-9, 2.5e-9, 1e-8}, tiny), 1e-8, 1e-23);
  const Triangle huge{{-1e8, -1e8, 0}, {1e8, -1e8, 0}, {0, 1e8, 0}};
  EXPECT_NEAR(distance_to_triangle({0, 0, 1e-8}, huge), 1e-8, 1e-14);
}

// Finite coordinates give a finite distance, even where squares of the
// coordinates overflow or underflow (accuracy is asserted up to 1e+-60,
// above).
TEST(BoundariesTriangleDistance, FiniteAtTheEndsOfTheRange)
{
  for (double s : {1e100, 1e150, 1e200, 1e300, 1e-100, 1e-150, 1e-200, 1e-300}) {
    const Triangle t{{0, 0, 0}, {s, 0, 0}, {0, s, 0}};
    const Vec3 x{0.1 * s, 0.1 * s, 0.1 * s};
    const double d = distance_to_triangle(x, t);
    EXPECT_TRUE(std::isfinite(d)) << "edge " << s << ": " << d;
    EXPECT_GE(d, 0) << "edge " << s;
  }
}

// A point that is NaN has no distance: the answer must not pass for one
// (no comparison with a radius may accept it). Infinite: infinitely far.
TEST(BoundariesTriangleDistance, NonFinitePoint)
{
  const Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  for (const Vec3 &x : {Vec3{NAN, 0, 0}, Vec3{0, NAN, 0}, Vec3{0, 0, NAN}}) {
    const double d = distance_to_triangle(x, t);
    EXPECT_FALSE(d >= 0) << d;
  }
  for (const Vec3 &x : {Vec3{INFINITY, 0, 0}, Vec3{0, -INFINITY, 0}, Vec3{0.2, 0.2, INFINITY}}) {
    const double d = distance_to_triangle(x, t);
    EXPECT_FALSE(std::isfinite(d) && d < 1e300) << d;
  }
}

// ===========================================================================
// segment_meets_triangle

TEST(BoundariesSegmentMeetsTriangle, CrossingsAndMisses)
{
  const Triangle t{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  // Through the interior, either way, upright or slanted.
  EXPECT_TRUE(segment_meets_triangle({0.2, 0.2, -1}, {0.2, 0.2, 1}, t));
  EXPECT_TRUE(segment_meets_triangle({0.2, 0.2, 1}, {0.2, 0.2, -1}, t));
  EXPECT_TRUE(segment_meets_triangle({-0.5, 0.1, -1}, {0.9, 0.3, 1}, t));
  // Misses: beyond an edge or a vertex, on one side, parallel above it.
  EXPECT_FALSE(segment_meets_triangle({0.6, 0.6, -1}, {0.6, 0.6, 1}, t));
  EXPECT_FALSE(segment_meets_triangle({-0.1, 0.5, -1}, {-0.1, 0.5, 1}, t));
  EXPECT_FALSE(segment_meets_triangle({1.1, -0.1, -1}, {1.1, -0.1, 1}, t));
  EXPECT_FALSE(segment_meets_triangle({0.2, 0.2, 0.1}, {0.2, 0.2, 1}, t));
  EXPECT_FALSE(segment_meets_triangle({0.2, 0.2, -0.1}, {0.3, 0.1, -1e-9}, t));
  EXPECT_FALSE(segment_meets_triangle({-1, 0.2, 0.5}, {2, 0.2, 0.5}, t));
  // It reaches the plane's crossing only beyond its end.
  EXPECT_FALSE(segment_meets_triangle({0.2, 0.2, 2}, {0.2, 0.2, 1}, t));
  // Ending (or starting) on the triangle: its closed surface is met.
  EXPECT_TRUE(segment_meets_triangle({0.2, 0.2, 1}, {0.2, 0.2, 0}, t));
  EXPECT_TRUE(segment_meets_triangle({0.2, 0.2, 0}, {0.5, 0.5, -1}, t));
  EXPECT_TRUE(segment_meets_triangle({0.3, 0.3, -1}, {0.5, 0.5, 0}, t));    // on edge bc
  EXPECT_TRUE(segment_meets_triangle({0.5, 0, 1}, {0.5, 0, 0}, t));         // on edge ab
  EXPECT_TRUE(segment_meets_triangle({1, 0, 1}, {1, 0, 0}, t));             // on vertex b
  EXPECT_TRUE(segment_meets_triangle({0, 0, 1}, {0, 0, -1}, t));            // through a
  EXPECT_FALSE(segment_meets_triangle({0.2, 0.2, 1}, {0.6, 0.6, 0}, t));    // ends beyond bc
  // In the triangle's plane: false by design (a sphere sliding in the plane
  // of a wall is held by the distance test), even across the triangle.
  EXPECT_FALSE(segment_meets_triangle({-1, 0.2, 0}, {2, 0.2, 0}, t));
  EXPECT_FALSE(segment_meets_triangle({0.1, 0.1, 0}, {0.2, 0.3, 0}, t));
  // A point segment on the triangle: in the plane, false.
  EXPECT_FALSE(segment_meets_triangle({0.1, 0.1, 0}, {0.1, 0.1, 0}, t));
  // Degenerate triangles have no side to cross.
  EXPECT_FALSE(
      segment_meets_triangle({0.5, 0, -1}, {0.5, 0, 1}, {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}}));
  EXPECT_FALSE(segment_meets_triangle({0, 0, -1}, {0, 0, 1}, {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}));
  // Non-finite ends never meet.
  EXPECT_FALSE(segment_meets_triangle({NAN, 0.2, -1}, {0.2, 0.2, 1}, t));
  EXPECT_FALSE(segment_meets_triangle({0.2, 0.2, -1}, {0.2, NAN, 1}, t));
  EXPECT_FALSE(segment_meets_triangle({0.2, 0.2, -INFINITY}, {0.2, 0.2, INFINITY}, t));
}

// Random segments and triangles against signed volumes in long double
// (cases that rounding could decide, within 1e-9 relative, are skipped:
// they must stay few); the answer does not depend on the order of the
// segment's ends or of the vertices, nor on a scale of 1e+-8.
TEST(BoundariesSegmentMeetsTriangle, MatchesSignedVolumes)
{
  Random rng(13);
  int met = 0, missed = 0, skipped = 0;
  for (int k = 0; k < 4000; ++k) {
    const Triangle t = random_triangle(rng, k % 8 == 7 ? 1 : 0);
    Vec3 p = rng.in_box(1.5), q = rng.in_box(1.5);
    if (k % 3 == 0) {    // through a point of the triangle's plane near it
      const Vec3 on = random_point_near(rng, t, 1) + 0.2 * rng.in_box(1);
      const Vec3 d = rng.direction();
      p = on - rng.uniform(0.01, 1) * d, q = on + rng.uniform(0.01, 1) * d;
    }
    bool borderline = false;
    const bool expected = ref_crosses(p, q, t, &borderline);
    if (borderline) {
      ++skipped;
      continue;
    }
    (expected ? met : missed)++;
    EXPECT_EQ(segment_meets_triangle(p, q, t), expected) << k;
    EXPECT_EQ(segment_meets_triangle(q, p, t), expected) << k;
    EXPECT_EQ(segment_meets_triangle(p, q, {t.b, t.a, t.c}), expected) << k;
    EXPECT_EQ(segment_meets_triangle(p, q, {t.c, t.a, t.b}), expected) << k;
    for (double s : {1e8, 1e-8, 1e40, 1e-40})
      EXPECT_EQ(segment_meets_triangle(s * p, s * q, {s * t.a, s * t.b, s * t.c}), expected)
          << k << " scale " << s;
  }
  EXPECT_GT(met, 500);
  EXPECT_GT(missed, 500);
  EXPECT_LT(skipped, 40);
}

// A segment through the diagonal two triangles of a square share meets at
// least one of them (no gap in a mesh for rounding to slip through): many
// points of the diagonal, squares of any orientation, size and place.
TEST(BoundariesSegmentMeetsTriangle, SharedEdgeIsWatertight)
{
  Random rng(17);
  int both = 0;
  for (int k = 0; k < 20000; ++k) {
    const double size = std::pow(10.0, rng.uniform(-8, 8));
    const Vec3 u = rng.direction();
    Vec3 v = cross(u, rng.direction());
    v = (1 / norm(v)) * v;
    const Vec3 o = k % 2 ? rng.in_box(10 * size) : rng.in_box(1e3);
    const Vec3 a = o, b = o + size * u, c = o + size * (u + v), d = o + size * v;
    const Triangle t1{a, b, c}, t2{a, c, d};    // sharing the diagonal a - c
    const double s = rng.uniform(0, 1);
    const Vec3 on = a + s * (c - a);
    Vec3 dir = rng.direction();
    if (k % 5 == 0) dir = cross(u, v);    // square on
    const double len = size * rng.uniform(1e-6, 2);
    const Vec3 p = on - len * dir, q = on + (len * rng.uniform(0.1, 2)) * dir;
    // The segment must cross the plane (not lie in it).
    if (std::fabs(dot(dir, cross(u, v))) < 1e-3) continue;
    const bool m1 = segment_meets_triangle(p, q, t1), m2 = segment_meets_triangle(p, q, t2);
    EXPECT_TRUE(m1 || m2) << k << " s " << s << " size " << size;
    both += m1 && m2;
  }
  EXPECT_GT(both, 0);    // the closed triangles both hold points of the edge
  // The exact diagonal of a unit square in the plane z = 0.
  const Triangle t1{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, t2{{0, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (int i = 0; i <= 1000; ++i) {
    const double s = i / 1000.0;
    const Vec3 p{s + 0.3, s - 0.2, 1}, q{s - 0.3, s + 0.2, -1};    // through (s, s, 0)
    EXPECT_TRUE(segment_meets_triangle(p, q, t1) || segment_meets_triangle(p, q, t2)) << s;
  }
}

// ===========================================================================
// Boundaries::add

TEST(BoundariesAdd, RefusesDegenerateOrNonFiniteWalls)
{
  Boundaries b;
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(b.size(), 0u);
  // Planes: a zero or non-finite normal, a non-finite point.
  EXPECT_FALSE(b.add(Plane{{0, 0, 0}, {0, 0, 0}}));
  EXPECT_FALSE(b.add(Plane{{0, 0, 0}, {NAN, 0, 1}}));
  EXPECT_FALSE(b.add(Plane{{0, 0, 0}, {0, INFINITY, 1}}));
  EXPECT_FALSE(b.add(Plane{{NAN, 0, 0}, {0, 0, 1}}));
  EXPECT_FALSE(b.add(Plane{{0, 0, -INFINITY}, {0, 0, 1}}));
  // Cylinders: zero axis, zero, negative, NaN or infinite radius.
  EXPECT_FALSE(b.add(Cylinder{{0, 0, 0}, {0, 0, 0}, 1}));
  EXPECT_FALSE(b.add(Cylinder{{0, 0, 0}, {0, 0, 1}, 0}));
  EXPECT_FALSE(b.add(Cylinder{{0, 0, 0}, {0, 0, 1}, -1}));
  EXPECT_FALSE(b.add(Cylinder{{0, 0, 0}, {0, 0, 1}, NAN}));
  EXPECT_FALSE(b.add(Cylinder{{0, 0, 0}, {0, 0, 1}, INFINITY}));
  EXPECT_FALSE(b.add(Cylinder{{0, 0, 0}, {NAN, 0, 1}, 1}));
  EXPECT_FALSE(b.add(Cylinder{{INFINITY, 0, 0}, {0, 0, 1}, 1}));
  // Triangles: any non-finite coordinate.
  EXPECT_FALSE(b.add(Triangle{{NAN, 0, 0}, {1, 0, 0}, {0, 1, 0}}));
  EXPECT_FALSE(b.add(Triangle{{0, 0, 0}, {1, INFINITY, 0}, {0, 1, 0}}));
  EXPECT_FALSE(b.add(Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, -INFINITY}}));
  EXPECT_TRUE(b.empty());
  EXPECT_EQ(b.size(), 0u);
  EXPECT_EQ(b.distance({0, 0, 0}), INFINITY);    // nothing was kept
  EXPECT_TRUE(b.admits({0, 0, 0}, {0, 0, 0}, 1, kTol));
  // Degenerate triangles are kept (a segment, a point).
  EXPECT_TRUE(b.add(Triangle{{0, 0, 0}, {0, 0, 0}, {1, 0, 0}}));
  EXPECT_TRUE(b.add(Triangle{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}));
  EXPECT_TRUE(b.add(Triangle{{5, 5, 5}, {5, 5, 5}, {5, 5, 5}}));
  EXPECT_EQ(b.size(), 3u);
  EXPECT_FALSE(b.empty());
  EXPECT_NEAR(b.distance({0.5, 1, 0}), 1, 1e-15);
  EXPECT_NEAR(b.distance({5, 5, 7}), 2, 1e-15);
  // Valid walls of any normal or axis length, and tiny or huge radii.
  EXPECT_TRUE(b.add(Plane{{0, 0, -10}, {0, 0, 1e-3}}));
  EXPECT_TRUE(b.add(Cylinder{{0, 0, 0}, {1e3, 0, 0}, 1e-9}));
  EXPECT_TRUE(b.add(Cylinder{{0, 0, 0}, {0, 1, 0}, 1e9}));
  EXPECT_EQ(b.size(), 6u);
}

// A plane or cylinder is either refused or kept as given: its normal or
// axis is "any length > 0" (reinforce_boundaries.h), so a very long or very short
// one, if accepted, must give the same distances as a unit one (to 1e-12).
TEST(BoundariesAdd, NormalAndAxisLengthDoNotMatter)
{
  for (double len :
       {1.0, 1e-100, 1e-150, 1e-160, 1e-200, 1e-300, 1e100, 1e150, 1e160, 1e200, 1e300}) {
    Boundaries p;
    if (p.add(Plane{{0, 0, 0}, {0, 0, len}})) {
      EXPECT_NEAR(p.distance({0, 0, 2}), 2, 1e-12) << "normal length " << len;
      EXPECT_TRUE(p.admits({0, 0, 3}, {0, 0, 2}, 1, kTol)) << "normal length " << len;
      EXPECT_FALSE(p.admits({0, 0, 3}, {0, 0, 0.5}, 1, kTol)) << "normal length " << len;
    }
    Boundaries c;
    if (c.add(Cylinder{{0, 0, 0}, {0, 0, len}, 1})) {
      EXPECT_NEAR(c.distance({3, 0, 5}), 2, 1e-12) << "axis length " << len;
      EXPECT_TRUE(c.admits({3, 0, 6}, {3, 0, 5}, 1, kTol)) << "axis length " << len;
    }
  }
}

// ===========================================================================
// Boundaries::admits, by hand: plane, cylinder, two-triangle floor. The
// "exactly touching" cases are exact in binary (axis-aligned walls).

TEST(BoundariesAdmits, Plane)
{
  Boundaries b;
  ASSERT_TRUE(b.add(Plane{{0, 0, 0}, {0, 0, 1}}));
  const double r = 1;
  EXPECT_TRUE(b.admits({0, 0, 3}, {0.5, 0, 1.5}, r, kTol));      // clear, its side
  EXPECT_TRUE(b.admits({0, 0, -3}, {0.5, 0, -1.5}, r, kTol));    // clear, the other side
  EXPECT_TRUE(b.admits({0, 0, 3}, {0, 0, 1}, r, kTol));          // touching
  EXPECT_TRUE(b.admits({0, 0, -3}, {0, 0, -1}, r, kTol));
  EXPECT_TRUE(b.admits({0, 0, 3}, {0, 0, 1 - 0.5 * kTol}, r, kTol));    // within tol * r
  EXPECT_FALSE(b.admits({0, 0, 3}, {0, 0, 1 - 2 * kTol}, r, kTol));     // beyond it
  EXPECT_FALSE(b.admits({0, 0, 3}, {0, 0, 0.9}, r, kTol));
  EXPECT_FALSE(b.admits({0, 0, 3}, {0, 0, 0}, r, kTol));
  EXPECT_FALSE(b.admits({0, 0, 3}, {0, 0, -1.5}, r, kTol));    // crossed, clear
  EXPECT_FALSE(b.admits({0, 0, -3}, {0, 0, 1.5}, r, kTol));
  EXPECT_FALSE(b.admits({0, 0, 3}, {0, 0, -1}, r, kTol));    // crossed, touching
  // The tolerance scales with r.
  EXPECT_TRUE(b.admits({0, 0, 3}, {0, 0, 1e-3 * (1 - 0.5 * kTol)}, 1e-3, kTol));
  EXPECT_FALSE(b.admits({0, 0, 3}, {0, 0, 1e-3 * (1 - 2 * kTol)}, 1e-3, kTol));
  // A point (r = 0) is admitted anywhere on its side, even on the plane.
  EXPECT_TRUE(b.admits({0, 0, 3}, {0, 0, 1e-300}, 0, kTol));
  EXPECT_TRUE(b.admits({0, 0, 3}, {0, 0, 0}, 0, kTol));
  EXPECT_FALSE(b.admits({0, 0, 3}, {0, 0, -1e-300}, 0, kTol));
  // Slanted normal, not of unit length: distances along the unit normal.
  Boundaries s;
  ASSERT_TRUE(s.add(Plane{{1, 1, 1}, {3, 0, 4}}));
  EXPECT_TRUE(s.admits({1, 1, 10}, Vec3{1, 1, 1} + 1.01 * Vec3{0.6, 0, 0.8}, 1, kTol));
  EXPECT_FALSE(s.admits({1, 1, 10}, Vec3{1, 1, 1} + 0.99 * Vec3{0.6, 0, 0.8}, 1, kTol));
  EXPECT_FALSE(s.admits({1, 1, 10}, Vec3{1, 1, 1} - 1.01 * Vec3{0.6, 0, 0.8}, 1, kTol));
  // At coordinates of 1e8 and 1e-8.
  for (double sc : {1e8, 1e-8}) {
    Boundaries f;
    ASSERT_TRUE(f.add(Plane{{0, 0, sc}, {0, 0, 1}}));
    EXPECT_TRUE(f.admits({sc, sc, 5 * sc}, {sc, sc, 2 * sc}, sc, kTol)) << sc;
    EXPECT_FALSE(f.admits({sc, sc, 5 * sc}, {sc, sc, 1.5 * sc}, sc, kTol)) << sc;
    EXPECT_FALSE(f.admits({sc, sc, 5 * sc}, {sc, sc, -5 * sc}, sc, kTol)) << sc;
  }
}

TEST(BoundariesAdmits, Cylinder)
{
  Boundaries b;
  ASSERT_TRUE(b.add(Cylinder{{0, 0, 0}, {0, 0, 1}, 1}));
  const double r = 0.5;
  // Outside.
  EXPECT_TRUE(b.admits({3, 0, 0}, {2, 0, 0}, r, kTol));
  EXPECT_TRUE(b.admits({3, 0, 0}, {1.5, 0, 7}, r, kTol));                    // touching
  EXPECT_TRUE(b.admits({3, 0, 0}, {1.5 - 0.25 * kTol, 0, 0}, r, kTol));      // within tol * r
  EXPECT_FALSE(b.admits({3, 0, 0}, {1.5 - 2 * r * kTol, 0, 0}, r, kTol));    // beyond it
  EXPECT_FALSE(b.admits({3, 0, 0}, {1.4, 0, 0}, r, kTol));
  // Inside.
  EXPECT_TRUE(b.admits({0, 0, 0}, {0.3, 0, 0}, r, kTol));
  EXPECT_TRUE(b.admits({0, 0, 0}, {0, -0.5, 5}, r, kTol));    // touching from inside
  EXPECT_FALSE(b.admits({0, 0, 0}, {0.6, 0, 0}, r, kTol));
  EXPECT_FALSE(b.admits({0, 0, 0}, {0, 0.5 + 2 * r * kTol, 0}, r, kTol));
  // Crossed (clear at the end).
  EXPECT_FALSE(b.admits({0, 0, 0}, {3, 0, 0}, r, kTol));
  EXPECT_FALSE(b.admits({3, 0, 0}, {0, 0.2, 0}, r, kTol));
  // From outside to outside through it.
  EXPECT_FALSE(b.admits({-3, 0.1, 0}, {3, -0.1, 1}, r, kTol));
  EXPECT_TRUE(b.admits({-3, 1.6, 0}, {3, 1.6, 1}, r, kTol));    // past it
  // A thin cylinder, passed through by a small sphere whose ends are clear:
  // refused; passed by: admitted; along its axis outside: admitted.
  Boundaries thin;
  ASSERT_TRUE(thin.add(Cylinder{{0, 0, 0}, {0, 0, 1}, 0.01}));
  EXPECT_FALSE(thin.admits({-1, 0, 0}, {1, 0, 0}, 0.001, kTol));
  EXPECT_FALSE(thin.admits({-1, 0.005, 3}, {1, 0.005, -3}, 0.001, kTol));
  EXPECT_FALSE(thin.admits({-0.1, -0.1, 0}, {0.1, 0.1, 0}, 0.001, kTol));    // through the axis
  EXPECT_TRUE(thin.admits({-1, 0.02, 0}, {1, 0.02, 0}, 0.001, kTol));
  EXPECT_TRUE(thin.admits({-1, 1, 0}, {1, 1, 0}, 0.001, kTol));
  EXPECT_TRUE(thin.admits({0.05, 0, -10}, {0.05, 0, 10}, 0.001, kTol));
  // Slanted axis, not of unit length, off the origin.
  Boundaries s;
  ASSERT_TRUE(s.add(Cylinder{{1, 2, 3}, {2, 0, 2}, 0.5}));
  const Vec3 off = Vec3{1, 2, 3} + Vec3{0, 1, 0};                // 1 from the axis
  EXPECT_TRUE(s.admits(off + Vec3{0, 1, 0}, off, 0.5, kTol));    // touching
  EXPECT_FALSE(s.admits(off + Vec3{0, 1, 0}, off + Vec3{0, -0.01, 0}, 0.5, kTol));
  EXPECT_FALSE(s.admits(off, Vec3{1, 2, 3} + Vec3{0, -1, 0}, 0.4, kTol));    // through it
  EXPECT_TRUE(s.admits(off, off + Vec3{5, 0, 5}, 0.4, kTol));                // along it
}

// The floor: a square of side 2 at z = 0 made of two triangles sharing the
// diagonal (-1, -1) - (1, 1).
TEST(BoundariesAdmits, TwoTriangleFloor)
{
  Boundaries b;
  for (const Triangle &t : square(1, 0)) ASSERT_TRUE(b.add(t));
  const double r = 0.25;
  EXPECT_TRUE(b.admits({0.3, 0.2, 2}, {0.3, 0.2, 0.5}, r, kTol));
  EXPECT_TRUE(b.admits({0.3, 0.2, -2}, {-0.3, 0.6, -0.5}, r, kTol));
  EXPECT_TRUE(b.admits({0.3, 0.2, 2}, {0.3, 0.2, r}, r, kTol));    // touching
  EXPECT_TRUE(b.admits({0.3, 0.2, -2}, {0.3, 0.2, -r}, r, kTol));
  EXPECT_TRUE(b.admits({0.3, 0.2, 2}, {0.3, 0.2, r * (1 - 0.5 * kTol)}, r, kTol));
  EXPECT_FALSE(b.admits({0.3, 0.2, 2}, {0.3, 0.2, r * (1 - 2 * kTol)}, r, kTol));
  EXPECT_FALSE(b.admits({0.3, 0.2, 2}, {0.3, 0.2, 0.1}, r, kTol));
  EXPECT_FALSE(b.admits({0.3, 0.2, 2}, {0.3, 0.2, -0.5}, r, kTol));    // crossed, clear
  EXPECT_FALSE(b.admits({-0.9, 0.5, -1}, {0.5, -0.9, 1}, r, kTol));
  // Through the shared diagonal, and through a corner.
  EXPECT_FALSE(b.admits({0.4, 0.4, 1}, {0.4, 0.4, -1}, r, kTol));
  EXPECT_FALSE(b.admits({0.6, 0.2, 1}, {0.2, 0.6, -1}, r, kTol));
  EXPECT_FALSE(b.admits({1, 1, 1}, {1, 1, -1}, 0.01, kTol));
  // The floor is finite: beside it, a sphere may go down past z = 0;
  // touching its edge is admitted, overlapping it is not.
  EXPECT_TRUE(b.admits({3, 0, 2}, {3, 0, -2}, r, kTol));
  EXPECT_TRUE(b.admits({1.25, 0, 2}, {1.25, 0, 0}, r, kTol));
  EXPECT_FALSE(b.admits({1.5, 0, 2}, {1.2, 0, 0}, r, kTol));
  EXPECT_FALSE(b.admits({1.5, 0, 2}, {1.1, 0, 0.1}, r, kTol));
  EXPECT_FALSE(b.admits({1.5, 1.5, 0.5}, {1.1, 1.1, 0.1}, r, kTol));    // near a corner
  // A sphere in the floor's plane, sliding across it: the distance test
  // refuses it (the crossing test is false in the plane, by design).
  EXPECT_FALSE(b.admits({-3, 0, 0}, {0, 0, 0}, r, kTol));
  // Added after queries: a second floor below, seen by the next query.
  EXPECT_TRUE(b.admits({0, 0, -0.5}, {0, 0, -3}, r, kTol));
  for (const Triangle &t : square(1, -2)) ASSERT_TRUE(b.add(t));
  EXPECT_FALSE(b.admits({0, 0, -0.5}, {0, 0, -3}, r, kTol));
  EXPECT_FALSE(b.admits({0, 0, -0.5}, {0, 0, -2.1}, r, kTol));
  EXPECT_TRUE(b.admits({0, 0, -0.5}, {0, 0, -1}, r, kTol));
}

TEST(BoundariesAdmits, NonFiniteIsNeverAdmitted)
{
  std::vector<Boundaries> all(4);
  ASSERT_TRUE(all[1].add(Plane{{0, 0, -10}, {0, 0, 1}}));
  ASSERT_TRUE(all[2].add(Cylinder{{10, 10, 0}, {0, 0, 1}, 1}));
  for (const Triangle &t : square(1, -10)) ASSERT_TRUE(all[3].add(t));
  const Vec3 ok{0, 0, 0}, moved{0.1, 0.2, 0.3};
  for (const Boundaries &b : all) {
    ASSERT_TRUE(b.admits(ok, moved, 0.5, kTol));    // the finite case is admitted
    for (double bad : {NAN, INFINITY, -INFINITY}) {
      for (int d = 0; d < 3; ++d) {
        Vec3 c = moved, f = ok;
        c[d] = bad;
        f[d] = bad;
        EXPECT_FALSE(b.admits(ok, c, 0.5, kTol)) << "centre " << bad << " walls " << b.size();
        EXPECT_FALSE(b.admits(f, moved, 0.5, kTol)) << "from " << bad << " walls " << b.size();
        EXPECT_FALSE(b.admits(f, c, 0.5, kTol));
      }
      EXPECT_FALSE(b.admits(ok, moved, bad, kTol)) << "radius " << bad;
    }
    EXPECT_FALSE(b.admits(ok, moved, -0.5, kTol));    // a negative radius
  }
}

// ===========================================================================
// Boundaries::admits and distance against brute force over every wall.

// Each wall set of wall_sets(), many random spheres and moves: admits()
// equals the rule checked wall by wall (no index), except for the few
// cases within 1e-9 of a threshold (rounding may decide those); both
// answers occur often in each kind of move, near the large floor too.
TEST(BoundariesBruteForce, AdmitsMatchesEveryWall)
{
  for (const Walls &w : wall_sets()) {
    const Boundaries b = w.build();
    Random rng(101);
    const std::vector<Move> moves = random_moves(rng, 3000);
    int admitted[6] = {}, refused[6] = {}, unsure = 0, wrong = 0;
    for (std::size_t i = 0; i < moves.size(); ++i) {
      const Move &m = moves[i];
      const Verdict v = ref_admits(w, m.from, m.c, m.r, m.tol);
      if (v == Verdict::Unsure) {
        ++unsure;
        continue;
      }
      const bool expected = v == Verdict::Admitted;
      (expected ? admitted : refused)[i % 6]++;
      const bool got = b.admits(m.from, m.c, m.r, m.tol);
      if (got != expected && ++wrong <= 10)
        ADD_FAILURE() << w.name << ": move " << i << " " << describe(m) << ": admits " << got
                      << ", brute force " << expected;
    }
    EXPECT_EQ(wrong, 0) << w.name;
    EXPECT_LT(unsure, 30) << w.name;
    // Both answers are common: overall, and for the mixed set in each kind
    // of move (for the others, in the kinds that meet their walls).
    int all_admitted = 0, all_refused = 0;
    for (int k = 0; k < 6; ++k) {
      all_admitted += admitted[k], all_refused += refused[k];
      const bool meets = w.name == "mixed" || (w.name == "mesh and floor" && k != 4) ||
                         (w.name == "floor alone" && k == 3);
      if (!meets) continue;
      EXPECT_GT(admitted[k], 10) << w.name << " kind " << k;
      EXPECT_GT(refused[k], 10) << w.name << " kind " << k;
    }
    EXPECT_GT(all_admitted, 60) << w.name;
    EXPECT_GT(all_refused, 60) << w.name;
  }
}

// distance() is the smallest distance to a wall, to rounding of the
// scene's coordinates (up to 60 here: 1e-13).
TEST(BoundariesBruteForce, DistanceMatchesEveryWall)
{
  for (const Walls &w : wall_sets()) {
    const Boundaries b = w.build();
    Random rng(202);
    for (const Move &m : random_moves(rng, 600)) {
      for (const Vec3 &x : {m.c, m.from}) {
        const double d = b.distance(x);
        ASSERT_TRUE(std::isfinite(d)) << w.name;
        EXPECT_NEAR(d, static_cast<double>(ref_distance(w, x)), 1e-13 * (1 + norm(x))) << w.name;
      }
    }
  }
  EXPECT_EQ(Boundaries().distance({1, 2, 3}), INFINITY);
}

// Near the far corners of the large floor (where no small triangle is,
// and the index's grid has nothing): the floor is still seen.
TEST(BoundariesBruteForce, LargeTrianglesSeenEverywhere)
{
  Random rng(5);
  Walls w;
  w.triangles = ball_mesh({0, 0, 0}, 0.5, 3, rng);
  const std::vector<Triangle> floor = square(1000, -1);
  w.triangles.insert(w.triangles.end(), floor.begin(), floor.end());
  const Boundaries b = w.build();
  for (const Vec3 &corner : {Vec3{999, 999, -1}, Vec3{-999, 999, -1}, Vec3{999, -999, -1},
                             Vec3{-999, -999, -1}, Vec3{500, -20, -1}, Vec3{0.1, 998, -1}}) {
    const Vec3 up{0, 0, 1};
    EXPECT_TRUE(b.admits(corner + 2.0 * up, corner + 0.5 * up, 0.5, kTol));
    EXPECT_FALSE(b.admits(corner + 2.0 * up, corner + 0.4 * up, 0.5, kTol));
    EXPECT_FALSE(b.admits(corner + 2.0 * up, corner - 0.6 * up, 0.5, kTol));    // crossed
    EXPECT_FALSE(b.admits(corner + 0.6 * up, corner - 0.6 * up, 0.01, kTol));
    EXPECT_NEAR(b.distance(corner + 0.3 * up), 0.3, 1e-12);
  }
  // Beyond the floor's edge, nothing.
  EXPECT_TRUE(b.admits({1001, 0, 1}, {1001, 0, -3}, 0.5, kTol));
  EXPECT_FALSE(b.admits({1000.2, 0, 1}, {1000.2, 0, -1}, 0.5, kTol));    // its edge is near
}

// ===========================================================================
// Degenerate meshes: the index of triangles must not hang on them. A mesh
// whose triangles are mostly points (radius 0) or tiny against the spheres
// asked about. Run in a child with a time limit (5 s; a query takes
// microseconds).

TEST(BoundariesDeathTest, MeshOfPointTrianglesAnswers)
{
  Boundaries b;
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(b.add(Triangle{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}));
  // The brute force first (the same point ten times).
  EXPECT_TRUE(b.admits({2, 0, 0}, {2, 0, 0}, 1, kTol));
  EXPECT_FALSE(b.admits({0.5, 0, 0}, {0.5, 0, 0}, 1, kTol));
  EXPECT_EXIT(
      {
        alarm(5);
        // Touching the point at the origin: admitted.
        const bool a = b.admits({-1, 0, 0}, {-1, 0, 0}, 1, kTol);
        const bool c = b.admits({-2, 0, 0}, {-0.5, 0, 0}, 0.5, kTol);
        std::_Exit(a && c ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST(BoundariesDeathTest, MeshOfTinyTrianglesAnswers)
{
  Random rng(9);
  Boundaries b;
  Walls w;
  for (int i = 0; i < 100; ++i) {
    const Vec3 a = rng.in_box(1);
    w.triangles.push_back({a, a + 1e-9 * rng.direction(), a + 1e-9 * rng.direction()});
    ASSERT_TRUE(b.add(w.triangles.back()));
  }
  EXPECT_EXIT(
      {
        alarm(5);
        int wrong = 0;
        for (int i = 0; i < 20; ++i) {
          const Vec3 c = rng.in_box(1);
          const Verdict v = ref_admits(w, c, c, 0.1, kTol);
          if (v != Verdict::Unsure && b.admits(c, c, 0.1, kTol) != (v == Verdict::Admitted))
            ++wrong;
        }
        std::_Exit(wrong);
      },
      ::testing::ExitedWithCode(0), "");
}

// ===========================================================================
// Boundaries::distance of a point that is not finite: not a distance (no
// comparison with a radius may accept it).

TEST(BoundariesDistance, NonFinitePoint)
{
  const std::vector<Walls> sets = wall_sets();
  for (const Walls &w : {sets[0], sets[2]}) {
    const Boundaries b = w.build();
    for (const Vec3 &x : {Vec3{NAN, 0, 0}, Vec3{0, NAN, 0}, Vec3{0, 0, NAN}}) {
      const double d = b.distance(x);
      EXPECT_FALSE(d >= 0) << w.name << ": distance " << d;
    }
  }
}

// ===========================================================================
// The triangle index (Boundaries::admits looks only at the triangles near
// the move): the same answer as every triangle tested, on meshes that
// defeat an index of bounding spheres, and few triangles looked at.

namespace {

// admits() with every triangle tested: the same predicate, no index.
bool admits_every_triangle(const std::vector<Triangle> &tris, const Move &m)
{
  const double clear = m.r * (1 - m.tol);
  for (const Triangle &t : tris)
    if (!(distance_to_triangle(m.c, t) >= clear) || segment_meets_triangle(m.from, m.c, t))
      return false;
  return true;
}

// A closed cylinder mould about the z axis through `base`, as an STL mesher
// makes it: each of `segments` side rectangles two slivers spanning the
// whole height, each cap a fan of thin triangles from its centre.
std::vector<Triangle> cylinder_mould(Vec3 base, double radius, double height, int segments)
{
  std::vector<Triangle> tris;
  const double pi = std::acos(-1.0);
  const Vec3 up{0, 0, height};
  for (int i = 0; i < segments; ++i) {
    const double a0 = 2 * pi * i / segments, a1 = 2 * pi * (i + 1) / segments;
    const Vec3 p0 = base + radius * Vec3{std::cos(a0), std::sin(a0), 0};
    const Vec3 p1 = base + radius * Vec3{std::cos(a1), std::sin(a1), 0};
    tris.push_back({p0, p1, p1 + up});
    tris.push_back({p0, p1 + up, p0 + up});
    tris.push_back({base, p1, p0});
    tris.push_back({base + up, p0 + up, p1 + up});
  }
  return tris;
}

// Moves about the mould of cylinder_mould(base, radius, height): spheres of
// radius 0.04 to 0.16 of the mould's radius by small steps (the
// relaxation's), by steps of a few radii, and long jumps across it (the
// relocation's), near its side, its caps and its rims, inside and outside.
std::vector<Move> mould_moves(Random &rng, Vec3 base, double radius, double height, int count)
{
  std::vector<Move> moves;
  const double tols[] = {kTol, 1e-10, 0.1, 0};
  const double pi = std::acos(-1.0);
  for (int i = 0; i < count; ++i) {
    Move m;
    m.r = radius * rng.uniform(0.04, 0.16);
    m.tol = tols[i % 4];
    const double angle = rng.uniform(0, 2 * pi), z = rng.uniform(-2 * m.r, height + 2 * m.r);
    const Vec3 across{std::cos(angle), std::sin(angle), 0};
    switch (i % 5) {
    case 0:    // about the side
      m.c = base + (radius + rng.uniform(-2, 2) * m.r) * across + Vec3{0, 0, z};
      break;
    case 1:    // about a cap
      m.c = base + (radius * std::sqrt(rng.uniform(0, 1.2))) * across +
            Vec3{0, 0, (i % 2 ? height : 0) + rng.uniform(-2, 2) * m.r};
      break;
    case 2:    // about a rim
      m.c = base + (radius + rng.uniform(-2, 2) * m.r) * across +
            Vec3{0, 0, (i % 2 ? height : 0) + rng.uniform(-2, 2) * m.r};
      break;
    default:    // anywhere about the mould
      m.c = base + (radius * rng.uniform(0, 1.3)) * across + Vec3{0, 0, z};
    }
    const int step = i % 3;
    if (i % 5 == 4) {    // a jump from elsewhere in or about the mould
      const double a = rng.uniform(0, 2 * pi);
      m.from = base + (radius * rng.uniform(0, 1.3)) * Vec3{std::cos(a), std::sin(a), 0} +
               Vec3{0, 0, rng.uniform(-0.2, 1.2) * height};
    } else {
      m.from = m.c + (step == 0 ? rng.uniform(0, 0.1) : rng.uniform(0, 3)) * m.r * rng.direction();
    }
    moves.push_back(m);
  }
  return moves;
}

// The indexed admits() against every triangle tested, move by move: equal
// always (the same predicate on each triangle; rounding cannot differ), and
// both answers common. distance() too.
void expect_same_as_every_triangle(const std::string &name, const std::vector<Triangle> &tris,
                                   const std::vector<Move> &moves)
{
  Boundaries b;
  for (const Triangle &t : tris) ASSERT_TRUE(b.add(t)) << name;
  int admitted = 0, refused = 0, wrong = 0;
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const Move &m = moves[i];
    const bool expected = admits_every_triangle(tris, m);
    (expected ? admitted : refused)++;
    const bool got = b.admits(m.from, m.c, m.r, m.tol);
    if (got != expected && ++wrong <= 10)
      ADD_FAILURE() << name << ": move " << i << " " << describe(m) << ": admits " << got
                    << ", every triangle " << expected;
  }
  EXPECT_EQ(wrong, 0) << name;
  EXPECT_GT(admitted, static_cast<int>(moves.size() / 10)) << name;
  EXPECT_GT(refused, static_cast<int>(moves.size() / 10)) << name;
  for (std::size_t i = 0; i < moves.size(); i += 7) {
    double best = INFINITY;
    for (const Triangle &t : tris) best = std::min(best, distance_to_triangle(moves[i].c, t));
    EXPECT_EQ(b.distance(moves[i].c), best) << name << " " << describe(moves[i].c);
  }
}

}    // namespace

// (a) A cylinder mould of long slivers (64 segments, each side triangle
// spanning the whole height), about the origin and far from it (cells of
// large coordinates), and of 7 segments (a coarse mesh).
TEST(BoundariesIndex, SliverCylinderSameAsEveryTriangle)
{
  Random rng(31);
  for (const Vec3 &base : {Vec3{0, 0, 0}, Vec3{1e4, -3e3, 7e2}}) {
    for (int segments : {64, 7}) {
      const std::vector<Triangle> tris = cylinder_mould(base, 0.05, 0.1, segments);
      expect_same_as_every_triangle("mould of " + std::to_string(segments) + " segments at " +
                                        describe(base),
                                    tris, mould_moves(rng, base, 0.05, 0.1, 6000));
    }
  }
}

// (b) Many small triangles (a bumpy ball) with a few huge ones: a floor of
// two triangles 2000 wide, and a huge tilted triangle across the scene (its
// bounding box is a cube: an index by boxes would put it everywhere).
TEST(BoundariesIndex, HugeTrianglesAmongSmallSameAsEveryTriangle)
{
  Random rng(37);
  std::vector<Triangle> tris = ball_mesh({-0.4, 0.3, 0.2}, 0.35, 3, rng);
  for (const Triangle &t : square(1000, -0.5)) tris.push_back(t);
  tris.push_back({{-50, -50, -50}, {60, -40, 70}, {-30, 80, 40}});
  tris.push_back({{-3, 2, -1}, {4, -1, 3}, {1, 5, 2}});    // large, among the small ones
  std::vector<Move> moves = random_moves(rng, 6000);
  // Near the tilted triangle, far from the ball.
  const Triangle &tilted = tris[tris.size() - 2];
  const Vec3 n = cross(tilted.b - tilted.a, tilted.c - tilted.a);
  for (int i = 0; i < 2000; ++i) {
    Move m;
    m.r = std::pow(10.0, rng.uniform(-2.5, -0.5));
    m.tol = i % 2 ? kTol : 0.1;
    double u = rng.uniform(0, 1), v = rng.uniform(0, 1);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    m.c = tilted.a + u * (tilted.b - tilted.a) + v * (tilted.c - tilted.a) +
          (rng.uniform(-2, 2) * m.r / norm(n)) * n;
    m.from = m.c + rng.uniform(0, 3) * m.r * rng.direction();
    moves.push_back(m);
  }
  expect_same_as_every_triangle("huge among small", tris, moves);
}

// (c) Degenerate triangles: segments (two equal vertices, or three
// collinear, exactly and to rounding), points, and triangles far thinner
// than rounding, among a few ordinary ones.
TEST(BoundariesIndex, DegenerateTrianglesSameAsEveryTriangle)
{
  Random rng(41);
  std::vector<Triangle> tris;
  for (int i = 0; i < 60; ++i) {
    const Vec3 a = rng.in_box(1), d = rng.uniform(0.01, 0.5) * rng.direction();
    switch (i % 6) {
    case 0:
      tris.push_back({a, a, a + d});    // a segment
      break;
    case 1:    // three collinear, exactly (coordinates in 1/8)
    {
      const Vec3 p{std::round(8 * a.x) / 8, std::round(8 * a.y) / 8, std::round(8 * a.z) / 8};
      tris.push_back({p, p + Vec3{0.25, 0.125, 0}, p + Vec3{0.5, 0.25, 0}});
      break;
    }
    case 2:
      tris.push_back({a, a + d, a + 0.3 * d});    // collinear up to rounding
      break;
    case 3:
      tris.push_back({a, a, a});    // a point
      break;
    case 4:    // a sliver of height 1e-20 of its length
      tris.push_back({a, a + d, a + 0.5 * d + 1e-20 * norm(d) * rng.direction()});
      break;
    default:
      tris.push_back({a, a + rng.uniform(0.05, 0.3) * rng.direction(),
                      a + rng.uniform(0.05, 0.3) * rng.direction()});
    }
  }
  std::vector<Move> moves;
  for (int i = 0; i < 6000; ++i) {
    const Triangle &t = tris[i % tris.size()];
    Move m;
    m.r = std::pow(10.0, rng.uniform(-2.5, -0.7));
    m.tol = i % 3 ? kTol : 0.1;
    const double s = rng.uniform(0, 1);
    m.c = t.a + s * (t.b - t.a) + rng.uniform(0, 1 - s) * (t.c - t.a) +
          rng.uniform(0, 2) * m.r * rng.direction();
    m.from = i % 4 ? m.c + rng.uniform(0, 3) * m.r * rng.direction() : rng.in_box(1.2);
    moves.push_back(m);
  }
  expect_same_as_every_triangle("degenerate", tris, moves);
}

// The mould of 64 segments (256 triangles; each side triangle is as long
// as the mould is high, so its bounding sphere reaches half of them): a
// sphere's small step looks at the few triangles next to it, a jump across
// the mould at those along its path, never at all of them.
TEST(BoundariesIndex, SliverCylinderLooksAtFewTriangles)
{
  Random rng(43);
  const Vec3 base{0.06, 0.06, 0};
  const std::vector<Triangle> tris = cylinder_mould(base, 0.05, 0.1, 64);
  Boundaries b;
  for (const Triangle &t : tris) ASSERT_TRUE(b.add(t));
  std::size_t step_sum = 0, step_max = 0, jump_sum = 0, jump_max = 0, steps = 0, jumps = 0;
  for (const Move &m : mould_moves(rng, base, 0.05, 0.1, 5000)) {
    // Spheres of 4 to 8 mm, as in the LIGGGHTS mould scene.
    const double r = std::min(std::max(m.r, 0.004), 0.008);
    const std::size_t n = b.triangles_tested(m.from, m.c, r);
    if (norm(m.c - m.from) <= 3 * r) {
      step_sum += n, step_max = std::max(step_max, n), ++steps;
    } else {
      jump_sum += n, jump_max = std::max(jump_max, n), ++jumps;
    }
  }
  ASSERT_GT(steps, 1000u);
  ASSERT_GT(jumps, 500u);
  std::printf("triangles looked at: small steps mean %.1f most %zu, jumps mean %.1f most %zu\n",
              double(step_sum) / steps, step_max, double(jump_sum) / jumps, jump_max);
  // Every triangle would be 256; a small step looks at about 9, a jump at
  // about 13 (the index of this file's version), bounds twice that.
  EXPECT_LE(step_sum, 16 * steps) << "mean over small steps";
  // At a cap's centre all 64 triangles of its fan meet.
  EXPECT_LE(step_max, 80u) << "most in a small step";
  EXPECT_LE(jump_sum, 32 * jumps) << "mean over jumps";
  EXPECT_LE(jump_max, tris.size() / 2) << "most in a jump";
}

// The index itself (reinforce_triangle_index.h): a query yields every
// triangle within `reach` of the move's end or met by its path, each once;
// small and medium triangles, tilted ones across many cells, degenerate
// ones, and a floor far larger than the cells (yielded by every query: the
// only ones, with the one marked so).
TEST(TriangleIndex, YieldsEveryTriangleNearTheMoveOnce)
{
  Random rng(47);
  std::vector<Triangle> tris = ball_mesh({0.2, -0.1, 0.1}, 0.4, 2, rng);
  for (int i = 0; i < 30; ++i) {    // tilted, 0.5 to 2 across: tens of cells each
    const Vec3 a = rng.in_box(1);
    const double size = rng.uniform(0.5, 2);
    tris.push_back({a, a + size * rng.direction(), a + size * rng.direction()});
  }
  // Any and very obtuse ones (not slivers nor needles: the reference below
  // is their computed distance, which Boundaries trusts only for triangles
  // it does not mark thin).
  for (int i = 0; i < 20; ++i) tris.push_back(random_triangle(rng, i % 2 ? 3 : 0));
  tris.push_back({{0.1, 0.1, 0.1}, {0.1, 0.1, 0.1}, {0.4, -0.2, 0.3}});      // a segment
  tris.push_back({{-0.3, 0.2, 0.5}, {-0.3, 0.2, 0.5}, {-0.3, 0.2, 0.5}});    // a point
  for (const Triangle &t : square(500, -1.2)) tris.push_back(t);
  std::vector<bool> every(tris.size(), false);
  every[3] = true;    // marked: yielded by every query
  TriangleIndex index;
  index.build(tris, every, 0.05);
  EXPECT_GE(index.cell_size(), 0.05);
  // The floor (its two triangles far larger than the cells) and the one
  // marked: nothing else is yielded everywhere.
  EXPECT_EQ(index.always_yielded(), 3u);
  std::vector<int> times(tris.size());
  std::size_t yielded = 0, queries = 0;
  for (int q = 0; q < 4000; ++q) {
    const double reach = std::pow(10.0, rng.uniform(-3, -0.5));
    const Vec3 to = rng.in_box(1.3);
    const Vec3 from = q % 3 ? to + rng.uniform(0, 3) * reach * rng.direction() : rng.in_box(1.3);
    std::fill(times.begin(), times.end(), 0);
    index.for_each_near_move(from, to, reach, [&](int i) { ++times[i]; });
    for (std::size_t i = 0; i < tris.size(); ++i) {
      ASSERT_LE(times[i], 1) << "triangle " << i << " yielded twice, query " << q;
      const bool near =
          distance_to_triangle(to, tris[i]) <= reach || segment_meets_triangle(from, to, tris[i]);
      if (near) {
        EXPECT_EQ(times[i], 1) << "triangle " << i << " missed, query " << q;
      }
      yielded += times[i];
    }
    ++queries;
  }
  // Not every triangle, most of the time.
  EXPECT_LT(yielded, queries * tris.size() / 4);
  // Anything not finite: every triangle, each once.
  for (const Vec3 &bad : {Vec3{NAN, 0, 0}, Vec3{0, INFINITY, 0}}) {
    std::fill(times.begin(), times.end(), 0);
    index.for_each_near_move(bad, {0, 0, 0}, 0.1, [&](int i) { ++times[i]; });
    EXPECT_EQ(std::count(times.begin(), times.end(), 1), static_cast<long>(tris.size()));
  }
}
