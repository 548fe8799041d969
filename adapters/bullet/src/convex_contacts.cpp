// Convex shape against convex shape or plane: gq's signed distance gives the normal and deepest point; when a flat
// face supports the contact (box or hull on a face, cylinder cap, capsule lying down) the incident feature is
// clipped to that face so the manifold gets its full support polygon in one frame, as Bullet's box-box does.
#include <algorithm>
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

void convexContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, ContactSink& sink) {
  DistanceResult<Real> d;
  if (!distance(d, a.view->geom, a.pose, b.view->geom, b.pose).ok()) return;
  const Real depth = d.distance - a.view->margin - b.view->margin;
  const V3 normalOnB = -d.normal;  // gq's normal runs from A to B
  if (!(depth <= threshold) || !isFinite(normalOnB) || normalOnB.squaredNorm() < Real(0.5)) return;
  // The exact closest point joins the clipped ones unless one of them already carries the exact depth.
  const Real clippedDeepest = clippedContacts(a, b, normalOnB, threshold, Clamp{depth}, sink);
  const Real tolerance = Real(tol::Rel<Real>::kEpsilon) * std::max(a.view->size, b.view->size);
  if (clippedDeepest > depth + tolerance)
    sink.add(normalOnB, d.point1 + normalOnB * b.view->margin, depth, TriangleIds(), true);
}

}  // namespace gq::bullet
