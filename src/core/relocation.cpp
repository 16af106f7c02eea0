#include "relocation.h"

#include "cell_grid.h"
#include "tangent_sphere.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace reinforce {

namespace {

constexpr double kPi = 3.14159265358979323846;

double ball_volume(double r)
{
  return 4.0 / 3.0 * kPi * r * r * r;
}

struct Candidate {
  double gap;
  std::int64_t id;
  int index;
  bool operator<(const Candidate &o) const
  {
    if (gap != o.gap) return gap < o.gap;
    if (id != o.id) return id < o.id;
    return index < o.index;
  }
};

// The spheres a process sees while it relocates: the particles, then the
// relocated spheres and their periodic images as they are added.
class View {
public:
  View(const std::vector<Particle> &particles, double cell) : grid_(cell)
  {
    for (const Particle &p : particles) add(p.x, p.r, p.id, p.role != Role::Target);
  }

  int add(Vec3 x, double r, std::int64_t id, bool present)
  {
    const int index = static_cast<int>(x_.size());
    x_.push_back(x);
    r_.push_back(r);
    id_.push_back(id);
    present_.push_back(present);
    grid_.insert(x, index);
    return index;
  }

  // True when sphere (c, r) overlaps no present sphere by more than
  // tol * min of the two radii; `deepest` gets its largest overlap (length).
  bool fits(Vec3 c, double r, double largest_r, double tol, double &deepest) const
  {
    bool ok = true;
    deepest = 0;
    grid_.for_each_near(c, r + largest_r, [&](int j) {
      if (!ok || !present_[j]) return;
      const double overlap = r + r_[j] - norm(c - x_[j]);
      deepest = std::max(deepest, overlap);
      ok = overlap <= tol * std::min(r, r_[j]);
    });
    return ok;
  }

  std::vector<Candidate> candidates(Vec3 x, double r, double search, double largest_r) const
  {
    std::vector<Candidate> out;
    grid_.for_each_near(x, r + search + largest_r, [&](int j) {
      if (!present_[j]) return;
      const double gap = norm(x_[j] - x) - r_[j] - r;
      if (gap <= search) out.push_back({gap, id_[j], j});
    });
    std::sort(out.begin(), out.end());
    return out;
  }

  Sphere sphere(int j) const { return {x_[j], r_[j]}; }
  void set_present(int j) { present_[j] = true; }

private:
  CellGrid grid_;
  std::vector<Vec3> x_;
  std::vector<double> r_;
  std::vector<std::int64_t> id_;
  std::vector<bool> present_;
};

// Calls f(a, b, c, d) for the groups of four of [0, n) in colex order (all
// groups of the k nearest before any group using the (k+1)-th), at most
// `limit` groups or until f returns true.
template <class F> void for_each_group(int n, int limit, F &&f)
{
  int done = 0;
  for (int d = 3; d < n; ++d)
    for (int c = 2; c < d; ++c)
      for (int b = 1; b < c; ++b)
        for (int a = 0; a < b; ++a) {
          if (done++ >= limit || f(a, b, c, d)) return;
        }
}

bool admissible(Vec3 c, double r, const Domain &domain)
{
  for (int d = 0; d < 3; ++d)
    if (!domain.periodic[d] && (c[d] - r < domain.lo[d] || c[d] + r > domain.hi[d])) return false;
  return !domain.region || domain.region(c);
}

}    // namespace

void Stats::add(const Stats &o)
{
  targets += o.targets;
  relocated += o.relocated;
  unplaced += o.unplaced;
  volume_before += o.volume_before;
  volume_after += o.volume_after;
  max_overlap = std::max(max_overlap, o.max_overlap);
  solves += o.solves;
}

double required_reach(const Settings &s, double target_rmax, double largest_r)
{
  // A new centre stays within target_r + search of the old one, and must be
  // checked against every sphere within rmax + largest_r of it.
  return target_rmax + s.search + s.rmax + largest_r;
}

bool spheres_overlap(Vec3 a, double ra, Vec3 b, double rb, double tol)
{
  return ra + rb - norm(a - b) > tol * std::min(ra, rb);
}

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
  // One query box spans at most two cells per dimension.
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
  double rebar_r = 0;
  for (const Particle &p : particles)
    if (p.role == Role::Rebar) rebar_r = std::max(rebar_r, p.r);
  if (!(rebar_r > 0)) return out;
  CellGrid grid(2 * rebar_r);
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
  for (const Particle &p : particles) r_max = std::max(r_max, p.r);
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
      const double overlap = p.r + q.r - norm(p.x - q.x);
      if (overlap > tol * std::min(p.r, q.r)) {
        ++pairs;
        largest = std::max(largest, overlap / rmin);
      }
    });
  }
  return pairs;
}

std::vector<Placement> relocate_targets(const std::vector<Particle> &particles,
                                        const Settings &settings, const Domain &domain,
                                        bool keep_unplaced, Stats &stats)
{
  std::vector<std::size_t> targets;
  std::unordered_map<std::int64_t, std::vector<int>> copies;    // vacant atoms by id
  double largest_r = settings.rmax;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Particle &p = particles[i];
    largest_r = std::max(largest_r, p.r);
    if (p.role != Role::Target) continue;
    copies[p.id].push_back(static_cast<int>(i));
    if (p.owned) targets.push_back(i);
  }
  std::vector<Placement> placements;
  if (targets.empty()) return placements;
  std::sort(targets.begin(), targets.end(), [&](std::size_t a, std::size_t b) {
    return particles[a].id != particles[b].id ? particles[a].id < particles[b].id : a < b;
  });

  View view(particles, 2 * largest_r);
  Vec3 period;
  for (int d = 0; d < 3; ++d) period[d] = domain.hi[d] - domain.lo[d];

  for (std::size_t t : targets) {
    const Particle &target = particles[t];
    stats.targets++;
    stats.volume_before += ball_volume(target.r);

    const std::vector<Candidate> near =
        view.candidates(target.x, target.r, settings.search, largest_r);
    const double max_shift = target.r + settings.search;
    Placement best;
    best.index = t;
    double best_score = INFINITY, best_overlap = 0;

    for_each_group(static_cast<int>(near.size()), settings.tries, [&](int a, int b, int c, int d) {
      const Sphere group[4] = {view.sphere(near[a].index), view.sphere(near[b].index),
                               view.sphere(near[c].index), view.sphere(near[d].index)};
      Sphere found[2];
      const int nfound = tangent_spheres_inversion(group, found, settings.newton_steps);
      stats.solves++;
      for (int k = 0; k < nfound; ++k) {
        const Sphere &s = found[k];
        if (s.r < settings.rmin || s.r > settings.rmax) continue;
        if (norm(s.c - target.x) > max_shift || !admissible(s.c, s.r, domain)) continue;
        const double score = settings.choice == Choice::Closest ? std::fabs(s.r - target.r) : 0.0;
        if (score >= best_score) continue;
        double deepest;
        if (!view.fits(s.c, s.r, largest_r, settings.tol, deepest)) continue;
        best.placed = true;
        best.x = s.c;
        best.r = s.r;
        best_score = score;
        best_overlap = deepest / settings.rmin;
      }
      return best.placed && settings.choice == Choice::First;
    });

    if (best.placed) {
      stats.relocated++;
      stats.volume_after += ball_volume(best.r);
      stats.max_overlap = std::max(stats.max_overlap, best_overlap);
      view.add(best.x, best.r, target.id, true);
      // Periodic images the host would make ghosts of, inside this view.
      for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j)
          for (int k = -1; k <= 1; ++k) {
            const int shift[3] = {i, j, k};
            Vec3 image = best.x;
            bool skip = (i == 0 && j == 0 && k == 0);
            for (int dim = 0; dim < 3 && !skip; ++dim) {
              skip = shift[dim] != 0 && !domain.periodic[dim];
              image[dim] += shift[dim] * period[dim];
              skip = skip || image[dim] < domain.view_lo[dim] || image[dim] > domain.view_hi[dim];
            }
            if (!skip) view.add(image, best.r, target.id, true);
          }
    } else {
      stats.unplaced++;
      if (keep_unplaced)
        for (int copy : copies[target.id]) view.set_present(copy);
    }
    placements.push_back(best);
  }
  return placements;
}

}    // namespace reinforce
