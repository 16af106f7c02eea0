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
