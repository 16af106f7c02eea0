// The engine's settings, made from the fix's arguments (reinforce_fix_options.h)
// and read by both stages: the relocation and the regrowth.
#pragma once

namespace reinforce {

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
  // The width of the zone regrown around the targets the relocation left
  // without a void or placed shrunk (reinforce_regrowth.h); 0: none, such a
  // target is deleted (or left shrunk).
  double regrow = 0;
  // The zone of a block rebuilt around all of its seeds, their count from
  // the volume balance (`grow balance`, the fix's default: make_settings).
  bool grow_balance = false;
  // Else the regrowth's seeds: all of a block's grown together (`grow
  // together`), or one by one (`grow each`: both false).
  bool grow_together = false;
};

}    // namespace reinforce
