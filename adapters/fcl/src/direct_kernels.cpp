// Direct calls of core's pair kernels (see direct_kernels.h). Kernels are written for a <= b in GeometryType
// order: overlap is symmetric, so a reversed pair swaps its inputs; a reversed distance swaps and flips the answer
// (witnesses exchanged, normal negated), as the façade's `swapped` wrapper does.
#include "direct_kernels.h"

#include <utility>

#include "custom/callback_queries.h"
#include "distance/distance.h"
#include "overlap/overlap.h"

namespace gq::fcl::detail {
namespace {

using GT = GeometryType;

constexpr int pairCode(GT a, GT b) { return int(a) * kGeometryTypeCount + int(b); }

template <class T> using Sph = SphereGeometry<T>;
template <class T> using Pln = PlaneGeometry<T>;
template <class T> using Cap = CapsuleGeometry<T>;
template <class T> using Box = BoxGeometry<T>;
template <class T> using Cvx = ConvexMeshGeometry<T>;
template <class T> using Cst = CustomGeometry<T>;

// b's pose in a's frame (the façade runs overlap kernels with pose0 = identity, keeping precision far from the
// origin). A sphere's pose has no rotation: only the translation changes.
template <class T> Transform<T> relative(const Transform<T>& pa, const Transform<T>& pb) {
  if (pa.q.w() == T(1)) return Transform<T>(Vec3<T>(pb.p - pa.p), pb.q);
  return pb.relativeTo(pa);
}

// A custom shape on either side: its own overlap callback first (as the façade), else the plane form or GJK.
template <class T>
bool overlapWithCustom(const Geometry<T>& a, const Transform<T>& pa, const Geometry<T>& b, const Transform<T>& pb) {
  bool hit = false;
  if (gq::detail::customOverlap(a, pa, b, pb, hit)) return hit;
  if (a.type() == GT::Plane) return gq::detail::overlapPlaneCustom(a.template get<Pln<T>>(), pa, b.template get<Cst<T>>(), pb);
  return gq::detail::overlapCustomAny(a, pa, b, pb);
}

// Ordered pair (a.type() <= b.type()), b's pose relative to a's.
template <class T>
bool overlapOrdered(const Geometry<T>& a, const Transform<T>& pa, const Geometry<T>& b, const Transform<T>& pb, bool& hit) {
  namespace k = gq::detail;
  if (b.type() == GT::Custom) {
    hit = overlapWithCustom(a, pa, b, pb);
    return true;
  }
  switch (pairCode(a.type(), b.type())) {
    case pairCode(GT::Sphere, GT::Sphere): hit = k::overlapSphereSphere(a.template get<Sph<T>>(), pa, b.template get<Sph<T>>(), pb); return true;
    case pairCode(GT::Sphere, GT::Plane): hit = k::overlapSpherePlane(a.template get<Sph<T>>(), pa, b.template get<Pln<T>>(), pb); return true;
    case pairCode(GT::Sphere, GT::Capsule): hit = k::overlapSphereCapsule(a.template get<Sph<T>>(), pa, b.template get<Cap<T>>(), pb); return true;
    case pairCode(GT::Sphere, GT::Box): hit = k::overlapSphereBox(a.template get<Sph<T>>(), pa, b.template get<Box<T>>(), pb); return true;
    case pairCode(GT::Sphere, GT::ConvexMesh): hit = k::overlapSphereConvex(a.template get<Sph<T>>(), pa, b.template get<Cvx<T>>(), pb); return true;
    case pairCode(GT::Plane, GT::Capsule): hit = k::overlapPlaneCapsule(a.template get<Pln<T>>(), pa, b.template get<Cap<T>>(), pb); return true;
    case pairCode(GT::Plane, GT::Box): hit = k::overlapPlaneBox(a.template get<Pln<T>>(), pa, b.template get<Box<T>>(), pb); return true;
    case pairCode(GT::Plane, GT::ConvexMesh): hit = k::overlapPlaneConvex(a.template get<Pln<T>>(), pa, b.template get<Cvx<T>>(), pb); return true;
    case pairCode(GT::Capsule, GT::Capsule): hit = k::overlapCapsuleCapsule(a.template get<Cap<T>>(), pa, b.template get<Cap<T>>(), pb); return true;
    case pairCode(GT::Capsule, GT::Box): hit = k::overlapCapsuleBox(a.template get<Cap<T>>(), pa, b.template get<Box<T>>(), pb); return true;
    case pairCode(GT::Capsule, GT::ConvexMesh): hit = k::overlapCapsuleConvex(a.template get<Cap<T>>(), pa, b.template get<Cvx<T>>(), pb); return true;
    case pairCode(GT::Box, GT::Box): hit = k::overlapBoxBox(a.template get<Box<T>>(), pa, b.template get<Box<T>>(), pb); return true;
    case pairCode(GT::Box, GT::ConvexMesh): hit = k::overlapBoxConvex(a.template get<Box<T>>(), pa, b.template get<Cvx<T>>(), pb); return true;
    case pairCode(GT::ConvexMesh, GT::ConvexMesh): hit = k::overlapConvexConvex(a.template get<Cvx<T>>(), pa, b.template get<Cvx<T>>(), pb); return true;
    default: return false;  // plane against plane, surfaces
  }
}

// The closed forms (ordered pair); false for pairs that go to GJK.
template <class T>
bool closedFormDistance(const Geometry<T>& a, const Transform<T>& pa, const Geometry<T>& b, const Transform<T>& pb,
                        DistanceResult<T>& out) {
  namespace k = gq::detail;
  switch (pairCode(a.type(), b.type())) {
    case pairCode(GT::Sphere, GT::Sphere): k::distanceSphereSphere(a.template get<Sph<T>>(), pa, b.template get<Sph<T>>(), pb, out); return true;
    case pairCode(GT::Sphere, GT::Plane): k::distanceSpherePlane(a.template get<Sph<T>>(), pa, b.template get<Pln<T>>(), pb, out); return true;
    case pairCode(GT::Sphere, GT::Capsule): k::distanceSphereCapsule(a.template get<Sph<T>>(), pa, b.template get<Cap<T>>(), pb, out); return true;
    case pairCode(GT::Sphere, GT::Box): k::distanceSphereBox(a.template get<Sph<T>>(), pa, b.template get<Box<T>>(), pb, out); return true;
    case pairCode(GT::Plane, GT::Capsule): k::distancePlaneCapsule(a.template get<Pln<T>>(), pa, b.template get<Cap<T>>(), pb, out); return true;
    case pairCode(GT::Plane, GT::Box): k::distancePlaneBox(a.template get<Pln<T>>(), pa, b.template get<Box<T>>(), pb, out); return true;
    case pairCode(GT::Plane, GT::ConvexMesh):
    case pairCode(GT::Plane, GT::Custom): k::distancePlaneConvex(a.template get<Pln<T>>(), pa, b, pb, out); return true;
    case pairCode(GT::Capsule, GT::Capsule): k::distanceCapsuleCapsule(a.template get<Cap<T>>(), pa, b.template get<Cap<T>>(), pb, out); return true;
    default: return false;
  }
}

template <class T> void flip(DistanceResult<T>& d) {
  std::swap(d.point0, d.point1);
  d.normal = -d.normal;
}

template <class T> bool isSupportMapped(GT t) {
  return t == GT::Sphere || t == GT::Capsule || t == GT::Box || t == GT::ConvexMesh || t == GT::Custom;
}

template <class T> bool finiteResult(const DistanceResult<T>& r) {
  return std::isfinite(r.distance) && isFinite(r.point0) && isFinite(r.point1) && isFinite(r.normal);
}

}  // namespace

template <class T>
bool directOverlap(const Geometry<T>& a, const Transform<T>& pa, const Geometry<T>& b, const Transform<T>& pb, bool& hit) {
  if (a.type() <= b.type()) return overlapOrdered(a, Transform<T>(), b, relative(pa, pb), hit);
  return overlapOrdered(b, Transform<T>(), a, relative(pb, pa), hit);
}

template <class T>
bool directDistance(const Geometry<T>& a, const Transform<T>& pa, const Geometry<T>& b, const Transform<T>& pb,
                    DistanceResult<T>& out) {
  const bool ordered = a.type() <= b.type();
  bool answered = ordered ? closedFormDistance(a, pa, b, pb, out) : closedFormDistance(b, pb, a, pa, out);
  if (answered && !ordered) flip(out);
  if (!answered && isSupportMapped<T>(a.type()) && isSupportMapped<T>(b.type()))
    answered = gq::detail::distanceGjk(a, pa, b, pb, static_cast<GjkCache<T>*>(nullptr), out).ok();
  return answered && finiteResult(out);
}

template bool directOverlap<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                   const Transform<float>&, bool&);
template bool directOverlap<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                    const Transform<double>&, bool&);
template bool directDistance<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                    const Transform<float>&, DistanceResult<float>&);
template bool directDistance<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                     const Transform<double>&, DistanceResult<double>&);

}  // namespace gq::fcl::detail
