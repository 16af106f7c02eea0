#include "reinforce_rearrangement.h"

#include <algorithm>
#include <cmath>

namespace reinforce {

Rearrangement::Rearrangement(Scene &scene, const Settings &s, const Domain &domain, Stats &stats)
    : scene_(scene), s_(s), domain_(domain), stats_(stats)
{
}

int Rearrangement::make_room(Vec3 c, Vec3 x0, double r0, std::int64_t id,
                             std::map<std::int64_t, Vec3> &pushes, std::vector<int> &touched)
{
  fresh_ = scene_.add(c, r0, id, true, true);
  centre_ = c;
  reach_ = r0 + 2 * s_.rmax;    // pushed spheres start this close to c
  start_.clear();
  moved_.clear();
  std::vector<int> active{fresh_};
  int sweep = 0;
  for (;; ++sweep) {
    if (sweep == kMaxSweeps) {
      stats_.sweeps += sweep;
      return undo();
    }
    std::vector<int> next;
    if (!push_apart(active, next)) {
      stats_.sweeps += sweep + 1;
      return undo();
    }
    back_into_box(next);
    if (next.empty()) break;
    if (!within_bounds(id)) {
      stats_.sweeps += sweep + 1;
      return undo();
    }
    std::sort(next.begin(), next.end(), [&](int a, int b) {
      return same_order_everywhere(scene_.id(a), scene_.x(a), scene_.id(b), scene_.x(b));
    });
    next.erase(std::unique(next.begin(), next.end()), next.end());
    active.swap(next);
  }
  stats_.sweeps += sweep + 1;
  if (!accepted(x0, r0)) return undo();
  // Accepted: what moved is checked once more at the end, and the pushes.
  for (const auto &entry : start_) touched.push_back(entry.first);
  for (const auto &[mid, dx] : moved_) {
    if (mid == id) continue;
    stats_.pushed++;
    Vec3 &p = pushes[mid];
    p = p + dx;
  }
  return fresh_;
}

Vec3 Rearrangement::origin(int j) const
{
  auto it = start_.find(j);
  return it == start_.end() ? scene_.x(j) : it->second;
}

// With a region, only spheres wholly inside it are pushed (and they must
// end inside it: accepted()).
bool Rearrangement::inside_region(Vec3 x, double r) const
{
  return !domain_.region || domain_.region(wrapped_into_box(x, domain_), r * (1 - s_.tol));
}

bool Rearrangement::movable(int j) const
{
  return j == fresh_ || (scene_.pushable(j) && norm(origin(j) - centre_) <= reach_ &&
                         inside_region(origin(j), scene_.r(j)));
}

void Rearrangement::shift(int j, Vec3 dx)
{
  for (int k : scene_.copies(scene_.id(j)))
    if (!start_.count(k)) start_[k] = scene_.x(k);
  scene_.shift(j, dx);
  Vec3 &m = moved_[scene_.id(j)];
  m = m + dx;
}

int Rearrangement::undo()
{
  for (const auto &[k, x] : start_) scene_.place(k, x);
  scene_.remove(fresh_);
  return -1;
}

bool Rearrangement::push_apart(const std::vector<int> &active, std::vector<int> &next)
{
  // Pushed until exact but for rounding (whatever tol), each push
  // separating the pair by tol / 2 of the smaller radius beyond contact.
  const double limit = kPushedClear, gap = 0.5 * s_.tol;
  for (int i : active) {
    for (int j : scene_.overlapping(i, limit)) {
      const double ri = scene_.r(i), rj = scene_.r(j);
      Vec3 n = scene_.x(j) - scene_.x(i);
      const double dist = norm(n);
      const double depth = ri + rj - dist;
      if (!(depth > limit * std::min(ri, rj))) continue;    // an earlier push resolved it
      const bool mi = movable(i), mj = movable(j);
      if (!mi && !mj) return false;
      n = dist > 0 ? (1 / dist) * n : Vec3{1, 0, 0};
      const double amount = depth + gap * std::min(ri, rj);
      const double vi = ri * ri * ri, vj = rj * rj * rj;
      const double share_i = mi ? (mj ? vj / (vi + vj) : 1.0) : 0.0;
      if (share_i > 0) shift(i, -(share_i * amount) * n);
      if (share_i < 1) shift(j, ((1 - share_i) * amount) * n);
      if (mi) next.push_back(i);
      if (share_i < 1) next.push_back(j);
    }
  }
  return true;
}

// The box faces: a moved sphere goes back inside them.
void Rearrangement::back_into_box(const std::vector<int> &moved)
{
  const double gap = 0.5 * s_.tol;
  for (int i : moved)
    for (int d = 0; d < 3; ++d) {
      if (domain_.periodic[d]) continue;
      const double r = scene_.r(i), x = scene_.x(i)[d];
      Vec3 dx;
      if (x - r < domain_.lo[d]) dx[d] = domain_.lo[d] + r * (1 + gap) - x;
      if (x + r > domain_.hi[d]) dx[d] = domain_.hi[d] - r * (1 + gap) - x;
      if (dx[d] != 0) shift(i, dx);
    }
}

// How far and how many.
bool Rearrangement::within_bounds(std::int64_t id) const
{
  for (const auto &[mid, dx] : moved_)
    if (mid != id && norm(dx) > s_.push) return false;
  return moved_.size() <= kMaxPushed + 1;
}

// The new sphere near the target's old centre, and every moved sphere
// inside the box, the region and clear of the walls, from where it started.
bool Rearrangement::accepted(Vec3 x0, double r0) const
{
  const Vec3 final_c = scene_.x(fresh_);
  if (norm(final_c - x0) > r0 + s_.search || !admissible(x0, final_c, r0, domain_, s_.tol))
    return false;
  for (const auto &[k, before] : start_)
    if (!admissible(before, scene_.x(k), scene_.r(k), domain_, s_.tol)) return false;
  return true;
}

}    // namespace reinforce
