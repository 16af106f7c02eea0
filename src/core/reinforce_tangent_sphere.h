// The geometric kernel: spheres externally tangent to four given spheres.
//
// Every solver returns only real external solutions with a finite centre and a
// positive finite radius whose tangency residual (see tangency_residual) is at
// most kAcceptResidual; degenerate, imaginary or ill-conditioned cases give no
// solution. They never return NaN or infinity.
#pragma once

#include "reinforce_vec3.h"

#include <functional>

namespace reinforce {

struct Sphere {
  Vec3 c;
  double r = 0;
};

// Residual above which a computed solution counts as garbage and is dropped.
constexpr double kAcceptResidual = 1e-6;

// max_i | |c - c_i| - (r + r_i) | / r; +infinity if s.r <= 0.
double tangency_residual(const Sphere in[4], const Sphere &s);

// Geometric inversion (Jerier et al.): shrink by the smallest radius, invert
// about that point, fit the planes tangent to the three inverted spheres,
// invert back. Works in local coordinates scaled to about 1. Fails (returns
// 0) when the three inverted centres are nearly collinear.
// newton_steps > 0 polishes each solution with Newton steps on the four
// tangency equations. Returns the number of solutions written to out (0..2).
//
// wanted, if given, sees each solution before the polish (in global
// coordinates) and drops it by returning false: a caller's test of what it
// would reject anyway (too large, overlapping a neighbour) saves the Newton
// steps of most solutions. Its test must allow for the polish moving the
// solution. Measured (one Newton step), the move is below 5e-9 r while r is
// under 1e3 times the largest of the four radii, 1.4e-7 r up to 1e4 times
// and 6e-6 r up to 1e5 times; the engine allows kAcceptResidual r, for
// voids at most about 1e3 times the spheres around them. A repeat of a
// dropped root (a double root) is dropped too.
int tangent_spheres_inversion(const Sphere in[4], Sphere out[2], int newton_steps,
                              const std::function<bool(const Sphere &)> &wanted);
int tangent_spheres_inversion(const Sphere in[4], Sphere out[2], int newton_steps = 0);

// Direct algebraic reference: linear system for the centre in terms of r,
// then a quadratic in r. Fails when the four centres are nearly coplanar.
int tangent_spheres_algebraic(const Sphere in[4], Sphere out[2], int newton_steps = 0);

// Newton steps on F_i(c, r) = |c - c_i| - (r + r_i). Keeps the iterate only
// while the residual decreases; returns true if s was improved or kept finite.
bool polish_tangent_sphere(const Sphere in[4], Sphere &s, int steps);

// Centres of a sphere of given radius r externally tangent to three spheres:
// the points at distance r + r_i from each centre c_i (trilateration), used
// to put a sphere back with its own radius. Works in coordinates relative to
// the first centre, scaled by the largest distance. Returns 0 for r <= 0, a
// negative or non-finite input, centres nearly collinear (relative 1e-9), or
// spheres too far apart to be touched at once; 1 when the two solutions
// coincide (within 1e-6 of the scale); else 2. Every point returned is
// finite and its distances match r + r_i to 1e-9 (r + r_i); others are
// dropped.
int centres_tangent_to_three(const Sphere in[3], double r, Vec3 out[2]);

}    // namespace reinforce
