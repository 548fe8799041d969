// Routes a pair of placed shapes to the convex or surface contact generator, swapping the roles when the plane or
// surface comes first.
#include "contacts.h"

namespace gq::bullet {

bool pairContacts(const PlacedShape& a, const PlacedShape& b, Real threshold, const HandOver& handOver,
                  ContactSink& sink, PairMemory* memory) {
  const ShapeKind ka = a.view->kind, kb = b.view->kind;
  if (ka == ShapeKind::Convex && (kb == ShapeKind::Convex || kb == ShapeKind::Plane)) {
    convexContacts(a, b, threshold, sink, memory);
    return true;
  }
  if (ka == ShapeKind::Convex) {
    surfaceContacts(a, b, threshold, handOver, sink);
    return true;
  }
  if (kb != ShapeKind::Convex) return false;
  SwappedSink swapped(sink);
  if (ka == ShapeKind::Plane)
    convexContacts(b, a, threshold, swapped, memory);
  else
    surfaceContacts(b, a, threshold, handOver, swapped);
  return true;
}

}  // namespace gq::bullet
