// Passes over a host's atoms or a process's view before the relocation:
// the spheres near the bars, the targets, the overlaps the packing already
// has.
#include "reinforce_packing_scan.h"

#include "reinforce_cell_grid.h"

#include <algorithm>
#include <cmath>

namespace reinforce {

std::vector<int> spheres_near_rebar(int n, const double *const *x, const double *radius,
                                    const unsigned char *is_rebar, double margin)
{
  std::vector<int> rebar;
  double rebar_r = 0, any_r = 0;
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (int i = 0; i < n; ++i) {
    any_r = std::max(any_r, radius[i]);
    if (!is_rebar[i]) continue;
    rebar.push_back(i);
    rebar_r = std::max(rebar_r, radius[i]);
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], x[i][d]);
      hi[d] = std::max(hi[d], x[i][d]);
    }
  }
  std::vector<int> out;
  if (rebar.empty()) return out;
  // Cells as wide as the query reach, so one query spans at most two cells
  // per dimension however thin the rebar.
  const double range = margin + any_r + rebar_r;
  CellGrid grid(2 * range);
  for (int i : rebar) grid.insert({x[i][0], x[i][1], x[i][2]}, i);
  for (int i = 0; i < n; ++i) {
    const Vec3 xi{x[i][0], x[i][1], x[i][2]};
    if (is_rebar[i]) {
      out.push_back(i);
      continue;
    }
    bool outside = false;
    for (int d = 0; d < 3; ++d) outside |= xi[d] < lo[d] - range || xi[d] > hi[d] + range;
    if (outside) continue;
    bool near = false;
    grid.for_each_near(xi, margin + radius[i] + rebar_r, [&](int b) {
      if (!near) {
        const Vec3 xb{x[b][0], x[b][1], x[b][2]};
        near = norm(xb - xi) - radius[b] - radius[i] <= margin;
      }
    });
    if (near) out.push_back(i);
  }
  return out;
}

std::vector<std::size_t> find_targets(const std::vector<Particle> &particles, double tol)
{
  std::vector<std::size_t> out;
  double rebar_r = 0, other_r = 0;
  for (const Particle &p : particles)
    (p.role == Role::Rebar ? rebar_r : other_r) =
        std::max(p.role == Role::Rebar ? rebar_r : other_r, p.r);
  if (!(rebar_r > 0)) return out;
  // Cells sized by the query (matrix radius + rebar radius), not by the
  // rebar alone: thin fibres would make each query span many cells.
  CellGrid grid(rebar_r + other_r);
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (particles[i].role == Role::Rebar) grid.insert(particles[i].x, static_cast<int>(i));
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Particle &p = particles[i];
    if (!p.owned || p.role == Role::Rebar) continue;
    bool hit = false;
    grid.for_each_near(p.x, p.r + rebar_r, [&](int b) {
      hit = hit || spheres_overlap(p.x, p.r, particles[b].x, particles[b].r, tol);
    });
    if (hit) out.push_back(i);
  }
  return out;
}

std::int64_t count_packing_overlaps(const std::vector<Particle> &particles, double tol, double rmin,
                                    double &largest)
{
  largest = 0;
  double r_max = 0;
  for (const Particle &p : particles)
    if (p.role != Role::Rebar) r_max = std::max(r_max, p.r);
  if (!(r_max > 0)) return 0;
  CellGrid grid(2 * r_max);
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (particles[i].role != Role::Rebar) grid.insert(particles[i].x, static_cast<int>(i));
  std::int64_t pairs = 0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Particle &p = particles[i];
    if (!p.owned || p.role == Role::Rebar) continue;
    grid.for_each_near(p.x, p.r + r_max, [&](int j) {
      const Particle &q = particles[j];
      // Once per pair: an owned partner by index, a ghost by id (its owner
      // counts the pair when its id is the lower one); never an image of p.
      if (q.id == p.id || (q.owned ? j <= static_cast<int>(i) : q.id < p.id)) return;
      if (p.other_rebar || q.other_rebar) return;
      const double overlap = p.r + q.r - norm(p.x - q.x);
      if (overlap > tol * std::min(p.r, q.r)) {
        ++pairs;
        largest = std::max(largest, overlap / rmin);
      }
    });
  }
  return pairs;
}

}    // namespace reinforce
