#include "reinforce_void_search.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace reinforce {

VoidSearch::VoidSearch(Scene &scene, const Settings &s, const Domain &domain, Stats &stats)
    : scene_(scene), s_(s), domain_(domain), stats_(stats)
{
}

// Runs the kernel over the groups of four nearest candidates of the
// target's old sphere; calls take(solution) for each solution whose
// radius lies in the range wanted() gives (asked again after each take,
// so a caller that found a good solution narrows the search), whose
// centre is within the shift bound and that overlaps none of the
// candidates; stops when take returns true.
template <class Range, class F>
void VoidSearch::for_each_solution(Vec3 x0, double r0, Range &&wanted, F &&take)
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
bool VoidSearch::overlaps_one_of(const std::vector<Candidate> &near, Vec3 c, double r,
                                 double slack) const
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
bool VoidSearch::own_size_void(Vec3 x0, double r0, Void &best)
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
    if (gap[a * n + b] > 2 * r0 || gap[a * n + c] > 2 * r0 || gap[b * n + c] > 2 * r0) return false;
    const Sphere group[3] = {scene_.sphere(near[a].index), scene_.sphere(near[b].index),
                             scene_.sphere(near[c].index)};
    Vec3 found[2];
    const int nfound = centres_tangent_to_three(group, r0, found);
    stats_.solves++;
    for (int k = 0; k < nfound; ++k) {
      const double shift = norm(found[k] - x0);
      if (shift > max_shift || shift >= best.score ||
          !admissible(x0, found[k], r0, domain_, s_.tol) || overlaps_one_of(near, found[k], r0))
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
bool VoidSearch::best_fit(Vec3 x0, double r0, Void &best)
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
std::vector<Void> VoidSearch::find_voids(Vec3 x0, double r0)
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

}    // namespace reinforce
