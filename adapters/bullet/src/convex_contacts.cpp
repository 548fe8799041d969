// Convex shape against convex shape or plane: gq's signed distance gives the normal and deepest point; when a flat
// face supports the contact (box or hull on a face, cylinder cap, capsule lying down) the incident feature is
// clipped to that face so the manifold gets its full support polygon in one frame, as Bullet's box-box does.
#include "contact_features.h"
#include "contacts.h"
#include "gq/query.h"

namespace gq::bullet {
namespace {

// The incident points clipped to the reference face, as contacts; `referenceIsB` says which shape owns the face.
int clippedContacts(const PlacedShape& a, const PlacedShape& b, const V3& normalOnB, Real threshold,
                    ContactSink& sink) {
  Feature reference, incident;
  bool referenceIsB = true;
  if (!(referenceFace(b, normalOnB, reference) && incidentFeature(a, -normalOnB, incident))) {
    referenceIsB = false;
    if (!(referenceFace(a, -normalOnB, reference) && incidentFeature(b, normalOnB, incident))) return 0;
  }
  clipToFace(reference, incident);
  const Real ma = a.view->margin, mb = b.view->margin;
  const V3 n = referenceIsB ? reference.normal : V3(-reference.normal);
  int added = 0;
  for (int i = 0; i < incident.count; ++i) {
    const V3& p = incident.points[i];
    const Real depth = (p - reference.origin).dot(reference.normal) - ma - mb;
    if (depth > threshold) continue;
    const V3 pointOnB = referenceIsB ? V3(p - n * ma - n * depth) : V3(p + n * mb);
    sink.add(n, pointOnB, depth, TriangleIds(), true);
    ++added;
  }
  return added;
}

}  // namespace

void convexContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, ContactSink& sink) {
  DistanceResult<Real> d;
  if (!distance(d, a.view->geom, a.pose, b.view->geom, b.pose).ok()) return;
  const Real depth = d.distance - a.view->margin - b.view->margin;
  const V3 normalOnB = -d.normal;  // gq's normal runs from A to B
  if (!(depth <= threshold) || !isFinite(normalOnB) || normalOnB.squaredNorm() < Real(0.5)) return;
  if (clippedContacts(a, b, normalOnB, threshold, sink) > 0) return;
  sink.add(normalOnB, d.point1 + normalOnB * b.view->margin, depth, TriangleIds(), true);
}

}  // namespace gq::bullet
