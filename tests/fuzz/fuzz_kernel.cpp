// libFuzzer target for the tangent-sphere kernel. The input is read as four
// spheres, either raw doubles (every bit pattern: NaN, infinities,
// subnormals) or, when the first byte is odd, as bounded values in a
// realistic range with tiny perturbations (degenerate geometry). Whatever
// the input, every returned solution must be finite, have r > 0 and satisfy
// the tangency equations to kAcceptResidual; anything else traps.
#include "reinforce_tangent_sphere.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <algorithm>

using namespace reinforce;

namespace {

void check(const Sphere in[4], const Sphere *out, int n)
{
  if (n < 0 || n > 2) __builtin_trap();
  for (int k = 0; k < n; ++k) {
    if (!is_finite(out[k].c) || !std::isfinite(out[k].r) || !(out[k].r > 0)) __builtin_trap();
    if (!(tangency_residual(in, out[k]) <= kAcceptResidual * 1.0000001)) __builtin_trap();
  }
}

}    // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
  if (size < 1) return 0;
  Sphere in[4];
  if (data[0] & 1) {
    // 16 values from 2 bytes each: a coarse grid (-4..4) plus a small
    // perturbation, radii 0..2: coplanar, collinear, touching and equal
    // spheres are all reachable.
    double v[16] = {};
    for (int i = 0; i < 16 && 1 + 2 * i + 1 < static_cast<int>(size); ++i) {
      const int coarse = data[1 + 2 * i] % 9 - 4;
      const double fine = (data[2 + 2 * i] - 128) * 1e-9;
      v[i] = coarse + fine;
    }
    for (int s = 0; s < 4; ++s)
      in[s] = {{v[4 * s], v[4 * s + 1], v[4 * s + 2]}, std::fabs(v[4 * s + 3]) * 0.5};
  } else {
    double v[16] = {};
    std::memcpy(v, data + 1, std::min<std::size_t>(size - 1, sizeof v));
    for (int s = 0; s < 4; ++s) in[s] = {{v[4 * s], v[4 * s + 1], v[4 * s + 2]}, v[4 * s + 3]};
  }
  Sphere out[2];
  for (int steps : {0, 1}) {
    check(in, out, tangent_spheres_inversion(in, out, steps));
    check(in, out, tangent_spheres_algebraic(in, out, steps));
  }
  Sphere s = in[0];
  if (polish_tangent_sphere(in, s, 2) && (!is_finite(s.c) || !(s.r > 0) || !std::isfinite(s.r)))
    __builtin_trap();
  return 0;
}
