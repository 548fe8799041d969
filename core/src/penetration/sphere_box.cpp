// Sphere/box MTD in the box frame: a centre outside pushes away from the clamped closest point by
// r - distance; a centre inside (or on the surface) pushes out through the nearest face by r + face distance.
#include "penetration/penetration.h"
#include "common/unit_vector.h"

namespace gq::detail {
namespace {

// Index and distance of the box face nearest to an interior point c.
template <class T> Eigen::Index nearestFace(const Vec3<T>& c, const Vec3<T>& half, T& faceDistance) {
  Eigen::Index axis;
  faceDistance = (half - c.cwiseAbs()).minCoeff(&axis);
  return axis;
}

}  // namespace

template <class T>
bool penetrationSphereBox(const SphereGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                          Vec3<T>& direction, T& depth) {
  const Vec3<T> c = p1.transformInv(p0.p);
  const Vec3<T> q = c.cwiseMax(-g1.halfExtents).cwiseMin(g1.halfExtents);
  const Vec3<T> d = c - q;
  const T dist2 = d.squaredNorm();
  if (dist2 > T(0)) {
    const T len = std::sqrt(dist2);
    if (len > g0.radius) return false;
    Vec3<T> unit;
    if (!tryUnitWithNorm(d, dist2, len, unit)) unit = Vec3<T>::UnitX();
    direction = p1.rotate(unit);
    depth = g0.radius - len;
    return true;
  }
  T faceDistance;
  const Eigen::Index axis = nearestFace(c, g1.halfExtents, faceDistance);
  Vec3<T> local = Vec3<T>::Zero();
  local[axis] = c[axis] < T(0) ? T(-1) : T(1);
  direction = p1.rotate(local);
  depth = g0.radius + faceDistance;
  return true;
}

template bool penetrationSphereBox<float>(const SphereGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&,
                                         Vec3<float>&, float&);
template bool penetrationSphereBox<double>(const SphereGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&,
                                          Vec3<double>&, double&);

}  // namespace gq::detail
