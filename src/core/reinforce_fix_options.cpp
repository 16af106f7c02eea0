#include "reinforce_fix_options.h"

#include "reinforce_regrowth_policy.h"

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

// The value of keyword `key`, one of two words: true for the second.
bool parse_either(const std::string &key, const std::string &word, const char *first,
                  const char *second)
{
  if (word == first) return false;
  if (word == second) return true;
  throw OptionError(kIllegal + key + " must be '" + first + "' or '" + second + "', got '" + word +
                    "'");
}

double positive(double v, const std::string &what)
{
  if (!(v > 0)) throw OptionError(kIllegal + what + " must be > 0");
  return v;
}

}    // namespace

namespace {

// A keyword: how many values follow it and what they set.
struct Keyword {
  const char *name;
  std::size_t values;
  void (*apply)(FixOptions &o, const std::string *v);
};

const Keyword kKeywords[] = {
    {"radius", 2,
     [](FixOptions &o, const std::string *v) {
       o.rmin = positive(parse_double(v[0], "radius rmin"), "radius rmin");
       o.rmax = positive(parse_double(v[1], "radius rmax"), "radius rmax");
       if (o.rmin > o.rmax) throw OptionError(kIllegal + "radius rmin must be <= rmax");
       o.radius_set = true;
     }},
    {"search", 1,
     [](FixOptions &o, const std::string *v) {
       o.search = positive(parse_double(v[0], "search"), "search");
       o.search_set = true;
     }},
    {"tries", 1,
     [](FixOptions &o, const std::string *v) {
       o.tries = parse_int(v[0], "tries");
       if (o.tries <= 0) throw OptionError(kIllegal + "tries must be > 0");
     }},
    {"choose", 1,
     [](FixOptions &o, const std::string *v) {
       o.choice =
           parse_either("choose", v[0], "first", "closest") ? Choice::Closest : Choice::First;
     }},
    {"unplaced", 1,
     [](FixOptions &o, const std::string *v) {
       o.keep_unplaced = parse_either("unplaced", v[0], "delete", "keep");
     }},
    {"region", 1, [](FixOptions &o, const std::string *v) { o.region = v[0]; }},
    {"tol", 1,
     [](FixOptions &o, const std::string *v) {
       o.tol = parse_double(v[0], "tol");
       if (!(o.tol >= kMinTol) || o.tol >= 1)
         throw OptionError(kIllegal + "tol must be in [1e-10, 1)");
     }},
    {"polish", 1,
     [](FixOptions &o, const std::string *v) {
       o.polish = parse_int(v[0], "polish");
       if (o.polish < 0 || o.polish > 10) throw OptionError(kIllegal + "polish must be in 0..10");
     }},
    {"size", 1,
     [](FixOptions &o, const std::string *v) {
       o.size = parse_either("size", v[0], "keep", "fit") ? SizeMode::Fit : SizeMode::Keep;
     }},
    {"zone", 1,
     [](FixOptions &o, const std::string *v) {
       o.zone = parse_double(v[0], "zone");
       if (!(o.zone >= 0)) throw OptionError(kIllegal + "zone must be >= 0");
       o.zone_set = true;
     }},
    {"push", 1,
     [](FixOptions &o, const std::string *v) {
       o.push = parse_double(v[0], "push");
       if (!(o.push >= 0)) throw OptionError(kIllegal + "push must be >= 0");
       o.push_set = true;
     }},
    {"displaced", 1,
     [](FixOptions &o, const std::string *v) {
       o.displaced_set = true;
       if (v[0] == "none") {
         o.displaced = 2;    // above any volume fraction: never
         return;
       }
       o.displaced = parse_double(v[0], "displaced");
       if (!(o.displaced > 0) || o.displaced > 1)
         throw OptionError(kIllegal + "displaced must be in (0, 1] or 'none'");
     }},
    {"regrow", 1,
     [](FixOptions &o, const std::string *v) {
       o.regrow_set = v[0] != "no";
       o.regrow_off = v[0] == "no";
       o.regrow = 0;    // yes: the default width
       if (v[0] == "no" || v[0] == "yes") return;
       o.regrow = parse_double(v[0], "regrow");
       if (!(o.regrow > 0)) throw OptionError(kIllegal + "regrow must be > 0, 'yes' or 'no'");
     }},
    {"grow", 1,
     [](FixOptions &o, const std::string *v) {
       if (v[0] == "together" || v[0] == "each")
         throw OptionError(kIllegal + "grow " + v[0] +
                           " is retired: the regrowth rebuilds one zone around every target "
                           "without a void (grow balance, the default)");
       if (v[0] != "balance")
         throw OptionError(kIllegal + "grow must be 'balance', got '" + v[0] + "'");
       o.grow_set = true;
     }},
    {"walls", 1,
     [](FixOptions &o, const std::string *v) {
       o.walls_ignore = parse_either("walls", v[0], "check", "ignore");
     }},
};

}    // namespace

bool regrowth_on(const FixOptions &o)
{
  return !o.regrow_off && !o.keep_unplaced && (o.regrow_set || o.size == SizeMode::Keep);
}

FixOptions parse_fix_arguments(const std::vector<std::string> &args)
{
  if (args.size() < 2) throw OptionError(kIllegal + "expected N and a rebar group ID");
  FixOptions o;
  o.every = parse_int(args[0], "N");
  if (o.every < 0) throw OptionError(kIllegal + "N must be >= 0");
  o.rebar_group = args[1];
  for (std::size_t i = 2; i < args.size();) {
    const std::string &key = args[i];
    const Keyword *keyword = nullptr;
    for (const Keyword &k : kKeywords)
      if (key == k.name) keyword = &k;
    if (!keyword) throw OptionError(kIllegal + "unknown keyword '" + key + "'");
    if (i + keyword->values >= args.size())
      throw OptionError(kIllegal + "missing value for keyword '" + key + "'");
    keyword->apply(o, &args[i + 1]);
    i += 1 + keyword->values;
  }
  if (o.regrow_set && o.keep_unplaced)
    throw OptionError(kIllegal + "regrow makes room for the targets unplaced keep leaves "
                                 "where they are: use one of them");
  if (o.grow_set && !regrowth_on(o))
    throw OptionError(kIllegal + "grow sets how the regrowth grows its seeds, and the "
                                 "regrowth is off (regrow no, unplaced keep, or size fit "
                                 "without regrow)");
  return o;
}

Settings make_settings(const FixOptions &o, double matrix_rmin, double matrix_rmax,
                       double box_diagonal)
{
  Settings s;
  s.rmin = o.radius_set ? o.rmin : matrix_rmin;
  s.rmax = o.radius_set ? o.rmax : matrix_rmax;
  if (!(s.rmin > 0) || !(s.rmax >= s.rmin) || !std::isfinite(s.rmax)) {
    char range[120];
    std::snprintf(range, sizeof range, "[%g, %g]", s.rmin, s.rmax);
    throw OptionError(std::string("Fix reinforce/invert: impossible radius range ") + range);
  }
  // Nothing larger than the box can matter: a new sphere lies in the box,
  // and a larger gap or push would only widen the ghost cutoff.
  const double cap = box_diagonal > 0 && std::isfinite(box_diagonal) ? box_diagonal : s.rmax;
  const double bound = std::max(cap, matrix_rmax);
  s.rmax = std::min(s.rmax, bound);
  s.rmin = std::min(s.rmin, s.rmax);
  s.search = std::min(o.search_set ? o.search : 2 * s.rmax, bound);
  s.zone = std::min(o.zone_set ? o.zone : 3 * s.rmax, bound);
  s.push = std::min(o.push_set ? o.push : 0.0, bound);
  s.tries = o.tries;
  s.choice = o.choice;
  s.tol = o.tol;
  s.newton_steps = o.polish;
  s.size = o.size;
  // Every target is tried unless told otherwise (`unplaced keep`: always):
  // measured, deleting the spheres mostly inside the bars leaves the shell
  // hollower than putting them in the voids near it (docs/design.md).
  s.displaced = o.keep_unplaced ? 2 : (o.displaced_set ? o.displaced : 2);
  // The regrowth: by default with size keep (the seed paper's size fit
  // stays as it was unless asked), never with unplaced keep (which leaves
  // such targets where they are); its zone reaches kZoneWidth radii
  // (narrower zones jam: docs/design.md, "Regrowth").
  const bool regrow = regrowth_on(o);
  const double width = regrowth_policy::kZoneWidth * matrix_rmax;
  s.regrow = regrow ? std::min(o.regrow > 0 ? o.regrow : width, bound) : 0;
  return s;
}

std::string summary_line(const Stats &t, bool keep_unplaced, double seconds, int rounds,
                         double rmin)
{
  const long long kept = keep_unplaced ? t.unplaced : 0;
  const long long deleted = t.unplaced - kept;
  char buf[600];
  std::snprintf(buf, sizeof buf,
                "fix reinforce/invert: %lld targets, %lld relocated, %lld deleted (%lld displaced "
                "by the bars), %lld kept, volume %.6g -> %.6g, max overlap %.2e rmin, %lld solves, "
                "%lld pushed (largest %.2f rmin, %lld sweeps), %d rounds, %.3f s (rmin %.9g)\n",
                static_cast<long long>(t.targets), static_cast<long long>(t.relocated), deleted,
                static_cast<long long>(t.displaced), kept, t.volume_before, t.volume_after,
                t.max_overlap, static_cast<long long>(t.solves), static_cast<long long>(t.pushed),
                t.max_push, static_cast<long long>(t.sweeps), rounds, seconds, rmin);
  return buf;
}

std::string lost_matrix_warning(const Stats &t, bool jammed)
{
  const long long shrunk = static_cast<long long>(t.shrunk);
  const long long outside = static_cast<long long>(t.unplaced - t.displaced);
  if (shrunk <= 0 && outside <= 0) return "";
  std::string what;
  char part[200];
  if (shrunk > 0) {
    std::snprintf(part, sizeof part, "left %lld targets smaller than their own radius", shrunk);
    what = part;
  }
  if (outside > 0) {
    std::snprintf(part, sizeof part,
                  "%sdeleted %lld targets beyond the %lld whose centre lies inside the bars",
                  what.empty() ? "" : " and ", outside, static_cast<long long>(t.displaced));
    what += part;
  }
  // The share of their volume the targets keep (relocated over before).
  const double kept = t.volume_before > 0 ? t.volume_after / t.volume_before : 0;
  std::snprintf(part, sizeof part, ": the targets keep %.2f of their volume", kept);
  what += part;
  if (jammed)
    what += "; its zone jammed (shrunk and grown back, the matrix did not reach its density "
            "again) and went back to the relocation's scene";
  return "Fix reinforce/invert regrowth " + what;
}

}    // namespace reinforce
