// Sweep against custom geometry: the target's own sweep callback when it answers (gq/custom.h), else conservative
// advancement on its support mapping (sweepConvexConvex). The callback works in the custom shape's frame; its hit is
// checked (finite, unit normal, distance within [0, maxDist]) and brought back to the kernel's frame.
#include <cmath>
#include <string>

#include "custom/callback_queries.h"
#include "gq/tolerances.h"
#include "sweep/sweep.h"

namespace gq::detail {
namespace {

template <class T> bool validHit(const SweepHit<T>& h, T maxDist) {
  return std::isfinite(h.distance) && h.distance >= T(0) && h.distance <= maxDist && isFinite(h.normal) &&
         isFinite(h.position) && std::abs(h.normal.norm() - T(1)) <= T(tol::kUnitDirection);
}

// Depth and depenetration direction of an initial overlap: the custom shape's penetration callback when there is no
// inflation (the callback knows only the bare swept geometry), else EPA. The reported point is the swept shape's
// deepest point, its support along the direction opposite to its escape.
template <class T>
void customMtd(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
               const SweepQuery<T>& q, SweepOutcome<T>& out) {
  const ConvexShape<T> a = makeSweptShape(g0, p0, q.inflation);
  bool answered = false, penetrating = false;
  Vec3<T> direction = Vec3<T>::UnitX();
  T depth = T(0);
  if (q.inflation == T(0)) {
    out.status = customPenetration(g0, p0, g1, p1, answered, penetrating, direction, depth);
    if (!out.status.ok()) return;
  }
  if (!answered || !penetrating) {
    convexMtd(a, makeConvexShape(g1, p1), out);
    return;
  }
  out.mtdValid = true;
  out.mtdDepth = depth;
  out.mtdNormal = direction;  // direction moves geom0, the swept shape
  out.mtdPosition = a.support(-direction) - a.margin * direction;
}

}  // namespace

template <class T>
void sweepConvexCustom(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                       const SweepQuery<T>& q, SweepOutcome<T>& out) {
  const CustomGeometryCallbacks<T>& cb = *g1.template get<CustomGeometry<T>>().callbacks;
  SweepHit<T> hit;
  bool hasHit = false;
  const Transform<T> sweptPose = p0.relativeTo(p1);
  if (!cb.sweep(p1.rotateInv(q.dir), q.maxDist, g0, sweptPose, q.inflation, hit, hasHit)) {
    sweepConvexConvex(g0, p0, g1, p1, q, out);
    return;
  }
  if (!hasHit) return;
  if (!validHit(hit, q.maxDist)) {
    out.status = Status::aboutCustom(StatusCode::InternalError, CustomIssue::BadSweepHit, cb.name());
    return;
  }
  out.hit = true;
  out.initialOverlap = hit.initialOverlap && q.testInitialOverlap;
  out.distance = hit.initialOverlap ? T(0) : hit.distance;
  out.normal = p1.rotate(hit.normal).normalized();
  out.position = p1.transform(hit.position);
  if (out.initialOverlap && q.mtd) customMtd(g0, p0, g1, p1, q, out);
}

template void sweepConvexCustom<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                       const Transform<float>&, const SweepQuery<float>&, SweepOutcome<float>&);
template void sweepConvexCustom<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                        const Transform<double>&, const SweepQuery<double>&, SweepOutcome<double>&);

}  // namespace gq::detail
