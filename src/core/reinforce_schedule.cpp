#include "reinforce_schedule.h"

#include <algorithm>
#include <cmath>

namespace reinforce {

BlockLattice make_block_lattice(Vec3 lo, Vec3 hi, const bool periodic[3], double min_width)
{
  BlockLattice l;
  l.lo = lo;
  for (int d = 0; d < 3; ++d) {
    const double length = hi[d] - lo[d];
    const double fit = min_width > 0 ? std::floor(length / min_width) : 1.0;
    int n = fit >= 1 << 20 ? 1 << 20 : std::max(1, static_cast<int>(fit));
    if (periodic[d] && n % 2 == 1 && n > 1) --n;
    l.count[d] = n;
    l.width[d] = length / n;
    l.colours[d] = n > 1 ? 2 : 1;
  }
  return l;
}

void BlockLattice::block_of(Vec3 x, int b[3]) const
{
  for (int d = 0; d < 3; ++d) {
    const double k = std::floor((x[d] - lo[d]) / width[d]);
    b[d] = k < 0 ? 0 : (k >= count[d] ? count[d] - 1 : static_cast<int>(k));
  }
}

int BlockLattice::colour_of(Vec3 x) const
{
  int b[3];
  block_of(x, b);
  return (b[0] % colours[0]) +
         colours[0] * ((b[1] % colours[1]) + colours[1] * (b[2] % colours[2]));
}

Vec3 BlockLattice::centre_of(Vec3 x) const
{
  int b[3];
  block_of(x, b);
  Vec3 c;
  for (int d = 0; d < 3; ++d) c[d] = lo[d] + (b[d] + 0.5) * width[d];
  return c;
}

double BlockLattice::reach_beyond(Vec3 sub_lo, Vec3 sub_hi) const
{
  double reach = 0;
  for (int d = 0; d < 3; ++d) {
    if (!(width[d] > 0)) continue;
    // The blocks whose centres lie in [sub_lo, sub_hi), tested as
    // centre_of() and in_subdomain() compute them, from a guess one block
    // wider on each side.
    const int from = std::max(0, static_cast<int>(std::floor((sub_lo[d] - lo[d]) / width[d])) - 1);
    const int to =
        std::min(count[d] - 1, static_cast<int>(std::floor((sub_hi[d] - lo[d]) / width[d])) + 1);
    for (int k = from; k <= to; ++k) {
      const double centre = lo[d] + (k + 0.5) * width[d];
      if (!(centre >= sub_lo[d] && centre < sub_hi[d])) continue;
      reach = std::max(
          {reach, sub_lo[d] - (lo[d] + k * width[d]), lo[d] + (k + 1) * width[d] - sub_hi[d]});
    }
  }
  return reach;
}

}    // namespace reinforce
