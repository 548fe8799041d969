// Convex shape vs triangle mesh: the BVH leaves under the shape's box in mesh space, then the exact shape-triangle
// test. A box first rejects the triangles one of its face axes separates from their mesh-space vertices
// (BoxFaceCull): most triangles under a box's bounds, without building their world triangles.
#include "mesh_pairs/box_face_cull.h"
#include "mesh_pairs/shape_triangle.h"
#include "mesh_pairs/surface.h"
#include "overlap/surface_overlap.h"

namespace gq::detail {

template <class T>
Status overlapConvexTriangleMesh(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                 const Transform<T>& p1, bool& overlapping) {
  const TriangleQueryShape<T> shape(g0, p0);
  const MeshSurface<T> mesh(g1.template get<TriangleMeshGeometry<T>>(), p1);
  const Bounds3<T> meshBox = shape.cullBoundsIn(mesh.worldToMesh(), mesh.position());
  if (const auto* box = g0.template getIf<BoxGeometry<T>>()) {
    const BoxFaceCull<T> cull(*box, p0, mesh.meshToWorld(), mesh.position(), mesh.mesh().localBounds);
    overlapping = mesh.forEachCookedTriangle(
        meshBox,
        [&](std::uint32_t k) {
          return !cull.separates(mesh.cookedVertices(k).data()) && shape.overlaps(mesh.triangle(k));
        },
        [&](const Bounds3<T>& node) { return cull.separatesBox(node); });
    return Status();
  }
  overlapping = mesh.forEachTriangleInMeshBox(meshBox, [&](std::uint32_t, const Triangle<T>& tri) { return shape.overlaps(tri); });
  return Status();
}

template Status overlapConvexTriangleMesh<float>(const Geometry<float>&, const Transform<float>&,
                                                 const Geometry<float>&, const Transform<float>&, bool&);
template Status overlapConvexTriangleMesh<double>(const Geometry<double>&, const Transform<double>&,
                                                  const Geometry<double>&, const Transform<double>&, bool&);

}  // namespace gq::detail
