// Small 3-vector used by the kernel and the engine (no host headers).
#pragma once

#include <cmath>

namespace reinforce {

struct Vec3 {
  double x = 0, y = 0, z = 0;
  double &operator[](int d) { return d == 0 ? x : (d == 1 ? y : z); }
  double operator[](int d) const { return d == 0 ? x : (d == 1 ? y : z); }
};

inline Vec3 operator+(Vec3 a, Vec3 b)
{
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(Vec3 a, Vec3 b)
{
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator*(double s, Vec3 a)
{
  return {s * a.x, s * a.y, s * a.z};
}
inline double dot(Vec3 a, Vec3 b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(Vec3 a, Vec3 b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm2(Vec3 a)
{
  return dot(a, a);
}
inline double norm(Vec3 a)
{
  return std::sqrt(dot(a, a));
}
inline bool is_finite(Vec3 a)
{
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

}    // namespace reinforce
