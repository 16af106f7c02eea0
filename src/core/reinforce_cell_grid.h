// A hashed uniform grid of points: the neighbour structure of the engine.
// Memory and time follow the number of points inserted, not the extent of
// the scene (sparse bars in a large box cost only what they touch). The
// cells live in an open-addressing table (a query looks up 27 cells or
// more, most of them empty: a lookup must be a few instructions).
#pragma once

#include "reinforce_vec3.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace reinforce {

class CellGrid {
public:
  // Any cell_size is accepted: one that is not positive and finite gives
  // a grid of one cell (correct, slow).
  explicit CellGrid(double cell_size);

  void insert(Vec3 x, int item);
  // Inserts `item` in the cell of x and its 26 neighbours: then the one
  // cell of any point within one cell size of x lists it (for_each_in_cell).
  void insert_around(Vec3 x, int item);
  // Inserts `item` in the cell of coordinates (i, j, k): the cell of the
  // points x with floor(x * cells_per_length()) = (i, j, k), where
  // for_each_near finds it (the one-cell grid: (0, 0, 0)). For items that
  // span several cells, such as the triangles of a mesh.
  void insert_in_cell(std::int64_t i, std::int64_t j, std::int64_t k, int item);
  // 1 / cell size as the grid uses it (0 for the one-cell grid).
  double cells_per_length() const { return inv_cell_; }
  // Removes `item`, inserted at (or last moved to) x.
  void erase(Vec3 x, int item);
  // Moves `item` from the cell of `from` to the cell of `to`.
  void move(Vec3 from, Vec3 to, int item);

  // Calls f(item) for every item inserted in a cell that meets the box
  // [x - range, x + range]; callers test the exact distance themselves.
  template <class F> void for_each_near(Vec3 x, double range, F &&f) const
  {
    std::int64_t lo[3], hi[3];
    double span = 1;
    for (int d = 0; d < 3; ++d) {
      lo[d] = coord(x[d] - range);
      hi[d] = coord(x[d] + range);
      span *= static_cast<double>(hi[d]) - static_cast<double>(lo[d]) + 1;
    }
    // A box over more cells than the grid holds (or not finite): every
    // cell, each once.
    if (!(span <= static_cast<double>(cell_items_.size())) || !(range < INFINITY)) {
      for (const std::vector<int> &items : cell_items_)
        for (int item : items) f(item);
      return;
    }
    for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int64_t k = lo[2]; k <= hi[2]; ++k) {
          const std::vector<int> *items = find(key(i, j, k));
          if (items)
            for (int item : *items) f(item);
        }
  }

  // Calls f(item) for every item inserted in the cell of x.
  template <class F> void for_each_in_cell(Vec3 x, F &&f) const
  {
    const std::vector<int> *items = find(key(coord(x.x), coord(x.y), coord(x.z)));
    if (items)
      for (int item : *items) f(item);
  }

private:
  // Clamped, so that a coordinate far outside the scene (or not finite)
  // still names a cell: converting a double out of range is undefined.
  std::int64_t coord(double v) const
  {
    constexpr double kLimit = 4.0e18;    // below 2^63
    const double c = std::floor(v * inv_cell_);
    if (c >= -kLimit && c <= kLimit) return static_cast<std::int64_t>(c);
    return c > 0 ? static_cast<std::int64_t>(kLimit) : -static_cast<std::int64_t>(kLimit);
  }
  static std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k);
  std::size_t slot_of(std::uint64_t key) const
  {
    return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_);
  }
  // The index of the cell of `key`, or -1.
  int find_cell(std::uint64_t key) const
  {
    for (std::size_t s = slot_of(key);; s = (s + 1) & (slot_cell_.size() - 1)) {
      const int c = slot_cell_[s];
      if (c < 0 || cell_key_[c] == key) return c;
    }
  }
  const std::vector<int> *find(std::uint64_t key) const
  {
    const int c = find_cell(key);
    return c < 0 ? nullptr : &cell_items_[c];
  }
  std::vector<int> &cell(std::uint64_t key);
  void put_in_table(int c);

  double inv_cell_;
  int shift_;                                   // 64 - log2(table size)
  std::vector<int> slot_cell_;                  // table: cell index or -1
  std::vector<std::uint64_t> cell_key_;         // per cell
  std::vector<std::vector<int>> cell_items_;    // per cell
};

}    // namespace reinforce
