#pragma once
// Signed-distance kernels, one per pair with a closed form (distance/<a>_<b>.cpp, a <= b in GeometryType order),
// and the GJK/EPA kernel for every other convex pair. Inputs are validated by the façade (dispatch/distance.cpp).
// Conventions (as gq::DistanceResult): normal is unit from geom0 towards geom1, point0 on geom0, point1 on geom1,
// point1 = point0 + distance * normal; when penetrating, translating geom1 by -distance * normal separates them.
// When the normal is undefined (coincident centres, intersecting axes) the kernels pick a documented direction.
#include <cmath>
#include <cstdint>
#include <limits>

#include "gq/kernels/vector.h"
#include "gq/kernels/segment.h"
#include "gq/geometry.h"
#include "gq/query.h"
#include "gq/transform.h"

namespace gq::kernels {

template <class T>
void distanceSphereSphere(const SphereGeometry<T>& g0, const Transform<T>& pose0, const SphereGeometry<T>& g1,
                          const Transform<T>& pose1, DistanceResult<T>& out);
template <class T>
void distanceSpherePlane(const SphereGeometry<T>& g0, const Transform<T>& pose0, const PlaneGeometry<T>& g1,
                         const Transform<T>& pose1, DistanceResult<T>& out);
template <class T>
void distanceSphereCapsule(const SphereGeometry<T>& g0, const Transform<T>& pose0, const CapsuleGeometry<T>& g1,
                           const Transform<T>& pose1, DistanceResult<T>& out);
template <class T>
void distanceSphereBox(const SphereGeometry<T>& g0, const Transform<T>& pose0, const BoxGeometry<T>& g1,
                       const Transform<T>& pose1, DistanceResult<T>& out);
template <class T>
void distancePlaneCapsule(const PlaneGeometry<T>& g0, const Transform<T>& pose0, const CapsuleGeometry<T>& g1,
                          const Transform<T>& pose1, DistanceResult<T>& out);
template <class T>
void distancePlaneBox(const PlaneGeometry<T>& g0, const Transform<T>& pose0, const BoxGeometry<T>& g1,
                      const Transform<T>& pose1, DistanceResult<T>& out);
// Plane against a convex mesh or a convex custom shape, through the support mapping (exact: a plane's distance
// to a convex set is attained at the support point along -normal).
template <class T>
void distancePlaneConvex(const PlaneGeometry<T>& g0, const Transform<T>& pose0, const Geometry<T>& g1,
                         const Transform<T>& pose1, DistanceResult<T>& out);
template <class T>
void distanceCapsuleCapsule(const CapsuleGeometry<T>& g0, const Transform<T>& pose0, const CapsuleGeometry<T>& g1,
                            const Transform<T>& pose1, DistanceResult<T>& out);
template <class T>
void distanceCapsuleBox(const CapsuleGeometry<T>& g0, const Transform<T>& pose0, const BoxGeometry<T>& g1,
                        const Transform<T>& pose1, DistanceResult<T>& out);

// Frame forms of the primitive pairs (the FCL adapter's matrix-pose fast path; the Transform kernels above call
// them). A capsule is its centre, unit axis, half height and radius, given in the same frame as the other shape;
// sphere/box and capsule/box work in the box's frame (box [-h, h]) and write `local` in that frame.
template <class T> struct CapsuleAxis {
  Vec3<T> centre, axis;
  T halfHeight, radius;
};
template <class T>
void distanceSphereCapsule(const Vec3<T>& c0, T r0, const CapsuleAxis<T>& capsule1, DistanceResult<T>& out);
// The sphere's centre inside the box (sphere_box.cpp); distanceSphereBox below answers every centre. These cold
// paths take scalars and return by value, as ballsNormalOutOfRange below (references kept the callers' values in
// memory).
template <class T> [[gnu::cold]] DistanceResult<T> distanceSphereInsideBox(T cx, T cy, T cz, T r0, T hx, T hy, T hz);
// The sphere's centre inside the cylinder (sphere_cylinder.cpp); distanceSphereCylinder below answers every centre.
template <class T> [[gnu::cold]] DistanceResult<T> distanceSphereInsideCylinder(T cx, T cy, T cz, T r0, T r, T hh);
// The normal of two capsules whose axes intersect (capsule_capsule.cpp): the minimum translation is along the common
// perpendicular d0 x d1, oriented along `towards` (the Minkowski difference of two segments is flat), or orthogonal
// to the axis when they are parallel.
template <class T> [[gnu::cold]] Vec3<T> intersectingAxesNormal(const Vec3<T>& d0, const Vec3<T>& d1, const Vec3<T>& towards);
// Capsule (segment c + s d, s in [-1, 1], radius r0) against the box [-h, h], exact (distance/capsule_box.cpp).
template <class T>
void distanceCapsuleBox(const Vec3<T>& cInBox, const Vec3<T>& dInBox, T r0, const Vec3<T>& h, DistanceResult<T>& local);

// Box [-h, h] against a cylinder (centre c, unit axis a, radius r, half height hh) in the box's frame, where a
// witness pair attaining a separating plane's gap proves the answer within GJK's tolerance for the pair
// (cylinderBoxTolerance; distance/box_cylinder.cpp):
// Separated (local written: point0 on the box, point1 on the cylinder), Overlapping (a common point found; local
// untouched) or Unknown (touching within the tolerance, or nothing proven: GJK answers).
enum class BoxCylinderDistance : std::uint8_t { Separated, Overlapping, Unknown };
template <class T>
BoxCylinderDistance distanceBoxCylinderLocal(const Vec3<T>& h, const Vec3<T>& c, const Vec3<T>& a, T r, T hh,
                                             DistanceResult<T>& local);

// Boxes in box 0's frame (box 1: axes r01 as columns, centre t01), exact (distance/box_box.cpp): the closest points
// of separated boxes, or the SAT depth and normal of overlapping ones with witnesses on both. False only in the rare
// overlapping parallel-face case where no witness is found (then GJK/EPA answers).
template <class T>
bool distanceBoxBoxLocal(const Vec3<T>& h0, const Vec3<T>& h1, const Mat3<T>& r01, const Vec3<T>& t01,
                         DistanceResult<T>& local);
// The same without an overlap's witnesses: separated boxes' closest points (true), or false for overlapping boxes
// with nothing written (the witnesses of a depth cost a search the caller may not want: the FCL adapter's distance
// without enable_signed_distance answers FCL's -1).
template <class T>
bool separatedBoxBoxLocal(const Vec3<T>& h0, const Vec3<T>& h1, const Mat3<T>& r01, const Vec3<T>& t01,
                          DistanceResult<T>& local);

// Any two of sphere, capsule, box, convex mesh, convex custom: GJK on the cores, EPA when they overlap. Returns Ok,
// or Warning when GJK/EPA stopped with an error bound above tolerance (the best answer is still written).
// `stopTolerance`: GJK's (gjk.h); EPA keeps its own. `farEnough`: GJK's; a pair proven farther gets only
// out.distance, a lower bound above it (distanceWithin's contract).
template <class T>
Status distanceGjk(const Geometry<T>& g0, const Transform<T>& pose0, const Geometry<T>& g1, const Transform<T>& pose1,
                   GjkCache<T>* cache, DistanceResult<T>& out, T stopTolerance = T(0),
                   T farEnough = std::numeric_limits<T>::infinity());

// |d| and the unit normal d / |d| when |d|^2 over- or underflows (rangeSafeNorm, tryUnit), `fallback` when d is zero
// or not finite. Out of line, d's components in and the answer out by value: a vector passed by reference would be
// address-taken, and GCC then kept the caller's vectors in memory on every call, not only on this path.
template <class T> struct NormAndUnit {
  T norm;
  Vec3<T> unit;
};
template <class T>
[[gnu::cold, gnu::noinline]] NormAndUnit<T> ballsNormalOutOfRange(T dx, T dy, T dz, const Vec3<T>* fallback) {
  const Vec3<T> d(dx, dy, dz);
  return {rangeSafeNorm(d), unitOr(d, *fallback)};
}

// Result of two balls: centres c0, c1, radii r0, r1. d = |c1 - c0| - r0 - r1 along n = (c1 - c0) / |c1 - c0|;
// witnesses c0 + r0 n and c1 - r1 n. `fallback()` gives the normal when the centres coincide; it is called only on
// the cold path where |c1 - c0|^2 is zero or out of range (an eager fallback kept its inputs and the closest points
// in memory on every call). Always inline: the building block of sphere/sphere, sphere/capsule, sphere/box and
// capsule/capsule, where a call and its spills cost ~20 instructions (plain `inline` was dropped by GCC once it had
// four callers). The inputs are read before `out` is written (the caller's centres may live in it).
template <class T, class Fallback>
[[gnu::always_inline]] inline void ballsDistanceOr(const Vec3<T>& c0, T r0, const Vec3<T>& c1, T r1, Fallback fallback,
                                                   DistanceResult<T>& out) {
  // Copies and delta written out: GCC sometimes leaves Eigen's difference constructor out of line here (a call on
  // every answer) and copied whole centres through memory.
  const Vec3<T> p0(c0.x(), c0.y(), c0.z()), p1(c1.x(), c1.y(), c1.z());
  const Vec3<T> delta(p1.x() - p0.x(), p1.y() - p0.y(), p1.z() - p0.z());
  const T len2 = delta.squaredNorm();
  Vec3<T> n;
  T len;
  if (len2 >= std::numeric_limits<T>::min() && len2 <= std::numeric_limits<T>::max()) [[likely]] {
    len = std::sqrt(len2);
    n = delta / len;
  } else {
    const Vec3<T> normal = fallback();
    const NormAndUnit<T> safe = ballsNormalOutOfRange(delta.x(), delta.y(), delta.z(), &normal);
    len = safe.norm;
    n = safe.unit;
  }
  out.distance = len - r0 - r1;
  out.normal = n;
  out.point0 = p0 + r0 * n;
  out.point1 = p1 - r1 * n;
}
// The same with +X as the coincident centres' normal.
template <class T>
[[gnu::always_inline]] inline void ballsDistance(const Vec3<T>& c0, T r0, const Vec3<T>& c1, T r1, DistanceResult<T>& out) {
  ballsDistanceOr(c0, r0, c1, r1, [] { return Vec3<T>(Vec3<T>::UnitX()); }, out);
}

// Sphere (centre c in the box's frame) vs box [-h, h], in that frame: outside, the closest box point is the
// clamped centre. Inline: the FCL adapter's sphere-box distance is a few dozen instructions around it.
template <class T>
[[gnu::always_inline]] inline void distanceSphereBox(const Vec3<T>& c, T r0, const Vec3<T>& h, DistanceResult<T>& local) {
  const Vec3<T> q = c.cwiseMax(-h).cwiseMin(h);
  if (q != c) [[likely]] {
    ballsDistance(c, r0, q, T(0), local);
  } else {
    local = distanceSphereInsideBox(c.x(), c.y(), c.z(), r0, h.x(), h.y(), h.z());
  }
}

// A sphere (centre c in the cylinder's frame, whose axis is X) against a cylinder of radius r and half height hh; the
// result is in that frame. Outside, the cylinder's closest point is beside the centre on the side (distance
// rho - r along the radial direction), over it on a cap (|x| - hh along the axis) or on a rim (two balls): the side
// and cap answers need no second square root and division, which chained after the first were most of a call's
// time. Inline: the FCL adapter's sphere-cylinder distance is a few dozen instructions around it.
template <class T>
[[gnu::always_inline]] inline void distanceSphereCylinder(const Vec3<T>& c, T r0, T r, T hh, DistanceResult<T>& local) {
  const T rho2 = c.y() * c.y() + c.z() * c.z();  // hypot where the squares over- or underflow
  const T rho = rho2 >= std::numeric_limits<T>::min() && rho2 <= std::numeric_limits<T>::max()
                    ? std::sqrt(rho2) : std::hypot(c.y(), c.z());
  const T axialGap = std::abs(c.x()) - hh, radialGap = rho - r;
  const T side = c.x() < T(0) ? T(-1) : T(1);
  if (axialGap <= T(0)) {
    if (radialGap <= T(0)) [[unlikely]] {
      local = distanceSphereInsideCylinder(c.x(), c.y(), c.z(), r0, r, hh);
      return;
    }
    const Vec3<T> radial(T(0), c.y() / rho, c.z() / rho);  // rho > r > 0
    local.distance = radialGap - r0;
    local.normal = -radial;
    local.point0 = c - r0 * radial;
    local.point1 = Vec3<T>(c.x(), r * radial.y(), r * radial.z());
  } else if (radialGap <= T(0)) {
    local.distance = axialGap - r0;
    local.normal = Vec3<T>(-side, T(0), T(0));
    local.point0 = Vec3<T>(c.x() - side * r0, c.y(), c.z());
    local.point1 = Vec3<T>(side * hh, c.y(), c.z());
  } else {
    ballsDistance(c, r0, Vec3<T>(side * hh, r * (c.y() / rho), r * (c.z() / rho)), T(0), local);
  }
}

// Capsule vs capsule: balls at the closest points of the two segments (inline: the FCL adapter's capsule-capsule
// distance is a few dozen instructions around it). Closest points that coincide (intersecting axes) take the normal
// `coincident()` returns, intersectingAxesNormal of the axes; a caller holding the axes in memory reads them there
// (a capture of k0 and k1 kept both in memory on every call).
template <class T, class Coincident>
[[gnu::always_inline]] inline void distanceCapsuleCapsule(const CapsuleAxis<T>& k0, const CapsuleAxis<T>& k1,
                                                          Coincident coincident, DistanceResult<T>& out) {
  const Vec3<T> a0 = k0.halfHeight * k0.axis, a1 = k1.halfHeight * k1.axis;
  const SegmentClosest<T> c = closestCentredSegments<T>(k0.centre, a0, k1.centre, a1);
  ballsDistanceOr(c.c0, k0.radius, c.c1, k1.radius, coincident, out);
}
template <class T>
[[gnu::always_inline]] inline void distanceCapsuleCapsule(const CapsuleAxis<T>& k0, const CapsuleAxis<T>& k1,
                                                          DistanceResult<T>& out) {
  distanceCapsuleCapsule(k0, k1, [&] { return intersectingAxesNormal<T>(k0.axis, k1.axis, k1.centre - k0.centre); },
                         out);
}

}  // namespace gq::kernels
