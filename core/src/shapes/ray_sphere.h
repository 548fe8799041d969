#pragma once
// Entry distance of a ray into a sphere whose centre is at -m from the origin (m = origin - centre), for an origin
// outside the sphere. Closest-approach form: with a = d.d, b = m.d, c = m.m - r^2 and q = m - (b/a) d (the offset
// of the closest approach, computed directly), the discriminant b^2 - a c equals a (r^2 - q.q); the near root
// t = (-b - sqrt(disc)) / a is evaluated as c / (-b + sqrt(disc)), which has no cancellation.
#include <cmath>

#include "gq/math.h"

namespace gq::detail {

template <class T> bool raySphereEntry(const Vec3<T>& m, const Vec3<T>& d, T radius, T& t) {
  const T b = m.dot(d);
  if (b >= T(0)) return false;  // moving away from the centre while outside
  const T a = d.squaredNorm();
  const T c = m.squaredNorm() - radius * radius;
  const Vec3<T> q = m - (b / a) * d;
  const T h2 = radius * radius - q.squaredNorm();
  if (h2 < T(0)) return false;
  t = std::max(c, T(0)) / (-b + std::sqrt(a * h2));
  return true;
}

}  // namespace gq::detail
