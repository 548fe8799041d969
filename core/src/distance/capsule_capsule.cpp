// Capsule vs capsule: balls at the closest points of the two segments. Intersecting segments have no
// centre-to-centre direction; the minimum translation is then along the common perpendicular d0 x d1 (the
// Minkowski difference of two segments is flat), or orthogonal to the axis when they are parallel.
#include "distance/distance.h"
#include "shapes/segment.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T> Vec3<T> intersectingAxesNormal(const Vec3<T>& d0, const Vec3<T>& d1, const Vec3<T>& towards) {
  const Vec3<T> c = d0.cross(d1);
  Vec3<T> n;
  if (!tryUnit(c, n)) n = anyPerpendicular<T>(d0.squaredNorm() > T(0) ? d0 : d1);
  return n.dot(towards) < T(0) ? Vec3<T>(-n) : n;
}

template <class T>
void distanceCapsuleCapsule(const CapsuleGeometry<T>& g0, const Transform<T>& pose0, const CapsuleGeometry<T>& g1,
                            const Transform<T>& pose1, DistanceResult<T>& out) {
  const CapsuleAxis<T> k0{pose0.p, pose0.rotate(Vec3<T>(Vec3<T>::UnitX())), g0.halfHeight, g0.radius};
  const CapsuleAxis<T> k1{pose1.p, pose1.rotate(Vec3<T>(Vec3<T>::UnitX())), g1.halfHeight, g1.radius};
  distanceCapsuleCapsule(k0, k1, out);
}

template void distanceCapsuleCapsule<float>(const CapsuleGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distanceCapsuleCapsule<double>(const CapsuleGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&, DistanceResult<double>&);
template Vec3<float> intersectingAxesNormal<float>(const Vec3<float>&, const Vec3<float>&, const Vec3<float>&);
template Vec3<double> intersectingAxesNormal<double>(const Vec3<double>&, const Vec3<double>&, const Vec3<double>&);

}  // namespace gq::kernels
