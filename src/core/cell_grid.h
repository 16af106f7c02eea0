// A hashed uniform grid of points: the neighbour structure of the engine.
// Memory and time follow the number of points inserted, not the extent of
// the scene (sparse bars in a large box cost only what they touch).
#pragma once

#include "vec3.h"

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace reinforce {

class CellGrid {
public:
  explicit CellGrid(double cell_size);

  void insert(Vec3 x, int item);
  // Removes `item`, inserted at (or last moved to) x.
  void erase(Vec3 x, int item);
  // Moves `item` from the cell of `from` to the cell of `to`.
  void move(Vec3 from, Vec3 to, int item);

  // Calls f(item) for every item inserted in a cell that meets the box
  // [x - range, x + range]; callers test the exact distance themselves.
  template <class F> void for_each_near(Vec3 x, double range, F &&f) const
  {
    std::int64_t lo[3], hi[3];
    for (int d = 0; d < 3; ++d) {
      lo[d] = coord(x[d] - range);
      hi[d] = coord(x[d] + range);
    }
    for (std::int64_t i = lo[0]; i <= hi[0]; ++i)
      for (std::int64_t j = lo[1]; j <= hi[1]; ++j)
        for (std::int64_t k = lo[2]; k <= hi[2]; ++k) {
          auto it = cells_.find(key(i, j, k));
          if (it == cells_.end()) continue;
          for (int item : it->second) f(item);
        }
  }

private:
  std::int64_t coord(double v) const
  {
    return static_cast<std::int64_t>(std::floor(v * inv_cell_));
  }
  static std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k);

  double inv_cell_;
  std::unordered_map<std::uint64_t, std::vector<int>> cells_;
};

}    // namespace reinforce
