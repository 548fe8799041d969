// Triangle mesh vs heightfield (not in the spec's engine): mesh triangles under the heightfield's box, each against
// the heightfield cells under its own box, exact triangle-triangle test.
#include "mesh_pairs/surface_pairs.h"
#include "overlap/surface_overlap.h"

namespace gq::detail {

template <class T>
Status overlapTriangleMeshHeightField(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                      const Transform<T>& p1, bool& overlapping) {
  const MeshSurface<T> a(g0.template get<TriangleMeshGeometry<T>>(), p0);
  const HeightFieldSurface<T> b(g1.template get<HeightFieldGeometry<T>>(), p1);
  overlapping = forEachSurfacePair(a, b, T(0), [](std::uint32_t, const Triangle<T>&, std::uint32_t,
                                                  const Triangle<T>&) { return true; });
  return Status();
}

template Status overlapTriangleMeshHeightField<float>(const Geometry<float>&, const Transform<float>&,
                                                      const Geometry<float>&, const Transform<float>&, bool&);
template Status overlapTriangleMeshHeightField<double>(const Geometry<double>&, const Transform<double>&,
                                                       const Geometry<double>&, const Transform<double>&, bool&);

}  // namespace gq::detail
