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

// ---- box against box: the incident face clipped to the reference face -----------------------------------------

struct BoxFrame {
  Vec center;
  Mat3<double> axes;  // columns
  Vec half;
};

BoxFrame boxFrame(const CollisionObject& o) {
  return {o.pose().p, o.pose().q.toRotationMatrix(), o.shape().geometry().get<BoxGeometry<double>>().halfExtents};
}

// The face of `box` whose outward normal is most aligned with `dir`: its axis index and sign.
void bestFace(const BoxFrame& box, const Vec& dir, int& axis, double& sign, double& alignment) {
  axis = 0;
  alignment = -1.0;
  sign = 1.0;
  for (int i = 0; i < 3; ++i) {
    const double d = box.axes.col(i).dot(dir);
    if (std::abs(d) > alignment) {
      alignment = std::abs(d);
      axis = i;
      sign = d >= 0.0 ? 1.0 : -1.0;
    }
  }
}

std::vector<Vec> faceVertices(const BoxFrame& box, int axis, double sign) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const Vec c = box.center + sign * box.half[axis] * box.axes.col(axis);
  const Vec du = box.half[u] * box.axes.col(u), dv = box.half[v] * box.axes.col(v);
  return {c + du + dv, c - du + dv, c - du - dv, c + du - dv};
}

// Keeps the part of `poly` with dot(n, x) <= offset.
std::vector<Vec> clip(const std::vector<Vec>& poly, const Vec& n, double offset) {
  std::vector<Vec> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec& a = poly[i];
    const Vec& b = poly[(i + 1) % poly.size()];
    const double da = n.dot(a) - offset, db = n.dot(b) - offset;
    if (da <= 0.0) out.push_back(a);
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

// Face-face alignment below which the contact is an edge or vertex contact and gets the single distance contact.
constexpr double kFaceAlignment = 0.95;

bool boxBoxContacts(const CollisionObject& o1, const CollisionObject& o2, std::vector<PairContact>& out) {
  DistanceResult<double> d;
  if (!distance(d, o1.shape(), o1.pose(), o2.shape(), o2.pose()).ok() || d.distance > 0.0) return false;
  const Vec n = -d.normal;  // from 2 towards 1
  const BoxFrame a = boxFrame(o1), b = boxFrame(o2);
  int axisA, axisB;
  double signA, signB, alignA, alignB;
  bestFace(b, n, axisB, signB, alignB);   // b's face towards a
  bestFace(a, -n, axisA, signA, alignA);  // a's face towards b
  const bool referenceIsB = alignB >= alignA;
  if (std::max(alignA, alignB) < kFaceAlignment) return distanceContact(o1, o2, out);
  const BoxFrame& ref = referenceIsB ? b : a;
  const BoxFrame& inc = referenceIsB ? a : b;
  const int refAxis = referenceIsB ? axisB : axisA;
  const double refSign = referenceIsB ? signB : signA;
  const Vec refNormal = refSign * ref.axes.col(refAxis);
  int incAxis;
  double incSign, incAlign;
  bestFace(inc, -refNormal, incAxis, incSign, incAlign);
  std::vector<Vec> poly = faceVertices(inc, incAxis, incSign);
  for (int k = 1; k <= 2 && !poly.empty(); ++k) {
    const int side = (refAxis + k) % 3;
    const Vec s = ref.axes.col(side);
    const double c = s.dot(ref.center);
    poly = clip(poly, s, c + ref.half[side]);
    if (!poly.empty()) poly = clip(poly, -s, -c + ref.half[side]);
  }
  const double refOffset = refNormal.dot(ref.center) + ref.half[refAxis];
  const Vec dartNormal = referenceIsB ? refNormal : Vec(-refNormal);
  const std::size_t before = out.size();
  for (const Vec& p : poly) {
    const double sep = refNormal.dot(p) - refOffset;
    if (sep > 0.0) continue;
    PairContact c;
    c.point = p - 0.5 * sep * refNormal;
    c.normal = dartNormal;
    c.depth = -sep;
    out.push_back(c);
  }
  if (out.size() == before) return distanceContact(o1, o2, out);
  return true;
}

// ---- a box or capsule on a plane: its vertices (segment ends) below the plane ---------------------------------

bool planeContacts(const CollisionObject& plane, const CollisionObject& solid, bool planeIsSecond,
                   std::vector<PairContact>& out) {
  const Vec n = plane.pose().rotate(Vec::UnitX());
  const double offset = n.dot(plane.pose().p);
  std::vector<Vec> points;
  double radius = 0.0;
  const Geometry<double>& g = solid.shape().geometry();
  const Transform<double>& pose = solid.pose();
  if (const auto* box = g.getIf<BoxGeometry<double>>()) {
    for (int i = 0; i < 8; ++i) {
      const Vec corner((i & 1) ? box->halfExtents.x() : -box->halfExtents.x(),
                       (i & 2) ? box->halfExtents.y() : -box->halfExtents.y(),
                       (i & 4) ? box->halfExtents.z() : -box->halfExtents.z());
      points.push_back(pose.transform(corner));
    }
  } else {
    const auto& cap = g.get<CapsuleGeometry<double>>();
    radius = cap.radius;
    points.push_back(pose.transform(Vec(-cap.halfHeight, 0, 0)));
    points.push_back(pose.transform(Vec(cap.halfHeight, 0, 0)));
  }
  const std::size_t before = out.size();
  for (const Vec& p : points) {
    const double sep = n.dot(p) - offset - radius;
    if (sep > 0.0) continue;
    PairContact c;
    c.point = p - (radius + 0.5 * sep) * n;
    c.normal = planeIsSecond ? n : Vec(-n);
    c.depth = -sep;
    out.push_back(c);
  }
  return out.size() > before;
}

// ---- a solid against a mesh or heightfield -------------------------------------------------------------------

// Triangles of `surface` under `solid`'s bounds (a box around them), in pages of 64.
template <class SurfaceGeometry>
void trianglesUnder(const CollisionObject& solid, const SurfaceGeometry& surface, const Transform<double>& surfacePose,
                    std::vector<std::uint32_t>& triangles) {
  Bounds3<double> bounds;
  if (!computeGeomBounds(bounds, solid.shape(), solid.pose()).ok()) return;
  const Geometry<double> box = BoxGeometry<double>(bounds.extents().cwiseMax(Vec::Constant(1e-12)));
  const Transform<double> boxPose(bounds.center());
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

bool meshMeshContacts(const CollisionObject& o1, const CollisionObject& o2, std::size_t room,
                      std::vector<PairContact>& out) {
  const auto* m1 = o1.shape().geometry().getIf<TriangleMeshGeometry<double>>();
  const auto* m2 = o2.shape().geometry().getIf<TriangleMeshGeometry<double>>();
  if (m1 == nullptr || m2 == nullptr) return false;
  bool found = false;
  const std::size_t before = out.size();
  const Status s = findOverlapTriangleMeshPairs(
      [&](std::uint32_t t1, std::uint32_t t2) {
        Triangle<double> a, b;
        if (getTriangle(*m1, o1.pose(), t1, a).ok() && getTriangle(*m2, o2.pose(), t2, b).ok()) {
          const Vec ca = (a.verts[0] + a.verts[1] + a.verts[2]) / 3.0;
          const Vec cb = (b.verts[0] + b.verts[1] + b.verts[2]) / 3.0;
          PairContact c;
          c.point = 0.5 * (ca + cb);
          c.normal = b.normal();
          if (c.normal.dot(ca - cb) < 0.0) c.normal = -c.normal;
          c.tri1 = int(t1);
          c.tri2 = int(t2);
          out.push_back(c);
        }
        return out.size() - before < room;
      },
      *m1, o1.pose(), *m2, o2.pose(), found);
  return s.ok() && out.size() > before;
}

void collect(const CollisionObject& o1, const CollisionObject& o2, std::size_t room, std::vector<PairContact>& out) {
  const GeometryType t1 = o1.shape().type(), t2 = o2.shape().type();
  const bool s1 = isSurface(t1), s2 = isSurface(t2);
  if (s1 && s2) {
    meshMeshContacts(o1, o2, room, out);
    return;
  }
  if (s1 || s2) {
    if (t1 == GeometryType::Plane || t2 == GeometryType::Plane) return;
    if (s2) {
      surfaceContacts(o1, o2, true, out);
    } else {
      surfaceContacts(o2, o1, false, out);
    }
    return;
  }
  if (t1 == GeometryType::Box && t2 == GeometryType::Box) {
    boxBoxContacts(o1, o2, out);
    return;
  }
  const auto onPlane = [](GeometryType t) { return t == GeometryType::Box || t == GeometryType::Capsule; };
  if (t2 == GeometryType::Plane && onPlane(t1)) {
    planeContacts(o2, o1, true, out);
    return;
  }
  if (t1 == GeometryType::Plane && onPlane(t2)) {
    planeContacts(o1, o2, false, out);
    return;
  }
  distanceContact(o1, o2, out);
}

}  // namespace

std::size_t fillContacts(const CollisionObject& object1, const CollisionObject& object2, std::size_t room,
                         ::dart::collision::CollisionResult& result) {
  if (room == 0) return 0;
  std::vector<PairContact> contacts;
  collect(object1, object2, room, contacts);
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
