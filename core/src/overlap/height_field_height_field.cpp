// Heightfield vs heightfield: cells of the first under the second's box, each triangle against the second's cells
// under its box, exact triangle-triangle test.
#include "mesh_pairs/surface_pairs.h"
#include "overlap/surface_overlap.h"

namespace gq::detail {

template <class T>
Status overlapHeightFieldHeightField(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                                     const Transform<T>& p1, bool& overlapping) {
  const HeightFieldSurface<T> a(g0.template get<HeightFieldGeometry<T>>(), p0);
  const HeightFieldSurface<T> b(g1.template get<HeightFieldGeometry<T>>(), p1);
  overlapping = forEachSurfacePair(a, b, T(0), [](std::uint32_t, const Triangle<T>&, std::uint32_t,
                                                  const Triangle<T>&) { return true; });
  return Status();
}

template Status overlapHeightFieldHeightField<float>(const Geometry<float>&, const Transform<float>&,
                                                     const Geometry<float>&, const Transform<float>&, bool&);
template Status overlapHeightFieldHeightField<double>(const Geometry<double>&, const Transform<double>&,
                                                      const Geometry<double>&, const Transform<double>&, bool&);

}  // namespace gq::detail
