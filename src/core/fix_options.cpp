#include "fix_options.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace reinforce {

namespace {

const std::string kIllegal = "Illegal fix reinforce/invert command: ";

double parse_double(const std::string &word, const std::string &what)
{
  char *end = nullptr;
  errno = 0;
  const double v = std::strtod(word.c_str(), &end);
  if (word.empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    throw OptionError(kIllegal + "expected a number for " + what + ", got '" + word + "'");
  return v;
}

int parse_int(const std::string &word, const std::string &what)
{
  char *end = nullptr;
  errno = 0;
  const long v = std::strtol(word.c_str(), &end, 10);
  if (word.empty() || *end != '\0' || errno == ERANGE || v > std::numeric_limits<int>::max() ||
      v < std::numeric_limits<int>::min())
    throw OptionError(kIllegal + "expected an integer for " + what + ", got '" + word + "'");
  return static_cast<int>(v);
}

double positive(double v, const std::string &what)
{
  if (!(v > 0)) throw OptionError(kIllegal + what + " must be > 0");
  return v;
}

}    // namespace

FixOptions parse_fix_arguments(const std::vector<std::string> &args)
{
  if (args.size() < 2) throw OptionError(kIllegal + "expected N and a rebar group ID");
  FixOptions o;
  o.every = parse_int(args[0], "N");
  if (o.every < 0) throw OptionError(kIllegal + "N must be >= 0");
  o.rebar_group = args[1];
  std::size_t i = 2;
  auto value = [&](const std::string &key, std::size_t count) {
    if (i + count >= args.size())
      throw OptionError(kIllegal + "missing value for keyword '" + key + "'");
  };
  while (i < args.size()) {
    const std::string key = args[i];
    if (key == "radius") {
      value(key, 2);
      o.rmin = positive(parse_double(args[i + 1], "radius rmin"), "radius rmin");
      o.rmax = positive(parse_double(args[i + 2], "radius rmax"), "radius rmax");
      if (o.rmin > o.rmax) throw OptionError(kIllegal + "radius rmin must be <= rmax");
      o.radius_set = true;
      i += 3;
    } else if (key == "search") {
      value(key, 1);
      o.search = positive(parse_double(args[i + 1], "search"), "search");
      o.search_set = true;
      i += 2;
    } else if (key == "tries") {
      value(key, 1);
      o.tries = parse_int(args[i + 1], "tries");
      if (o.tries <= 0) throw OptionError(kIllegal + "tries must be > 0");
      i += 2;
    } else if (key == "choose") {
      value(key, 1);
      if (args[i + 1] == "first")
        o.choice = Choice::First;
      else if (args[i + 1] == "closest")
        o.choice = Choice::Closest;
      else
        throw OptionError(kIllegal + "choose must be 'first' or 'closest', got '" + args[i + 1] +
                          "'");
      i += 2;
    } else if (key == "unplaced") {
      value(key, 1);
      if (args[i + 1] == "delete")
        o.keep_unplaced = false;
      else if (args[i + 1] == "keep")
        o.keep_unplaced = true;
      else
        throw OptionError(kIllegal + "unplaced must be 'delete' or 'keep', got '" + args[i + 1] +
                          "'");
      i += 2;
    } else if (key == "region") {
      value(key, 1);
      o.region = args[i + 1];
      i += 2;
    } else if (key == "tol") {
      value(key, 1);
      o.tol = positive(parse_double(args[i + 1], "tol"), "tol");
      if (o.tol >= 1) throw OptionError(kIllegal + "tol must be < 1");
      i += 2;
    } else if (key == "polish") {
      value(key, 1);
      o.polish = parse_int(args[i + 1], "polish");
      if (o.polish < 0 || o.polish > 10) throw OptionError(kIllegal + "polish must be in 0..10");
      i += 2;
    } else {
      throw OptionError(kIllegal + "unknown keyword '" + key + "'");
    }
  }
  return o;
}

Settings make_settings(const FixOptions &o, double matrix_rmin, double matrix_rmax)
{
  Settings s;
  s.rmin = o.radius_set ? o.rmin : matrix_rmin;
  s.rmax = o.radius_set ? o.rmax : matrix_rmax;
  if (!(s.rmin > 0) || !(s.rmax >= s.rmin) || !std::isfinite(s.rmax)) {
    char range[120];
    std::snprintf(range, sizeof range, "[%g, %g]", s.rmin, s.rmax);
    throw OptionError(std::string("Fix reinforce/invert: impossible radius range ") + range);
  }
  s.search = o.search_set ? o.search : 2 * s.rmax;
  s.tries = o.tries;
  s.choice = o.choice;
  s.tol = o.tol;
  s.newton_steps = o.polish;
  return s;
}

Rounds colour_rounds(const int procgrid[3], const int myloc[3], const bool periodic[3])
{
  Rounds r;
  int stride = 1;
  for (int d = 0; d < 3; ++d) {
    const int p = procgrid[d], loc = myloc[d];
    int colours = 1, colour = 0;
    if (p > 1) {
      const bool odd_ring = periodic[d] && p % 2 == 1;
      colours = odd_ring ? 3 : 2;
      // On an odd ring the last process would touch the first one of its
      // parity: it gets a colour of its own.
      colour = (odd_ring && loc == p - 1) ? 2 : loc % 2;
    }
    r.mine += colour * stride;
    stride *= colours;
  }
  r.count = stride;
  return r;
}

std::string summary_line(const Stats &t, bool keep_unplaced, double seconds)
{
  const long long deleted = keep_unplaced ? 0 : t.unplaced, kept = keep_unplaced ? t.unplaced : 0;
  char buf[400];
  std::snprintf(buf, sizeof buf,
                "fix reinforce/invert: %lld targets, %lld relocated, %lld deleted, %lld kept, "
                "volume %.6g -> %.6g, max overlap %.2e rmin, %lld solves, %.3f s\n",
                static_cast<long long>(t.targets), static_cast<long long>(t.relocated), deleted,
                kept, t.volume_before, t.volume_after, t.max_overlap,
                static_cast<long long>(t.solves), seconds);
  return buf;
}

}    // namespace reinforce
