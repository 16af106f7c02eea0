// What the two host fixes share that is not geometry: the command's
// arguments, the colouring of the processor grid into rounds, and the
// summary line. No host headers.
#pragma once

#include "reinforce_relocation.h"
#include "reinforce_settings.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace reinforce {

// A malformed command; what() is the whole ERROR text.
struct OptionError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct FixOptions {
  int every = 0;    // N: 0 = once at the next run
  std::string rebar_group;
  bool radius_set = false;    // else rmin/rmax from the matrix spheres
  double rmin = 0, rmax = 0;
  bool search_set = false;    // else 2 * rmax
  double search = 0;
  int tries = 1000;
  Choice choice = Choice::Closest;
  bool keep_unplaced = false;
  std::string region;    // empty: no region test
  double tol = 1e-6;
  int polish = 1;
  SizeMode size = SizeMode::Keep;
  bool zone_set = false;    // else 3 * rmax
  double zone = 0;
  bool push_set = false;    // else 0: no pushing
  double push = 0;
  bool displaced_set = false;    // else never
  double displaced = 0.5;
  // walls ignore: the host's wall fixes are not read, and a wall the host
  // cannot describe does not stop the run (the user takes the risk).
  bool walls_ignore = false;
  // regrow yes (the default with size keep, not with unplaced keep) or W:
  // on, W the zone's width (else the grow mode's default width, below); set
  // explicitly, an error with unplaced keep. regrow no: off.
  bool regrow_set = false;
  bool regrow_off = false;
  double regrow = 0;
  // grow balance (the only mode, the default): given, it changes nothing.
  bool grow_set = false;
};

// Smallest accepted `tol`: below it the rounding of coordinates (and of the
// kernel's solutions, about 1e-15 of the radius) decides what overlaps.
constexpr double kMinTol = 1e-10;

// Whether the regrowth runs: by default with size keep, with size fit
// when asked, never with regrow no or unplaced keep.
bool regrowth_on(const FixOptions &o);

// Parses the arguments that follow "fix ID group-ID reinforce/invert":
// N rebar-group-ID keyword value ... Throws OptionError naming the problem.
FixOptions parse_fix_arguments(const std::vector<std::string> &args);

// The engine settings for one invocation, given the matrix radius range
// found in the scene (used when the `radius` keyword was not given) and the
// box diagonal (gaps and radii beyond it cannot matter and are capped).
// Throws OptionError for an impossible range.
Settings make_settings(const FixOptions &o, double matrix_rmin, double matrix_rmax,
                       double box_diagonal);

// One log line per invocation: error against run time.
// rmin is the unit of the overlaps it reports.
std::string summary_line(const Stats &totals, bool keep_unplaced, double seconds, int rounds,
                         double rmin);

// The text of the WARNING (no "WARNING: ") when the invocation's totals,
// the regrowth on, show matrix lost beyond what the bars displace: targets
// left smaller than their own radius, or deleted beyond those whose centre
// lies inside the bars (and the share of their volume the targets keep);
// empty when neither.
std::string lost_matrix_warning(const Stats &totals, bool jammed);

}    // namespace reinforce
