// Enclosing spheres of shapes in their own frame, for culling. Centre: the local AABB centre. Radius: the largest
// distance from it to a hull or mesh vertex (the solid is their convex hull), closed forms for primitives, the
// AABB half-diagonal for custom shapes and scaled meshes.
#include <cmath>

#include "gq/cooking.h"
#include "gq/query.h"
#include "internal.h"

namespace gq::urdf::detail {
namespace {

template <class T> T farthestVertex(const std::vector<Vec3<T>>& vertices, const Vec3<T>& centre) {
  T r2 = T(0);
  for (const auto& v : vertices) r2 = std::max(r2, (v - centre).squaredNorm());
  return std::sqrt(r2);
}

template <class T> bool unscaled(const MeshScale<T>& s) { return (s.scale.array() == T(1)).all(); }

}  // namespace

template <class T> Status shapeLocalBounds(const Geometry<T>& g, Bounds3<T>& box, Vec3<T>& centre, T& radius) {
  if (Status s = computeGeomBounds(box, g, Transform<T>(), T(0), T(1)); !s.ok()) return s;
  centre = box.center();
  radius = box.extents().norm();
  if (const auto* sphere = g.template getIf<SphereGeometry<T>>()) radius = sphere->radius;
  else if (const auto* capsule = g.template getIf<CapsuleGeometry<T>>()) radius = capsule->radius + capsule->halfHeight;
  else if (const auto* hull = g.template getIf<ConvexMeshGeometry<T>>(); hull && unscaled(hull->scale))
    radius = farthestVertex(hull->mesh->vertices, centre);
  else if (const auto* mesh = g.template getIf<TriangleMeshGeometry<T>>(); mesh && unscaled(mesh->scale))
    radius = farthestVertex(mesh->mesh->vertices, centre);
  return {};
}

template Status shapeLocalBounds<float>(const Geometry<float>&, Bounds3<float>&, Vec3<float>&, float&);
template Status shapeLocalBounds<double>(const Geometry<double>&, Bounds3<double>&, Vec3<double>&, double&);

}  // namespace gq::urdf::detail
