// Capsule vs box in the box's frame (overlap/segment_box.h), exact: the capsule is the segment c + s d (s in
// [-1, 1]) grown by r0, the box is [-h, h].
//  - Segment outside the box: balls at the exact closest points of segment and box (closestSegmentBox); the
//    normal is their difference or the SAT axis, whichever separates segment and box more (see outsideNormal).
//  - Segment entering the box: the Minkowski difference is box - segment grown by r0, so the depth is the SAT
//    overlap plus r0 along the SAT axis L. Moving the segment out by the overlap along L makes it touch the box;
//    the closest points there are the touching point, which gives witnesses on both surfaces.
// The façade's capsule/box cells and the FCL adapter's fast path both call it.
#include <cmath>

#include "distance/distance.h"
#include "overlap/segment_box.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers
namespace {

// Separation of the segment and the box along the unit direction n (from the segment towards the box):
// min over the box of n.x minus max over the segment. It never exceeds their distance and equals it along the
// true normal.
template <class T> T separationAlong(const Vec3<T>& n, const Vec3<T>& c, const Vec3<T>& d, const Vec3<T>& h) {
  return -h.dot(n.cwiseAbs()) - n.dot(c) - std::abs(n.dot(d));
}

// Normal from the capsule to the box for a segment outside the box (dist > 0 is the segment-box distance): the
// closest-point difference, or the SAT axis where that separates more (nearly coincident closest points give a
// difference with an angle error of ~eps * size / dist; the facet's axis has none).
template <class T>
Vec3<T> outsideNormal(const SegmentBoxSat<T>& sat, const SegmentBoxClosest<T>& closest, T dist, const Vec3<T>& c,
                      const Vec3<T>& d, const Vec3<T>& h) {
  const Vec3<T> axis = -sat.direction;
  if (!(dist > T(0))) return axis;
  const Vec3<T> between = (closest.onBox - closest.onSegment) / dist;
  return separationAlong(axis, c, d, h) > separationAlong(between, c, d, h) ? axis : between;
}

}  // namespace

template <class T>
void distanceCapsuleBox(const Vec3<T>& c, const Vec3<T>& d, T r0, const Vec3<T>& h, DistanceResult<T>& local) {
  const SegmentBoxSat<T> sat = satSegmentBox(c, d, h);
  if (sat.overlap >= T(0)) {
    const SegmentBoxClosest<T> touch = closestSegmentBox(Vec3<T>(c + sat.overlap * sat.direction), d, h);
    const T depth = sat.overlap + r0;
    local.normal = -sat.direction;
    local.distance = -depth;
    local.point1 = touch.onBox;
    local.point0 = touch.onBox - depth * sat.direction;  // the segment point's ball, r0 deep along -L
    return;
  }
  const SegmentBoxClosest<T> closest = closestSegmentBox(c, d, h);
  const T dist = std::sqrt(closest.distSq);
  local.normal = outsideNormal(sat, closest, dist, c, d, h);
  local.distance = dist - r0;
  local.point0 = closest.onSegment + r0 * local.normal;
  local.point1 = closest.onBox;
}

// The capsule's segment (local X axis, half length halfHeight) in the box frame; results back in world space.
template <class T>
void distanceCapsuleBox(const CapsuleGeometry<T>& g0, const Transform<T>& pose0, const BoxGeometry<T>& g1,
                        const Transform<T>& pose1, DistanceResult<T>& out) {
  const Transform<T> inBox = pose0.relativeTo(pose1);
  const Vec3<T> d = inBox.rotate(Vec3<T>(g0.halfHeight * Vec3<T>::UnitX()));
  DistanceResult<T> local;
  distanceCapsuleBox(inBox.p, d, g0.radius, g1.halfExtents, local);
  out.distance = local.distance;
  out.normal = pose1.rotate(local.normal);
  out.point0 = pose1.transform(local.point0);
  out.point1 = pose1.transform(local.point1);
}

template void distanceCapsuleBox<float>(const CapsuleGeometry<float>&, const Transform<float>&, const BoxGeometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distanceCapsuleBox<double>(const CapsuleGeometry<double>&, const Transform<double>&, const BoxGeometry<double>&, const Transform<double>&, DistanceResult<double>&);
template void distanceCapsuleBox<float>(const Vec3<float>&, const Vec3<float>&, float, const Vec3<float>&, DistanceResult<float>&);
template void distanceCapsuleBox<double>(const Vec3<double>&, const Vec3<double>&, double, const Vec3<double>&, DistanceResult<double>&);

}  // namespace gq::kernels
