#pragma once
// FCL 0.7's contact point of three points straddling its two-sided Plane (a triangle of a BVHModel, or a cone's apex
// and the two rim points in the plane of its axis and the normal): the midpoint of the two points where the segments
// from the lone point (the only one on its side) to the other two cross the plane.
#include <cmath>

#include "convert.h"

namespace gq::fcl::internal {

// Where the segment p-q crosses the plane; hp, hq: the points' signed heights, of opposite signs.
template <class T> Vec3<T> planeCrossing(const Vec3<T>& p, T hp, const Vec3<T>& q, T hq) {
  return (p * hq - q * hp) / (hq - hp);
}

// `h`: the points' signed heights. A height of 0 counts on the positive side when `zeroIsPositive` (FCL's cone
// rule), on the negative side otherwise (its triangle rule). Points all on one side (a touch FCL does not report):
// the point nearest the plane.
template <class T> Vec3<T> straddleMidpoint(const Vec3<T> (&p)[3], const T (&h)[3], bool zeroIsPositive) {
  bool positive[3];
  int positives = 0;
  for (int i = 0; i < 3; ++i) positives += positive[i] = zeroIsPositive ? h[i] >= T(0) : h[i] > T(0);
  if (positives == 0 || positives == 3) {
    int nearest = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(h[i]) < std::abs(h[nearest])) nearest = i;
    return p[nearest];
  }
  const bool loneSide = positives == 1;  // the lone point is the positive one, else the only non-positive one
  int lone = 0;
  while (positive[lone] != loneSide) ++lone;
  const int i = (lone + 1) % 3, j = (lone + 2) % 3;
  return (planeCrossing(p[i], h[i], p[lone], h[lone]) + planeCrossing(p[j], h[j], p[lone], h[lone])) * T(0.5);
}

}  // namespace gq::fcl::internal
