#include "reinforce_triangle_index.h"

#include <array>

namespace reinforce {

namespace {

// A triangle meeting more cells than this (a floor far larger than the
// cells) is yielded by every query instead: one distance test a query
// costs less than listing it in thousands of cells.
constexpr std::size_t kMostCellsOfOne = 4096;
// Cell coordinates up to 2^40: exact in a double, far inside CellGrid's
// clamp. A triangle beyond (coordinates 1e12 cells from the origin) is
// yielded by every query.
constexpr double kFarthestCell = 1099511627776.0;

using Cell = std::array<std::int64_t, 3>;

// A triangle in cell units (cell i of an axis spans [i, i + 1)), the axes
// that may separate it from a box (the box's three, the triangle's normal,
// each edge across each of the box's), and how much both are widened.
struct Footprint {
  Vec3 v[3];
  Vec3 axes[13];
  int axis_count = 0;
  double room = 0;
};

double largest_component(Vec3 v)
{
  return std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
}

// Any axis decides separation (the test need not find the best one), so
// axes are scaled to a largest component of 1: the tests' rounding is then
// relative to the coordinates. Axes too short to scale are dropped (fewer
// axes: the test says "may meet" more often, never less).
void add_axis(Footprint &f, Vec3 a)
{
  const double m = largest_component(a);
  if (m > 1e-150 && m < INFINITY) f.axes[f.axis_count++] = (1 / m) * a;
}

Footprint footprint(const Triangle &t, double per_length)
{
  Footprint f;
  f.v[0] = per_length * t.a, f.v[1] = per_length * t.b, f.v[2] = per_length * t.c;
  const Vec3 e[3] = {f.v[1] - f.v[0], f.v[2] - f.v[1], f.v[0] - f.v[2]};
  add_axis(f, {1, 0, 0});
  add_axis(f, {0, 1, 0});
  add_axis(f, {0, 0, 1});
  add_axis(f, cross(e[0], e[1]));
  for (const Vec3 &d : e) {
    add_axis(f, {0, d.z, -d.y});    // d x (1, 0, 0)
    add_axis(f, {-d.z, 0, d.x});    // d x (0, 1, 0)
    add_axis(f, {d.y, -d.x, 0});    // d x (0, 0, 1)
  }
  const double size =
      std::max({largest_component(e[0]), largest_component(e[1]), largest_component(e[2])});
  const double far =
      std::max({largest_component(f.v[0]), largest_component(f.v[1]), largest_component(f.v[2])});
  f.room = 1e-9 * (1 + size + far);
  return f;
}

// True when the triangle, widened, cannot meet the cells [lo, hi] (a
// separating axis between it and their box, widened by the room).
bool separated(const Footprint &f, const Cell &lo, const Cell &hi)
{
  Vec3 centre, half;
  for (int d = 0; d < 3; ++d) {
    centre[d] = 0.5 * (static_cast<double>(lo[d]) + static_cast<double>(hi[d]) + 1);
    half[d] = 0.5 * (static_cast<double>(hi[d]) - static_cast<double>(lo[d]) + 1) + f.room;
  }
  const Vec3 p[3] = {f.v[0] - centre, f.v[1] - centre, f.v[2] - centre};
  for (int k = 0; k < f.axis_count; ++k) {
    const Vec3 &a = f.axes[k];
    const double s0 = dot(p[0], a), s1 = dot(p[1], a), s2 = dot(p[2], a);
    const double reach =
        half.x * std::fabs(a.x) + half.y * std::fabs(a.y) + half.z * std::fabs(a.z);
    if (std::min({s0, s1, s2}) > reach || std::max({s0, s1, s2}) < -reach) return true;
  }
  return false;
}

// Appends the cells of [lo, hi] the triangle meets, halving the block
// along its longest side: the work follows the cells met, not the block's
// volume. False when more than `most` would be listed.
bool cells_met(const Footprint &f, const Cell &lo, const Cell &hi, std::size_t most,
               std::vector<Cell> &out)
{
  if (separated(f, lo, hi)) return true;
  int widest = 0;
  for (int d = 1; d < 3; ++d)
    if (hi[d] - lo[d] > hi[widest] - lo[widest]) widest = d;
  if (hi[widest] == lo[widest]) {
    if (out.size() >= most) return false;
    out.push_back(lo);
    return true;
  }
  const std::int64_t mid = lo[widest] + (hi[widest] - lo[widest]) / 2;
  Cell first_hi = hi, second_lo = lo;
  first_hi[widest] = mid;
  second_lo[widest] = mid + 1;
  return cells_met(f, lo, first_hi, most, out) && cells_met(f, second_lo, hi, most, out);
}

// The cells the triangle meets, or false (too many, or too far out).
bool cells_of(const Triangle &t, double per_length, std::vector<Cell> &out)
{
  const Footprint f = footprint(t, per_length);
  Cell lo, hi;
  for (int d = 0; d < 3; ++d) {
    const double a = std::min({f.v[0][d], f.v[1][d], f.v[2][d]}) - f.room;
    const double b = std::max({f.v[0][d], f.v[1][d], f.v[2][d]}) + f.room;
    if (!(a >= -kFarthestCell && b <= kFarthestCell)) return false;
    lo[d] = static_cast<std::int64_t>(std::floor(a));
    hi[d] = static_cast<std::int64_t>(std::floor(b));
  }
  return cells_met(f, lo, hi, kMostCellsOfOne, out);
}

// The height of the triangle over its longest edge (0 when degenerate):
// its small extent.
double height(const Triangle &t)
{
  const double longest = std::max({norm(t.b - t.a), norm(t.c - t.b), norm(t.a - t.c)});
  const double h = norm(cross(t.b - t.a, t.c - t.a)) / longest;
  return std::isfinite(h) ? h : 0.0;
}

double median(std::vector<double> v)
{
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}    // namespace

void TriangleIndex::build(const std::vector<Triangle> &triangles,
                          const std::vector<bool> &every_query, double radius)
{
  count_ = triangles.size();
  seen_.assign(count_, 0u);
  stamp_ = 0;
  always_.clear();
  grid_ = CellGrid(1.0);
  cell_ = 0;
  std::vector<int> indexed;
  std::vector<double> heights, lengths;
  for (std::size_t i = 0; i < count_; ++i) {
    if (every_query[i]) {
      always_.push_back(static_cast<int>(i));
      continue;
    }
    const Triangle &t = triangles[i];
    indexed.push_back(static_cast<int>(i));
    heights.push_back(height(t));
    const double longest = std::max({norm(t.b - t.a), norm(t.c - t.b), norm(t.a - t.c)});
    lengths.push_back(std::isfinite(longest) ? longest : 0.0);
  }
  // Cells about the triangles' typical height, at least twice the spheres'
  // radius; for segments and points (no height) and no radius, their
  // typical length. None of these (a mesh of points, asked about points):
  // no grid, every triangle yielded.
  double cell = std::max(median(heights), std::isfinite(radius) ? radius : 0.0);
  if (!(cell > 0)) cell = median(lengths);
  if (!(cell > 0 && cell < INFINITY && 1 / cell < INFINITY)) {
    always_.insert(always_.end(), indexed.begin(), indexed.end());
    return;
  }
  // A mesh of needles far longer than the cells would list each in many
  // cells: the cells double until the lists hold about 64 entries a
  // triangle.
  const std::size_t budget = 64 * indexed.size() + 4096;
  std::vector<std::pair<Cell, int>> entries;
  std::vector<int> too_large;
  std::vector<Cell> cells;
  for (int attempt = 0;; ++attempt) {
    entries.clear();
    too_large.clear();
    grid_ = CellGrid(cell);
    for (int i : indexed) {
      cells.clear();
      if (!cells_of(triangles[i], grid_.cells_per_length(), cells)) {
        too_large.push_back(i);
        continue;
      }
      for (const Cell &c : cells) entries.push_back({c, i});
    }
    if (entries.size() <= budget || attempt == 40) break;
    cell *= 2;
  }
  cell_ = cell;
  for (const auto &e : entries) grid_.insert_in_cell(e.first[0], e.first[1], e.first[2], e.second);
  always_.insert(always_.end(), too_large.begin(), too_large.end());
}

}    // namespace reinforce
