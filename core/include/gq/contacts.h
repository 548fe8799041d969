#pragma once
// Contact generation between a convex geometry and one triangle (the spec's PxGeometryQuery::generateTriangleContacts).
#include <array>
#include <cstdint>

#include "gq/geometry.h"
#include "gq/math.h"
#include "gq/mesh_query.h"
#include "gq/status.h"
#include "gq/transform.h"

namespace gq {

template <class T> struct ContactPoint {
  Vec3<T> position = Vec3<T>::Zero();  // on the geometry's surface (world)
  Vec3<T> normal = Vec3<T>::Zero();    // unit, from the triangle towards the geometry
  T separation = T(0);                 // signed along normal: > 0 gap, < 0 penetration depth
  std::uint32_t triangleIndex = kInvalidFaceIndex;
};

inline constexpr std::uint32_t kMaxTriangleContacts = 4;
template <class T> struct ContactBuffer {
  std::array<ContactPoint<T>, kMaxTriangleContacts> contacts{};
  std::uint32_t count = 0;
};

// The distances of a triangle-contact query, all lengths in the caller's unit.
template <class T> struct TriangleContactSettings {
  // >= 0: points whose separation is <= contactDistance are reported.
  T contactDistance = T(0);
  // >= 0: the triangle's face normal replaces the closest-feature normal when the separation along the face normal is
  // within meshContactMargin of the true separation (stable resting contacts on flat areas); otherwise (edge-on
  // contacts) the single closest point is reported along the closest-feature normal.
  T meshContactMargin = T(0);
  // > 0: the length unit of the simulation; contact points closer than kContactMergeFactor * toleranceLength are
  // merged and points within it of the triangle's boundary count as inside.
  T toleranceLength = T(1);
};

// Contacts of a capsule, box or convex mesh (others: Unsupported) at `pose` with `triangle` (vertices in the same
// world space; either side counts). `contacts` receives at most 4 points, the deepest always kept, all sharing one
// normal (from the triangle towards the shape); contacts.count == 0 when none is within contactDistance. Each point
// carries `triangleIndex`.
// Invalid input (non-finite pose or vertices, negative distances, toleranceLength <= 0): InvalidArgument, nothing
// written.
template <class T>
Status generateTriangleContacts(const Geometry<T>& geom, const Transform<T>& pose, const Triangle<T>& triangle,
                                std::uint32_t triangleIndex, ContactBuffer<T>& contacts,
                                const TriangleContactSettings<T>& settings = TriangleContactSettings<T>()) noexcept;

template <class T>
[[deprecated("pass the distances in a TriangleContactSettings; hasContacts is contacts.count > 0")]] inline Status
generateTriangleContacts(const Geometry<T>& geom, const Transform<T>& pose, const Triangle<T>& triangle,
                         std::uint32_t triangleIndex, T contactDistance, T meshContactMargin, T toleranceLength,
                         ContactBuffer<T>& contacts, bool& hasContacts) noexcept {
  TriangleContactSettings<T> settings;
  settings.contactDistance = contactDistance;
  settings.meshContactMargin = meshContactMargin;
  settings.toleranceLength = toleranceLength;
  const Status s = generateTriangleContacts(geom, pose, triangle, triangleIndex, contacts, settings);
  if (s.ok()) hasContacts = contacts.count > 0;
  return s;
}

}  // namespace gq
