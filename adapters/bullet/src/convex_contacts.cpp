// Convex shape against convex shape or plane: gq's contact set (generateContacts: the exact deepest point, and for
// flat contacts the incident feature clipped to the supporting face, so the manifold gets its full support polygon in
// one frame, as Bullet's box-box does), at most the 4 points Bullet's persistent manifold holds.
#include <algorithm>
#include <limits>

#include "contacts.h"
#include "gq/contacts.h"
#include "gq/cooking.h"
#include "gq/query.h"

namespace gq::bullet {
namespace {

// The largest extent of `s` along unit `n` (n . x over the shape, margin included); false when unbounded or not
// modelled here (planes, custom shapes).
bool extentAlong(const PlacedShape& s, const V3& n, Real& out) {
  const Geometry<Real>& g = s.view->geom;
  Real e;
  switch (g.type()) {
    case GeometryType::Sphere: e = g.get<SphereGeometry<Real>>().radius; break;
    case GeometryType::Capsule: {
      const auto& c = g.get<CapsuleGeometry<Real>>();
      e = std::abs(s.pose.rotate(V3::UnitX()).dot(n)) * c.halfHeight + c.radius;
      break;
    }
    case GeometryType::Box: e = s.pose.rotateInv(n).cwiseAbs().dot(g.get<BoxGeometry<Real>>().halfExtents); break;
    case GeometryType::ConvexMesh: {
      const auto& hull = g.get<ConvexMeshGeometry<Real>>();
      const V3 local = hull.scale.isIdentity() ? s.pose.rotateInv(n) : V3(hull.scale.toMatrix().transpose() * s.pose.rotateInv(n));
      e = -std::numeric_limits<Real>::max();
      for (const V3& v : hull.mesh->vertices) e = std::max(e, v.dot(local));
      break;
    }
    default: return false;
  }
  out = n.dot(s.pose.p) + e + s.view->margin;
  return true;
}

// Whether unit `axis` (either way) separates the pair by more than `threshold` (the pair then has no contact).
bool separatesBeyond(const PlacedShape& a, const PlacedShape& b, V3 axis, Real threshold) {
  if (axis.dot(b.pose.p - a.pose.p) < 0) axis = -axis;
  Real hiA, loB;
  if (!extentAlong(a, axis, hiA) || !extentAlong(b, -axis, loB)) return false;
  return -loB - hiA > threshold;
}

// The cheap cull before any exact work: the axis that separated the pair last frame, the centre line, and a box's
// face normals. On success `memory` keeps the separating axis for the next frame.
bool culledBySeparatingAxis(const PlacedShape& a, const PlacedShape& b, Real threshold, PairMemory* memory) {
  if (a.view->kind != ShapeKind::Convex || b.view->kind != ShapeKind::Convex) return false;
  const auto keep = [&](const V3& axis) {
    if (memory) memory->separatingAxis = a.pose.rotateInv(axis);
    return true;
  };
  if (memory && memory->separatingAxis != V3::Zero()) {
    const V3 axis = a.pose.rotate(memory->separatingAxis);
    if (separatesBeyond(a, b, axis, threshold)) return true;
  }
  const V3 centres = b.pose.p - a.pose.p;
  const Real length = centres.norm();
  if (length > Real(0) && separatesBeyond(a, b, centres / length, threshold)) return keep(centres / length);
  for (const PlacedShape* s : {&a, &b}) {
    if (s->view->geom.type() != GeometryType::Box) continue;
    const Mat3<Real> r = s->pose.q.toRotationMatrix();
    for (int k = 0; k < 3; ++k)
      if (separatesBeyond(a, b, r.col(k), threshold)) return keep(r.col(k));
  }
  if (memory) memory->separatingAxis = V3::Zero();
  return false;
}

// Bullet's manifold holds 4 points: sending it more makes it sort its cache once per extra point.
constexpr std::uint32_t kManifoldPoints = 4;

// The points of `set` (bit i for point i) whose separation is <= threshold.
std::uint32_t pointsWithin(const ContactSet<Real>& set, Real threshold) {
  std::uint32_t bits = 0;
  for (std::uint32_t i = 0; i < set.count; ++i)
    if (set.points[i].separation <= threshold) bits |= 1u << i;
  return bits;
}

// The points of a box pair the manifold gets: the penetrating ones, as Bullet's box-box algorithm adds them (the
// manifold keeps older points until they pass the breaking threshold); a pair with none gets only its closest point
// within the threshold. Boxes lying next to each other (many in a pile) so hand the solver one row instead of four,
// and the one speculative row keeps an approaching box from bouncing (penetrating points only was measured to keep
// a box pile awake longer, costing more than the rows saved).
std::uint32_t boxPairPoints(const ContactSet<Real>& set, Real threshold) {
  std::uint32_t penetrating = 0, closest = 0;
  for (std::uint32_t i = 0; i < set.count; ++i) {
    if (set.points[i].separation <= Real(0)) penetrating |= 1u << i;
    if (set.points[i].separation < set.points[closest].separation) closest = i;
  }
  if (penetrating != 0 || set.count == 0) return penetrating;
  return set.points[closest].separation <= threshold ? 1u << closest : 0u;
}

// The pair's contact set on the prepared shapes when both views carry them (validated once, derived data kept).
bool convexContactsExact(const PlacedShape& a, const PlacedShape& b, Real threshold, ContactSink& sink,
                         GjkCache<Real>* gjk) {
  ContactSetSettings<Real> settings;
  settings.contactDistance = std::max(threshold, Real(0));
  settings.maxContacts = kManifoldPoints;
  settings.margin0 = a.view->margin;
  settings.margin1 = b.view->margin;
  settings.toleranceLength = std::max(a.view->size, b.view->size);
  settings.cache = gjk;
  ContactSet<Real> set;
  const Status s = a.view->prepared && b.view->prepared
                       ? generateContacts(*a.view->prepared, a.pose, *b.view->prepared, b.pose, set, settings)
                       : generateContacts(a.view->geom, a.pose, b.view->geom, b.pose, set, settings);
  if (!s.ok()) return false;
  const bool boxes = a.view->geom.type() == GeometryType::Box && b.view->geom.type() == GeometryType::Box;
  const std::uint32_t sent = boxes ? boxPairPoints(set, threshold) : pointsWithin(set, threshold);
  for (std::uint32_t i = 0; i < set.count; ++i)
    if (sent >> i & 1u) sink.add(set.normal, set.points[i].position, set.points[i].separation, TriangleIds(), true);
  return set.count > 0;
}

}  // namespace

void convexContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, ContactSink& sink,
                    PairMemory* memory) {
  // A pair in contact range last frame most likely still is: the cull is tried on the others only.
  if (!(memory && memory->touching) && culledBySeparatingAxis(a, b, threshold, memory)) return;
  const bool touching = convexContactsExact(a, b, threshold, sink, memory ? &memory->gjk : nullptr);
  if (memory) memory->touching = touching;
}

}  // namespace gq::bullet
