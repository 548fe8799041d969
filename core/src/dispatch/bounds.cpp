// computeGeomBounds façade: validation, one dispatch table indexed by GeometryType, then offset and inflation.
// Semantics (the spec): extents grow by `offset`, then the box is scaled about its centre by `inflation`;
// offset = 0, inflation = 1 is the tight box. Offset must be finite and >= 0, inflation finite and > 0.
// Infinite extents (planes, whose boxes reach +-max on their unbounded sides) stay at +-max: along such an axis
// only the finite face moves, outwards by offset (inflation about an infinite centre is meaningless).
#include <array>
#include <limits>

#include "bounds/bounds.h"
#include "common/validate.h"
#include "gq/query.h"
#include "prepared/shape_ref.h"

namespace gq {
namespace {

template <class T> using BoundsFn = Bounds3<T> (*)(const Geometry<T>&, const Transform<T>&);

template <class T, class G, Bounds3<T> (*Kernel)(const G&, const Transform<T>&)>
Bounds3<T> call(const Geometry<T>& g, const Transform<T>& pose) {
  return Kernel(g.template get<G>(), pose);
}

template <class T> constexpr std::array<BoundsFn<T>, kGeometryTypeCount> kBoundsTable = {
    call<T, SphereGeometry<T>, detail::boundsSphere<T>>,
    call<T, PlaneGeometry<T>, detail::boundsPlane<T>>,
    call<T, CapsuleGeometry<T>, detail::boundsCapsule<T>>,
    call<T, BoxGeometry<T>, detail::boundsBox<T>>,
    call<T, ConvexMeshGeometry<T>, detail::boundsConvex<T>>,
    call<T, TriangleMeshGeometry<T>, detail::boundsTriangleMesh<T>>,
    call<T, HeightFieldGeometry<T>, detail::boundsHeightField<T>>,
    call<T, CustomGeometry<T>, detail::boundsCustom<T>>,
};
static_assert(kBoundsTable<float>.size() == kGeometryTypeCount, "one bounds kernel per GeometryType");

template <class T> bool isUnbounded(T x) { return std::abs(x) >= std::numeric_limits<T>::max(); }

// Grows a box with an unbounded side: finite faces move out by offset, +-max stays.
template <class T> Bounds3<T> growUnbounded(Bounds3<T> b, T offset) {
  for (int i = 0; i < 3; ++i) {
    if (!isUnbounded(b.min[i])) b.min[i] -= offset;
    if (!isUnbounded(b.max[i])) b.max[i] += offset;
  }
  return b;
}

// (extents + offset) * inflation about the centre.
template <class T> Bounds3<T> grow(const Bounds3<T>& b, T offset, T inflation) {
  const Vec3<T> c = b.center();
  const Vec3<T> e = (b.extents() + Vec3<T>::Constant(offset)) * inflation;
  return Bounds3<T>::fromCenterExtents(c, e);
}

}  // namespace

namespace {

// The one path of both overloads once the geometry is valid.
template <class T>
Status boundsOfGeometry(Bounds3<T>& bounds, const Geometry<T>& geom, const Transform<T>& pose, T offset, T inflation) {
  if (Status s = detail::checkPose(pose, detail::kGeometryPoseField); !s.ok()) return s;
  if (!std::isfinite(offset) || offset < T(0)) return Status::invalid("bounds offset must be finite and >= 0");
  if (!std::isfinite(inflation) || !(inflation > T(0))) return Status::invalid("bounds inflation must be finite and > 0");
  const Bounds3<T> tight = kBoundsTable<T>[static_cast<std::size_t>(geom.type())](geom, pose);
  if (tight.isEmpty() || !isFinite(tight.min) || !isFinite(tight.max))
    return Status::internal("the bounds kernel of this geometry type returned no box").withType(geom.type());
  const bool unbounded = isUnbounded(tight.min.minCoeff()) || isUnbounded(tight.max.maxCoeff());
  const Bounds3<T> out = unbounded ? growUnbounded(tight, offset) : grow(tight, offset, inflation);
  if (!isFinite(out.min) || !isFinite(out.max)) return Status::invalid("bounds overflow the scalar range");
  bounds = out;
  return {};
}

}  // namespace

template <class T>
Status computeGeomBounds(Bounds3<T>& bounds, const Geometry<T>& geom, const Transform<T>& pose, T offset,
                         T inflation) noexcept {
  return detail::guarded([&]() -> Status {
    if (const detail::Problem p = detail::geometryProblem(geom)) return p.status();
    return boundsOfGeometry(bounds, geom, pose, offset, inflation);
  });
}

template <class T>
Status computeGeomBounds(Bounds3<T>& bounds, const Shape<T>& shape, const Transform<T>& pose, T offset,
                         T inflation) noexcept {
  return detail::guarded([&]() -> Status {
    if (!detail::ShapeAccess<T>::made(shape)) return Status::invalid(detail::emptyShapeText());
    return boundsOfGeometry(bounds, shape.geometry(), pose, offset, inflation);
  });
}

template Status computeGeomBounds<float>(Bounds3<float>&, const Geometry<float>&, const Transform<float>&, float, float);
template Status computeGeomBounds<double>(Bounds3<double>&, const Geometry<double>&, const Transform<double>&, double,
                                          double);
template Status computeGeomBounds<float>(Bounds3<float>&, const Shape<float>&, const Transform<float>&, float,
                                         float) noexcept;
template Status computeGeomBounds<double>(Bounds3<double>&, const Shape<double>&, const Transform<double>&, double,
                                          double) noexcept;

}  // namespace gq
