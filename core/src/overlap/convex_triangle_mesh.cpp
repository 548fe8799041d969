// Convex shape vs triangle mesh: the BVH leaves under the shape's box, then the exact shape-triangle test.
#include "mesh_pairs/shape_triangle.h"
#include "mesh_pairs/surface.h"
#include "overlap/surface_overlap.h"

namespace gq::detail {

template <class T>
Status overlapConvexTriangleMesh(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                 const Transform<T>& p1, bool& overlapping) {
  const TriangleQueryShape<T> shape(g0, p0);
  const MeshSurface<T> mesh(g1.template get<TriangleMeshGeometry<T>>(), p1);
  overlapping = mesh.forEachTriangle(shape.cullBounds(),
                                     [&](std::uint32_t, const Triangle<T>& tri) { return shape.overlaps(tri); });
  return Status();
}

template Status overlapConvexTriangleMesh<float>(const Geometry<float>&, const Transform<float>&,
                                                 const Geometry<float>&, const Transform<float>&, bool&);
template Status overlapConvexTriangleMesh<double>(const Geometry<double>&, const Transform<double>&,
                                                  const Geometry<double>&, const Transform<double>&, bool&);

}  // namespace gq::detail
