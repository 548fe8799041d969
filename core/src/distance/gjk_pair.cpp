// Every other convex pair: GJK on the cores; when they overlap, EPA for depth, normal and witnesses.
#include "distance/distance.h"
#include "gjk/gjk.h"

namespace gq::detail {

template <class T>
Status distanceGjk(const Geometry<T>& g0, const Transform<T>& pose0, const Geometry<T>& g1, const Transform<T>& pose1,
                   GjkCache<T>* cache, DistanceResult<T>& out, T stopTolerance) {
  const ConvexShape<T> a = makeConvexShape(g0, pose0);
  const ConvexShape<T> b = makeConvexShape(g1, pose1);
  const GjkResult<T> g = gjkDistance(a, b, cache, stopTolerance);
  if (!g.coresOverlap) {
    writeSeparated(g, out);
    return g.status.ok() ? Status() : Status::warning(g.status.message);
  }
  const EpaResult<T> e = epaPenetration(a, b, &g.simplex);
  out.distance = -e.depth;
  out.normal = e.normal;
  out.point0 = e.point0;
  out.point1 = e.point1;
  return e.status.ok() ? Status() : Status::warning(e.status.message);
}

template Status distanceGjk<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                   const Transform<float>&, GjkCache<float>*, DistanceResult<float>&, float);
template Status distanceGjk<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                    const Transform<double>&, GjkCache<double>*, DistanceResult<double>&, double);

}  // namespace gq::detail
