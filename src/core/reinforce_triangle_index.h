// The triangles of a mesh by where they pass: a query about a move looks
// only at the triangles near it (Boundaries::admits asks for every move of
// every sphere, and a mesh may hold thousands of triangles).
//
// Each triangle is listed in every cell of a hashed grid (CellGrid) that it
// meets, not in every cell of its bounding box: a long sliver of a
// cylinder's side, or a tilted triangle, sits only in the cells along it.
// The cells are as large as the triangles' typical height or twice the
// radius of the spheres asked about, whichever is larger: a query covers a
// few cells, and a cell meets a few triangles.
//
// Tolerance: a query yields every triangle that comes within `reach` of the
// point, or meets the segment, with room to spare: boxes and triangles are
// widened by 1e-9 of their size and of their coordinates, a million times
// the rounding of the grid's cell coordinates and far more than that of
// the distances and crossings Boundaries computes for the triangles the
// index holds (reinforce_boundaries.h). So testing what a query yields
// gives the answer of testing every triangle. Each triangle is yielded at
// most once a query; more than the nearest ones come (whole cells).
#pragma once

#include "reinforce_cell_grid.h"
#include "reinforce_vec3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace reinforce {

struct Triangle {
  Vec3 a, b, c;
};

class TriangleIndex {
public:
  // Indexes `triangles` (finite) for spheres of about `radius` (a value
  // that is not positive and finite: the triangles' own size decides).
  // Those marked in `every_query` are yielded by every query, unindexed.
  void build(const std::vector<Triangle> &triangles, const std::vector<bool> &every_query,
             double radius);

  // Calls f(i) once for each triangle i that may come within `reach` of
  // `to`, or may meet the segment [from, to] (with the room above). Any
  // input that is not finite yields every triangle.
  template <class F> void for_each_near_move(Vec3 from, Vec3 to, double reach, F &&f);

  // The cell size chosen, and how many triangles every query yields.
  double cell_size() const { return cell_; }
  std::size_t always_yielded() const { return always_.size(); }

private:
  std::size_t count_ = 0;
  double cell_ = 0;
  CellGrid grid_{1.0};
  std::vector<int> always_;    // yielded by every query: not in the grid
  // A query's stamp on each triangle it yielded (each yielded once);
  // cleared when the stamp wraps around.
  std::vector<std::uint32_t> seen_;
  std::uint32_t stamp_ = 0;

  static constexpr double kRoom = 1e-9;
};

template <class F> void TriangleIndex::for_each_near_move(Vec3 from, Vec3 to, double reach, F &&f)
{
  if (count_ == 0) return;
  if (++stamp_ == 0) {
    std::fill(seen_.begin(), seen_.end(), 0u);
    stamp_ = 1;
  }
  auto once = [&](int i) {
    if (seen_[i] != stamp_) {
      seen_[i] = stamp_;
      f(i);
    }
  };
  for (int i : always_) once(i);
  const Vec3 step = to - from;
  const double length = std::max({std::fabs(step.x), std::fabs(step.y), std::fabs(step.z)});
  const double scale = std::max({std::fabs(from.x), std::fabs(from.y), std::fabs(from.z),
                                 std::fabs(to.x), std::fabs(to.y), std::fabs(to.z)});
  const double room = kRoom * (reach + length + scale);
  // The segment in pieces at most a cell long, each looked up as a box
  // about its middle (a box about the whole segment would cover a volume
  // of cells); a segment within the box about `to` needs none. More pieces
  // than triangles, or anything not finite: every triangle.
  const double pieces = length > reach ? std::ceil(length / cell_) : 0;
  if (!(pieces <= static_cast<double>(count_)) || !(room < INFINITY) || !(reach >= 0)) {
    for (std::size_t i = 0; i < count_; ++i) once(static_cast<int>(i));
    return;
  }
  grid_.for_each_near(to, reach + room, once);
  for (double k = 0; k < pieces; ++k) {
    const Vec3 p = from + (k / pieces) * step, q = from + ((k + 1) / pieces) * step;
    const Vec3 half = 0.5 * (q - p);
    grid_.for_each_near(
        p + half, std::max({std::fabs(half.x), std::fabs(half.y), std::fabs(half.z)}) + room, once);
  }
}

}    // namespace reinforce
