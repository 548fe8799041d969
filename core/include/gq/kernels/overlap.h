#pragma once
// Boolean overlap kernels, one per pair (overlap/<a>_<b>.cpp, a <= b in GeometryType order). Touching counts as
// overlapping. Inputs are validated by the façade (dispatch/overlap.cpp), which also expresses both poses relative
// to pose0 so that far-from-origin poses keep their precision.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

#include "gq/geometry.h"
#include "gq/kernels/gjk.h"
#include "gq/kernels/vector.h"
#include "gq/transform.h"

namespace gq::kernels {

template <class T> bool overlapSphereSphere(const SphereGeometry<T>& g0, const Transform<T>& p0, const SphereGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapSpherePlane(const SphereGeometry<T>& g0, const Transform<T>& p0, const PlaneGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapSphereCapsule(const SphereGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapSphereBox(const SphereGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapSphereConvex(const SphereGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapPlaneCapsule(const PlaneGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapPlaneBox(const PlaneGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapPlaneConvex(const PlaneGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapCapsuleCapsule(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapCapsuleBox(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapCapsuleConvex(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapBoxBox(const BoxGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapBoxConvex(const BoxGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1);
template <class T> bool overlapConvexConvex(const ConvexMeshGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1);

}  // namespace gq::kernels

namespace gq::kernels {
// Frame forms of the primitive pairs (the FCL adapter's matrix-pose fast path; the Transform kernels above call
// them). A capsule is its centre c, half-axis vector a (segment [c - a, c + a]) and radius; a box is centred at the
// origin of the frame the other shape is given in, with half extents h. Box/box: box 1 has axes r01 (columns) and
// centre t01 in box 0's frame.
// The sphere pairs' closed forms are a few instructions: inline (as calls, with the centre spilled to pass it, they
// cost the adapter's sphere rows 10-20 instructions each).
template <class T> inline bool overlapSphereSphere(const Vec3<T>& c0, T r0, const Vec3<T>& c1, T r1) {
  return normWithin(Vec3<T>(c0 - c1), r0 + r1);
}
template <class T> bool overlapSphereCapsule(const Vec3<T>& c0, T r0, const Vec3<T>& c1, const Vec3<T>& a1, T r1);
template <class T> inline bool overlapSphereBox(const Vec3<T>& cInBox, T r0, const Vec3<T>& h) {
  const Vec3<T> q = cInBox.cwiseMax(-h).cwiseMin(h);  // the box point nearest the centre
  return normWithin(Vec3<T>(cInBox - q), r0);
}
template <class T> bool overlapCapsuleCapsule(const Vec3<T>& c0, const Vec3<T>& a0, T r0, const Vec3<T>& c1, const Vec3<T>& a1, T r1);
template <class T> bool overlapCapsuleBox(const Vec3<T>& cInBox, const Vec3<T>& aInBox, T r0, const Vec3<T>& h);
template <class T> bool overlapBoxBox(const Vec3<T>& h0, const Vec3<T>& h1, const Mat3<T>& r01, const Vec3<T>& t01);
template <class T> bool overlapPlaneCustom(const PlaneGeometry<T>& g0, const Transform<T>& p0, const CustomGeometry<T>& g1, const Transform<T>& p1);
// A sphere (centre c in the cylinder's frame, whose axis is X, radius r, half height hh) against a cylinder: the solid
// cylinder's point nearest the centre clamps its axial coordinate to [-hh, hh] and its distance from the axis to
// [0, r], so the centre's distance to the cylinder is |(axial excess, radial excess)|.
template <class T> inline bool overlapSphereCylinder(const Vec3<T>& c, T radius, T cylinderRadius, T halfHeight) {
  const T axial = std::max(std::abs(c.x()) - halfHeight, T(0));
  const T radial = std::max(std::sqrt(c.y() * c.y() + c.z() * c.z()) - cylinderRadius, T(0));
  return axial * axial + radial * radial <= radius * radius;
}
// A cylinder (centre c, unit axis a, radius, half height, in the box's frame) against a box of half extents h
// centred at the origin, decided without GJK when a separating axis (a gap beyond GJK's tolerance) or a common
// point is cheap to find (cylinder_box.cpp); Unknown otherwise.
enum class OverlapCertificate : std::uint8_t { Apart, Overlapping, Unknown };
// A cylinder/box pair's length scale in the box's frame (the larger bounding radius, or the centres' distance), and
// GJK's tolerance for it (its relative tolerance times that): the certificates and the distance certificates
// (distance/box_cylinder.cpp) work to it.
template <class T> T cylinderBoxLength(const Vec3<T>& h, const Vec3<T>& c, T radius, T halfHeight);
template <class T> T cylinderBoxTolerance(const Vec3<T>& h, const Vec3<T>& c, T radius, T halfHeight);
template <class T>
OverlapCertificate cylinderBoxCertificate(const Vec3<T>& c, const Vec3<T>& a, T radius, T halfHeight, const Vec3<T>& h);
// Two convex hulls by their cooked balls (ConvexMesh::innerRadius / outerRadius about `center`, placed and
// scaled): Apart when the outer balls are apart, Overlapping when the inner ones overlap, each by more than GJK's
// band; Unknown otherwise (convex_convex.cpp).
template <class T> struct HullBalls {
  Vec3<T> center;
  T inner, outer;
};
template <class T> OverlapCertificate hullBallsCertificate(const HullBalls<T>& a, const HullBalls<T>& b);
// The balls of a placed hull (convex_convex.cpp), and of a sphere, capsule (the ball of its radius about its centre,
// and the one reaching its caps) and box (the largest inside, the one through its corners): the sphere, capsule and
// box pairs with a hull run the same certificate before GJK.
template <class T> HullBalls<T> hullBalls(const ConvexMeshGeometry<T>& g, const Transform<T>& pose);
template <class T> HullBalls<T> hullBalls(const SphereGeometry<T>& g, const Transform<T>& pose) {
  return {pose.p, g.radius, g.radius};
}
template <class T> HullBalls<T> hullBalls(const CapsuleGeometry<T>& g, const Transform<T>& pose) {
  return {pose.p, g.radius, g.radius + g.halfHeight};
}
template <class T> HullBalls<T> hullBalls(const BoxGeometry<T>& g, const Transform<T>& pose) {
  return {pose.p, g.halfExtents.minCoeff(), g.halfExtents.norm()};
}
// Convex custom geometry (either side) against sphere, capsule, box, convex or custom: GJK.
template <class T> bool overlapCustomAny(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1);

// Half-width of the band of touching, relative to the larger shape's size, inside which GJK's boolean answer is not
// trusted (it is 50x (float) / 1000x (double) GJK's stopping tolerance, see gjk.h).
template <class T> inline constexpr T kGjkOverlapBand = std::is_same_v<T, float> ? T(1e-4) : T(1e-9);

// Boolean overlap of two convex shapes (sphere, capsule, box, convex mesh): GJK decides, except within a band of
// touching (kGjkOverlapBand) where GJK's tolerance could flip the answer;
// there the exact kernels above decide. Touching counts as overlapping.
template <class T>
bool overlapConvexShapes(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1);
// Its GJK part on prepared shapes: Apart or Overlapping when GJK decides beyond the band, else Unknown (the exact
// kernels' turn). `a` is taken by value: the function grows its own copy by the band (a temporary is not copied).
template <class T> OverlapCertificate overlapByGjk(ConvexShape<T> a, const ConvexShape<T>& b);

}  // namespace gq::kernels
