#include "reinforce_boundaries.h"

#include <algorithm>
#include <cmath>

namespace reinforce {

namespace {

bool finite(double v)
{
  return std::isfinite(v);
}

// v / |v|, scaled first by its largest component so that no square
// overflows or underflows (lengths from 1e-300 to 1e300).
Vec3 unit(Vec3 v)
{
  const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  const Vec3 s = (1 / m) * v;
  return (1 / norm(s)) * s;
}

bool usable_direction(Vec3 v)
{
  return is_finite(v) && (v.x != 0 || v.y != 0 || v.z != 0) && is_finite(unit(v));
}

// The part of v across the axis (unit).
Vec3 across(Vec3 v, Vec3 axis)
{
  return v - dot(v, axis) * axis;
}

// Smallest |p + t d| over t in [0, 1].
double closest_approach(Vec3 p, Vec3 d)
{
  const double len2 = norm2(d);
  double t = len2 > 0 ? -dot(p, d) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return norm(p + t * d);
}

// Triangles are measured in long double (x86-64: 64-bit mantissa, 15-bit
// exponent): no square of a double overflows or underflows there, and the
// normal of a sliver (height h, edges L) comes out to about 5e-20 L / h
// instead of 1e-16 L / h.
struct Wide {
  long double x, y, z;
  Wide(Vec3 v) : x(v.x), y(v.y), z(v.z) {}
  Wide(long double a, long double b, long double c) : x(a), y(b), z(c) {}
};
Wide operator-(const Wide &a, const Wide &b)
{
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Wide operator+(const Wide &a, const Wide &b)
{
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Wide operator*(long double s, const Wide &a)
{
  return {s * a.x, s * a.y, s * a.z};
}
long double dot(const Wide &a, const Wide &b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
Wide cross(const Wide &a, const Wide &b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// Distance from x to the segment [a, b] (a point when a == b).
long double wide_distance_to_segment(const Wide &x, const Wide &a, const Wide &b)
{
  const Wide ab = b - a;
  const long double len2 = dot(ab, ab);
  long double t = len2 > 0 ? dot(x - a, ab) / len2 : 0.0L;
  t = std::min(1.0L, std::max(0.0L, t));
  const Wide d = x - (a + t * ab);
  return std::sqrt(dot(d, d));
}

// The normal of a triangle (twice its area), the one distance_to_triangle,
// segment_meets_triangle and the choice of thin triangles use.
Wide wide_normal(const Triangle &t)
{
  const Wide a(t.a), b(t.b), c(t.c);
  return cross(b - a, c - a);
}

}    // namespace

double distance_to_triangle(Vec3 x, const Triangle &t)
{
  if (!is_finite(x) || !is_finite(t.a) || !is_finite(t.b) || !is_finite(t.c)) return NAN;
  const Wide p(x), a(t.a), b(t.b), c(t.c);
  // The nearest point of each edge; and where the foot of x in the plane
  // lies inside, the distance to the plane (a triangle of no area: its
  // edges).
  long double best = std::min({wide_distance_to_segment(p, a, b), wide_distance_to_segment(p, b, c),
                               wide_distance_to_segment(p, c, a)});
  const Wide n = wide_normal(t);
  const long double n2 = dot(n, n);
  if (n2 > 0) {
    const long double height = dot(p - a, n) / std::sqrt(n2);
    const Wide foot = p - (height / std::sqrt(n2)) * n;
    if (dot(cross(b - foot, c - foot), n) >= 0 && dot(cross(c - foot, a - foot), n) >= 0 &&
        dot(cross(a - foot, b - foot), n) >= 0)
      best = std::min(best, std::fabs(height));
  }
  return static_cast<double>(best);
}

bool segment_meets_triangle(Vec3 p, Vec3 q, const Triangle &t)
{
  if (!is_finite(p) || !is_finite(q) || !is_finite(t.a) || !is_finite(t.b) || !is_finite(t.c))
    return false;
  const Wide lp(p), lq(q), a(t.a), b(t.b), c(t.c);
  const Wide n = wide_normal(t);
  const long double dp = dot(lp - a, n), dq = dot(lq - a, n);
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0)) return false;
  // In the triangle's plane (or degenerate): a sphere sliding in the plane
  // of a wall is held by the distance test, not by a crossing.
  if (dp == dq) return false;
  const long double s = dp / (dp - dq);
  const Wide hit = lp + s * (lq - lp);
  // Inside the closed triangle, with room for rounding (a segment through
  // an edge shared by two triangles meets at least one of them).
  const long double slack = -1e-12L * dot(n, n);
  return dot(cross(b - hit, c - hit), n) >= slack && dot(cross(c - hit, a - hit), n) >= slack &&
         dot(cross(a - hit, b - hit), n) >= slack;
}

bool Boundaries::add(const Plane &p)
{
  if (!is_finite(p.point) || !usable_direction(p.normal)) return false;
  planes_.push_back({p.point, unit(p.normal)});
  return true;
}

bool Boundaries::add(const Cylinder &c)
{
  if (!is_finite(c.point) || !usable_direction(c.axis) || !finite(c.radius) || !(c.radius > 0))
    return false;
  cylinders_.push_back({c.point, unit(c.axis), c.radius});
  return true;
}

bool Boundaries::add(const Triangle &t)
{
  if (!is_finite(t.a) || !is_finite(t.b) || !is_finite(t.c)) return false;
  // Beyond the range of doubles (a triangle spanning 1e308): refused.
  const Vec3 centre = (1.0 / 3) * t.a + (1.0 / 3) * t.b + (1.0 / 3) * t.c;
  const double radius = std::max({norm(t.a - centre), norm(t.b - centre), norm(t.c - centre)});
  if (!is_finite(centre) || !finite(radius)) return false;
  // Height h = |n| / L below 1e-6 L; n is exactly 0 only for a triangle
  // that is a segment or a point, whose distance is its edges' (exact).
  const Wide n = wide_normal(t);
  const long double n2 = dot(n, n);
  const Wide e[3] = {Wide(t.b) - Wide(t.a), Wide(t.c) - Wide(t.b), Wide(t.a) - Wide(t.c)};
  const long double longest2 = std::max({dot(e[0], e[0]), dot(e[1], e[1]), dot(e[2], e[2])});
  triangles_.push_back(t);
  thin_.push_back(n2 > 0 && n2 < 1e-12L * longest2 * longest2);
  indexed_ = false;
  return true;
}

template <class F> void Boundaries::for_each_triangle_near(Vec3 from, Vec3 c, double r, F &&f) const
{
  if (triangles_.empty()) return;
  if (!indexed_) {
    index_.build(triangles_, thin_, r);
    indexed_ = true;
  }
  index_.for_each_near_move(from, c, r, [&](int i) { f(triangles_[i]); });
}

bool Boundaries::admits(Vec3 from, Vec3 c, double r, double tol) const
{
  if (!is_finite(c) || !is_finite(from) || !finite(r) || !(r >= 0) || !(tol >= 0 && tol < 1))
    return false;
  const double clear = r * (1 - tol);
  for (const Plane &p : planes_) {
    const double before = dot(from - p.point, p.normal), after = dot(c - p.point, p.normal);
    if ((before >= 0) != (after >= 0) || std::fabs(after) < clear) return false;
  }
  for (const Cylinder &y : cylinders_) {
    const Vec3 start = across(from - y.point, y.axis), end = across(c - y.point, y.axis);
    const double before = norm(start) - y.radius, after = norm(end) - y.radius;
    if ((before >= 0) != (after >= 0) || std::fabs(after) < clear) return false;
    // Outside at both ends: the path must not pass through the cylinder.
    if (after >= 0 && closest_approach(start, end - start) < y.radius) return false;
  }
  // A triangle refuses the move when nearer c than clear <= r, or met by
  // the path: the index yields every such triangle.
  bool ok = true;
  for_each_triangle_near(from, c, r, [&](const Triangle &t) {
    if (ok) ok = distance_to_triangle(c, t) >= clear && !segment_meets_triangle(from, c, t);
  });
  return ok;
}

std::size_t Boundaries::triangles_tested(Vec3 from, Vec3 c, double r) const
{
  std::size_t count = 0;
  for_each_triangle_near(from, c, r, [&](const Triangle &) { ++count; });
  return count;
}

double Boundaries::distance(Vec3 x) const
{
  if (!is_finite(x)) return NAN;
  double best = INFINITY;
  for (const Plane &p : planes_) best = std::min(best, std::fabs(dot(x - p.point, p.normal)));
  for (const Cylinder &y : cylinders_)
    best = std::min(best, std::fabs(norm(across(x - y.point, y.axis)) - y.radius));
  for (const Triangle &t : triangles_) best = std::min(best, distance_to_triangle(x, t));
  return best;
}

}    // namespace reinforce
