// Culling volumes of shapes in their own frame. Sphere: centred at the local AABB centre, radius the largest
// distance from it to a hull or mesh vertex (the solid is their convex hull), closed forms for primitives, the AABB
// half-diagonal for custom shapes and scaled meshes. Box: the local AABB, or for hulls and meshes the box along the
// vertices' principal axes when its volume is smaller (robot links are often long and diagonal in their frame).
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

// Vertices whose convex hull is the solid (unscaled hulls and meshes), else null.
template <class T> const std::vector<Vec3<T>>* solidVertices(const Geometry<T>& g) {
  if (const auto* hull = g.template getIf<ConvexMeshGeometry<T>>(); hull && unscaled(hull->scale))
    return &hull->mesh->vertices;
  if (const auto* mesh = g.template getIf<TriangleMeshGeometry<T>>(); mesh && unscaled(mesh->scale))
    return &mesh->mesh->vertices;
  return nullptr;
}

// Replaces the box by the principal-axes box of the vertices when that one is smaller.
template <class T> void tryPrincipalBox(const std::vector<Vec3<T>>& v, CullVolume<T>& out) {
  Vec3<double> mean, lo, hi;
  const Mat3<double> axes = principalAxes(v, mean);
  extentsIn(v, axes, lo, hi);
  const Vec3<double> half = (hi - lo) * 0.5;
  if (!(half.prod() < out.halfExtents.template cast<double>().prod())) return;
  out.boxAxes = axes.cast<T>();
  out.boxCentre = (axes * ((lo + hi) * 0.5)).cast<T>();
  // Rounding of the rotated extents: grow by a few ulps of the box size so every vertex stays inside.
  out.halfExtents = (half.array() + 8.0 * std::numeric_limits<T>::epsilon() * half.norm()).template cast<T>();
}

}  // namespace

template <class T> Status shapeCullVolume(const Geometry<T>& g, CullVolume<T>& out) {
  Bounds3<T> box;
  if (Status s = computeGeomBounds(box, g, Transform<T>(), T(0), T(1)); !s.ok()) return s;
  out = CullVolume<T>();
  out.boxCentre = out.sphereCentre = box.center();
  out.halfExtents = box.extents();
  out.radius = box.extents().norm();
  if (const auto* sphere = g.template getIf<SphereGeometry<T>>()) out.radius = sphere->radius;
  else if (const auto* capsule = g.template getIf<CapsuleGeometry<T>>()) out.radius = capsule->radius + capsule->halfHeight;
  if (const auto* vertices = solidVertices(g)) {
    out.radius = farthestVertex(*vertices, out.sphereCentre);
    tryPrincipalBox(*vertices, out);
  }
  return {};
}

template Status shapeCullVolume<float>(const Geometry<float>&, CullVolume<float>&);
template Status shapeCullVolume<double>(const Geometry<double>&, CullVolume<double>&);

}  // namespace gq::urdf::detail
