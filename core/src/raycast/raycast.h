#pragma once
// Raycast kernels, one per target shape (raycast/<shape>.cpp). Inputs are validated by the façade
// (dispatch/raycast.cpp): finite origin, unit dir, maxDist >= 0, maxHits >= 1, valid geometry and pose.
// A kernel writes at most ray.maxHits hits and returns how many; it fills only the fields ray.flags ask for and
// sets each hit's flags to what it filled.
#include <cstdint>

#include "gq/custom.h"
#include "gq/geometry.h"
#include "gq/hit.h"
#include "gq/transform.h"

namespace gq::detail {

template <class T> struct RayQuery {
  Vec3<T> origin;  // world
  Vec3<T> dir;     // world, unit
  T maxDist;
  HitFlags flags;
  std::uint32_t maxHits;
};

template <class T>
std::uint32_t raycastSphere(const SphereGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastPlane(const PlaneGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastCapsule(const CapsuleGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastBox(const BoxGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastConvex(const ConvexMeshGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastTriangleMesh(const TriangleMeshGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
// Mesh raycasts walk 8-wide nodes with AVX2 where the CPU has it; true makes them use the SSE4.2 baseline (two 4-lane
// halves per node) on any CPU, so tests can compare both walks on one machine. Not for use while rays are cast.
void setMeshRaycastBaselineOnly(bool baselineOnly);
template <class T>
std::uint32_t raycastHeightField(const HeightFieldGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);
template <class T>
std::uint32_t raycastCustom(const CustomGeometry<T>& g, const Transform<T>& pose, const RayQuery<T>& ray, RaycastHit<T>* hits);

}  // namespace gq::detail
