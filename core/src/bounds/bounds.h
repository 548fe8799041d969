#pragma once
// World-space AABB kernels, one per shape (bounds/<shape>.cpp), without offset/inflation (the façade in
// dispatch/bounds.cpp applies those). Inputs are validated.
#include "gq/custom.h"
#include "gq/geometry.h"
#include "gq/transform.h"

namespace gq::detail {

template <class T> Bounds3<T> boundsSphere(const SphereGeometry<T>& g, const Transform<T>& pose);
template <class T> Bounds3<T> boundsPlane(const PlaneGeometry<T>& g, const Transform<T>& pose);
template <class T> Bounds3<T> boundsCapsule(const CapsuleGeometry<T>& g, const Transform<T>& pose);
template <class T> Bounds3<T> boundsBox(const BoxGeometry<T>& g, const Transform<T>& pose);
template <class T> Bounds3<T> boundsConvex(const ConvexMeshGeometry<T>& g, const Transform<T>& pose);
template <class T> Bounds3<T> boundsTriangleMesh(const TriangleMeshGeometry<T>& g, const Transform<T>& pose);
template <class T> Bounds3<T> boundsHeightField(const HeightFieldGeometry<T>& g, const Transform<T>& pose);
template <class T> Bounds3<T> boundsCustom(const CustomGeometry<T>& g, const Transform<T>& pose);

}  // namespace gq::detail
