// Capsule/box MTD, exact, in the box's frame (overlap/segment_box.h): when the segment enters the box, the
// segment-box SAT depth plus the radius (the Minkowski difference is box - segment grown by the radius); otherwise
// the radius minus the exact segment-box distance, along the closest-point difference.
#include "overlap/segment_box.h"
#include "penetration/penetration.h"

namespace gq::detail {

template <class T>
bool penetrationCapsuleBox(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                           Vec3<T>& direction, T& depth) {
  const Vec3<T>& h = g1.halfExtents;
  const Vec3<T> c = p1.transformInv(p0.p);
  const Vec3<T> d = p1.rotateInv(p0.rotate(Vec3<T>(g0.halfHeight, T(0), T(0))));
  const SegmentBoxSat<T> sat = satSegmentBox(c, d, h);
  if (sat.overlap >= T(0)) {
    direction = p1.rotate(sat.direction);
    depth = sat.overlap + g0.radius;
    return true;
  }
  if (-sat.overlap > g0.radius) return false;
  const SegmentBoxClosest<T> closest = closestSegmentBox(c, d, h);
  const T dist = std::sqrt(closest.distSq);
  if (dist > g0.radius) return false;
  // When the closest points lie on the SAT axis's facet the axis realises the distance exactly, whereas the
  // difference of two nearly coincident closest points has an angle error of about eps * size / distance.
  const T scale = g0.radius + T(2) * d.norm() + h.maxCoeff() + c.cwiseAbs().maxCoeff();
  const bool onSatFacet = std::abs(-sat.overlap - dist) <= T(tol::Rel<T>::kEpsilon) * scale;
  const Vec3<T> local = (onSatFacet || !(dist > T(0))) ? sat.direction
                                                        : Vec3<T>((closest.onSegment - closest.onBox) / dist);
  direction = p1.rotate(local);
  depth = g0.radius - dist;
  return true;
}

template bool penetrationCapsuleBox<float>(const CapsuleGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&,
                                 Vec3<float>&, float&);
template bool penetrationCapsuleBox<double>(const CapsuleGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&,
                                  Vec3<double>&, double&);

}  // namespace gq::detail
