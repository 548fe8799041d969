// Plane vs triangle mesh distance: the lowest vertex's signed height (distance/plane_surface.h; the search is in
// overlap/plane_triangle_mesh.cpp). A closed form: distanceWithin's bound is not used.
#include "distance/plane_surface.h"

namespace gq::detail {

template <class T>
Status distancePlaneTriangleMesh(const Geometry<T>&, const Transform<T>& p0, const Geometry<T>& g1,
                                 const Transform<T>& p1, GjkCache<T>* cache, DistanceResult<T>& out, T) {
  const T all = -std::numeric_limits<T>::infinity();
  return distanceFromLowestVertex(lowestVertexTriangleMesh(g1.template get<TriangleMeshGeometry<T>>(), p1, p0, all),
                                  p0, cache, out);
}

template Status distancePlaneTriangleMesh<float>(const Geometry<float>&, const Transform<float>&,
                                                 const Geometry<float>&, const Transform<float>&, GjkCache<float>*,
                                                 DistanceResult<float>&, float);
template Status distancePlaneTriangleMesh<double>(const Geometry<double>&, const Transform<double>&,
                                                  const Geometry<double>&, const Transform<double>&, GjkCache<double>*,
                                                  DistanceResult<double>&, double);

}  // namespace gq::detail
