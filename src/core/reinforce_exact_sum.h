// Sums that do not depend on how their terms are split over processes or
// in which order they are added (docs/design.md, "Regrowth"): each term is
// rounded to a multiple of a fixed quantum and added as a 128-bit integer;
// the processes' sums travel as four limbs of 32 bits, each exact in a
// double, so one MPI sum of doubles adds them exactly for up to 2^21
// processes. Tolerance: a term is off by at most half a quantum
// (kQuantumBits below the unit); a term beyond 2^62 units is clamped there.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace reinforce {

class ExactSum {
public:
  static constexpr int kLimbs = 4;
  static constexpr int kQuantumBits = 64;    // the quantum: unit * 2^-64

  // `unit`: the scale of the terms (> 0 and finite; else 1).
  explicit ExactSum(double unit)
      : unit_(unit > 0 && std::isfinite(unit) ? unit : 1.0), scale_(std::ldexp(1.0 / unit_, kQuantumBits))
  {
  }

  void add(double term)
  {
    const double q = term * scale_;
    if (std::fabs(q) < 0x1p62) {    // the usual case: one integer conversion
      total_ += static_cast<std::int64_t>(std::nearbyint(q));
      return;
    }
    constexpr double kLimit = 0x1p126;    // 2^62 units, far below 2^127 quanta
    if (!(q == q)) return;                  // NaN adds nothing
    const double clamped = q > kLimit ? kLimit : (q < -kLimit ? -kLimit : q);
    // |clamped| (a whole number) split into 64-bit halves, each exact in a
    // double.
    const double magnitude = std::fabs(clamped);
    const double high = std::floor(magnitude * 0x1p-64);
    const double low = magnitude - high * 0x1p64;    // in [0, 2^64): exact
    const __int128 whole = (static_cast<__int128>(static_cast<std::uint64_t>(high)) << 64) +
                           static_cast<__int128>(static_cast<std::uint64_t>(low));
    total_ += clamped < 0 ? -whole : whole;
  }

  // The limbs of this sum: three unsigned 32-bit ones, then the signed rest.
  std::array<double, kLimbs> limbs() const
  {
    std::array<double, kLimbs> out{};
    __int128 rest = total_;
    for (int k = 0; k < kLimbs - 1; ++k) {
      out[k] = static_cast<double>(static_cast<std::uint32_t>(rest & 0xffffffff));
      rest >>= 32;    // arithmetic shift: the sign stays in the rest
    }
    out[kLimbs - 1] = static_cast<double>(static_cast<std::int64_t>(rest));
    return out;
  }

  // The sum whose limbs were summed over processes (each limb an integer
  // below 2^53 in magnitude).
  static double from_limbs(const double *limbs, double unit)
  {
    __int128 total = 0;
    for (int k = kLimbs; k-- > 0;)
      total = total * (static_cast<__int128>(1) << 32) +
              static_cast<__int128>(static_cast<std::int64_t>(limbs[k]));
    return value_of(total, unit > 0 && std::isfinite(unit) ? unit : 1.0);
  }

  double value() const { return value_of(total_, unit_); }

private:
  static double value_of(__int128 total, double unit)
  {
    const double high = static_cast<double>(static_cast<std::int64_t>(total >> 64));
    const double low = static_cast<double>(static_cast<std::uint64_t>(total));
    return std::ldexp(std::ldexp(high, 64) + low, -kQuantumBits) * unit;
  }

  double unit_;
  double scale_;    // quanta per unit of a term
  __int128 total_ = 0;
};

}    // namespace reinforce
