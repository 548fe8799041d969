// Sweep of a support-mapped shape against another (sphere, capsule, box, convex mesh, convex custom), by
// conservative advancement on the exact GJK distance.
//
// With a moving along dir, d(t) = dist(A + t dir, B) is the distance from a point moving on a line to the convex
// set B - A, hence convex in t, with slope d'(t) = -dot(dir, n) (n = unit normal from A to B). The advancement step
// t += d / dot(dir, n) is Newton's method on d: for a convex decreasing function it never overshoots the root, it is
// exact in one step while the closest features stay flat (face contacts) and converges quadratically on curved ones.
// When dot(dir, n) <= 0 the distance no longer decreases, so by convexity it never reaches 0: a miss.
#include "sweep/sweep.h"

namespace gq::detail {

template <class T> ConvexShape<T> makeSweptShape(const Geometry<T>& g, const Transform<T>& pose, T inflation) {
  ConvexShape<T> s = makeConvexShape(g, pose);
  s.margin += inflation;
  s.size += inflation;
  return s;
}

template <class T>
ToiResult<T> sweepConvexShapes(const ConvexShape<T>& a, const ConvexShape<T>& b, const Vec3<T>& dir, T maxDist,
                               bool testInitialOverlap) {
  // Rounding of the moved support points grows with the distance travelled: include it in the length scale.
  ConvexShape<T> moving = a;
  moving.size = std::max(a.size, std::min(maxDist, T(a.size + b.size + (a.position - b.position).norm())));
  const T touch = T(kSweepTouchFactor) * gjkTolerance(moving, b);
  const T target = T(0.5) * touch;  // aim a little short of contact so that the normal stays defined
  GjkCache<T> cache;
  ToiResult<T> out;
  auto distanceAt = [&](T t, GjkCache<T>* c) {
    moving.position = a.position + t * dir;
    return gjkDistance(moving, b, c);
  };
  auto isTouching = [&](const GjkResult<T>& r) { return r.coresOverlap || r.distance <= touch; };
  auto hitAt = [&](T t, const GjkResult<T>& r) {
    out.kind = ToiResult<T>::Kind::Hit;
    out.distance = t;
    out.normal = r.coresOverlap ? Vec3<T>(-dir) : Vec3<T>(-r.normal);
    out.position = r.coresOverlap ? Vec3<T>(a.center() + t * dir) : r.point1;
  };
  // Contact inside [lo, hi] (separated at lo, touching at hi), by bisection on the touching verdict: the guard for
  // a Newton step that landed past the contact, which only an over-estimated distance at lo can cause.
  auto bisectContact = [&](T lo, GjkResult<T> rLo, T hi) {
    const T resolution = touch;
    while (hi - lo > resolution) {
      const T mid = T(0.5) * (lo + hi);
      if (!(mid > lo && mid < hi)) break;  // adjacent values: a resolution below T's spacing here cannot be met
      const GjkResult<T> r = distanceAt(mid, nullptr);
      if (isTouching(r)) hi = mid;
      else { lo = mid; rLo = r; }
    }
    hitAt(lo, rLo);
    return out;
  };
  T t = T(0), previousT = T(0);
  GjkResult<T> r, previous;
  for (std::uint32_t it = 0; it < kSweepMaxIterations; ++it) {
    r = distanceAt(t, &cache);
    // By convexity d(t) >= target after a Newton step, so an overlap verdict there (or an unconverged GJK) is
    // suspect: ask GJK again from a cold start before trusting it.
    if ((it > 0 && r.coresOverlap) || !r.status.ok()) r = distanceAt(t, nullptr);
    if (isTouching(r)) {
      if (it == 0) {
        hitAt(t, r);
        if (testInitialOverlap) out.kind = ToiResult<T>::Kind::InitialOverlap;
        return out;
      }
      if (r.coresOverlap) return bisectContact(previousT, previous, t);
      hitAt(t, r);
      return out;
    }
    const T closing = dir.dot(r.normal);
    if (!(closing > T(0))) return out;  // the distance does not decrease any more: it never reaches 0
    const T step = (r.distance - target) / closing;
    if (!(t + step <= maxDist)) {
      // Newton under-estimates the root, so the root is beyond maxDist too; one check at maxDist guards against
      // an over-estimated distance.
      const GjkResult<T> end = distanceAt(maxDist, nullptr);
      if (isTouching(end)) return bisectContact(t, r, maxDist);
      return out;
    }
    previous = r;
    previousT = t;
    t += step;
  }
  // Out of iterations (a grazing contact, where d'(root) = 0, converges only linearly): accept a near touch.
  if (r.distance <= T(1e3) * touch) hitAt(t, r);
  return out;
}

template <class T> void convexMtd(const ConvexShape<T>& a, const ConvexShape<T>& b, SweepOutcome<T>& out) {
  const EpaResult<T> e = epaPenetration(a, b);
  out.mtdValid = isFinite(e.normal) && std::isfinite(e.depth);
  if (!out.mtdValid) return;
  out.mtdDepth = std::max(T(0), e.depth);
  out.mtdNormal = -e.normal;  // e.normal points from a to b: a leaves along -normal
  out.mtdPosition = e.point0;
}

template <class T> void outcomeFromToi(const ToiResult<T>& toi, SweepOutcome<T>& out) {
  out.hit = toi.kind != ToiResult<T>::Kind::Miss;
  out.initialOverlap = toi.kind == ToiResult<T>::Kind::InitialOverlap;
  out.distance = toi.distance;
  out.normal = toi.normal;
  out.position = toi.position;
}

template <class T>
void sweepConvexConvex(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                       const SweepQuery<T>& q, SweepOutcome<T>& out) {
  const ConvexShape<T> a = makeSweptShape(g0, p0, q.inflation);
  const ConvexShape<T> b = makeConvexShape(g1, p1);
  outcomeFromToi(sweepConvexShapes(a, b, q.dir, q.maxDist, q.testInitialOverlap), out);
  if (out.initialOverlap && q.mtd) convexMtd(a, b, out);
  // faceIndex of a convex mesh is its polygon: found only when asked (it scans the polygons).
  const auto* convex = g1.template getIf<ConvexMeshGeometry<T>>();
  if (convex && out.hit && !out.initialOverlap && q.flags.has(HitFlag::FaceIndex))
    out.faceIndex = convexPolygonAt(*convex, p1, out.position, out.normal);
}

template ConvexShape<float> makeSweptShape<float>(const Geometry<float>&, const Transform<float>&, float);
template ToiResult<float> sweepConvexShapes<float>(const ConvexShape<float>&, const ConvexShape<float>&, const Vec3<float>&, float, bool);
template void convexMtd<float>(const ConvexShape<float>&, const ConvexShape<float>&, SweepOutcome<float>&);
template void outcomeFromToi<float>(const ToiResult<float>&, SweepOutcome<float>&);
template void sweepConvexConvex<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&, const Transform<float>&,
                                   const SweepQuery<float>&, SweepOutcome<float>&);
template ConvexShape<double> makeSweptShape<double>(const Geometry<double>&, const Transform<double>&, double);
template ToiResult<double> sweepConvexShapes<double>(const ConvexShape<double>&, const ConvexShape<double>&, const Vec3<double>&, double, bool);
template void convexMtd<double>(const ConvexShape<double>&, const ConvexShape<double>&, SweepOutcome<double>&);
template void outcomeFromToi<double>(const ToiResult<double>&, SweepOutcome<double>&);
template void sweepConvexConvex<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&, const Transform<double>&,
                                   const SweepQuery<double>&, SweepOutcome<double>&);

}  // namespace gq::detail
