// The relocation engine: one process's view of the spheres near the bars,
// relocation of the targets it owns. Host independent: the LAMMPS and
// LIGGGHTS fixes translate their atoms into this view and back.
#pragma once

#include "vec3.h"

#include <cstdint>
#include <functional>
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
};

enum class Choice { First, Closest };

struct Settings {
  double rmin = 0, rmax = 0;    // accepted radius range of a relocated sphere
  double search = 0;            // surface gap of candidate neighbours (> 0)
  int tries = 1000;             // groups of four tried per target, at most
  Choice choice = Choice::Closest;
  double tol = 1e-6;       // spheres overlap when d_ij > tol * min(r_i, r_j)
  int newton_steps = 1;    // Newton polish of each kernel solution
};

// Placement domain of one process.
struct Domain {
  Vec3 lo, hi;    // global box
  bool periodic[3] = {false, false, false};
  // Bounds of the spheres this process can see (its subdomain grown by the
  // ghost cutoff): a periodic image of a new sphere is added to the view
  // when its centre falls inside, as the host's own ghost images would be.
  Vec3 view_lo, view_hi;
  std::function<bool(const Vec3 &)> region;    // optional extra test on a new centre
};

struct Placement {
  std::size_t index = 0;    // the target, an index into the particle vector
  bool placed = false;      // false: no relocation was found
  Vec3 x;                   // new centre (may lie outside the box in periodic dims)
  double r = 0;             // new radius
};

// Totals of one relocation call (the host sums them over processes and rounds).
struct Stats {
  std::int64_t targets = 0, relocated = 0, unplaced = 0;
  double volume_before = 0, volume_after = 0;
  double max_overlap = 0;     // largest overlap of a relocated sphere, relative to rmin
  std::int64_t solves = 0;    // kernel calls
  void add(const Stats &o);
};

// Distance from a target's old centre to the farthest sphere centre that can
// decide its relocation: the ghost cutoff a process needs. target_rmax is the
// largest target radius, largest_r the largest radius of any sphere.
double required_reach(const Settings &s, double target_rmax, double largest_r);

// True when spheres (a, ra) and (b, rb) overlap by more than tol * min(ra, rb).
bool spheres_overlap(Vec3 a, double ra, Vec3 b, double rb, double tol);

// Indices (ascending) of the spheres in [0, n) whose surface comes within
// `margin` of a rebar sphere's surface, rebar spheres included. x[i] points
// at three doubles (the hosts' double **x). Cost: O(n) with a grid over the
// rebar spheres only. These are all the spheres a relocation can involve
// when margin >= 2 * required_reach.
std::vector<int> spheres_near_rebar(int n, const double *const *x, const double *radius,
                                    const unsigned char *is_rebar, double margin);

// Indices of the owned non-rebar particles that overlap a rebar particle.
std::vector<std::size_t> find_targets(const std::vector<Particle> &particles, double tol);

// Pairs of non-rebar particles that already overlap (by more than tol *
// min radius), each pair counted on exactly one process: by the owner of
// the lower id. `largest` gets the largest such overlap relative to rmin.
std::int64_t count_packing_overlaps(const std::vector<Particle> &particles, double tol, double rmin,
                                    double &largest);

// Relocates every owned Target of `particles`, in increasing id order, and
// returns one Placement per such target in that order. Particles with role
// Target (owned or not) are vacant; all others are present. A relocated
// sphere is present for the targets after it. With keep_unplaced, a target
// that found no place stays where it is and is present for the later ones.
std::vector<Placement> relocate_targets(const std::vector<Particle> &particles,
                                        const Settings &settings, const Domain &domain,
                                        bool keep_unplaced, Stats &stats);

}    // namespace reinforce
