// Plane vs triangle mesh / heightfield distance: the lowest vertex over the plane (distance/plane_surface.h), the
// signed height of plane-convex distance. Closed forms: the bound of distanceWithin is not used.
#include "distance/plane_surface.h"

namespace gq::detail {
namespace {

template <class T>
Status fromLowest(const LowestVertex<T>& lowest, const Transform<T>& planePose, GjkCache<T>* cache,
                  DistanceResult<T>& out) {
  if (!(lowest.height < std::numeric_limits<T>::infinity()))
    return Status::degenerate("the surface has no triangles (every heightfield cell is a hole)");
  const Vec3<T> n = planePose.rotate(Vec3<T>::UnitX());
  out.distance = lowest.height;
  out.normal = n;
  out.point1 = lowest.point;
  out.point0 = lowest.point - lowest.height * n;
  if (cache) cache->iterations = 0;
  return Status();
}

}  // namespace

template <class T>
Status distancePlaneTriangleMesh(const Geometry<T>&, const Transform<T>& p0, const Geometry<T>& g1,
                                 const Transform<T>& p1, GjkCache<T>* cache, DistanceResult<T>& out, T) {
  const T all = -std::numeric_limits<T>::infinity();
  return fromLowest(lowestVertexTriangleMesh(g1.template get<TriangleMeshGeometry<T>>(), p1, p0, all), p0, cache, out);
}

template <class T>
Status distancePlaneHeightField(const Geometry<T>&, const Transform<T>& p0, const Geometry<T>& g1,
                                const Transform<T>& p1, GjkCache<T>* cache, DistanceResult<T>& out, T) {
  const T all = -std::numeric_limits<T>::infinity();
  return fromLowest(lowestVertexHeightField(g1.template get<HeightFieldGeometry<T>>(), p1, p0, all), p0, cache, out);
}

template Status distancePlaneTriangleMesh<float>(const Geometry<float>&, const Transform<float>&,
                                                 const Geometry<float>&, const Transform<float>&, GjkCache<float>*,
                                                 DistanceResult<float>&, float);
template Status distancePlaneTriangleMesh<double>(const Geometry<double>&, const Transform<double>&,
                                                  const Geometry<double>&, const Transform<double>&, GjkCache<double>*,
                                                  DistanceResult<double>&, double);
template Status distancePlaneHeightField<float>(const Geometry<float>&, const Transform<float>&,
                                                const Geometry<float>&, const Transform<float>&, GjkCache<float>*,
                                                DistanceResult<float>&, float);
template Status distancePlaneHeightField<double>(const Geometry<double>&, const Transform<double>&,
                                                 const Geometry<double>&, const Transform<double>&, GjkCache<double>*,
                                                 DistanceResult<double>&, double);

}  // namespace gq::detail
