// Sphere/capsule MTD: sphere against the closest segment point; a centre on the segment pushes
// perpendicular to it (every perpendicular gives the same depth r0 + r1).
#include "penetration/penetration.h"
#include "shapes/segment.h"
#include "common/unit_vector.h"

namespace gq::detail {

template <class T>
bool penetrationSphereCapsule(const SphereGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1,
                              Vec3<T>& direction, T& depth) {
  const Vec3<T> axis = p1.rotate(Vec3<T>(g1.halfHeight, T(0), T(0)));
  const Vec3<T> q = closestPointOnSegment(Vec3<T>(p1.p - axis), Vec3<T>(p1.p + axis), p0.p);
  const Vec3<T> d = p0.p - q;
  const T len2 = d.squaredNorm(), len = std::sqrt(len2);
  const T pen = g0.radius + g1.radius - len;
  if (!(pen >= T(0))) return false;
  if (!tryUnitWithNorm(d, len2, len, direction)) direction = anyPerpendicular(p1.rotate(Vec3<T>::UnitX()));
  depth = pen;
  return true;
}

template bool penetrationSphereCapsule<float>(const SphereGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&,
                                             Vec3<float>&, float&);
template bool penetrationSphereCapsule<double>(const SphereGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&,
                                              Vec3<double>&, double&);

}  // namespace gq::detail
