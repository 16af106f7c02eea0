// Plain 3-vector arithmetic for the independent references: check_scene's
// wall geometry (double) and test_boundaries.cpp's brute force (long
// double). Shared by those two only: the fix's own Vec3
// (reinforce_boundaries.h) is what they check, so they must not use it.
#pragma once

#include <cmath>

namespace tools {

template <class T> struct Vec {
  using Scalar = T;
  T x = 0, y = 0, z = 0;
};

template <class T> Vec<T> operator+(Vec<T> a, Vec<T> b)
{
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T> Vec<T> operator-(Vec<T> a, Vec<T> b)
{
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
// The scalar converts to T (not deduced): 2 * v and 1.0 * v as before.
template <class T> Vec<T> operator*(typename Vec<T>::Scalar s, Vec<T> a)
{
  return {s * a.x, s * a.y, s * a.z};
}
template <class T> T dot(Vec<T> a, Vec<T> b)
{
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T> Vec<T> cross(Vec<T> a, Vec<T> b)
{
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T> T norm(Vec<T> a)
{
  return std::sqrt(dot(a, a));
}

}    // namespace tools
