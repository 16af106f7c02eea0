// Geometry of the placement domain: what it admits, wrapping a centre into
// the box and the images of a sphere a process's view holds, as the host's
// own ghosts would be (declared in reinforce_domain.h).
#include "reinforce_domain.h"

#include <cmath>

namespace reinforce {

bool admissible(Vec3 from, Vec3 c, double r, const Domain &domain, double tol)
{
  if (!is_finite(c) || !std::isfinite(r)) return false;
  // The box faces as before: a new sphere wholly inside them.
  for (int d = 0; d < 3; ++d)
    if (!domain.periodic[d] && (c[d] - r < domain.lo[d] || c[d] + r > domain.hi[d])) return false;
  const double inner = r * (1 - tol);
  if (domain.region && !domain.region(wrapped_into_box(c, domain), inner)) return false;
  return !domain.walls || domain.walls->admits(from, c, r, tol);
}

bool in_box(Vec3 x, const Domain &d)
{
  for (int k = 0; k < 3; ++k)
    if (d.periodic[k] && (x[k] < d.lo[k] || x[k] >= d.hi[k])) return false;
  return true;
}

bool in_subdomain(Vec3 x, const Domain &d)
{
  for (int k = 0; k < 3; ++k)
    if (x[k] < d.sub_lo[k] || x[k] >= d.sub_hi[k]) return false;
  return true;
}

Vec3 wrapped_into_box(Vec3 c, const Domain &domain)
{
  for (int d = 0; d < 3; ++d) {
    if (!domain.periodic[d]) continue;
    const double period = domain.hi[d] - domain.lo[d];
    c[d] -= period * std::floor((c[d] - domain.lo[d]) / period);
    if (c[d] >= domain.hi[d]) c[d] = domain.lo[d];    // rounding at the top edge
  }
  return c;
}

std::vector<Vec3> images_in_view(Vec3 c, const Domain &domain, bool with_centre)
{
  std::vector<Vec3> out;
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        const int shift[3] = {i, j, k};
        if (!with_centre && i == 0 && j == 0 && k == 0) continue;
        Vec3 image = c;
        bool inside = true;
        for (int d = 0; d < 3 && inside; ++d) {
          inside = shift[d] == 0 || domain.periodic[d];
          image[d] += shift[d] * (domain.hi[d] - domain.lo[d]);
          inside = inside && image[d] >= domain.view_lo[d] && image[d] <= domain.view_hi[d];
        }
        if (inside) out.push_back(image);
      }
  return out;
}

}    // namespace reinforce
