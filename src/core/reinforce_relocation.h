// The relocation engine: one process's view of the spheres near the bars,
// relocation of the targets it is given. Host independent: the LAMMPS and
// LIGGGHTS fixes translate their atoms into this view and back
// (docs/design.md, "The relocation engine").
#pragma once

#include "reinforce_boundaries.h"
#include "reinforce_vec3.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace reinforce {

enum class Role : unsigned char {
  Rebar,     // never moved, always present
  Matrix,    // present, may be a neighbour of a relocated sphere
  Target,    // vacant: waiting for (or owned elsewhere and waiting for) a new place
};

// One sphere of a process's view: an owned atom or a ghost (a copy of an atom
// owned elsewhere, or a periodic image). Copies of one atom share its id.
struct Particle {
  Vec3 x;
  double r = 0;
  std::int64_t id = 0;
  Role role = Role::Matrix;
  bool owned = false;
  // A present matrix sphere that rearrangement may push: in the fix group,
  // not a kept target. Atoms outside the fix group are obstacles only.
  bool pushable = true;
  // In the rebar of another reinforce/invert fix: an obstacle that never
  // moves, not a bar of this one; its overlaps are not the packing's.
  bool other_rebar = false;
};

enum class Choice { First, Closest };

// How a target is put back: with its own radius where a void holds it
// (tangent to three spheres), or where room can be made by pushing (push >
// 0), else as Fit (Keep, the default); or with the radius of the void it
// fits, within [rmin, rmax], as in the seed paper (Fit).
enum class SizeMode { Keep, Fit };

struct Settings {
  double rmin = 0, rmax = 0;    // accepted radius range (Fit); largest matrix radius (reach)
  double search = 0;            // surface gap of candidate neighbours (> 0)
  int tries = 1000;             // groups of four tried per target, at most
  Choice choice = Choice::Closest;
  double tol = 1e-6;       // spheres overlap when d_ij > tol * min(r_i, r_j)
  int newton_steps = 1;    // Newton polish of each kernel solution
  SizeMode size = SizeMode::Keep;
  double zone = 0;    // Keep: only matrix spheres within this gap of a bar are pushed
  double push = 0;    // Keep: largest displacement of a pushed sphere (0: no pushing)
  double displaced =
      0.5;    // a target with at least this volume fraction inside the bars is deleted
  // The width of the zone regrown around a target the relocation left
  // without a place (reinforce_regrowth.h); 0: none, such a target is deleted.
  double regrow = 0;
};

// Placement domain of one process.
struct Domain {
  Vec3 lo, hi;    // global box
  bool periodic[3] = {false, false, false};
  // Bounds of the spheres this process can see (its subdomain grown by the
  // ghost cutoff): a periodic image of a new sphere is added to the view
  // when its centre falls inside, as the host's own ghost images would be.
  Vec3 view_lo, view_hi;
  Vec3 sub_lo, sub_hi;    // this process's subdomain, [sub_lo, sub_hi)
  // Optional: true when the sphere of radius r about c (wrapped into the
  // box) lies wholly inside the user's region (the region's own surface
  // distance, as the host's region walls use it).
  std::function<bool(const Vec3 &c, double r)> region;
  // Optional: the walls of the host's wall fixes, which no placed or pushed
  // sphere may cross or overlap (the same for every process).
  std::shared_ptr<const Boundaries> walls;
};

// True when a sphere of radius r moved from `from` to c is inside the box
// in its non-periodic dimensions, inside the region and clear of the
// walls, each up to tol * r.
bool admissible(Vec3 from, Vec3 c, double r, const Domain &domain, double tol);

// How far the relocation of one target reaches from the target's old centre:
// `write` bounds the centres of the spheres it moves or places (before and
// after), `read` the centres of every sphere it looks at. The ghost cutoff
// and the width of the blocks of the schedule follow from these.
struct Footprint {
  double write = 0, read = 0;
};
Footprint footprint(const Settings &s, double target_rmax, double largest_r);

// Totals of one relocation call (summed over the calls of a process, then
// combined over the processes as reinforce_totals.h says).
struct Stats {
  std::int64_t targets = 0, relocated = 0, unplaced = 0;
  std::int64_t displaced = 0;    // deleted without search: mostly inside the bars
  double volume_before = 0, volume_after = 0;
  double volume_removed = 0;      // volume of the targets not put back (deleted or kept)
  double max_overlap = 0;         // largest overlap of a relocated or pushed sphere, / rmin
  double max_kept_overlap = 0;    // largest overlap of a kept target with a present sphere, / rmin
  std::int64_t solves = 0;        // kernel calls
  std::int64_t pushed = 0;        // spheres pushed (counted once per target that pushed them)
  double max_push = 0;            // largest displacement of a pushed sphere in one call, / rmin
  std::int64_t sweeps = 0;        // rearrangement sweeps
  std::int64_t isolated = 0;      // unplaced with fewer than four spheres within `search`
  std::int64_t matrix_deleted = 0;    // matrix spheres (not targets) deleted to make room
  std::int64_t shrunk = 0;            // relocated with a radius below its own
};

// The one copy of an atom that lies in the box (periodic images lie
// outside it), and whether x lies in this process's subdomain.
bool in_box(Vec3 x, const Domain &domain);
bool in_subdomain(Vec3 x, const Domain &domain);
// c wrapped into the box in its periodic dimensions, as the host wraps an
// atom that left it.
Vec3 wrapped_into_box(Vec3 c, const Domain &domain);
// c and its periodic images (shifted by one box length) that lie inside the
// process's view, as the host's ghosts would; with_centre false leaves c out.
std::vector<Vec3> images_in_view(Vec3 c, const Domain &domain, bool with_centre);

// True when spheres (a, ra) and (b, rb) overlap by more than tol * min(ra, rb).
bool spheres_overlap(Vec3 a, double ra, Vec3 b, double rb, double tol);

// Indices (ascending) of the spheres in [0, n) whose surface comes within
// `margin` of a rebar sphere's surface, rebar spheres included. x[i] points
// at three doubles (the hosts' double **x). Cost: O(n) plus the work near
// the rebar, whatever the rebar radius.
std::vector<int> spheres_near_rebar(int n, const double *const *x, const double *radius,
                                    const unsigned char *is_rebar, double margin);

// Indices of the owned non-rebar particles that overlap a rebar particle.
std::vector<std::size_t> find_targets(const std::vector<Particle> &particles, double tol);

// Pairs of non-rebar particles that already overlap (by more than tol *
// min radius), each pair counted on exactly one process: by the owner of
// the lower id. `largest` gets the largest such overlap relative to rmin.
std::int64_t count_packing_overlaps(const std::vector<Particle> &particles, double tol, double rmin,
                                    double &largest);

// What became of one target.
enum class Outcome { Placed, Displaced, Unplaced };
struct TargetResult {
  std::size_t index = 0;    // the target's copy in the particle vector
  std::int64_t id = 0;
  Outcome outcome = Outcome::Unplaced;
  Vec3 x;          // Placed: final centre (the frame of the target's copy; may lie outside
                   // the box in periodic dims)
  double r = 0;    // Placed: final radius
};
// The accumulated displacement of a present sphere pushed to make room.
struct Push {
  std::int64_t id = 0;
  Vec3 dx;
};
// A target placed with a radius below its own although only bars thin
// beside it crossed it (no rebar sphere it overlaps is larger than
// kThinBar of its radius): it displaced little, and the regrowth tries it
// again at its own radius near where it was.
constexpr double kThinBar = 0.5;
struct ShrunkTarget {
  std::int64_t id = 0;
  Vec3 x0;          // where it was (the frame of the target's copy)
  double r0 = 0;    // its own radius
};
struct Relocation {
  std::vector<TargetResult> targets;           // in the order they were relocated
  std::vector<Push> pushes;                    // increasing id; none of the targets above
  std::vector<ShrunkTarget> shrunk_by_thin;    // the targets above shrunk across thin bars
};

// Relocates the Target particles for which `mine` is true (default: the
// owned ones), in increasing id order (size keep: largest first, then by
// id). Particles with role Target are
// vacant, all others present. A relocated sphere is present for the targets
// after it. With keep_unplaced, a target that found no place stays where it
// is, present and never pushed.
Relocation relocate_targets(const std::vector<Particle> &particles, const Settings &settings,
                            const Domain &domain, bool keep_unplaced, Stats &stats,
                            const std::function<bool(const Particle &)> &mine = nullptr);

}    // namespace reinforce
