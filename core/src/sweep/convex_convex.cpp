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
  moving.size = std::max(a.size, std::min(maxDist, T(a.size + b.size + (a.pose.p - b.pose.p).norm())));
  const T touch = T(kSweepTouchFactor) * gjkTolerance(moving, b);
  const T target = T(0.5) * touch;  // aim a little short of contact so that the normal stays defined
  GjkCache<T> cache;
  ToiResult<T> out;
  T t = T(0);
  GjkResult<T> r;
  for (std::uint32_t it = 0; it < kSweepMaxIterations; ++it) {
    moving.pose.p = a.pose.p + t * dir;
    r = gjkDistance(moving, b, &cache);
    // By convexity d(t) >= target after a Newton step, so an overlap verdict there (or an unconverged GJK) is
    // suspect: ask GJK again from a cold start before trusting it.
    if ((it > 0 && r.coresOverlap) || !r.status.ok()) r = gjkDistance(moving, b);
    const bool touching = r.coresOverlap || r.distance <= touch;
    if (touching) {
      out.kind = (it == 0 && testInitialOverlap) ? ToiResult<T>::Kind::InitialOverlap : ToiResult<T>::Kind::Hit;
      out.distance = t;
      out.normal = r.coresOverlap ? Vec3<T>(-dir) : Vec3<T>(-r.normal);
      out.position = r.coresOverlap ? moving.center() : r.point1;
      return out;
    }
    const T closing = dir.dot(r.normal);
    if (!(closing > T(0))) return out;  // the distance does not decrease any more: it never reaches 0
    const T step = (r.distance - target) / closing;
    if (!(t + step <= maxDist)) return out;  // Newton under-estimates the root, so the root is beyond maxDist too
    t += step;
  }
  // Out of iterations (a grazing contact, where d'(root) = 0, converges only linearly): accept a near touch.
  if (r.distance <= T(1e3) * touch) {
    out.kind = ToiResult<T>::Kind::Hit;
    out.distance = t;
    out.normal = -r.normal;
    out.position = r.point1;
  }
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
