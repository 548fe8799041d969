// Culling volumes of shapes in their own frame. Sphere: centred at the local AABB centre, radius the largest
// distance from it to a hull or mesh vertex (the solid is their convex hull), closed forms for primitives, the AABB
// half-diagonal for custom shapes and scaled meshes. Box: the local AABB, or for hulls and meshes the box along the
// vertices' principal axes when its volume is smaller (robot links are often long and diagonal in their frame).
// Capsule: capsules and cylinders are their own; hulls and meshes along the vertices' principal axis, boxes along
// their longest axis (enclosingCapsule, mesh_shape.cpp).
#include <cmath>

#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "gq/query.h"
#include "internal.h"

namespace gq::urdf::internal {
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

template <class T> void setCapsule(CullVolume<T>& out, const Vec3<double>& centre, const Vec3<double>& axis, double half,
                                   double radius) {
  out.hasCapsule = true;
  out.capsuleStart = (centre - half * axis).cast<T>();
  out.capsuleSpan = (2.0 * half * axis).cast<T>();
  // Rounding of the placed ends: a few ulps of the capsule's size.
  out.capsuleRadius = T(radius + 8.0 * std::numeric_limits<T>::epsilon() * (half + radius + centre.norm()));
}

// Capsule of a cylinder or capsule along local X; of the corners of a box along its longest axis.
template <class T> void primitiveCapsule(const Geometry<T>& g, CullVolume<T>& out) {
  if (const auto* capsule = g.template getIf<CapsuleGeometry<T>>()) {
    setCapsule(out, Vec3<double>::Zero(), Vec3<double>::UnitX(), double(capsule->halfHeight), double(capsule->radius));
  } else if (const auto* custom = g.template getIf<CustomGeometry<T>>()) {
    if (const auto* cyl = dynamic_cast<const CylinderCallbacks<T>*>(custom->callbacks.get()))
      setCapsule(out, Vec3<double>::Zero(), Vec3<double>::UnitX(), double(cyl->halfHeight()), double(cyl->radius()));
  } else if (const auto* box = g.template getIf<BoxGeometry<T>>()) {
    std::vector<Vec3<T>> corners;
    for (int k = 0; k < 8; ++k)
      corners.push_back(box->halfExtents.cwiseProduct(Vec3<T>(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1)));
    int longest = 0;
    box->halfExtents.maxCoeff(&longest);
    Mat3<double> r;  // columns: the longest axis first, right-handed
    r << Vec3<double>::Unit(longest), Vec3<double>::Unit((longest + 1) % 3), Vec3<double>::Unit((longest + 2) % 3);
    const EnclosingCapsule c = enclosingCapsule(corners, r, 0.0);
    setCapsule(out, c.centre, c.axis, c.halfHeight, c.radius);
  }
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
  primitiveCapsule(g, out);
  if (const auto* vertices = solidVertices(g)) {
    out.radius = farthestVertex(*vertices, out.sphereCentre);
    tryPrincipalBox(*vertices, out);
    Vec3<double> mean;
    const EnclosingCapsule c = enclosingCapsule(*vertices, principalAxes(*vertices, mean), 0.0);
    setCapsule(out, c.centre, c.axis, c.halfHeight, c.radius);
  }
  // A capsule no thinner than the sphere culls nothing the sphere does not.
  if (out.hasCapsule && !(out.capsuleRadius < out.radius)) out.hasCapsule = false;
  return {};
}

template Status shapeCullVolume<float>(const Geometry<float>&, CullVolume<float>&);
template Status shapeCullVolume<double>(const Geometry<double>&, CullVolume<double>&);

}  // namespace gq::urdf::internal
