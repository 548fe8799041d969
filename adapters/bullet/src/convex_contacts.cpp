// Convex shape against convex shape or plane: gq's signed distance gives the normal and deepest point; when a flat
// face supports the contact (box or hull on a face, cylinder cap, capsule lying down) the incident feature is
// clipped to that face so the manifold gets its full support polygon in one frame, as Bullet's box-box does.
#include <algorithm>
#include <array>
#include <limits>

#include "contact_features.h"
#include "contacts.h"
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

// The incident points clipped to the reference face, as contacts; `referenceIsB` says which shape owns the face.
// Returns the smallest depth reported (or +max when none).
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
  for (int i = 0; i < incident.count; ++i) {
    const V3& p = incident.points[i];
    const Real depth = std::max((p - reference.origin).dot(reference.normal) - ma - mb, clamp.exactDepth);
    if (depth > threshold) continue;
    const V3 pointOnB = referenceIsB ? V3(p - n * ma - n * depth) : V3(p + n * mb);
    sink.add(n, pointOnB, depth, TriangleIds(), true);
    deepest = std::min(deepest, depth);
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

// Penetrating polytopes: the SAT normal and depth, then the clipped face contacts. False when the cores do not
// penetrate or no clipped point carries the exact depth (the signed-distance path then answers).
bool penetratingPolytopeContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, ContactSink& sink) {
  PenetrationResult<Real> mtd;
  if (!computePenetration(mtd, a.view->geom, a.pose, b.view->geom, b.pose).ok() || !mtd.penetrating) return false;
  const Real depth = -mtd.depth - a.view->margin - b.view->margin;
  const V3 normalOnB = mtd.direction;  // moving A along it separates: it points from B to A
  if (!isFinite(normalOnB) || normalOnB.squaredNorm() < Real(0.5)) return false;
  BufferedSink buffered;
  if (clippedContacts(a, b, normalOnB, threshold, Clamp{depth}, buffered) > depth + toleranceOf(a, b)) return false;
  buffered.flush(sink);
  return true;
}

}  // namespace

void convexContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, ContactSink& sink) {
  if (hasSatPenetration(a, b) && penetratingPolytopeContacts(a, b, threshold, sink)) return;
  // Only a pair within the contact threshold makes contacts: GJK may stop once it proves the pair farther.
  DistanceResult<Real> d;
  bool beyond = false;
  const Real within = threshold + a.view->margin + b.view->margin;
  if (!distanceWithin(d, beyond, within, a.view->geom, a.pose, b.view->geom, b.pose).ok() || beyond) return;
  const Real depth = d.distance - a.view->margin - b.view->margin;
  const V3 normalOnB = -d.normal;  // gq's normal runs from A to B
  if (!(depth <= threshold) || !isFinite(normalOnB) || normalOnB.squaredNorm() < Real(0.5)) return;
  // The exact closest point joins the clipped ones unless one of them already carries the exact depth.
  const Real clippedDeepest = clippedContacts(a, b, normalOnB, threshold, Clamp{depth}, sink);
  if (clippedDeepest > depth + toleranceOf(a, b))
    sink.add(normalOnB, d.point1 + normalOnB * b.view->margin, depth, TriangleIds(), true);
}

}  // namespace gq::bullet
