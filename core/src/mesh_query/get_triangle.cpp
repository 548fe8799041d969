// getTriangle for triangle meshes: the world triangle of an input triangle index (the faceIndex of hits).
#include "common/validate.h"
#include "gq/mesh_query.h"
#include "mesh/mesh_instance.h"

namespace gq {

template <class T>
Status getTriangle(const TriangleMeshGeometry<T>& mesh, const Transform<T>& pose, std::uint32_t triangleIndex,
                   Triangle<T>& triangle, std::uint32_t* vertexIndices) noexcept {
  return detail::guarded([&]() -> Status {
    if (Status s = detail::checkGeometryAndPose(Geometry<T>(mesh), pose, detail::kPoseField); !s.ok()) return s;
    if (triangleIndex >= mesh.mesh->inputTriangleCount())
      return Status::invalid("triangle index is out of range of the mesh's input triangles").withIndex(triangleIndex);
    const std::uint32_t cooked = mesh.mesh->cookedIndex[triangleIndex];
    if (cooked == kRemovedTriangle)
      return Status::invalid("the triangle was removed as degenerate at cooking").withIndex(triangleIndex);
    triangle = detail::MeshInstance<T>(mesh, pose).worldTriangle(cooked, vertexIndices);
    return Status();
  });
}

template Status getTriangle<float>(const TriangleMeshGeometry<float>&, const Transform<float>&, std::uint32_t,
                                   Triangle<float>&, std::uint32_t*);
template Status getTriangle<double>(const TriangleMeshGeometry<double>&, const Transform<double>&, std::uint32_t,
                                    Triangle<double>&, std::uint32_t*);

}  // namespace gq
