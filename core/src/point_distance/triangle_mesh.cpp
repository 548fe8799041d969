// PLACEHOLDER
#include "point_distance/point_distance.h"
namespace gq::detail {
template <class T>
void pointDistanceTriangleMesh(const TriangleMeshGeometry<T>&, const Transform<T>&, const Vec3<T>&, PointDistanceResult<T>&) {}
template void pointDistanceTriangleMesh<float>(const TriangleMeshGeometry<float>&, const Transform<float>&, const Vec3<float>&, PointDistanceResult<float>&);
template void pointDistanceTriangleMesh<double>(const TriangleMeshGeometry<double>&, const Transform<double>&, const Vec3<double>&, PointDistanceResult<double>&);
}  // namespace gq::detail
