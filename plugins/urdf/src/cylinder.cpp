// A URDF cylinder (axis local Z, `length` along it) as the convex hull of the inscribed n-gon prism. The prism lies
// inside the cylinder; the farthest cylinder point from it is mid-edge on the rim, at the sagitta r (1 - cos(pi/n)).
#include <cmath>

#include "internal.h"

namespace gq::urdf::detail {

template <class T> std::size_t hullBytes(const ConvexMesh<T>& h) {
  return h.vertices.size() * sizeof(Vec3<T>) + h.polygons.size() * sizeof(HullPolygon<T>) +
         (h.polygonVertices.size() + h.adjacency.size() + h.adjacencyOffsets.size()) * sizeof(std::uint32_t);
}

template <class T> Status cylinderShape(T radius, T length, std::uint32_t segments, Shape<T>& shape) {
  if (!(radius > T(0)) || !(length > T(0)) || !std::isfinite(radius) || !std::isfinite(length))
    return Status::parseError("cylinder needs a positive finite radius and length (radius " +
                              std::to_string(double(radius)) + ", length " + std::to_string(double(length)) + ")");
  std::vector<Vec3<T>> points;
  points.reserve(2 * segments);
  const double step = 2.0 * M_PI / segments;
  for (std::uint32_t k = 0; k < segments; ++k) {
    const T c = T(radius * std::cos(k * step)), s = T(radius * std::sin(k * step));
    points.emplace_back(c, s, T(-0.5) * length);
    points.emplace_back(c, s, T(0.5) * length);
  }
  std::shared_ptr<const ConvexMesh<T>> hull;
  Status st = cookConvexMesh(points, hull);
  if (!st.ok()) return st;
  shape.geometry = ConvexMeshGeometry<T>(hull);
  shape.source = ShapeSource::Cylinder;
  shape.representation = Representation::Hull;
  shape.modelTriangles = std::uint32_t(hull->polygons.size());
  shape.bytes = hullBytes(*hull);
  shape.error.meshToApproximation = T(radius * (1.0 - std::cos(M_PI / segments)));
  shape.error.approximationToMesh = T(0);
  return {};
}

template std::size_t hullBytes<float>(const ConvexMesh<float>&);
template std::size_t hullBytes<double>(const ConvexMesh<double>&);
template Status cylinderShape<float>(float, float, std::uint32_t, Shape<float>&);
template Status cylinderShape<double>(double, double, std::uint32_t, Shape<double>&);

}  // namespace gq::urdf::detail
