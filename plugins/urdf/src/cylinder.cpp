// A URDF cylinder (axis local Z, `length` along it) as gq's exact custom Cylinder (gq/custom_shapes.h), whose axis
// is local X: the shape frame is the URDF frame turned a quarter about Y (-pi/2 maps X onto Z). No approximation:
// its error bound is 0.
#include <cmath>

#include "gq/custom_shapes.h"
#include "internal.h"

namespace gq::urdf::internal {

template <class T> std::size_t hullBytes(const ConvexMesh<T>& h) {
  return h.vertices.size() * sizeof(Vec3<T>) + h.polygons.size() * sizeof(HullPolygon<T>) +
         (h.polygonVertices.size() + h.adjacency.size() + h.adjacencyOffsets.size()) * sizeof(std::uint32_t);
}

template <class T> Transform<T> cylinderAxisToUrdfZ() {
  return Transform<T>(Vec3<T>::Zero(), Quat<T>(Eigen::AngleAxis<T>(T(-0.5 * M_PI), Vec3<T>::UnitY())));
}

template <class T> Status cylinderShape(T radius, T length, Shape<T>& shape, Transform<T>& fit) {
  CustomGeometry<T> cylinder;
  if (Status s = makeCylinder(radius, T(0.5) * length, cylinder); !s.ok())
    return Status::owned(StatusCode::ParseError, "cylinder needs a positive finite radius and length (radius " +
                              std::to_string(double(radius)) + ", length " + std::to_string(double(length)) + ")");
  shape.geometry = cylinder;
  shape.source = ShapeSource::Cylinder;
  shape.representation = Representation::Hull;  // unused for non-mesh sources
  shape.modelTriangles = 0;
  shape.bytes = sizeof(Geometry<T>) + sizeof(CylinderCallbacks<T>);
  shape.errorBound = T(0);
  fit = cylinderAxisToUrdfZ<T>();
  return {};
}

template std::size_t hullBytes<float>(const ConvexMesh<float>&);
template std::size_t hullBytes<double>(const ConvexMesh<double>&);
template Status cylinderShape<float>(float, float, Shape<float>&, Transform<float>&);
template Status cylinderShape<double>(double, double, Shape<double>&, Transform<double>&);

}  // namespace gq::urdf::internal
