// The surfaces a relocated or pushed sphere must not cross: the walls of the
// host's wall fixes (planes, cylinders, triangles of a mesh), given to the
// engine without any host type (docs/design.md, "Walls and regions").
//
// A sphere moved from `from` to c with radius r is admitted when it overlaps
// no surface by more than tol * r (its centre at least r (1 - tol) from the
// surface) and its centre stays on the side of each surface where it
// started: a wall holds the spheres on both of its sides, as a host's wall
// does. Tolerance: plane and cylinder distances are exact up to the
// rounding of a few products of coordinates (relative 1e-15 of the
// scene's size); triangle distances are computed in long double, within
// 1e-12 of the scene plus 2e-18 L |x - a| / h for a triangle of longest
// edge L and height h (a sliver's normal is ill-conditioned). A sphere that
// exactly touches a surface is admitted. A non-finite centre, start, radius
// or tol is never admitted.
#pragma once

#include "reinforce_triangle_index.h"
#include "reinforce_vec3.h"

#include <vector>

namespace reinforce {

// An infinite plane through `point` with normal `normal` (any length > 0).
struct Plane {
  Vec3 point, normal;
};

// An infinite circular cylinder about the line through `point` along
// `axis` (any length > 0), radius > 0.
struct Cylinder {
  Vec3 point, axis;
  double radius = 0;
};

class Boundaries {
public:
  // A plane or cylinder with a degenerate normal, axis or radius, or a
  // non-finite value, is refused (false); a triangle may be degenerate
  // (a segment or a point), never non-finite.
  bool add(const Plane &p);
  bool add(const Cylinder &c);
  bool add(const Triangle &t);

  bool empty() const { return planes_.empty() && cylinders_.empty() && triangles_.empty(); }
  std::size_t size() const { return planes_.size() + cylinders_.size() + triangles_.size(); }

  // True when the sphere (c, r), moved from `from`, crosses no surface and
  // overlaps none by more than tol * r (see above). Of a mesh it tests only
  // the triangles its index yields near the move (reinforce_triangle_index.h),
  // with the answer of testing every triangle.
  bool admits(Vec3 from, Vec3 c, double r, double tol) const;

  // The smallest distance from x to a surface (+infinity with none).
  double distance(Vec3 x) const;

  // How many triangles admits(from, c, r, ...) looks at, each counted once
  // (all it would test before a verdict): the work of the index, for tests.
  std::size_t triangles_tested(Vec3 from, Vec3 c, double r) const;

private:
  std::vector<Plane> planes_;
  std::vector<Cylinder> cylinders_;
  std::vector<Triangle> triangles_;
  // Slivers so thin (height below 1e-6 of the longest edge, not exactly
  // degenerate) that the rounding of their normal is not bounded by a small
  // part of their size: the index yields them to every query, so that its
  // answer stays that of testing every triangle.
  std::vector<bool> thin_;
  // Built at the first query after a triangle is added, for spheres of that
  // query's radius (reinforce_triangle_index.h).
  mutable TriangleIndex index_;
  mutable bool indexed_ = false;
  template <class F> void for_each_triangle_near(Vec3 from, Vec3 c, double r, F &&f) const;
};

// Distance from x to the triangle (a segment or a point when degenerate).
double distance_to_triangle(Vec3 x, const Triangle &t);
// True when the segment [p, q] meets the triangle (its closed surface).
bool segment_meets_triangle(Vec3 p, Vec3 q, const Triangle &t);

}    // namespace reinforce
