// libFuzzer target for the fix's argument parsing (shared by both hosts).
// The input is split into words at spaces and NULs; parsing must either
// give options that satisfy every documented invariant or throw
// OptionError, never anything else.
#include "reinforce_fix_options.h"
#include "reinforce_regrowth.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace reinforce;

namespace {

// The numeric keywords over the whole double range: the input's bytes read
// as doubles (any bit pattern: inf, nan, denormals, 1e308 ...), written as
// the words a user would type. Whatever parses must give settings whose
// reach is finite, with the scene's radii and box taken from the input too.
void numeric_arguments(const std::uint8_t *data, std::size_t size)
{
  double v[11];
  if (size < sizeof v) return;
  std::memcpy(v, data, sizeof v);
  auto word = [](double x) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", x);
    return std::string(text);
  };
  std::vector<std::string> args = {"0", "bars", "radius", word(v[0]), word(v[1])};
  const char *keywords[] = {"search", "zone", "push", "tol", "displaced", "regrow"};
  const int value_of[] = {2, 3, 4, 5, 6, 10};
  for (int k = 0; k < 6; ++k) {
    args.push_back(keywords[k]);
    args.push_back(word(v[value_of[k]]));
  }
  args.push_back("size");
  args.push_back((data[0] & 1) ? "keep" : "fit");
  try {
    const FixOptions o = parse_fix_arguments(args);
    if (!(o.tol >= kMinTol && o.tol < 1)) __builtin_trap();
    const Settings s = make_settings(o, std::fabs(v[7]), std::fabs(v[8]), std::fabs(v[9]));
    const Footprint f = footprint(s, std::fabs(v[8]), std::fabs(v[8]));
    // Radii and boxes of real scenes (run_invocation stops with an ERROR
    // line on a reach that is not finite).
    const bool physical = std::fabs(v[8]) < 1e100 && std::fabs(v[9]) < 1e100;
    if (physical && (!std::isfinite(f.read) || !std::isfinite(f.write) || !std::isfinite(s.search)))
      __builtin_trap();
    // The regrowth's zone (asked for here): positive, and the ghost reach
    // it needs finite.
    const double reach = regrowth_ghost_reach(std::fabs(v[8]), std::fabs(v[8]), s.search);
    if (physical && (!(s.regrow > 0) || !std::isfinite(reach))) __builtin_trap();
  } catch (const OptionError &) {
  }
}

}    // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  numeric_arguments(data, size);
  std::vector<std::string> words(1);
  for (std::size_t i = 0; i < size; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c == ' ' || c == '\0') {
      if (!words.back().empty()) words.emplace_back();
    } else {
      words.back() += c;
    }
  }
  if (words.back().empty()) words.pop_back();
  try {
    const FixOptions o = parse_fix_arguments(words);
    if (o.every < 0 || o.tries <= 0 || !(o.tol >= kMinTol && o.tol < 1) || o.polish < 0 ||
        o.polish > 10)
      __builtin_trap();
    if (o.radius_set && !(o.rmin > 0 && o.rmin <= o.rmax && std::isfinite(o.rmax)))
      __builtin_trap();
    if (o.search_set && !(o.search > 0 && std::isfinite(o.search))) __builtin_trap();
    const Settings s = make_settings(o, 0.5, 1.0, 10.0);
    if (!(s.search > 0) || !(s.rmin > 0) || s.rmax < s.rmin) __builtin_trap();
  } catch (const OptionError &) {
  }
  return 0;
}
