// faceIndex of a sweep hit on a convex mesh: the polygon whose plane passes through the touching point (within a
// tolerance relative to the hull size) and whose outward normal agrees best with the contact normal. At an edge or
// vertex several planes pass through the point; the contact normal picks the face the swept shape came from.
#include "gq/cooking.h"
#include "shapes/hull_scale.h"
#include "sweep/sweep.h"

namespace gq::detail {

template <class T>
std::uint32_t convexPolygonAt(const ConvexMeshGeometry<T>& g, const Transform<T>& pose, const Vec3<T>& point,
                              const Vec3<T>& normal) {
  const ConvexMesh<T>& hull = *g.mesh;
  const HullScale<T> s(g.scale);
  // Mesh space: x_mesh = S^-1 x_shape; a mesh-space plane normal m maps to S^-1 m in shape space, so the contact
  // normal maps back as S n (normalised), and plane distances are compared after that scaling.
  const Vec3<T> xm = s.toMesh * pose.transformInv(point);
  const Vec3<T> nm = (s.toShape * pose.rotateInv(normal)).stableNormalized();
  const T size = std::max(hull.localBounds.extents().norm(), std::numeric_limits<T>::min());
  const T planeTol = std::sqrt(std::numeric_limits<T>::epsilon()) * size;
  std::uint32_t best = kInvalidFaceIndex, fallback = 0;
  T bestDot = -std::numeric_limits<T>::infinity(), fallbackDot = -std::numeric_limits<T>::infinity();
  for (std::uint32_t i = 0; i < hull.polygons.size(); ++i) {
    const HullPolygon<T>& poly = hull.polygons[i];
    const T alignment = poly.normal.dot(nm);
    if (alignment > fallbackDot) { fallbackDot = alignment; fallback = i; }
    const T planeDistance = poly.normal.dot(xm) + poly.d;
    if (std::abs(planeDistance) <= planeTol && alignment > bestDot) { bestDot = alignment; best = i; }
  }
  return best != kInvalidFaceIndex ? best : fallback;
}

template std::uint32_t convexPolygonAt<float>(const ConvexMeshGeometry<float>&, const Transform<float>&,
                                              const Vec3<float>&, const Vec3<float>&);
template std::uint32_t convexPolygonAt<double>(const ConvexMeshGeometry<double>&, const Transform<double>&,
                                               const Vec3<double>&, const Vec3<double>&);

}  // namespace gq::detail
