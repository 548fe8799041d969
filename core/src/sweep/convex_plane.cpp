// Sweep of a support-mapped shape against a plane (a solid half-space), in closed form: the shape first touches the
// plane with its support point along -n, whose height above the plane is h = n.(s - p) - margin; it reaches the
// plane after h / (-n.dir). h <= 0 is an initial overlap of depth -h.
#include "sweep/sweep.h"

namespace gq::detail {

template <class T>
void sweepConvexPlane(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>&, const Transform<T>& p1,
                      const SweepQuery<T>& q, SweepOutcome<T>& out) {
  const ConvexShape<T> a = makeSweptShape(g0, p0, q.inflation);
  const Vec3<T> n = p1.rotate(Vec3<T>::UnitX());
  const Vec3<T> lowest = a.support(-n) - a.margin * n;  // the swept shape's point deepest along -n
  const T h = n.dot(lowest - p1.p);
  if (h <= T(0)) {
    out.hit = true;
    out.initialOverlap = q.testInitialOverlap;
    out.distance = T(0);
    out.normal = n;
    out.position = lowest;
    out.mtdValid = true;
    out.mtdDepth = -h;
    out.mtdNormal = n;
    out.mtdPosition = lowest;
    return;
  }
  const T closing = -n.dot(q.dir);
  if (!(closing > T(0))) return;
  const T t = h / closing;
  if (!(t <= q.maxDist)) return;
  out.hit = true;
  out.distance = t;
  out.normal = n;
  out.position = lowest + t * q.dir;
}

template void sweepConvexPlane<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                      const Transform<float>&, const SweepQuery<float>&, SweepOutcome<float>&);
template void sweepConvexPlane<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                       const Transform<double>&, const SweepQuery<double>&, SweepOutcome<double>&);

}  // namespace gq::detail
