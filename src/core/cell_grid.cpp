#include "cell_grid.h"

#include <stdexcept>

namespace reinforce {

CellGrid::CellGrid(double cell_size)
{
  if (!(cell_size > 0) || !std::isfinite(cell_size))
    throw std::invalid_argument("CellGrid: cell size must be positive and finite");
  inv_cell_ = 1.0 / cell_size;
}

void CellGrid::insert(Vec3 x, int item)
{
  cells_[key(coord(x.x), coord(x.y), coord(x.z))].push_back(item);
}

void CellGrid::erase(Vec3 x, int item)
{
  auto it = cells_.find(key(coord(x.x), coord(x.y), coord(x.z)));
  if (it == cells_.end()) return;
  std::vector<int> &items = it->second;
  for (std::size_t k = 0; k < items.size(); ++k)
    if (items[k] == item) {
      items.erase(items.begin() + static_cast<std::ptrdiff_t>(k));
      break;
    }
}

void CellGrid::move(Vec3 from, Vec3 to, int item)
{
  if (coord(from.x) == coord(to.x) && coord(from.y) == coord(to.y) && coord(from.z) == coord(to.z))
    return;
  erase(from, item);
  insert(to, item);
}

// Cell coordinates are wrapped to 21 bits each. Distinct cells that share a
// key only share a bucket; the callers' exact distance test keeps the answer
// right.
std::uint64_t CellGrid::key(std::int64_t i, std::int64_t j, std::int64_t k)
{
  const std::uint64_t mask = (1u << 21) - 1;
  return (static_cast<std::uint64_t>(i) & mask) | ((static_cast<std::uint64_t>(j) & mask) << 21) |
         ((static_cast<std::uint64_t>(k) & mask) << 42);
}

}    // namespace reinforce
