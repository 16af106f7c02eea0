// Spheres externally tangent to four spheres: geometric inversion (primary),
// a direct algebraic solve (reference) and a Newton polish.
//
// All work is done in a local frame: origin at the centre of the smallest
// input sphere, lengths divided by the largest centre distance to it, so the
// intermediate numbers stay near 1 wherever the scene is and whatever its
// units. Only the final centre is translated back.

#include "reinforce_tangent_sphere.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace reinforce {

namespace {

// sin^2 of the angle of the triangle of inverted centres (inversion) or the
// normalised volume of the tetrahedron of centres (algebraic) below which the
// problem is treated as singular. Closer to zero, the answer would carry
// fewer than ~4 correct digits; such inputs are "no solution".
constexpr double kSingular = 1e-24;
// A shrunk sphere whose power with respect to the inversion centre is this
// small (relative) passes through it and inverts to a plane: no solution.
constexpr double kThroughCentre = 1e-14;
// 1 - |n0|^2 down to -kTangentSlack is rounding of a double root, not an
// imaginary plane.
constexpr double kTangentSlack = 1e-12;
// Solutions closer than this (relative to their radius) are one double root.
constexpr double kSameSolution = 1e-9;

// The four spheres in the local frame.
struct Local {
  Vec3 origin;     // global centre of the smallest input sphere
  double scale;    // local length = global length / scale
  Vec3 p[4];
  double r[4];
  int smallest;
};

bool make_local(const Sphere in[4], Local &L)
{
  int s = 0;
  for (int i = 0; i < 4; ++i) {
    if (!is_finite(in[i].c) || !std::isfinite(in[i].r) || in[i].r < 0) return false;
    if (in[i].r < in[s].r) s = i;
  }
  L.origin = in[s].c;
  L.smallest = s;
  double far = 0;
  for (int i = 0; i < 4; ++i) far = std::max(far, norm(in[i].c - L.origin));
  if (!(far > 0) || !std::isfinite(far)) return false;
  L.scale = far;
  const double inv = 1.0 / far;
  for (int i = 0; i < 4; ++i) {
    L.p[i] = inv * (in[i].c - L.origin);
    L.r[i] = inv * in[i].r;
  }
  return std::isfinite(L.r[s]);
}

double local_residual(const Local &L, const Sphere &s)
{
  if (!(s.r > 0) || !std::isfinite(s.r) || !is_finite(s.c))
    return std::numeric_limits<double>::infinity();
  double worst = 0;
  for (int i = 0; i < 4; ++i)
    worst = std::max(worst, std::fabs(norm(s.c - L.p[i]) - (s.r + L.r[i])));
  return worst / s.r;
}

// Solves the 4x4 system a x = b by Gaussian elimination with partial
// pivoting. False if a pivot is below 1e-14 of the largest entry.
bool solve4(double a[4][4], double b[4], double x[4])
{
  double big = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) big = std::max(big, std::fabs(a[i][j]));
  if (!(big > 0)) return false;
  for (int k = 0; k < 4; ++k) {
    int piv = k;
    for (int i = k + 1; i < 4; ++i)
      if (std::fabs(a[i][k]) > std::fabs(a[piv][k])) piv = i;
    if (std::fabs(a[piv][k]) <= 1e-14 * big) return false;
    if (piv != k) {
      std::swap(a[piv], a[k]);
      std::swap(b[piv], b[k]);
    }
    for (int i = k + 1; i < 4; ++i) {
      const double f = a[i][k] / a[k][k];
      for (int j = k; j < 4; ++j) a[i][j] -= f * a[k][j];
      b[i] -= f * b[k];
    }
  }
  for (int k = 3; k >= 0; --k) {
    double sum = b[k];
    for (int j = k + 1; j < 4; ++j) sum -= a[k][j] * x[j];
    x[k] = sum / a[k][k];
  }
  return true;
}

// Newton on F_i(c, r) = |c - p_i| - (r + r_i), in the local frame.
void local_polish(const Local &L, Sphere &s, int steps)
{
  double res = local_residual(L, s);
  for (int it = 0; it < steps && res > 0; ++it) {
    double jac[4][4], rhs[4], dx[4];
    for (int i = 0; i < 4; ++i) {
      const Vec3 d = s.c - L.p[i];
      const double len = norm(d);
      if (!(len > 0)) return;
      jac[i][0] = d.x / len;
      jac[i][1] = d.y / len;
      jac[i][2] = d.z / len;
      jac[i][3] = -1;
      rhs[i] = -(len - (s.r + L.r[i]));
    }
    if (!solve4(jac, rhs, dx)) return;
    Sphere next{s.c + Vec3{dx[0], dx[1], dx[2]}, s.r + dx[3]};
    const double next_res = local_residual(L, next);
    if (!(next_res < res)) return;
    s = next;
    res = next_res;
  }
}

// A root the caller's filter dropped before the polish: a repeat of it (a
// double root) is dropped too, as a repeat of a kept root would be. Unpolished,
// the two copies may differ by what the polish would have moved them.
struct Dropped {
  bool any = false;
  Sphere root;
};

// Keeps a local solution if it is valid, polished as asked; returns the new
// count. Drops a repeat of the previous solution (a double root).
int keep_solution(const Sphere in[4], const Local &L, Sphere s, int newton_steps, Sphere out[2],
                  int count, const std::function<bool(const Sphere &)> &wanted = {},
                  Dropped *dropped = nullptr)
{
  if (!(s.r > 0) || !is_finite(s.c)) return count;
  if (wanted) {
    const Sphere raw{L.origin + L.scale * s.c, L.scale * s.r};
    if (dropped && dropped->any &&
        norm(dropped->root.c - raw.c) + std::fabs(dropped->root.r - raw.r) <=
            (kSameSolution + 2 * kAcceptResidual) * raw.r)
      return count;
    if (!wanted(raw)) {
      if (dropped) *dropped = {true, raw};
      return count;
    }
  }
  if (newton_steps > 0) local_polish(L, s, newton_steps);
  if (!(local_residual(L, s) <= kAcceptResidual)) return count;
  // The contract is on the global spheres: far from the origin, or with
  // radii far below the rounding of the coordinates, a solution exact in
  // the local frame may not be representable (found by fuzzing).
  Sphere g{L.origin + L.scale * s.c, L.scale * s.r};
  if (!(tangency_residual(in, g) <= kAcceptResidual)) return count;
  if (count == 1 && norm(out[0].c - g.c) + std::fabs(out[0].r - g.r) <= kSameSolution * g.r)
    return count;
  out[count] = g;
  return count + 1;
}

int sorted(Sphere out[2], int n)
{
  if (n == 2 && out[1].r < out[0].r) std::swap(out[0], out[1]);
  return n;
}

}    // namespace

double tangency_residual(const Sphere in[4], const Sphere &s)
{
  if (!(s.r > 0) || !std::isfinite(s.r) || !is_finite(s.c))
    return std::numeric_limits<double>::infinity();
  double worst = 0;
  for (int i = 0; i < 4; ++i)
    worst = std::max(worst, std::fabs(norm(s.c - in[i].c) - (s.r + in[i].r)));
  return worst / s.r;
}

bool polish_tangent_sphere(const Sphere in[4], Sphere &s, int steps)
{
  Local L;
  if (!make_local(in, L) || !(s.r > 0) || !is_finite(s.c)) return false;
  Sphere loc{(1.0 / L.scale) * (s.c - L.origin), s.r / L.scale};
  local_polish(L, loc, steps);
  Sphere g{L.origin + L.scale * loc.c, L.scale * loc.r};
  if (!is_finite(g.c) || !(g.r > 0) || !std::isfinite(g.r)) return false;
  s = g;
  return true;
}

int tangent_spheres_inversion(const Sphere in[4], Sphere out[2], int newton_steps,
                              const std::function<bool(const Sphere &)> &wanted)
{
  Local L;
  if (!make_local(in, L)) return 0;
  // Shrink by the smallest radius m: sphere `smallest` becomes the point O
  // (the local origin) and the unknown sphere, grown by m, passes through O.
  const double m = L.r[L.smallest];
  Vec3 q[3];
  double sigma[3];
  for (int i = 0, j = 0; i < 4; ++i) {
    if (i == L.smallest) continue;
    const double rho = L.r[i] - m;
    // Inversion about O with radius 1. The power may be negative when O lies
    // inside the shrunk sphere: the signed radius carries that through.
    const double power = norm2(L.p[i]) - rho * rho;
    if (std::fabs(power) <= kThroughCentre * norm2(L.p[i])) return 0;
    q[j] = (1.0 / power) * L.p[i];
    sigma[j] = rho / power;
    ++j;
  }
  // The unknown sphere maps to a plane n.y = h (h > 0) with every inverted
  // sphere on O's side, touching it: n.q_j + sigma_j = h.
  const Vec3 u = q[1] - q[0], v = q[2] - q[0];
  const double a = sigma[0] - sigma[1], b = sigma[0] - sigma[2];
  const Vec3 w = cross(u, v);
  const double w2 = norm2(w);
  if (!(w2 > kSingular * norm2(u) * norm2(v))) return 0;    // collinear: no plane
  // In-plane part of n solving n.u = a, n.v = b; the rest is along w.
  const Vec3 n0 = (1.0 / w2) * (a * cross(v, w) + b * cross(w, u));
  double t = 1 - norm2(n0);
  if (t < -kTangentSlack) return 0;    // imaginary: no real tangent plane
  t = std::max(t, 0.0);
  const Vec3 w_unit = (1.0 / std::sqrt(w2)) * w;
  int count = 0;
  Dropped dropped;
  for (double sign : {1.0, -1.0}) {
    const Vec3 n = n0 + (sign * std::sqrt(t)) * w_unit;
    const double h =
        (dot(n, q[0]) + sigma[0] + dot(n, q[1]) + sigma[1] + dot(n, q[2]) + sigma[2]) / 3;
    if (!(h > 0)) continue;    // plane through or behind O: no sphere through O
    // Back to a sphere through O: centre n / (2h), radius 1 / (2h); then
    // subtract the shrink.
    const double grown = 0.5 / h;
    count = keep_solution(in, L, Sphere{grown * n, grown - m}, newton_steps, out, count, wanted,
                          &dropped);
    if (t == 0) break;
  }
  return sorted(out, count);
}

int tangent_spheres_inversion(const Sphere in[4], Sphere out[2], int newton_steps)
{
  return tangent_spheres_inversion(in, out, newton_steps, {});
}

int tangent_spheres_algebraic(const Sphere in[4], Sphere out[2], int newton_steps)
{
  Local L;
  if (!make_local(in, L)) return 0;
  // Origin sphere 0 is the smallest (at the local origin); subtracting its
  // equation from the others leaves c.p_i = e_i + r f_i, linear in c.
  const int s = L.smallest;
  const double r0 = L.r[s];
  Vec3 p[3];
  double e[3], f[3];
  for (int i = 0, j = 0; i < 4; ++i) {
    if (i == s) continue;
    p[j] = L.p[i];
    e[j] = 0.5 * (norm2(L.p[i]) + r0 * r0 - L.r[i] * L.r[i]);
    f[j] = r0 - L.r[i];
    ++j;
  }
  const Vec3 c0 = cross(p[1], p[2]), c1 = cross(p[2], p[0]), c2 = cross(p[0], p[1]);
  const double det = dot(p[0], c0);
  // Coplanar centres: singular system.
  if (!(det * det > kSingular * norm2(p[0]) * norm2(p[1]) * norm2(p[2]))) return 0;
  const double inv = 1.0 / det;
  const Vec3 g = inv * (e[0] * c0 + e[1] * c1 + e[2] * c2);
  const Vec3 hv = inv * (f[0] * c0 + f[1] * c1 + f[2] * c2);
  // |g + r hv|^2 = (r + r0)^2  ->  A r^2 + 2 B r + C = 0
  const double A = norm2(hv) - 1, B = dot(g, hv) - r0, C = norm2(g) - r0 * r0;
  double roots[2];
  int nroots = 0;
  if (std::fabs(A) <= 1e-14 * (std::fabs(B) + std::fabs(C))) {
    if (B != 0) roots[nroots++] = -C / (2 * B);
  } else {
    double disc = B * B - A * C;
    if (disc < -kTangentSlack * B * B) return 0;
    disc = std::max(disc, 0.0);
    // Stable form: no cancellation between B and the root.
    const double qq = -(B + std::copysign(std::sqrt(disc), B));
    if (qq != 0) {
      roots[nroots++] = qq / A;
      roots[nroots++] = C / qq;
    } else {
      roots[nroots++] = 0;
    }
  }
  int count = 0;
  for (int k = 0; k < nroots && count < 2; ++k) {
    const double r = roots[k];
    if (!(r > 0) || !std::isfinite(r)) continue;
    count = keep_solution(in, L, Sphere{g + r * hv, r}, newton_steps, out, count);
  }
  return sorted(out, count);
}

int centres_tangent_to_three(const Sphere in[3], double r, Vec3 out[2])
{
  if (!(r > 0) || !std::isfinite(r)) return 0;
  for (int k = 0; k < 3; ++k)
    if (!(in[k].r >= 0) || !std::isfinite(in[k].r) || !is_finite(in[k].c)) return 0;
  const double d1 = in[0].r + r, d2 = in[1].r + r, d3 = in[2].r + r;
  const Vec3 u = in[1].c - in[0].c, v = in[2].c - in[0].c;
  const double scale = std::max({norm(u), norm(v), d1, d2, d3});
  if (!(scale > 0) || !std::isfinite(scale)) return 0;
  const double inv = 1 / scale;
  // Frame: e1 along u, e2 in the plane of the centres, e3 normal to it.
  const Vec3 us = inv * u, vs = inv * v;
  const double a = norm(us);
  if (!(a > 1e-9)) return 0;
  const Vec3 e1 = (1 / a) * us;
  const double i = dot(e1, vs);
  const Vec3 w = vs - i * e1;
  const double j = norm(w);
  if (!(j > 1e-9)) return 0;
  const Vec3 e2 = (1 / j) * w, e3 = cross(e1, e2);
  const double s1 = d1 * inv, s2 = d2 * inv, s3 = d3 * inv;
  const double x = (s1 * s1 - s2 * s2 + a * a) / (2 * a);
  const double y = (s1 * s1 - s3 * s3 + i * i + j * j) / (2 * j) - i * x / j;
  const double z2 = s1 * s1 - x * x - y * y;
  if (!(z2 >= -1e-12)) return 0;
  // Two solutions closer than 1e-6 of the scale are one (their tangency
  // differs by z^2 / 2, below 1e-12).
  const double z = z2 > 1e-12 ? std::sqrt(z2) : 0;
  int n = 0;
  for (int sign : {1, -1}) {
    if (sign < 0 && z == 0) break;
    const Vec3 c = in[0].c + scale * (x * e1 + y * e2 + (sign * z) * e3);
    if (!is_finite(c)) continue;
    bool tangent = true;
    for (int k = 0; k < 3; ++k)
      tangent = tangent && std::fabs(norm(c - in[k].c) - (in[k].r + r)) <= 1e-9 * (in[k].r + r);
    if (tangent) out[n++] = c;
  }
  return n;
}

}    // namespace reinforce
