// Exact world AABB of a triangle-mesh instance: the extremes of the scaled, posed hull vertices (any extreme point
// of the mesh in any direction is a hull vertex, so this equals the AABB of all vertices).
#include "bounds/bounds.h"
#include "mesh/mesh_instance.h"

namespace gq::detail {

template <class T> Bounds3<T> boundsTriangleMesh(const TriangleMeshGeometry<T>& g, const Transform<T>& pose) {
  const MeshInstance<T> inst(g, pose);
  // World = rotation * S * v + p: fold both linear maps into one matrix.
  const Mat3<T> linear = pose.q.toRotationMatrix() * inst.scale;
  Bounds3<T> b;
  for (std::uint32_t i : inst.mesh.hullVertices) b.include(Vec3<T>(linear * inst.mesh.vertices[i]));
  b.min += pose.p;
  b.max += pose.p;
  return b;
}

template Bounds3<float> boundsTriangleMesh<float>(const TriangleMeshGeometry<float>&, const Transform<float>&);
template Bounds3<double> boundsTriangleMesh<double>(const TriangleMeshGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
