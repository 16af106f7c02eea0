#include "relocation.h"

#include "cell_grid.h"
#include "tangent_sphere.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace reinforce {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Rearrangement bounds (docs/design.md, "Making room"): sweeps over the
// pushed spheres, and voids tried per target before it counts as unplaced.
constexpr int kMaxSweeps = 40;
constexpr int kMaxAttempts = 2;
constexpr std::size_t kMaxPushed = 48;
// Rebar spheres among the candidates of one target, at most (the nearest).
constexpr int kMaxRebarCandidates = 3;

double ball_volume(double r)
{
  return 4.0 / 3.0 * kPi * r * r * r;
}

// Fixed sample points of the unit ball (a cubic lattice, 9 per axis, 389
// points): the volume fraction of a target inside the bars to about 1 %.
const std::vector<Vec3> &unit_ball_points()
{
  static const std::vector<Vec3> points = [] {
    std::vector<Vec3> p;
    const int n = 9;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          const Vec3 u{(2 * i + 1.0) / n - 1, (2 * j + 1.0) / n - 1, (2 * k + 1.0) / n - 1};
          if (norm2(u) <= 1) p.push_back(u);
        }
    return p;
  }();
  return points;
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

// A fixed order of spheres that does not depend on where they sit in a
// process's view: by id, then position (periodic images of one atom).
bool same_order_everywhere(std::int64_t ida, Vec3 a, std::int64_t idb, Vec3 b)
{
  if (ida != idb) return ida < idb;
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

// The smallest n with C(n, 4) >= tries: the colex enumeration of the first
// `tries` groups of four uses only the n nearest candidates.
std::size_t candidates_needed(int tries)
{
  double groups = 0;
  std::size_t n = 4;
  for (;; ++n) {
    groups = static_cast<double>(n) * (n - 1) * (n - 2) * (n - 3) / 24;
    if (groups >= tries) return n;
  }
}

// The smallest n with C(n, 3) >= tries.
std::size_t candidates_needed_for_triples(int tries)
{
  std::size_t n = 3;
  while (static_cast<double>(n) * (n - 1) * (n - 2) / 6 < tries) ++n;
  return n;
}

// Calls f(a, b, c) for the triples of [0, n) in colex order (all triples of
// the k nearest before any using the (k+1)-th), at most `limit` of them or
// until f returns true.
template <class F> void for_each_triple(int n, int limit, F &&f)
{
  int done = 0;
  for (int c = 2; c < n; ++c)
    for (int b = 1; b < c; ++b)
      for (int a = 0; a < b; ++a) {
        if (done++ >= limit || f(a, b, c)) return;
      }
}

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

// Surface gaps between the first n candidates, pair by pair (row-major,
// n x n): the groups and triples reuse each pair many times.
template <class SphereOf>
std::vector<double> pair_gaps(const std::vector<Candidate> &near, std::size_t n,
                              SphereOf &&sphere_of)
{
  std::vector<double> gap(n * n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      const Sphere a = sphere_of(near[i].index), b = sphere_of(near[j].index);
      gap[i * n + j] = gap[j * n + i] = norm(a.c - b.c) - a.r - b.r;
    }
  return gap;
}

// The spheres a process sees while it relocates: the particles, then the
// relocated spheres and their periodic images as they are added. Present
// spheres can be pushed; every copy of an atom moves with it.
class Scene {
public:
  Scene(const std::vector<Particle> &particles, double cell, double zone)
      : grid_(cell), largest_r_(0)
  {
    for (const Particle &p : particles) largest_r_ = std::max(largest_r_, p.r);
    for (const Particle &p : particles)
      add(p.x, p.r, p.id, p.role != Role::Target, p.role == Role::Matrix && p.pushable,
          p.role == Role::Rebar);
    // Only matrix spheres within `zone` of a bar may be pushed (none with
    // a negative zone: size fit pushes nothing).
    for (std::size_t i = 0; i < x_.size(); ++i)
      if (pushable_[i]) pushable_[i] = zone >= 0 && gap_to_rebar(x_[i], r_[i], zone) <= zone;
  }

  int add(Vec3 x, double r, std::int64_t id, bool present, bool pushable, bool rebar = false)
  {
    const int index = static_cast<int>(x_.size());
    x_.push_back(x);
    r_.push_back(r);
    id_.push_back(id);
    present_.push_back(present);
    pushable_.push_back(pushable);
    rebar_.push_back(rebar);
    grid_.insert(x, index);
    if (present && copies_built_) copies_[id].push_back(index);
    largest_r_ = std::max(largest_r_, r);
    return index;
  }

  // Takes a sphere out of the view (a failed attempt's new sphere).
  void remove(int j)
  {
    grid_.erase(x_[j], j);
    build_copies();
    present_[j] = false;
    std::vector<int> &c = copies_[id_[j]];
    c.erase(std::remove(c.begin(), c.end(), j), c.end());
  }

  void set_present(int j, bool pushable)
  {
    build_copies();
    present_[j] = true;
    pushable_[j] = pushable;
    copies_[id_[j]].push_back(j);
  }

  // Moves every present copy of sphere j's atom by dx.
  void shift(int j, Vec3 dx)
  {
    build_copies();
    for (int c : copies_[id_[j]]) place(c, x_[c] + dx);
  }
  void place(int j, Vec3 x)
  {
    grid_.move(x_[j], x, j);
    x_[j] = x;
  }

  // Smallest surface gap from sphere (x, r) to a rebar sphere, searched out
  // to `range` (beyond it: +infinity).
  double gap_to_rebar(Vec3 x, double r, double range) const
  {
    double best = INFINITY;
    grid_.for_each_near(x, r + range + largest_r_, [&](int b) {
      if (rebar_[b]) best = std::min(best, norm(x_[b] - x) - r_[b] - r);
    });
    return best;
  }

  // Volume fraction of sphere (x, r) inside the union of the rebar spheres.
  double fraction_in_rebar(Vec3 x, double r) const
  {
    std::vector<int> bars;
    grid_.for_each_near(x, r + largest_r_, [&](int b) {
      if (rebar_[b] && norm(x_[b] - x) < r + r_[b]) bars.push_back(b);
    });
    if (bars.empty()) return 0;
    const std::vector<Vec3> &points = unit_ball_points();
    std::size_t inside = 0;
    for (const Vec3 &u : points) {
      const Vec3 p = x + r * u;
      for (int b : bars)
        if (norm2(p - x_[b]) < r_[b] * r_[b]) {
          ++inside;
          break;
        }
    }
    return static_cast<double>(inside) / points.size();
  }

  // True when sphere (c, r) overlaps no present sphere by more than
  // tol * min of the two radii; `deepest` gets its largest overlap (length).
  bool fits(Vec3 c, double r, double tol, double &deepest, int skip_id = -1) const
  {
    bool ok = true;
    deepest = 0;
    grid_.for_each_near(c, r + largest_r_, [&](int j) {
      if (!ok || !present_[j] || id_[j] == skip_id) return;
      const double overlap = r + r_[j] - norm(c - x_[j]);
      deepest = std::max(deepest, overlap);
      ok = overlap <= tol * std::min(r, r_[j]);
    });
    return ok;
  }

  // Largest overlap (length) of sphere j with a present sphere of another
  // atom; with matrix_only, rebar spheres are left out.
  double deepest_overlap(int j, bool matrix_only = false) const
  {
    double deepest = 0;
    grid_.for_each_near(x_[j], r_[j] + largest_r_, [&](int k) {
      if (!present_[k] || id_[k] == id_[j] || (matrix_only && rebar_[k])) return;
      deepest = std::max(deepest, r_[j] + r_[k] - norm(x_[j] - x_[k]));
    });
    return deepest;
  }

  // Present spheres whose surface gap to sphere (x, r) is at most `search`,
  // nearest first, with at most `max_rebar` rebar spheres (the nearest): at
  // least the `wanted` nearest (all of them when fewer lie within
  // `search`). The query grows until it holds them, so its cost follows the
  // spheres found, not the gap asked. A thin bar is a chain of many small
  // spheres: left alone they would fill the list, and four beads of one
  // chain share only tangent spheres of their own size.
  std::vector<Candidate> candidates(Vec3 x, double r, double search, std::size_t wanted,
                                    int max_rebar) const
  {
    double range = r + 2 * largest_r_;
    for (;;) {
      const double complete = std::min(search, range - r - largest_r_);
      std::vector<Candidate> out;
      grid_.for_each_near(x, range, [&](int j) {
        if (!present_[j]) return;
        const double gap = norm(x_[j] - x) - r_[j] - r;
        if (gap <= complete) out.push_back({gap, id_[j], j});
      });
      std::sort(out.begin(), out.end());
      int rebar = 0;
      out.erase(std::remove_if(
                    out.begin(), out.end(),
                    [&](const Candidate &c) { return rebar_[c.index] && ++rebar > max_rebar; }),
                out.end());
      // Every view that holds the spheres within `complete` gives the same
      // list up to here: the answer does not depend on the process count.
      if (out.size() >= wanted || complete >= search) return out;
      range *= 2;
    }
  }

  // Present spheres overlapping sphere j by more than `limit` of the
  // smaller radius, in the same order on every process.
  std::vector<int> overlapping(int j, double limit) const
  {
    std::vector<int> out;
    grid_.for_each_near(x_[j], r_[j] + largest_r_, [&](int k) {
      if (k == j || !present_[k] || id_[k] == id_[j]) return;
      if (r_[j] + r_[k] - norm(x_[j] - x_[k]) > limit * std::min(r_[j], r_[k])) out.push_back(k);
    });
    std::sort(out.begin(), out.end(),
              [&](int a, int b) { return same_order_everywhere(id_[a], x_[a], id_[b], x_[b]); });
    return out;
  }

  Sphere sphere(int j) const { return {x_[j], r_[j]}; }
  Vec3 x(int j) const { return x_[j]; }
  double r(int j) const { return r_[j]; }
  std::int64_t id(int j) const { return id_[j]; }
  bool pushable(int j) const { return pushable_[j]; }
  const std::vector<int> &copies(std::int64_t id)
  {
    build_copies();
    return copies_[id];
  }

private:
  CellGrid grid_;
  double largest_r_;
  std::vector<Vec3> x_;
  std::vector<double> r_;
  std::vector<std::int64_t> id_;
  std::vector<bool> present_, pushable_, rebar_;
  // Present copies by id, built on first use: only pushing and kept targets
  // need them, and building them for every sphere of every round costs more
  // than the relocation of a small round.
  std::unordered_map<std::int64_t, std::vector<int>> copies_;
  bool copies_built_ = false;
  void build_copies()
  {
    if (copies_built_) return;
    copies_built_ = true;
    for (std::size_t i = 0; i < x_.size(); ++i)
      if (present_[i]) copies_[id_[i]].push_back(static_cast<int>(i));
  }
};

// Radii a search still wants: [lo, hi].
struct RadiusRange {
  double lo, hi;
};

// A place for a target: the centre of a sphere tangent to four present
// spheres that overlaps none (a void), with that sphere's radius.
struct Void {
  Vec3 c;
  double r;
  double score;    // lower is better
};

// One target's relocation, given the scene and the settings.
class Relocator {
public:
  Relocator(Scene &scene, const Settings &s, const Domain &domain, Stats &stats)
      : scene_(scene), s_(s), domain_(domain), stats_(stats)
  {
  }

  // Spheres placed or moved so far (indices; repeats allowed).
  std::vector<int> touched;

  // Places the target at index t, or returns -1. On success the index of the
  // new sphere's primary copy.
  int relocate(int t, std::map<std::int64_t, Vec3> &pushes)
  {
    const Vec3 x0 = scene_.x(t);
    const double r0 = scene_.r(t);
    const std::int64_t id = scene_.id(t);
    if (s_.size == SizeMode::Keep) {
      // Its own radius, in a void that holds it as it is;
      Void own;
      if (own_size_void(x0, r0, own)) return commit(scene_.add(own.c, r0, id, true, true));
      // with `push`, where room can be made: first its own place, pushed
      // out of the bars, its neighbours pushed on (it was part of the
      // packing, so that disturbs least), then the voids the inversion
      // finds nearby;
      if (s_.push > 0) {
        const int in_place = make_room(x0, x0, r0, id, pushes);
        if (in_place >= 0) return commit(in_place);
        for (const Void &v : find_voids(x0, r0)) {
          const int fresh = make_room(v.c, x0, r0, id, pushes);
          if (fresh >= 0) return commit(fresh);
        }
      }
    }
    // else the seed paper's placement, in the void it fits.
    Void v;
    if (!best_fit(x0, r0, v)) return -1;
    return commit(scene_.add(v.c, v.r, id, true, true));
  }

private:
  Scene &scene_;
  const Settings &s_;
  const Domain &domain_;
  Stats &stats_;

  // Runs the kernel over the groups of four nearest candidates of the
  // target's old sphere; calls take(solution) for each solution whose
  // radius lies in the range wanted() gives (asked again after each take,
  // so a caller that found a good solution narrows the search), whose
  // centre is within the shift bound and that overlaps none of the
  // candidates; stops when take returns true.
  template <class Range, class F>
  void for_each_solution(Vec3 x0, double r0, Range &&wanted, F &&take)
  {
    const std::vector<Candidate> near =
        scene_.candidates(x0, r0, s_.search, candidates_needed(s_.tries), kMaxRebarCandidates);
    const double max_shift = r0 + s_.search;
    RadiusRange radii = wanted();
    // Before the Newton polish, the same tests with room for what the
    // polish may move (kAcceptResidual of the radius): most solutions fail
    // them, and are not polished.
    const double slack = kAcceptResidual;
    const std::function<bool(const Sphere &)> worth_polishing = [&](const Sphere &sol) {
      return sol.r >= radii.lo * (1 - slack) && sol.r <= radii.hi * (1 + slack) &&
             norm(sol.c - x0) <= max_shift + slack * sol.r &&
             !overlaps_one_of(near, sol.c, sol.r, slack * sol.r);
    };
    // The first `tries` groups use only the nearest candidates_needed(tries).
    const std::size_t n = std::min(near.size(), candidates_needed(s_.tries));
    const std::vector<double> gap = pair_gaps(near, n, [&](int j) { return scene_.sphere(j); });
    for_each_group(static_cast<int>(n), s_.tries, [&](int a, int b, int c, int d) {
      // Two spheres whose gap exceeds 2 rho share no tangent sphere of
      // radius rho or less: skip the solve.
      const int member[4] = {a, b, c, d};
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          if (gap[member[i] * n + member[j]] > 2 * radii.hi) return false;
      const Sphere group[4] = {scene_.sphere(near[a].index), scene_.sphere(near[b].index),
                               scene_.sphere(near[c].index), scene_.sphere(near[d].index)};
      Sphere found[2];
      const int nfound = tangent_spheres_inversion(group, found, s_.newton_steps, worth_polishing);
      stats_.solves++;
      for (int k = 0; k < nfound; ++k) {
        const Sphere &sol = found[k];
        if (!(sol.r > 0) || sol.r < radii.lo || sol.r > radii.hi || norm(sol.c - x0) > max_shift)
          continue;
        if (overlaps_one_of(near, sol.c, sol.r)) continue;    // take() would reject it too
        if (take(sol)) return true;
        radii = wanted();
      }
      return false;
    });
  }

  // True when sphere (c, r) overlaps one of the candidates by more than
  // tol (the test of Scene::fits) plus `slack` (a length): most solutions
  // fail on the nearest spheres, and this list is shorter than a grid query.
  bool overlaps_one_of(const std::vector<Candidate> &near, Vec3 c, double r, double slack = 0) const
  {
    for (const Candidate &q : near) {
      const double rq = scene_.r(q.index);
      if (r + rq - norm(c - scene_.x(q.index)) > s_.tol * std::min(r, rq) + slack) return true;
    }
    return false;
  }

  // A place for a sphere of the target's own radius r0: tangent to three
  // present spheres among the candidates of its old sphere (the kernel of
  // centres_tangent_to_three), wholly admissible, overlapping nothing, its
  // centre within r0 + search of the old one; the nearest to the old centre
  // of the first `tries` triples.
  bool own_size_void(Vec3 x0, double r0, Void &best)
  {
    const std::vector<Candidate> near = scene_.candidates(
        x0, r0, s_.search, candidates_needed_for_triples(s_.tries), kMaxRebarCandidates);
    const double max_shift = r0 + s_.search;
    const std::size_t n = std::min(near.size(), candidates_needed_for_triples(s_.tries));
    const std::vector<double> gap = pair_gaps(near, n, [&](int j) { return scene_.sphere(j); });
    // A centre tangent to candidate i is at least its gap from x0 (less the
    // kernel's 1e-9 (r0 + r_i), doubled for the rounding of the gap): with
    // the candidates nearest first, once the newest one of a triple is that
    // far, no later triple can beat the best.
    double largest_r = 0;
    for (const Candidate &q : near) largest_r = std::max(largest_r, scene_.r(q.index));
    const double margin = 2e-9 * (r0 + largest_r);
    best.score = INFINITY;
    for_each_triple(static_cast<int>(n), s_.tries, [&](int a, int b, int c) {
      if (near[c].gap - margin >= best.score) return true;
      // Two spheres whose gap exceeds 2 r0 cannot both touch it.
      if (gap[a * n + b] > 2 * r0 || gap[a * n + c] > 2 * r0 || gap[b * n + c] > 2 * r0)
        return false;
      const Sphere group[3] = {scene_.sphere(near[a].index), scene_.sphere(near[b].index),
                               scene_.sphere(near[c].index)};
      Vec3 found[2];
      const int nfound = centres_tangent_to_three(group, r0, found);
      stats_.solves++;
      for (int k = 0; k < nfound; ++k) {
        const double shift = norm(found[k] - x0);
        if (shift > max_shift || shift >= best.score || !admissible(x0, found[k], r0, domain_, s_.tol) ||
            overlaps_one_of(near, found[k], r0))
          continue;
        double deepest;
        if (scene_.fits(found[k], r0, s_.tol, deepest)) best = {found[k], r0, shift};
      }
      return false;
    });
    return best.score < INFINITY;
  }

  // The seed paper's placement: a tangent sphere with its radius in
  // [rmin, rmax] that overlaps nothing; first found or closest in radius.
  bool best_fit(Vec3 x0, double r0, Void &best)
  {
    bool found = false;
    best.score = INFINITY;
    // With choose closest, once a void is found only radii closer to r0
    // can do better: the search narrows to them.
    auto wanted = [&]() {
      if (s_.choice != Choice::Closest || !found) return RadiusRange{s_.rmin, s_.rmax};
      return RadiusRange{std::max(s_.rmin, r0 - best.score), std::min(s_.rmax, r0 + best.score)};
    };
    for_each_solution(x0, r0, wanted, [&](const Sphere &sol) {
      if (sol.r < s_.rmin || !admissible(x0, sol.c, sol.r, domain_, s_.tol)) return false;
      const double score = s_.choice == Choice::Closest ? std::fabs(sol.r - r0) : 0.0;
      double deepest;
      if (score >= best.score || !scene_.fits(sol.c, sol.r, s_.tol, deepest)) return false;
      best = {sol.c, sol.r, score};
      found = true;
      return s_.choice == Choice::First;
    });
    return found;
  }

  // Voids near the target, best first: for `choose closest` the ones whose
  // radius is closest to the target's, for `choose first` in the order the
  // groups were tried. At most kMaxAttempts, distinct.
  std::vector<Void> find_voids(Vec3 x0, double r0)
  {
    std::vector<Void> voids;
    const RadiusRange radii{0, std::max(r0, s_.rmax)};
    int order = 0;
    for_each_solution(
        x0, r0, [&]() { return radii; },
        [&](const Sphere &sol) {
          if (!admissible(x0, sol.c, std::min(sol.r, r0), domain_, s_.tol)) return false;
          const double score = s_.choice == Choice::Closest ? std::fabs(sol.r - r0) : order;
          if (voids.size() == kMaxAttempts && score >= voids.back().score) return false;
          for (const Void &v : voids)
            if (norm(v.c - sol.c) <= 1e-9 * r0) return false;
          double deepest;
          if (!scene_.fits(sol.c, sol.r, s_.tol, deepest)) return false;
          ++order;
          const Void v{sol.c, sol.r, score};
          voids.insert(
              std::upper_bound(voids.begin(), voids.end(), v,
                               [](const Void &a, const Void &b) { return a.score < b.score; }),
              v);
          if (voids.size() > kMaxAttempts) voids.pop_back();
          return false;
        });
    return voids;
  }

  // Puts a sphere of the target's radius r0 at c and pushes overlapping
  // spheres apart along their line of centres until no pair involving a
  // moved sphere overlaps by more than tol / 2 (collective rearrangement,
  // Jodrey-Tory style). Rebar, atoms outside the fix group, kept targets
  // and matrix spheres farther than `zone` from the bars never move; no
  // pushed sphere moves more than `push`; the new sphere stays within
  // r0 + search of the target's old centre x0. On failure everything is
  // put back and -1 returned.
  int make_room(Vec3 c, Vec3 x0, double r0, std::int64_t id, std::map<std::int64_t, Vec3> &pushes)
  {
    const int fresh = scene_.add(c, r0, id, true, true);
    const double reach = r0 + 2 * s_.rmax;    // pushed spheres start this close to c
    const double limit = 0.5 * s_.tol, gap = 0.5 * s_.tol;
    std::map<int, Vec3> start;             // index -> position before (for undo)
    std::map<std::int64_t, Vec3> moved;    // id -> displacement in this attempt
    auto origin = [&](int j) {
      auto it = start.find(j);
      return it == start.end() ? scene_.x(j) : it->second;
    };
    // With a region, only spheres wholly inside it are pushed (and they
    // must end inside it: admissible below).
    auto in_region = [&](Vec3 x, double r) {
      return !domain_.region || domain_.region(wrapped_into_box(x, domain_), r * (1 - s_.tol));
    };
    auto movable = [&](int j) {
      return j == fresh || (scene_.pushable(j) && norm(origin(j) - c) <= reach &&
                            in_region(origin(j), scene_.r(j)));
    };
    auto shift = [&](int j, Vec3 dx) {
      for (int k : scene_.copies(scene_.id(j)))
        if (!start.count(k)) start[k] = scene_.x(k);
      scene_.shift(j, dx);
      Vec3 &m = moved[scene_.id(j)];
      m = m + dx;
    };
    auto undo = [&]() {
      for (const auto &[k, x] : start) scene_.place(k, x);
      scene_.remove(fresh);
      return -1;
    };

    std::vector<int> active{fresh};
    int sweep = 0;
    for (;; ++sweep) {
      if (sweep == kMaxSweeps) {
        stats_.sweeps += sweep;
        return undo();
      }
      std::vector<int> next;
      for (int i : active) {
        for (int j : scene_.overlapping(i, limit)) {
          const double ri = scene_.r(i), rj = scene_.r(j);
          Vec3 n = scene_.x(j) - scene_.x(i);
          const double dist = norm(n);
          const double depth = ri + rj - dist;
          if (!(depth > limit * std::min(ri, rj))) continue;    // an earlier push resolved it
          const bool mi = movable(i), mj = movable(j);
          if (!mi && !mj) {
            stats_.sweeps += sweep + 1;
            return undo();
          }
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
      // Walls: a moved sphere goes back inside the box.
      for (int i : next)
        for (int d = 0; d < 3; ++d) {
          if (domain_.periodic[d]) continue;
          const double r = scene_.r(i), x = scene_.x(i)[d];
          Vec3 dx;
          if (x - r < domain_.lo[d]) dx[d] = domain_.lo[d] + r * (1 + gap) - x;
          if (x + r > domain_.hi[d]) dx[d] = domain_.hi[d] - r * (1 + gap) - x;
          if (dx[d] != 0) shift(i, dx);
        }
      if (next.empty()) break;
      // Bounds: how far and how many.
      for (const auto &[mid, dx] : moved)
        if (mid != id && norm(dx) > s_.push) {
          stats_.sweeps += sweep + 1;
          return undo();
        }
      if (moved.size() > kMaxPushed + 1) {
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
    const Vec3 final_c = scene_.x(fresh);
    if (norm(final_c - x0) > r0 + s_.search || !admissible(x0, final_c, r0, domain_, s_.tol))
      return undo();
    // Every pushed sphere inside the region and clear of the walls, from
    // where it started.
    for (const auto &[k, before] : start)
      if (!admissible(before, scene_.x(k), scene_.r(k), domain_, s_.tol)) return undo();
    // Accepted: what moved is checked once more at the end, and the pushes.
    for (const auto &entry : start) touched.push_back(entry.first);
    for (const auto &[mid, dx] : moved) {
      if (mid == id) continue;
      stats_.pushed++;
      Vec3 &p = pushes[mid];
      p = p + dx;
    }
    return fresh;
  }

  // The new sphere is present for the targets after it, with its periodic
  // images inside this view (the host would make ghosts of them).
  int commit(int fresh)
  {
    const Vec3 c = scene_.x(fresh);
    const double r = scene_.r(fresh);
    touched.push_back(fresh);
    for (const Vec3 &image : images_in_view(c, domain_, false))
      touched.push_back(scene_.add(image, r, scene_.id(fresh), true, true));
    return fresh;
  }
};

}    // namespace

void Stats::add(const Stats &o)
{
  targets += o.targets;
  relocated += o.relocated;
  unplaced += o.unplaced;
  displaced += o.displaced;
  volume_before += o.volume_before;
  volume_after += o.volume_after;
  volume_removed += o.volume_removed;
  max_overlap = std::max(max_overlap, o.max_overlap);
  max_kept_overlap = std::max(max_kept_overlap, o.max_kept_overlap);
  solves += o.solves;
  pushed += o.pushed;
  max_push = std::max(max_push, o.max_push);
  sweeps += o.sweeps;
  isolated += o.isolated;
}

Footprint footprint(const Settings &s, double target_rmax, double largest_r)
{
  Footprint f;
  // A new centre stays within target_r + search of the old one.
  const double placed = target_rmax + s.search;
  if (s.size == SizeMode::Fit || !(s.push > 0)) {
    f.write = placed;
    f.read = placed + s.rmax + largest_r;
    return f;
  }
  // Pushed spheres start within target_r + 2 rmax of the new centre and
  // move at most `push`; whether one may move depends on the bars within
  // `zone` of it.
  f.write = placed + target_rmax + 2 * s.rmax + s.push;
  f.read = f.write + std::max(s.rmax + largest_r, s.zone + s.rmax + largest_r);
  return f;
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

bool spheres_overlap(Vec3 a, double ra, Vec3 b, double rb, double tol)
{
  return ra + rb - norm(a - b) > tol * std::min(ra, rb);
}

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

namespace {

// The particles that can matter to the targets picked by `mine`: those
// whose centre lies within the footprint's read reach of one of them (the
// host's view is usually much larger). `index` maps back to `particles`.
std::vector<Particle> near_targets(const std::vector<Particle> &particles, const Settings &settings,
                                   const std::function<bool(const Particle &)> &mine,
                                   std::vector<std::size_t> &index)
{
  std::vector<std::size_t> targets;
  double target_rmax = 0, largest_r = settings.rmax;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Particle &p = particles[i];
    largest_r = std::max(largest_r, p.r);
    if (p.role == Role::Target && (mine ? mine(p) : p.owned)) {
      targets.push_back(i);
      target_rmax = std::max(target_rmax, p.r);
    }
  }
  std::vector<Particle> out;
  index.clear();
  if (targets.empty()) return out;
  const double read = footprint(settings, target_rmax, largest_r).read;
  // Each target listed in the cells around its own (cells `read` wide): a
  // particle within `read` of it finds it in its one cell. One lookup per
  // particle, as this runs every round over the whole view.
  CellGrid grid(read * (1 + 1e-9));    // a hair wider: rounding of floor()
  for (std::size_t t : targets) grid.insert_around(particles[t].x, static_cast<int>(t));
  for (std::size_t i = 0; i < particles.size(); ++i) {
    bool near = false;
    grid.for_each_in_cell(particles[i].x, [&](int t) {
      near = near || norm(particles[t].x - particles[i].x) <= read;
    });
    if (!near) continue;
    index.push_back(i);
    out.push_back(particles[i]);
  }
  return out;
}

}    // namespace

Relocation relocate_targets(const std::vector<Particle> &all, const Settings &settings,
                            const Domain &domain, bool keep_unplaced, Stats &stats,
                            const std::function<bool(const Particle &)> &mine)
{
  std::vector<std::size_t> index;
  const std::vector<Particle> particles = near_targets(all, settings, mine, index);
  Relocation out;
  std::vector<std::size_t> targets;
  std::unordered_map<std::int64_t, std::vector<int>> vacant;    // target copies by id
  double largest_r = settings.rmax;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const Particle &p = particles[i];
    largest_r = std::max(largest_r, p.r);
    if (p.role != Role::Target) continue;
    vacant[p.id].push_back(static_cast<int>(i));
    if (mine ? mine(p) : p.owned) targets.push_back(i);
  }
  if (targets.empty()) return out;
  // size keep: largest first, so that the voids that hold a sphere as it is
  // go to the spheres that need them most (a smaller one may still find a
  // void of its own size after). The order among the targets of one block
  // of the schedule is the same whichever process relocates it.
  const bool largest_first = settings.size == SizeMode::Keep;
  std::sort(targets.begin(), targets.end(), [&](std::size_t a, std::size_t b) {
    if (largest_first && particles[a].r != particles[b].r) return particles[a].r > particles[b].r;
    return same_order_everywhere(particles[a].id, particles[a].x, particles[b].id, particles[b].x);
  });

  Scene scene(particles, 2 * largest_r,
              settings.size == SizeMode::Keep && settings.push > 0 ? settings.zone : -1);
  Relocator relocator(scene, settings, domain, stats);
  std::map<std::int64_t, Vec3> pushes;
  std::vector<int> placed_at;    // the new sphere's index, per placed result
  for (std::size_t t : targets) {
    const Particle &target = particles[t];
    stats.targets++;
    stats.volume_before += ball_volume(target.r);
    TargetResult result;
    result.index = t;
    result.id = target.id;
    int fresh = -1;
    if (settings.displaced <= 1 &&
        scene.fraction_in_rebar(target.x, target.r) >= settings.displaced) {
      result.outcome = Outcome::Displaced;
      stats.displaced++;
    } else {
      fresh = relocator.relocate(static_cast<int>(t), pushes);
      result.outcome = fresh >= 0 ? Outcome::Placed : Outcome::Unplaced;
    }
    if (result.outcome == Outcome::Placed) {
      stats.relocated++;
      stats.volume_after += ball_volume(scene.r(fresh));
    } else {
      stats.unplaced++;
      // Why, for the log: no group of four spheres to be tangent to at all.
      if (result.outcome == Outcome::Unplaced &&
          scene.candidates(target.x, target.r, settings.search, 4, kMaxRebarCandidates).size() < 4)
        stats.isolated++;
      if (keep_unplaced && result.outcome == Outcome::Unplaced) {
        // Present from now on, never pushed; what it overlaps is reported.
        for (int copy : vacant[target.id]) scene.set_present(copy, false);
        stats.max_kept_overlap =
            std::max(stats.max_kept_overlap,
                     scene.deepest_overlap(static_cast<int>(t), true) / settings.rmin);
      } else {
        stats.volume_removed += ball_volume(target.r);
      }
    }
    out.targets.push_back(result);
    placed_at.push_back(fresh);
  }
  // The largest overlap left by what was placed or moved, after every push.
  for (int j : relocator.touched) {
    stats.max_overlap = std::max(stats.max_overlap, scene.deepest_overlap(j) / settings.rmin);
  }
  // Final places: a relocated sphere may have been pushed by later ones.
  for (std::size_t k = 0; k < out.targets.size(); ++k) {
    if (placed_at[k] < 0) continue;
    out.targets[k].x = scene.x(placed_at[k]);
    out.targets[k].r = scene.r(placed_at[k]);
    pushes.erase(out.targets[k].id);
  }
  for (TargetResult &t : out.targets) t.index = index[t.index];
  for (const auto &[id, dx] : pushes) {
    out.pushes.push_back({id, dx});
    stats.max_push = std::max(stats.max_push, norm(dx) / settings.rmin);
  }
  return out;
}

}    // namespace reinforce
