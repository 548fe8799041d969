#pragma once
// Closest points between points and segments: the exact kernels behind every sphere/capsule pair.
#include "gq/math.h"
#include "gq/transform.h"

namespace gq::detail {

template <class T> struct Segment {
  Vec3<T> a, b;
};

// Parameter t in [0,1] of the point of segment s closest to p.
template <class T> T closestParameterOnSegment(const Segment<T>& s, const Vec3<T>& p);
template <class T> Vec3<T> closestPointOnSegment(const Segment<T>& s, const Vec3<T>& p);

template <class T> struct SegmentPair {
  Vec3<T> p0, p1;  // closest point on the first and on the second segment
};
// Closest points of two segments (either may have zero length); exact up to rounding.
template <class T> SegmentPair<T> closestPointsSegmentSegment(const Segment<T>& s0, const Segment<T>& s1);

// A unit vector perpendicular to v (v need not be unit; v == 0 gives +Y).
template <class T> Vec3<T> anyPerpendicular(const Vec3<T>& v);

}  // namespace gq::detail

namespace gq::detail {
// Outward normal (+X of its frame) of a plane at `pose`; the solid half-space is n.(x - pose.p) <= 0.
template <class T> Vec3<T> planeNormal(const Transform<T>& pose) { return pose.rotate(Vec3<T>::UnitX()); }
}  // namespace gq::detail
