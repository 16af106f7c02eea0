// What the two host fixes share that is not geometry: the command's
// arguments, the colouring of the processor grid into rounds, and the
// summary line. No host headers.
#pragma once

#include "relocation.h"

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
};

// Parses the arguments that follow "fix ID group-ID reinforce/invert":
// N rebar-group-ID keyword value ... Throws OptionError naming the problem.
FixOptions parse_fix_arguments(const std::vector<std::string> &args);

// The engine settings for one invocation, given the matrix radius range
// found in the scene (used when the `radius` keyword was not given).
// Throws OptionError for an impossible range.
Settings make_settings(const FixOptions &o, double matrix_rmin, double matrix_rmax);

// Rounds of a processor grid: two colours per dimension with more than one
// process, three where a periodic dimension has an odd number (> 1) of them,
// so that no two processes of one round are neighbours.
struct Rounds {
  int count = 1;    // number of rounds
  int mine = 0;     // the round in which this process relocates
};
Rounds colour_rounds(const int procgrid[3], const int myloc[3], const bool periodic[3]);

// One log line per invocation: error against run time.
std::string summary_line(const Stats &totals, bool keep_unplaced, double seconds);

}    // namespace reinforce
