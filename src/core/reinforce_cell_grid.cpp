#include "reinforce_cell_grid.h"

namespace reinforce {

namespace {
constexpr int kInitialBits = 6;
}

CellGrid::CellGrid(double cell_size)
    : shift_(64 - kInitialBits), slot_cell_(std::size_t{1} << kInitialBits, -1)
{
  // A size that is not positive and finite (or so small that its inverse
  // overflows) puts every item in one cell: queries stay right, only slower.
  const double inverse = 1.0 / cell_size;
  inv_cell_ = cell_size > 0 && std::isfinite(cell_size) && std::isfinite(inverse) ? inverse : 0.0;
}

// The cell of `key`, made empty if it was not there. The table is kept at
// most half full, so probes stay short.
std::vector<int> &CellGrid::cell(std::uint64_t key)
{
  int c = find_cell(key);
  if (c >= 0) return cell_items_[c];
  c = static_cast<int>(cell_key_.size());
  cell_key_.push_back(key);
  cell_items_.emplace_back();
  if (2 * cell_key_.size() <= slot_cell_.size()) {
    put_in_table(c);
  } else {
    --shift_;    // twice the slots, every cell hashed again
    slot_cell_.assign(slot_cell_.size() * 2, -1);
    for (int k = 0; k <= c; ++k) put_in_table(k);
  }
  return cell_items_[c];
}

void CellGrid::put_in_table(int c)
{
  std::size_t s = slot_of(cell_key_[c]);
  while (slot_cell_[s] >= 0) s = (s + 1) & (slot_cell_.size() - 1);
  slot_cell_[s] = c;
}

void CellGrid::insert(Vec3 x, int item)
{
  cell(key(coord(x.x), coord(x.y), coord(x.z))).push_back(item);
}

void CellGrid::insert_around(Vec3 x, int item)
{
  const std::int64_t i = coord(x.x), j = coord(x.y), k = coord(x.z);
  for (std::int64_t a = i - 1; a <= i + 1; ++a)
    for (std::int64_t b = j - 1; b <= j + 1; ++b)
      for (std::int64_t c = k - 1; c <= k + 1; ++c) cell(key(a, b, c)).push_back(item);
}

void CellGrid::insert_in_cell(std::int64_t i, std::int64_t j, std::int64_t k, int item)
{
  cell(key(i, j, k)).push_back(item);
}

void CellGrid::erase(Vec3 x, int item)
{
  const int c = find_cell(key(coord(x.x), coord(x.y), coord(x.z)));
  if (c < 0) return;
  std::vector<int> &items = cell_items_[c];
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
// key share a cell; the callers' exact distance test keeps the answer right.
std::uint64_t CellGrid::key(std::int64_t i, std::int64_t j, std::int64_t k)
{
  const std::uint64_t mask = (1u << 21) - 1;
  return (static_cast<std::uint64_t>(i) & mask) | ((static_cast<std::uint64_t>(j) & mask) << 21) |
         ((static_cast<std::uint64_t>(k) & mask) << 42);
}

}    // namespace reinforce
