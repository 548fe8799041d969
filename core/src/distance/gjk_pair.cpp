// Every other convex pair: GJK on the cores; when they overlap, EPA for depth, normal and witnesses (two hulls whose
// EPA does not converge: the exact SAT depth instead).
#include "distance/distance.h"
#include "gjk/gjk.h"
#include "gjk/support_map.h"
#include "penetration/penetration.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers
namespace {

// Two overlapping hulls whose EPA did not converge (slivers near the minimum that float cannot expand): the exact
// SAT depth over both hulls' faces and edge pairs (as computePenetration), with witnesses B's deepest point along
// the normal and its translate by the depth, which lies on A's support plane. False: the SAT found them apart.
template <class T>
bool exactHullDepth(const ConvexMeshGeometry<T>& h0, const Transform<T>& p0, const ConvexMeshGeometry<T>& h1,
                    const Transform<T>& p1, const ConvexShape<T>& b, DistanceResult<T>& out) {
  Vec3<T> direction;  // moves geom0 out: the normal from 0 to 1 is its opposite
  T depth;
  if (!penetrationConvexConvex(h0, p0, h1, p1, direction, depth)) return false;
  const Vec3<T> n = -direction;
  SupportMap<T> sb(b);
  out.distance = -depth;
  out.normal = n;
  out.point1 = sb(Vec3<T>(-n));
  out.point0 = out.point1 + depth * n;
  return true;
}

}  // namespace

template <class T>
Status distanceGjk(const Geometry<T>& g0, const Transform<T>& pose0, const Geometry<T>& g1, const Transform<T>& pose1,
                   GjkCache<T>* cache, DistanceResult<T>& out, T stopTolerance, T farEnough) {
  const ConvexShape<T> a = makeConvexShape(g0, pose0);
  const ConvexShape<T> b = makeConvexShape(g1, pose1);
  const GjkResult<T> g = gjkDistance(a, b, cache, stopTolerance, static_cast<const Vec3<T>*>(nullptr), farEnough);
  if (g.beyond) {
    out.distance = g.distance;
    return Status();
  }
  if (!g.coresOverlap) {
    writeSeparated(g, out);
    return g.status.ok() ? Status() : g.status.withCode(StatusCode::Warning);
  }
  const EpaResult<T> e = epaPenetration(a, b, &g.simplex);
  const auto* h0 = g0.template getIf<ConvexMeshGeometry<T>>();
  const auto* h1 = g1.template getIf<ConvexMeshGeometry<T>>();
  if (!e.status.ok() && h0 && h1 && exactHullDepth(*h0, pose0, *h1, pose1, b, out)) return Status();
  out.distance = -e.depth;
  out.normal = e.normal;
  out.point0 = e.point0;
  out.point1 = e.point1;
  return e.status.ok() ? Status() : e.status.withCode(StatusCode::Warning);
}

template Status distanceGjk<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                                   const Transform<float>&, GjkCache<float>*, DistanceResult<float>&, float, float);
template Status distanceGjk<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                    const Transform<double>&, GjkCache<double>*, DistanceResult<double>&, double, double);

}  // namespace gq::kernels
