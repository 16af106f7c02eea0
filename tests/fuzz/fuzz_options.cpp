// libFuzzer target for the fix's argument parsing (shared by both hosts).
// The input is split into words at spaces and NULs; parsing must either
// give options that satisfy every documented invariant or throw
// OptionError, never anything else.
#include "fix_options.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

using namespace reinforce;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
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
    if (o.every < 0 || o.tries <= 0 || !(o.tol > 0 && o.tol < 1) || o.polish < 0 || o.polish > 10)
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
