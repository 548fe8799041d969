// Convex shape vs heightfield: the cells under the shape's box, then the exact shape-triangle test.
#include "mesh_pairs/shape_triangle.h"
#include "mesh_pairs/surface.h"
#include "overlap/surface_overlap.h"

namespace gq::detail {

template <class T>
Status overlapConvexHeightField(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                const Transform<T>& p1, bool& overlapping) {
  const TriangleQueryShape<T> shape(g0, p0);
  const HeightFieldSurface<T> field(g1.template get<HeightFieldGeometry<T>>(), p1);
  overlapping = field.forEachTriangle(shape.cullBounds(),
                                      [&](std::uint32_t, const Triangle<T>& tri) { return shape.overlaps(tri); });
  return Status();
}

template Status overlapConvexHeightField<float>(const Geometry<float>&, const Transform<float>&,
                                                 const Geometry<float>&, const Transform<float>&, bool&);
template Status overlapConvexHeightField<double>(const Geometry<double>&, const Transform<double>&,
                                                  const Geometry<double>&, const Transform<double>&, bool&);

}  // namespace gq::detail
