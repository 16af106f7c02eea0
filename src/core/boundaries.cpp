#include "boundaries.h"

#include <algorithm>
#include <cmath>

namespace reinforce {

namespace {

bool finite(double v)
{
  return std::isfinite(v);
}

Vec3 unit(Vec3 v)
{
  return (1 / norm(v)) * v;
}

// Distance from x to the segment [a, b] (a point when a == b).
double distance_to_segment(Vec3 x, Vec3 a, Vec3 b)
{
  const Vec3 ab = b - a;
  const double len2 = norm2(ab);
  double t = len2 > 0 ? dot(x - a, ab) / len2 : 0.0;
  t = std::min(1.0, std::max(0.0, t));
  return norm(x - (a + t * ab));
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

}    // namespace

double distance_to_triangle(Vec3 x, const Triangle &t)
{
  const Vec3 ab = t.b - t.a, ac = t.c - t.a;
  const Vec3 n = cross(ab, ac);
  const double area2 = norm2(n);
  const double edges = std::max({norm2(ab), norm2(ac), norm2(t.c - t.b)});
  const double to_edges = std::min({distance_to_segment(x, t.a, t.b),
                                    distance_to_segment(x, t.b, t.c),
                                    distance_to_segment(x, t.c, t.a)});
  // A degenerate triangle (area below rounding of its edges) is its edges.
  if (!(area2 > 1e-24 * edges * edges)) return to_edges;
  // The foot of x in the plane lies inside: the distance to the plane;
  // else the nearest point is on an edge.
  const Vec3 ax = x - t.a;
  const double height = dot(ax, n) / std::sqrt(area2);
  const Vec3 foot = x - (height / std::sqrt(area2)) * n;
  const double u = dot(cross(t.b - foot, t.c - foot), n), v = dot(cross(t.c - foot, t.a - foot), n),
               w = dot(cross(t.a - foot, t.b - foot), n);
  if (u >= 0 && v >= 0 && w >= 0) return std::min(std::fabs(height), to_edges);
  return to_edges;
}

bool segment_meets_triangle(Vec3 p, Vec3 q, const Triangle &t)
{
  const Vec3 n = cross(t.b - t.a, t.c - t.a);
  const double dp = dot(p - t.a, n), dq = dot(q - t.a, n);
  if ((dp > 0 && dq > 0) || (dp < 0 && dq < 0)) return false;
  // In the triangle's plane (or degenerate): a sphere sliding in the plane
  // of a wall is held by the distance test, not by a crossing.
  if (dp == dq) return false;
  const double s = dp / (dp - dq);
  const Vec3 hit = p + s * (q - p);
  // Inside the closed triangle, with room for rounding (a segment through
  // an edge shared by two triangles meets at least one of them).
  const double n2 = norm2(n);
  const double slack = -1e-12 * n2;
  return dot(cross(t.b - hit, t.c - hit), n) >= slack && dot(cross(t.c - hit, t.a - hit), n) >= slack &&
         dot(cross(t.a - hit, t.b - hit), n) >= slack;
}

bool Boundaries::add(const Plane &p)
{
  if (!is_finite(p.point) || !is_finite(p.normal) || !(norm(p.normal) > 0)) return false;
  planes_.push_back({p.point, unit(p.normal)});
  return true;
}

bool Boundaries::add(const Cylinder &c)
{
  if (!is_finite(c.point) || !is_finite(c.axis) || !(norm(c.axis) > 0) || !finite(c.radius) ||
      !(c.radius > 0))
    return false;
  cylinders_.push_back({c.point, unit(c.axis), c.radius});
  return true;
}

bool Boundaries::add(const Triangle &t)
{
  if (!is_finite(t.a) || !is_finite(t.b) || !is_finite(t.c)) return false;
  triangles_.push_back(t);
  const Vec3 centre = (1.0 / 3) * (t.a + t.b + t.c);
  bounds_.push_back(
      {centre, std::max({norm(t.a - centre), norm(t.b - centre), norm(t.c - centre)})});
  indexed_ = false;
  return true;
}

// Cells twice the bounding radius of nine triangles in ten; the rest (far
// larger than the mesh's typical triangle) are tested on every query.
void Boundaries::index() const
{
  indexed_ = true;
  std::vector<double> radii;
  for (const Bound &b : bounds_) radii.push_back(b.radius);
  if (radii.empty()) return;
  std::vector<double> sorted = radii;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() * 9 / 10, sorted.end());
  const double typical = sorted[sorted.size() * 9 / 10];
  cell_ = std::max(2 * typical, 1e-300);
  grid_ = CellGrid(cell_);
  large_.clear();
  small_radius_ = 0;
  for (std::size_t i = 0; i < bounds_.size(); ++i) {
    if (bounds_[i].radius > 4 * typical) {
      large_.push_back(static_cast<int>(i));
    } else {
      grid_.insert(bounds_[i].centre, static_cast<int>(i));
      small_radius_ = std::max(small_radius_, bounds_[i].radius);
    }
  }
}

template <class F> void Boundaries::for_each_triangle_near(Vec3 x, double range, F &&f) const
{
  if (triangles_.empty()) return;
  if (!indexed_) index();
  for (int i : large_) f(triangles_[i]);
  grid_.for_each_near(x, range + small_radius_, [&](int i) { f(triangles_[i]); });
}

bool Boundaries::admits(Vec3 from, Vec3 c, double r, double tol) const
{
  if (!is_finite(c) || !is_finite(from) || !finite(r) || !(r >= 0)) return false;
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
  bool ok = true;
  const double range = std::max(r, norm(c - from));
  for_each_triangle_near(c, range, [&](const Triangle &t) {
    if (ok) ok = distance_to_triangle(c, t) >= clear && !segment_meets_triangle(from, c, t);
  });
  return ok;
}

double Boundaries::distance(Vec3 x) const
{
  double best = INFINITY;
  for (const Plane &p : planes_) best = std::min(best, std::fabs(dot(x - p.point, p.normal)));
  for (const Cylinder &y : cylinders_)
    best = std::min(best, std::fabs(norm(across(x - y.point, y.axis)) - y.radius));
  for (const Triangle &t : triangles_) best = std::min(best, distance_to_triangle(x, t));
  return best;
}

}    // namespace reinforce
