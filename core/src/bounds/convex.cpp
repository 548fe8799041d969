// Convex bounds: exact, the box of every hull vertex under scale and pose.
#include "bounds/bounds.h"
#include "gq/cooking.h"
#include "shapes/hull_scale.h"

namespace gq::detail {

template <class T> Bounds3<T> boundsConvex(const ConvexMeshGeometry<T>& g, const Transform<T>& pose) {
  const HullScale<T> scale(g.scale);
  const Mat3<T> toWorld = pose.q.toRotationMatrix() * scale.toShape;
  Bounds3<T> b;
  for (const Vec3<T>& v : g.mesh->vertices) b.include(Vec3<T>(toWorld * v));
  b.min += pose.p;
  b.max += pose.p;
  return b;
}

template Bounds3<float> boundsConvex<float>(const ConvexMeshGeometry<float>&, const Transform<float>&);
template Bounds3<double> boundsConvex<double>(const ConvexMeshGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
