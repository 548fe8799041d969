#pragma once
// The gq side of the adapter: contacts and distances of one converted pair in world space, FCL's conventions
// (normal from the first geometry to the second, positive depth, triangle ids of mesh sides). No FCL types here.
#include <cstddef>
#include <limits>
#include <vector>

#include "convert.h"
#include "gq/mesh_query.h"
#include "gq/status.h"

namespace gq::fcl::internal {

inline constexpr int kNoPrimitive = -1;  // FCL's Contact::NONE / DistanceResult::NONE

template <class T> struct PairContact {
  Vec3<T> position = Vec3<T>::Zero();  // midway between the two deepest points
  Vec3<T> normal = Vec3<T>::Zero();    // from a to b
  T depth = T(0);                      // >= 0
  int b1 = kNoPrimitive, b2 = kNoPrimitive;
};

template <class T> struct PairDistance {
  T distance = T(0);  // signed for convex pairs; meshes are thin surfaces (>= 0)
  Vec3<T> point1 = Vec3<T>::Zero(), point2 = Vec3<T>::Zero();
  int b1 = kNoPrimitive, b2 = kNoPrimitive;
};

// The candidate volume of a shape findOverlapTriangleMesh does not take itself (not a sphere, capsule or box): its
// local bounding box or, for a convex mesh whose circumsphere about the box's centre has the smaller volume (round
// hulls), that sphere: a sphere-triangle test costs a fraction of the box-triangle separating-axis test.
template <class T> Status candidateVolume(const Geometry<T>& g, CandidateVolume<T>& out);

// Contact of `shape` with one world triangle (hit: distance <= 0); normal from the triangle to the shape, position
// midway between the deepest points (a sphere: FCL's, the triangle's point nearest its centre).
template <class T>
Status triangleContact(const Geometry<T>& shape, const Transform<T>& pose, const Triangle<T>& triangle,
                       PairContact<T>& contact, bool& hit);

// Appends up to `room` contacts of a colliding pair (one per primitive pair, as FCL). Without `withGeometry` only
// b1/b2 are meaningful. A non-ok status means gq cannot answer the pair (the caller falls back to FCL).
template <class T>
Status pairContacts(const Converted<T>& a, const Transform<T>& poseA, const Converted<T>& b, const Transform<T>& poseB,
                    bool withGeometry, std::size_t room, std::vector<PairContact<T>>& out);

// `farEnough`: the distance to beat (FCL's pre-seeded min_distance); a pair proven farther gets only a lower bound
// above it in out.distance (gq's distanceWithin), no witnesses or triangle ids.
template <class T>
Status pairDistance(const Converted<T>& a, const Transform<T>& poseA, const Converted<T>& b, const Transform<T>& poseB,
                    PairDistance<T>& out, T farEnough = std::numeric_limits<T>::infinity());

}  // namespace gq::fcl::internal
