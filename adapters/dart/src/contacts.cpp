#include "contacts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include <dart/collision/Contact.hpp>

#include <gq/contacts.h>
#include <gq/custom_shapes.h>
#include <gq/mesh_query.h>
#include <gq/query.h>
#include <gq/shape.h>

#include "collision_object.h"

namespace gq {
namespace dart {
namespace {

using Vec = Vec3<double>;

// A contact before it is written in DART's form: normal from object 2 towards object 1.
struct PairContact {
  Vec point = Vec::Zero();
  Vec normal = Vec::Zero();
  double depth = 0.0;
  int tri1 = -1;
  int tri2 = -1;
};

constexpr std::size_t kMaxPairContacts = 4;

bool isSurface(GeometryType t) { return t == GeometryType::TriangleMesh || t == GeometryType::HeightField; }

// Keeps at most kMaxPairContacts: the deepest, then each time the point farthest from those kept.
void reduce(std::vector<PairContact>& contacts) {
  if (contacts.size() <= kMaxPairContacts) return;
  std::vector<PairContact> kept;
  auto deepest = std::max_element(contacts.begin(), contacts.end(),
                                  [](const PairContact& a, const PairContact& b) { return a.depth < b.depth; });
  kept.push_back(*deepest);
  contacts.erase(deepest);
  while (kept.size() < kMaxPairContacts && !contacts.empty()) {
    std::size_t best = 0;
    double bestDist = -1.0;
    for (std::size_t i = 0; i < contacts.size(); ++i) {
      double d = std::numeric_limits<double>::infinity();
      for (const PairContact& k : kept) d = std::min(d, (contacts[i].point - k.point).squaredNorm());
      if (d > bestDist) {
        bestDist = d;
        best = i;
      }
    }
    kept.push_back(contacts[best]);
    contacts.erase(contacts.begin() + std::ptrdiff_t(best));
  }
  contacts.swap(kept);
}

// The one contact of the signed distance: between the witness points, depth = -distance (0 when touching).
bool distanceContact(const CollisionObject& o1, const CollisionObject& o2, std::vector<PairContact>& out) {
  DistanceResult<double> d;
  if (!distance(d, o1.shape(), o1.pose(), o2.shape(), o2.pose()).ok()) return false;
  if (d.distance > 0.0) return false;
  PairContact c;
  c.point = 0.5 * (d.point0 + d.point1);
  c.normal = -d.normal;
  c.depth = -d.distance;
  out.push_back(c);
  return true;
}

// ---- two convex shapes, or a plane and a convex shape: gq's contact set ---------------------------------------

// The exact deepest point plus, where a face supports the contact, the other shape's clipped face (a box resting on
// a box: its 4 corners), at most 4 points sharing one normal from object 2 towards object 1. Each point sits midway
// between the two surfaces. Pairs without a contact set (none here in practice) take the signed distance's point.
bool convexContacts(const CollisionObject& o1, const CollisionObject& o2, std::vector<PairContact>& out) {
  ContactSet<double> set;
  ContactSetSettings<double> settings;
  settings.maxContacts = kMaxPairContacts;
  if (!generateContacts(o1.shape(), o1.pose(), o2.shape(), o2.pose(), set, settings).ok())
    return distanceContact(o1, o2, out);
  for (std::uint32_t i = 0; i < set.count; ++i) {
    PairContact c;
    c.point = set.points[i].position + set.normal * (0.5 * set.points[i].separation);
    c.normal = set.normal;
    c.depth = -set.points[i].separation;
    out.push_back(c);
  }
  return set.count > 0;
}

// ---- a solid against a mesh or heightfield -------------------------------------------------------------------

// Triangles of `surface` overlapping a box, in pages of 64.
template <class SurfaceGeometry>
void trianglesUnder(const Geometry<double>& box, const Transform<double>& boxPose, const SurfaceGeometry& surface,
                    const Transform<double>& surfacePose, std::vector<std::uint32_t>& triangles) {
  std::array<std::uint32_t, 64> page{};
  TriangleOverlapPage request{page.data(), std::uint32_t(page.size()), 0};
  for (;;) {
    TriangleOverlapPageResult got;
    Status s;
    if constexpr (std::is_same_v<SurfaceGeometry, TriangleMeshGeometry<double>>) {
      s = findOverlapTriangleMesh(box, boxPose, surface, surfacePose, request, got);
    } else {
      s = findOverlapHeightField(box, boxPose, surface, surfacePose, request, got);
    }
    if (!s.ok()) return;
    triangles.insert(triangles.end(), page.begin(), page.begin() + got.count);
    if (!got.overflow || got.count == 0) return;
    request.start += got.count;
  }
}

// Triangles of `surface` under `solid`'s bounds (a box around them).
template <class SurfaceGeometry>
void trianglesUnder(const CollisionObject& solid, const SurfaceGeometry& surface, const Transform<double>& surfacePose,
                    std::vector<std::uint32_t>& triangles) {
  Bounds3<double> bounds;
  if (!computeGeomBounds(bounds, solid.shape(), solid.pose()).ok()) return;
  const Geometry<double> box = BoxGeometry<double>(bounds.extents().cwiseMax(Vec::Constant(1e-12)));
  trianglesUnder(box, Transform<double>(bounds.center()), surface, surfacePose, triangles);
}

// The point of a sphere or convex custom shape farthest along `dir` (world).
Vec supportPoint(const Geometry<double>& geom, const Transform<double>& pose, const Vec& dir) {
  if (const auto* sphere = geom.getIf<SphereGeometry<double>>()) return pose.p + sphere->radius * dir.normalized();
  const auto& custom = geom.get<CustomGeometry<double>>();
  return pose.transform(custom.callbacks->support(pose.rotateInv(dir)));
}

// A sphere or convex custom shape against one triangle of a surface: when they overlap (gq::overlap with the solid
// triangle), one contact along the triangle's face normal (turned towards the shape's centre), as deep as the shape
// reaches below the triangle's plane. Along the face normal, not the solid triangle's MTD: a surface is pushed out of
// through its face, never sideways through a triangle's edge.
std::optional<PairContact> faceContact(const Geometry<double>& geom, const Transform<double>& pose,
                                       const Triangle<double>& tri, std::uint32_t index) {
  CustomGeometry<double> triangleShape;
  if (!makeTriangle(tri.verts[0], tri.verts[1], tri.verts[2], triangleShape).ok()) return std::nullopt;
  bool overlapping = false;
  if (!overlap(geom, pose, Geometry<double>(triangleShape), Transform<double>(), overlapping).ok() || !overlapping) {
    return std::nullopt;
  }
  Vec n = tri.normal();
  if (n.dot(pose.p - tri.verts[0]) < 0.0) n = -n;
  const Vec deepest = supportPoint(geom, pose, -n);
  const double separation = n.dot(deepest - tri.verts[0]);
  PairContact c;
  c.normal = n;  // from the triangle towards the shape
  c.depth = std::max(0.0, -separation);
  c.point = deepest + 0.5 * c.depth * n;
  c.tri1 = int(index);
  return c;
}

bool usesTriangleContacts(GeometryType t) {
  return t == GeometryType::Capsule || t == GeometryType::Box || t == GeometryType::ConvexMesh;
}

bool surfaceContacts(const CollisionObject& solid, const CollisionObject& surface, bool solidIsFirst,
                     std::vector<PairContact>& out) {
  const Geometry<double>& sg = surface.shape().geometry();
  std::vector<std::uint32_t> triangles;
  if (const auto* mesh = sg.getIf<TriangleMeshGeometry<double>>()) {
    trianglesUnder(solid, *mesh, surface.pose(), triangles);
  } else {
    trianglesUnder(solid, sg.get<HeightFieldGeometry<double>>(), surface.pose(), triangles);
  }
  const Geometry<double>& geom = solid.shape().geometry();
  const Bounds3<double>& local = solid.shape().localBounds();
  TriangleContactSettings<double> settings;
  settings.toleranceLength = std::max(1e-9, (local.max - local.min).norm());
  settings.meshContactMargin = 1e-3 * settings.toleranceLength;
  std::vector<PairContact> found;
  for (std::uint32_t index : triangles) {
    Triangle<double> tri;
    Status s;
    if (const auto* mesh = sg.getIf<TriangleMeshGeometry<double>>()) {
      s = getTriangle(*mesh, surface.pose(), index, tri);
    } else {
      s = getTriangle(sg.get<HeightFieldGeometry<double>>(), surface.pose(), index, tri);
    }
    if (!s.ok()) continue;
    if (usesTriangleContacts(geom.type())) {
      ContactBuffer<double> buffer;
      if (!generateTriangleContacts(geom, solid.pose(), tri, index, buffer, settings).ok()) continue;
      for (std::uint32_t i = 0; i < buffer.count; ++i) {
        const ContactPoint<double>& p = buffer.contacts[i];
        PairContact c;
        c.normal = p.normal;  // from the triangle towards the solid
        c.depth = std::max(0.0, -p.separation);
        c.point = p.position + 0.5 * c.depth * p.normal;
        c.tri1 = int(index);
        found.push_back(c);
      }
      continue;
    }
    const auto contact = faceContact(geom, solid.pose(), tri, index);
    if (contact) found.push_back(*contact);
  }
  reduce(found);
  for (PairContact& c : found) {
    if (solidIsFirst) {
      std::swap(c.tri1, c.tri2);  // the triangle is object 2's
    } else {
      c.normal = -c.normal;  // from the surface (object 1) towards the solid (object 2): flipped
    }
    out.push_back(c);
  }
  return !found.empty();
}

// ---- a plane against a mesh or heightfield ----------------------------------------------------------------------

// The surface's vertices at or below the plane (the plane's solid side), each a contact along the plane's normal, as
// deep as the vertex lies below it: a surface reaches into a half-space only through its vertices, so these are
// exact. The triangles come from an oriented box in the plane's frame around the part of the surface's bounds below
// the plane (the mesh queries take a box, not a half-space).
bool planeSurfaceContacts(const CollisionObject& plane, const CollisionObject& surface, bool planeIsFirst,
                          std::vector<PairContact>& out) {
  Bounds3<double> world;
  if (!computeGeomBounds(world, surface.shape(), surface.pose()).ok()) return false;
  const Transform<double>& planePose = plane.pose();  // gq's plane: x = 0 of its frame, solid at x <= 0
  Bounds3<double> local;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec c((corner & 1) ? world.max.x() : world.min.x(), (corner & 2) ? world.max.y() : world.min.y(),
                (corner & 4) ? world.max.z() : world.min.z());
    local.include(planePose.transformInv(c));
  }
  if (local.min.x() > 0.0) return false;
  local.max.x() = 0.0;
  const Geometry<double> box = BoxGeometry<double>(local.extents().cwiseMax(Vec::Constant(1e-12)));
  const Transform<double> boxPose(planePose.transform(local.center()), planePose.q);
  const Geometry<double>& sg = surface.shape().geometry();
  std::vector<std::uint32_t> triangles;
  if (const auto* mesh = sg.getIf<TriangleMeshGeometry<double>>()) {
    trianglesUnder(box, boxPose, *mesh, surface.pose(), triangles);
  } else {
    trianglesUnder(box, boxPose, sg.get<HeightFieldGeometry<double>>(), surface.pose(), triangles);
  }
  const Vec n = planePose.rotate(Vec::UnitX());
  std::vector<PairContact> found;
  for (std::uint32_t index : triangles) {
    Triangle<double> tri;
    const Status s = sg.getIf<TriangleMeshGeometry<double>>()
                         ? getTriangle(*sg.getIf<TriangleMeshGeometry<double>>(), surface.pose(), index, tri)
                         : getTriangle(sg.get<HeightFieldGeometry<double>>(), surface.pose(), index, tri);
    if (!s.ok()) continue;
    for (const Vec& v : tri.verts) {
      const double height = n.dot(v - planePose.p);
      if (height > 0.0) continue;
      PairContact c;
      c.depth = -height;
      c.point = v + 0.5 * c.depth * n;
      // A vertex shared by several triangles is one contact.
      if (std::any_of(found.begin(), found.end(), [&](const PairContact& f) { return f.point == c.point; })) continue;
      c.normal = planeIsFirst ? Vec(-n) : n;  // from object 2 towards object 1; the surface is pushed along n
      (planeIsFirst ? c.tri2 : c.tri1) = int(index);
      found.push_back(c);
    }
  }
  reduce(found);
  out.insert(out.end(), found.begin(), found.end());
  return !found.empty();
}

// ---- two surfaces (mesh against mesh or heightmap) -----------------------------------------------------------------

// gq::generateMeshContacts: each crossing triangle pair along the shallower of its two face normals (normal from
// object 2 towards object 1), reduced to the deepest and the points farthest apart. Two heightmaps give none.
bool surfaceSurfaceContacts(const CollisionObject& o1, const CollisionObject& o2, std::vector<PairContact>& out) {
  if (o1.shape().type() == GeometryType::HeightField && o2.shape().type() == GeometryType::HeightField) return false;
  std::vector<PairContact> found;
  bool any = false;
  const MeshContactCallback<double> keep = [&](const MeshContact<double>& m) {
    PairContact c;
    c.point = m.position;
    c.normal = m.normal;
    c.depth = m.depth;
    c.tri1 = int(m.triangle0);
    c.tri2 = int(m.triangle1);
    found.push_back(c);
    return true;
  };
  if (!generateMeshContacts(keep, o1.shape().geometry(), o1.pose(), o2.shape().geometry(), o2.pose(), any).ok())
    return false;
  reduce(found);
  out.insert(out.end(), found.begin(), found.end());
  return !found.empty();
}

void collect(const CollisionObject& o1, const CollisionObject& o2, std::vector<PairContact>& out) {
  const GeometryType t1 = o1.shape().type(), t2 = o2.shape().type();
  const bool s1 = isSurface(t1), s2 = isSurface(t2);
  if (s1 && s2) {
    surfaceSurfaceContacts(o1, o2, out);
    return;
  }
  if (s1 || s2) {
    if (t1 == GeometryType::Plane) {
      planeSurfaceContacts(o1, o2, true, out);
    } else if (t2 == GeometryType::Plane) {
      planeSurfaceContacts(o2, o1, false, out);
    } else if (s2) {
      surfaceContacts(o1, o2, true, out);
    } else {
      surfaceContacts(o2, o1, false, out);
    }
    return;
  }
  convexContacts(o1, o2, out);
}

}  // namespace

std::size_t fillContacts(const CollisionObject& object1, const CollisionObject& object2, std::size_t room,
                         ::dart::collision::CollisionResult& result) {
  if (room == 0) return 0;
  std::vector<PairContact> contacts;
  collect(object1, object2, contacts);
  reduce(contacts);
  const std::size_t count = std::min(room, contacts.size());
  for (std::size_t i = 0; i < count; ++i) {
    const PairContact& c = contacts[i];
    ::dart::collision::Contact contact;
    contact.point = c.point;
    contact.normal = c.normal;
    contact.penetrationDepth = c.depth;
    contact.collisionObject1 = const_cast<CollisionObject*>(&object1);
    contact.collisionObject2 = const_cast<CollisionObject*>(&object2);
    contact.triID1 = c.tri1;
    contact.triID2 = c.tri2;
    result.addContact(contact);
  }
  return count;
}

}  // namespace dart
}  // namespace gq
