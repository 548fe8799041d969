// MTD of a convex custom geometry with any support-mapped shape: GJK, then EPA when the cores overlap
// (gjk/gjk.h). EPA's normal points from geom0 to geom1, so geom0 separates along -normal.
#include "gjk/gjk.h"
#include "penetration/penetration.h"

namespace gq::detail {

template <class T>
Status penetrationCustomAny(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                            bool& penetrating, Vec3<T>& direction, T& depth) {
  const ConvexShape<T> a = makeConvexShape(g0, p0), b = makeConvexShape(g1, p1);
  if (!gjkOverlap(a, b)) {
    penetrating = false;
    return Status();
  }
  const EpaResult<T> epa = epaPenetration(a, b);
  if (!epa.status.ok()) return epa.status;
  penetrating = true;
  direction = -epa.normal;
  depth = std::max(epa.depth, T(0));
  return Status();
}

template Status penetrationCustomAny<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&, const Transform<float>&,
                                            bool&, Vec3<float>&, float&);
template Status penetrationCustomAny<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&, const Transform<double>&,
                                             bool&, Vec3<double>&, double&);

}  // namespace gq::detail
