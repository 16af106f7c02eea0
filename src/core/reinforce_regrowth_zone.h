// The regrowth's zone on one process (docs/design.md, "Regrowth"): the
// host's atoms near the seeds, owned and ghost, as bodies. Each process
// moves the zone's spheres it owns and sees the others' as its ghosts,
// refreshed by the host's forward communication. Every per-atom decision
// (in the zone or not, its radius, its mobility) is made by the atom's
// owner from its own coordinates and sent to the ghosts, so it is the same
// for any process count.
#pragma once

#include "reinforce_domain.h"
#include "reinforce_host_hooks.h"
#include "reinforce_vec3.h"

#include <cstdint>
#include <vector>

namespace reinforce {

// A target the regrowth takes up: one left without a void (vacant, its
// atom at its old centre) or one placed shrunk (its atom where the
// relocation put it).
struct Seed {
  std::int64_t id = 0;
  Vec3 x;             // its old centre, in the box
  double R = 0;       // its own radius
  double r = 0;       // its radius now: 0 when vacant, else the shrunk radius
  double depth = 0;   // its old centre to the nearest bar surface (< 0: inside a bar)
  double inside = 0;  // its volume inside the bars
  bool kept = false;  // grown back at its own radius (else deleted, or left shrunk)
};

// One copy of a host atom near the seeds.
struct ZoneBody {
  Vec3 x0;               // where it was at the start (where it is now: Zone::x)
  double R = 0;          // its radius at full size (a kept shrunk seed: its own)
  std::int64_t id = 0;
  int local = -1;        // the host's index
  bool owned = false;
  bool rebar = false;    // of this fix's bars
  bool present = true;   // false: a seed deleted or given up
  bool movable = false;  // in the zone: its owner moves it
  bool growing = false;  // a seed growing back (given up when it does not fit)
  bool packing = true;   // as the packing had it (not a seed): its overlaps at the start stay allowed
  double w = 0;          // owned movable: mobility, 1 at a seed, 0 at the zone's edge
  double cap = 0;        // owned movable: the largest distance from x0
  int bar = -1;          // owned movable matrix: its nearest rebar body, or -1
};

// How wide the zone is and how far it reaches.
struct ZoneShape {
  double width = 0;       // a matrix sphere within this of a seed moves
  double cap = 0;         // how far a sphere at a seed may move (0 at the zone's edge)
  double reach = 0;       // bodies: the atoms within this of a seed
  double pull_range = 0;  // a matrix sphere's bar: the nearest rebar sphere within this
};

class Zone {
public:
  // The bodies of the atoms `a` (after the host's refresh) within
  // shape.reach of a seed (every process's, `seeds`, their `kept` decided).
  // Collective.
  Zone(HostHooks &host, const AtomArrays &a, const std::vector<Seed> &seeds,
       const ZoneShape &shape, const Domain &domain);

  std::vector<ZoneBody> bodies;
  std::vector<Vec3> x;        // where each body is now
  std::vector<int> moving;    // the owned movable bodies, ascending

  // The owned bodies' positions, or their flags (present, movable,
  // growing), sent to their ghost copies. Collective.
  void forward_positions();
  void forward_flags();
  // The bodies (owned or ghost) of atom `id` on this process.
  std::vector<int> copies_of(std::int64_t id) const;

private:
  HostHooks &host_;
  std::vector<double> rows_;    // the forward buffer: a row per host atom
  std::vector<int> by_id_;      // bodies sorted by id
  void decide_owned(const AtomArrays &a, const std::vector<Seed> &seeds, const ZoneShape &shape,
                    const Domain &domain);
  void find_bars(double range);
};

}    // namespace reinforce
