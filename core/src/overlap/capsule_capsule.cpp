// Capsule/capsule overlap: segment-segment distance <= r0 + r1.
#include "overlap/overlap.h"
#include "shapes/segment.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
bool overlapCapsuleCapsule(const Vec3<T>& c0, const Vec3<T>& a0, T r0, const Vec3<T>& c1, const Vec3<T>& a1, T r1) {
  const SegmentClosest<T> cp = closestSegmentSegment(Vec3<T>(c0 - a0), Vec3<T>(c0 + a0), Vec3<T>(c1 - a1), Vec3<T>(c1 + a1));
  const T r = r0 + r1;
  return (cp.c0 - cp.c1).squaredNorm() <= r * r;
}

template <class T>
bool overlapCapsuleCapsule(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1) {
  return overlapCapsuleCapsule<T>(p0.p, p0.rotate(Vec3<T>(g0.halfHeight, T(0), T(0))), g0.radius, p1.p,
                                  p1.rotate(Vec3<T>(g1.halfHeight, T(0), T(0))), g1.radius);
}

template bool overlapCapsuleCapsule<float>(const CapsuleGeometry<float>&, const Transform<float>&, const CapsuleGeometry<float>&, const Transform<float>&);
template bool overlapCapsuleCapsule<double>(const CapsuleGeometry<double>&, const Transform<double>&, const CapsuleGeometry<double>&, const Transform<double>&);
template bool overlapCapsuleCapsule<float>(const Vec3<float>&, const Vec3<float>&, float, const Vec3<float>&, const Vec3<float>&, float);
template bool overlapCapsuleCapsule<double>(const Vec3<double>&, const Vec3<double>&, double, const Vec3<double>&, const Vec3<double>&, double);

}  // namespace gq::kernels
