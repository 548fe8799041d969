#pragma once
// Contact generation: a convex geometry against one triangle (the spec's PxGeometryQuery::generateTriangleContacts),
// the contact set of a convex pair (generateContacts), and the contacts of two triangle surfaces
// (generateMeshContacts).
#include <array>
#include <cstdint>
#include <functional>

#include "gq/geometry.h"
#include "gq/math.h"
#include "gq/mesh_query.h"
#include "gq/query.h"
#include "gq/shape.h"
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

// Contacts of a capsule, box, convex mesh or convex custom shape (others: Unsupported) at `pose` with `triangle`
// (a custom shape: its closest point, or the outline of a cylinder's cap or side resting along the face, clipped) (vertices in the same
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

// ---- Contact sets of convex pairs -----------------------------------------------------------------------------

// The most points a contact set holds (the clipped overlap of two rectangles has at most 8 corners).
inline constexpr std::uint32_t kMaxContactSetPoints = 8;

template <class T> struct ContactSetPoint {
  Vec3<T> position;  // on geom1's surface (world); geom0's point is position + normal * separation
  T separation;      // signed along the set's normal: > 0 gap, < 0 penetration depth
};

template <class T> struct ContactSet {
  // Unit, shared by every point, from geom1 towards geom0 (translating geom0 along it separates the pair; the
  // direction of PenetrationResult::direction and of ContactPoint::normal). Zero when count == 0.
  Vec3<T> normal = Vec3<T>::Zero();
  // points[0, count) are written; the others are left as they were (not initialised: a set lives on a hot path).
  std::array<ContactSetPoint<T>, kMaxContactSetPoints> points;
  std::uint32_t count = 0;
};

template <class T> struct ContactSetSettings {
  // >= 0: points whose separation is <= contactDistance are reported.
  T contactDistance = T(0);
  // In [1, kMaxContactSetPoints]: the set keeps the deepest point, then the points spanning the largest area.
  std::uint32_t maxContacts = 4;
  // >= 0: a rounding radius added outside geom0 / geom1 (a rounded shape: the geometry grown by a sphere, as
  // Bullet's convex margins are); separations and positions are those of the rounded shapes.
  T margin0 = T(0);
  T margin1 = T(0);
  // > 0: the length unit of the pair; a clipped point within 1e-5 (float) or 1e-12 (double) of it of the exact
  // separation counts as carrying it.
  T toleranceLength = T(1);
  // Optional warm start of the signed distance (see distance()); pass the same cache for the same pair across frames.
  GjkCache<T>* cache = nullptr;
};

// The contact set of two convex geometries (sphere, capsule, box, convex mesh, custom convex shapes) or of one of
// them and a plane (either order); other pairs: Unsupported, nothing written.
//  - The deepest point is exact: its separation is the signed distance (minus the penetration depth of the
//    MTD when penetrating) of the pair, rounding included, and the normal is the exact one.
//  - When a flat face supports the contact (a box or hull face, or a plane, within ~8 degrees of the exact normal)
//    and the other side rests on it with a face, a cylinder cap or side, or a capsule's side, the incident feature
//    is clipped to the face: a box resting on a box face gives the 4 corners of the overlap rectangle, a capsule lying
//    on a face its 2 ends. The set's normal is then the face's normal (pointing from geom1 towards geom0), and no
//    point is reported deeper than the exact separation.
//  - out.count == 0 when the pair is farther apart than contactDistance.
// Invalid input (non-finite poses, invalid geometry, settings out of range): InvalidArgument, nothing written.
template <class T>
Status generateContacts(const Geometry<T>& geom0, const Transform<T>& pose0, const Geometry<T>& geom1,
                        const Transform<T>& pose1, ContactSet<T>& out,
                        const ContactSetSettings<T>& settings = ContactSetSettings<T>()) noexcept;

// The same on prepared shapes (gq/shape.h): the geometries are not validated again; bit-identical answers.
template <class T>
Status generateContacts(const Shape<T>& shape0, const Transform<T>& pose0, const Shape<T>& shape1,
                        const Transform<T>& pose1, ContactSet<T>& out,
                        const ContactSetSettings<T>& settings = ContactSetSettings<T>()) noexcept;

// ---- Contacts of two triangle surfaces (mesh or heightfield against mesh or heightfield) ----------------------

// One crossing triangle pair. Each triangle is pushed out through the other's face: triangle 0 along triangle 1's
// face normal (turned towards triangle 0's centroid) by as far as its deepest vertex lies below triangle 1's plane,
// and triangle 1 likewise along triangle 0's; the contact is the shallower of the two (a surface is pushed out of
// through a face, never sideways through an edge).
template <class T> struct MeshContact {
  Vec3<T> position = Vec3<T>::Zero();  // world: the pushed triangle's deepest vertex moved half the depth along normal
  Vec3<T> normal = Vec3<T>::Zero();    // unit, from surface 1 towards surface 0 (moving surface 0 along it separates)
  T depth = T(0);                      // >= 0
  std::uint32_t triangle0 = kInvalidFaceIndex;  // input triangle index (heightfield: 2*cell or 2*cell+1)
  std::uint32_t triangle1 = kInvalidFaceIndex;
};

// Receives each crossing pair's contact; return false to stop the query.
template <class T> using MeshContactCallback = std::function<bool(const MeshContact<T>&)>;

// The contacts of two surfaces, each a triangle mesh or a heightfield (other types: Unsupported): one per pair of
// intersecting (touching counts) triangles, found as findOverlapTriangleMeshPairs finds them (exact
// triangle-triangle test), in unspecified order. `contactFound` says whether any contact was reported. A pair whose
// triangles both lack a face normal (zero area) is skipped.
// Invalid input (non-finite or non-unit poses, invalid geometry, empty callback): InvalidArgument, nothing reported.
template <class T>
Status generateMeshContacts(const MeshContactCallback<T>& callback, const Geometry<T>& surface0,
                            const Transform<T>& pose0, const Geometry<T>& surface1, const Transform<T>& pose1,
                            bool& contactFound) noexcept;

}  // namespace gq
