// World AABB of a heightfield. In shape space the field lies in the box
// [0, (rows-1)*rowScale] x [minHeight, maxHeight]*heightScale x [0, (columns-1)*columnScale], and that box is tight:
// the corner samples reach the X/Z extremes and the min/max samples reach the Y extremes (heightScale > 0). The world
// AABB is the exact bound of the box's 8 rotated corners (not of the triangles themselves, which may be smaller under
// rotation).
#include "bounds/bounds.h"
#include "gq/cooking.h"

namespace gq::detail {

template <class T> Bounds3<T> boundsHeightField(const HeightFieldGeometry<T>& g, const Transform<T>& pose) {
  const HeightField<T>& hf = *g.heightField;
  const Vec3<T> lo(T(0), hf.minHeight * g.heightScale, T(0));
  const Vec3<T> hi(T(hf.rows - 1) * g.rowScale, hf.maxHeight * g.heightScale, T(hf.columns - 1) * g.columnScale);
  Bounds3<T> out;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3<T> p((corner & 1) ? hi.x() : lo.x(), (corner & 2) ? hi.y() : lo.y(), (corner & 4) ? hi.z() : lo.z());
    out.include(pose.transform(p));
  }
  return out;
}

template Bounds3<float> boundsHeightField<float>(const HeightFieldGeometry<float>&, const Transform<float>&);
template Bounds3<double> boundsHeightField<double>(const HeightFieldGeometry<double>&, const Transform<double>&);

}  // namespace gq::detail
