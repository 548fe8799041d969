#pragma once
// Point-distance kernels (point_distance/<shape>.cpp); the façade is dispatch/point_distance.cpp.
// Each writes distance (0 inside solids), closestPoint (world) and closestIndex (meshes).
#include "gq/geometry.h"
#include "gq/query.h"
#include "gq/transform.h"

namespace gq::detail {

template <class T>
void pointDistanceSphere(const SphereGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point, PointDistanceResult<T>& out);
template <class T>
void pointDistanceCapsule(const CapsuleGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point, PointDistanceResult<T>& out);
template <class T>
void pointDistanceBox(const BoxGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point, PointDistanceResult<T>& out);
template <class T>
void pointDistanceConvex(const ConvexMeshGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point, PointDistanceResult<T>& out);
template <class T>
void pointDistanceTriangleMesh(const TriangleMeshGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point, PointDistanceResult<T>& out);

}  // namespace gq::detail
