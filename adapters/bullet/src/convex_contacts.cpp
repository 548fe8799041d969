// Convex shape against convex shape or plane: gq's signed distance gives the normal and deepest point; when a flat
// face supports the contact (box or hull on a face, cylinder cap, capsule lying down) the incident feature is
// clipped to that face so the manifold gets its full support polygon in one frame, as Bullet's box-box does.
#include <algorithm>
#include <array>
#include <limits>

#include "contact_features.h"
#include "contacts.h"
#include "gq/cooking.h"
#include "gq/query.h"

namespace gq::bullet {
namespace {

// A manifold point is never deeper than the exact signed distance (the MTD when penetrating): clipped points on a
// face tilted from the contact normal would otherwise overstate their depth.
struct Clamp {
  Real exactDepth;
};

// Holds contacts until the caller decides to keep them.
class BufferedSink final : public ContactSink {
 public:
  void add(const V3& normalOnB, const V3& pointOnB, Real depth, TriangleIds ids, bool surfaceIsB) override {
    if (count_ < kMaxFeaturePoints) points_[count_++] = {normalOnB, pointOnB, depth, ids, surfaceIsB};
  }
  void flush(ContactSink& sink) const {
    for (int i = 0; i < count_; ++i) sink.add(points_[i].n, points_[i].p, points_[i].depth, points_[i].ids, points_[i].surfaceIsB);
  }

 private:
  struct Held {
    V3 n, p;
    Real depth;
    TriangleIds ids;
    bool surfaceIsB;
  };
  std::array<Held, kMaxFeaturePoints> points_;
  int count_ = 0;
};

// A manifold keeps at most this many points (Bullet's persistent manifold holds 4).
constexpr int kManifoldPoints = 4;

// Picks kManifoldPoints of `count` points (normal n) spanning the largest area: the deepest, the farthest from it,
// the farthest from their line, and the farthest from that line on the other side. Sending Bullet's manifold more
// than it holds makes it sort its cache once per extra point.
int reduceToManifold(const std::array<V3, kMaxFeaturePoints>& p, const std::array<Real, kMaxFeaturePoints>& depth,
                     int count, const V3& n, std::array<int, kManifoldPoints>& keep) {
  if (count <= kManifoldPoints) {
    for (int i = 0; i < count; ++i) keep[i] = i;
    return count;
  }
  int first = 0;
  for (int i = 1; i < count; ++i)
    if (depth[i] < depth[first]) first = i;
  int second = first == 0 ? 1 : 0;
  for (int i = 0; i < count; ++i)
    if ((p[i] - p[first]).squaredNorm() > (p[second] - p[first]).squaredNorm()) second = i;
  const V3 edge = p[second] - p[first];
  const auto side = [&](int i) { return edge.cross(p[i] - p[first]).dot(n); };  // signed area x 2
  int third = -1, fourth = -1;
  Real most = 0, least = 0;
  for (int i = 0; i < count; ++i) {
    const Real a = side(i);
    if (a > most) most = a, third = i;
    if (a < least) least = a, fourth = i;
  }
  int k = 0;
  keep[k++] = first;
  keep[k++] = second;
  if (third >= 0) keep[k++] = third;
  if (fourth >= 0) keep[k++] = fourth;
  return k;
}

// The incident points clipped to the reference face, as contacts (at most kManifoldPoints); `referenceIsB` says
// which shape owns the face. Returns the smallest depth reported (or +max when none).
Real clippedContacts(const PlacedShape& a, const PlacedShape& b, const V3& normalOnB, Real threshold, Clamp clamp,
                     ContactSink& sink) {
  Real deepest = std::numeric_limits<Real>::max();
  Feature reference, incident;
  bool referenceIsB = true;
  if (!(referenceFace(b, normalOnB, reference) && incidentFeature(a, -normalOnB, incident))) {
    referenceIsB = false;
    if (!(referenceFace(a, -normalOnB, reference) && incidentFeature(b, normalOnB, incident))) return deepest;
  }
  clipToFace(reference, incident);
  const Real ma = a.view->margin, mb = b.view->margin;
  const V3 n = referenceIsB ? reference.normal : V3(-reference.normal);
  std::array<V3, kMaxFeaturePoints> points;
  std::array<Real, kMaxFeaturePoints> depths;
  int count = 0;
  for (int i = 0; i < incident.count; ++i) {
    const V3& p = incident.points[i];
    const Real depth = std::max((p - reference.origin).dot(reference.normal) - ma - mb, clamp.exactDepth);
    if (depth > threshold) continue;
    points[count] = referenceIsB ? V3(p - n * ma - n * depth) : V3(p + n * mb);
    depths[count++] = depth;
  }
  std::array<int, kManifoldPoints> keep;
  const int kept = reduceToManifold(points, depths, count, n, keep);
  for (int k = 0; k < kept; ++k) {
    sink.add(n, points[keep[k]], depths[keep[k]], TriangleIds(), true);
    deepest = std::min(deepest, depths[keep[k]]);
  }
  return deepest;
}

}  // namespace

namespace {

// Polytope pairs (box, hull, plane) have an exact and cheaper penetration query (SAT) than the signed distance's
// EPA: resting contacts, which penetrate slightly, take that path.
bool hasSatPenetration(const PlacedShape& a, const PlacedShape& b) {
  const auto flat = [](const PlacedShape& s) { return s.view->isPolytope() || s.view->kind == ShapeKind::Plane; };
  return flat(a) && flat(b) && (a.view->isPolytope() || b.view->isPolytope());
}

Real toleranceOf(const PlacedShape& a, const PlacedShape& b) {
  return Real(tol::Rel<Real>::kEpsilon) * std::max(a.view->size, b.view->size);
}

// The queries on the prepared shapes when the views carry them (validated once, derived data kept).
Status penetration(PenetrationResult<Real>& mtd, const PlacedShape& a, const PlacedShape& b) {
  if (a.view->prepared && b.view->prepared)
    return computePenetration(mtd, *a.view->prepared, a.pose, *b.view->prepared, b.pose);
  return computePenetration(mtd, a.view->geom, a.pose, b.view->geom, b.pose);
}

Status distanceUpTo(DistanceResult<Real>& d, bool& beyond, Real within, const PlacedShape& a, const PlacedShape& b,
                    GjkCache<Real>* gjk) {
  if (a.view->prepared && b.view->prepared)
    return distanceWithin(d, beyond, within, *a.view->prepared, a.pose, *b.view->prepared, b.pose, gjk);
  return distanceWithin(d, beyond, within, a.view->geom, a.pose, b.view->geom, b.pose, gjk);
}

// Penetrating polytopes: the SAT normal and depth, then the clipped face contacts. False when the cores do not
// penetrate or no clipped point carries the exact depth (the signed-distance path then answers).
bool penetratingPolytopeContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, ContactSink& sink) {
  PenetrationResult<Real> mtd;
  if (!penetration(mtd, a, b).ok() || !mtd.penetrating) return false;
  const Real depth = -mtd.depth - a.view->margin - b.view->margin;
  const V3 normalOnB = mtd.direction;  // moving A along it separates: it points from B to A
  if (!isFinite(normalOnB) || normalOnB.squaredNorm() < Real(0.5)) return false;
  BufferedSink buffered;
  if (clippedContacts(a, b, normalOnB, threshold, Clamp{depth}, buffered) > depth + toleranceOf(a, b)) return false;
  buffered.flush(sink);
  return true;
}

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

// The signed-distance path: contacts of a pair whose distance `d` (cores) is known.
void distanceContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, const DistanceResult<Real>& d,
                      ContactSink& sink) {
  const Real depth = d.distance - a.view->margin - b.view->margin;
  const V3 normalOnB = -d.normal;  // gq's normal runs from A to B
  if (!(depth <= threshold) || !isFinite(normalOnB) || normalOnB.squaredNorm() < Real(0.5)) return;
  // The exact closest point joins the clipped ones unless one of them already carries the exact depth.
  const Real clippedDeepest = clippedContacts(a, b, normalOnB, threshold, Clamp{depth}, sink);
  if (clippedDeepest > depth + toleranceOf(a, b))
    sink.add(normalOnB, d.point1 + normalOnB * b.view->margin, depth, TriangleIds(), true);
}

// Passes contacts on and notes whether there was any.
class TouchSink final : public ContactSink {
 public:
  explicit TouchSink(ContactSink& inner) : inner_(inner) {}
  void add(const V3& normalOnB, const V3& pointOnB, Real depth, TriangleIds ids, bool surfaceIsB) override {
    any = true;
    inner_.add(normalOnB, pointOnB, depth, ids, surfaceIsB);
  }
  bool any = false;

 private:
  ContactSink& inner_;
};

void convexContactsExact(const PlacedShape& a, const PlacedShape& b, Real threshold, ContactSink& sink,
                         GjkCache<Real>* gjk) {
  const bool sat = hasSatPenetration(a, b);
  const Real margins = a.view->margin + b.view->margin;
  // Only a pair within the contact threshold makes contacts: GJK may stop once it proves the pair farther.
  DistanceResult<Real> d;
  bool beyond = false;
  const Real within = threshold + margins;
  // Rounded polytopes (hulls with a margin) rest with their cores apart: the distance answers first, and the SAT
  // penetration runs only when the cores touch. Exact polytopes (boxes) rest penetrating: the SAT runs first.
  if (sat && margins > Real(0)) {
    if (!distanceUpTo(d, beyond, within, a, b, gjk).ok() || beyond) return;
    if (d.distance > toleranceOf(a, b) || !penetratingPolytopeContacts(a, b, threshold, sink))
      distanceContacts(a, b, threshold, d, sink);
    return;
  }
  if (sat && penetratingPolytopeContacts(a, b, threshold, sink)) return;
  if (!distanceUpTo(d, beyond, within, a, b, gjk).ok() || beyond) return;
  distanceContacts(a, b, threshold, d, sink);
}

}  // namespace

void convexContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, ContactSink& sink,
                    PairMemory* memory) {
  // A pair in contact range last frame most likely still is: the cull is tried on the others only.
  if (!(memory && memory->touching) && culledBySeparatingAxis(a, b, threshold, memory)) return;
  if (!memory) return convexContactsExact(a, b, threshold, sink, nullptr);
  TouchSink touch(sink);
  convexContactsExact(a, b, threshold, touch, &memory->gjk);
  memory->touching = touch.any;
}

}  // namespace gq::bullet
