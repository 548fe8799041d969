#pragma once
// Point-distance kernels (point_distance/<shape>.cpp); the façade is dispatch/point_distance.cpp.
// Each writes distance (0 inside solids), closestPoint (world) and closestIndex (meshes).
#include "gq/geometry.h"
#include "gq/query.h"
#include "gq/transform.h"
#include "common/unit_vector.h"

namespace gq::detail {

// Point vs the ball of `radius` about `center` (world): distance 0 and the point itself inside, else |m| - r and
// center + r m/|m| with m = point - center (`away`, a unit vector, when m is too short to have a direction).
template <class T>
void pointDistanceBall(const Vec3<T>& center, T radius, const Vec3<T>& point, const Vec3<T>& away,
                       PointDistanceResult<T>& out) {
  const Vec3<T> m = point - center;
  const T len = m.norm();
  out.closestIndex = kInvalidFaceIndex;
  if (len <= radius) {
    out.distance = T(0);
    out.closestPoint = point;
    return;
  }
  out.distance = len - radius;
  out.closestPoint = center + radius * unitOr(m, away);
}

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
