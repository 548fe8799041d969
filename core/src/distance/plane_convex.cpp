// Plane vs convex mesh or convex custom shape: the support point along -normal is the deepest point
// (hill-climbing support for large hulls).
#include "distance/distance.h"
#include "gjk/gjk.h"

namespace gq::kernels {
using namespace detail;  // core's internal helpers

template <class T>
void distancePlaneConvex(const PlaneGeometry<T>&, const Transform<T>& pose0, const Geometry<T>& g1,
                         const Transform<T>& pose1, DistanceResult<T>& out) {
  const ConvexShape<T> shape = makeConvexShape(g1, pose1);
  const Vec3<T> n = pose0.rotate(Vec3<T>(Vec3<T>::UnitX()));
  const Vec3<T> deepest = shape.support(Vec3<T>(-n));
  const T height = n.dot(deepest - pose0.p);
  out.normal = n;
  out.distance = height;
  out.point0 = deepest - height * n;
  out.point1 = deepest;
}

template void distancePlaneConvex<float>(const PlaneGeometry<float>&, const Transform<float>&, const Geometry<float>&, const Transform<float>&, DistanceResult<float>&);
template void distancePlaneConvex<double>(const PlaneGeometry<double>&, const Transform<double>&, const Geometry<double>&, const Transform<double>&, DistanceResult<double>&);

}  // namespace gq::kernels
