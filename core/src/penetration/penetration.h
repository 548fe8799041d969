#pragma once
// Penetration (MTD) kernels, one per pair (penetration/<a>_<b>.cpp, a <= b in GeometryType order). Each returns
// false when separated; otherwise writes a unit `direction` and `depth` >= 0 such that translating geom0 by
// direction * depth separates the shapes (touching: depth 0). Inputs are validated by the façade
// (dispatch/penetration.cpp), which also expresses both poses relative to pose0.
#include "gq/geometry.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq::detail {

template <class T> bool penetrationSphereSphere(const SphereGeometry<T>& g0, const Transform<T>& p0, const SphereGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationSpherePlane(const SphereGeometry<T>& g0, const Transform<T>& p0, const PlaneGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationSphereCapsule(const SphereGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationSphereBox(const SphereGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationSphereConvex(const SphereGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationPlaneCapsule(const PlaneGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationPlaneBox(const PlaneGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationPlaneConvex(const PlaneGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationCapsuleCapsule(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const CapsuleGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationCapsuleBox(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationCapsuleConvex(const CapsuleGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationBoxBox(const BoxGeometry<T>& g0, const Transform<T>& p0, const BoxGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationBoxConvex(const BoxGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);
template <class T> bool penetrationConvexConvex(const ConvexMeshGeometry<T>& g0, const Transform<T>& p0, const ConvexMeshGeometry<T>& g1, const Transform<T>& p1,
                                     Vec3<T>& direction, T& depth);

}  // namespace gq::detail

namespace gq::detail {
template <class T> bool penetrationPlaneCustom(const PlaneGeometry<T>& g0, const Transform<T>& p0, const CustomGeometry<T>& g1, const Transform<T>& p1,
                                               Vec3<T>& direction, T& depth);
// Convex custom geometry (either side) against sphere, capsule, box, convex or custom: GJK + EPA. EPA out of
// iterations: its best upper bound, with a Warning.
template <class T> Status penetrationCustomAny(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                                               bool& penetrating, Vec3<T>& direction, T& depth);
}  // namespace gq::detail
