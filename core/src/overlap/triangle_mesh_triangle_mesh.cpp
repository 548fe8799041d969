// Triangle mesh vs triangle mesh: dual BVH traversal (mesh_pairs/mesh_mesh.h), exact triangle-triangle SAT test.
// The second mesh is expressed in the first's frame, so only its boxes are loosened by the relative rotation.
#include "mesh_pairs/mesh_mesh.h"
#include "overlap/surface_overlap.h"

namespace gq::detail {

template <class T>
Status overlapTriangleMeshTriangleMesh(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                       const Transform<T>& p1, bool& overlapping) {
  const MeshSurface<T> a(g0.template get<TriangleMeshGeometry<T>>(), Transform<T>());
  const MeshSurface<T> b(g1.template get<TriangleMeshGeometry<T>>(), p1.relativeTo(p0));
  overlapping = forEachTrianglePair(a, b, T(0), [](std::uint32_t, const Triangle<T>& ta, std::uint32_t,
                                                   const Triangle<T>& tb) { return overlapTriangleTriangle(ta, tb); });
  return Status();
}

template Status overlapTriangleMeshTriangleMesh<float>(const Geometry<float>&, const Transform<float>&,
                                                       const Geometry<float>&, const Transform<float>&, bool&);
template Status overlapTriangleMeshTriangleMesh<double>(const Geometry<double>&, const Transform<double>&,
                                                        const Geometry<double>&, const Transform<double>&, bool&);

}  // namespace gq::detail
