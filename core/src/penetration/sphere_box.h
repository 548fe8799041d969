#pragma once
// Sphere/box MTD, inline: the façade's cell (dispatch/penetration.cpp) runs it without a call or the poses' copies,
// and penetrationSphereBox (sphere_box.cpp) is this code.
// In the box frame: a centre outside pushes away from the clamped closest point by r - distance; a centre inside (or
// on the surface) pushes out through the nearest face by r + face distance.
#include <cmath>

#include "common/unit_vector.h"
#include "gq/geometry.h"

namespace gq::detail {

template <class T>
[[gnu::always_inline]] inline bool sphereBoxPenetration(const SphereGeometry<T>& g0, const Transform<T>& p0,
                                                        const BoxGeometry<T>& g1, const Transform<T>& p1,
                                                        Vec3<T>& direction, T& depth) {
  const Vec3<T> c = p1.transformInv(p0.p);
  const Vec3<T> q = c.cwiseMax(-g1.halfExtents).cwiseMin(g1.halfExtents);
  const Vec3<T> d = c - q;
  if (q != c) {  // outside (|d|^2 may underflow to 0 while d is not 0)
    const T dist2 = d.squaredNorm(), len = normFromSquared(d, dist2);
    if (len > g0.radius) return false;
    Vec3<T> unit;
    if (!tryUnitWithNorm(d, dist2, len, unit)) [[unlikely]]
      unit = Vec3<T>::UnitX();
    direction = p1.rotate(unit);
    depth = g0.radius - len;
    return true;
  }
  // The nearest face of an interior centre: the axis of the smallest half - |c|.
  Eigen::Index axis;
  const T faceDistance = (g1.halfExtents - c.cwiseAbs()).minCoeff(&axis);
  Vec3<T> local = Vec3<T>::Zero();
  local[axis] = c[axis] < T(0) ? T(-1) : T(1);
  direction = p1.rotate(local);
  depth = g0.radius + faceDistance;
  return true;
}

}  // namespace gq::detail
