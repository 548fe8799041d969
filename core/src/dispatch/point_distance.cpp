// pointDistance façade: validation, then one dispatch table indexed by GeometryType. Plane, heightfield and custom
// geometries are not supported (as the spec: box, sphere, capsule, convex and mesh only).
#include <array>

#include "common/validate.h"
#include "gq/query.h"
#include "point_distance/point_distance.h"
#include "prepared/shape_ref.h"

namespace gq {
namespace {

template <class T>
using PointDistanceFn = Status (*)(const Geometry<T>&, const Transform<T>&, const Vec3<T>&, PointDistanceResult<T>&);

template <class T, class G,
          void (*Kernel)(const G&, const Transform<T>&, const Vec3<T>&, PointDistanceResult<T>&)>
Status call(const Geometry<T>& g, const Transform<T>& pose, const Vec3<T>& point, PointDistanceResult<T>& out) {
  Kernel(g.template get<G>(), pose, point, out);
  return {};
}

template <class T>
Status unsupported(const Geometry<T>& g, const Transform<T>&, const Vec3<T>&, PointDistanceResult<T>&) {
  return Status::unsupported("pointDistance is not available for this geometry type").withType(g.type());
}

template <class T> constexpr std::array<PointDistanceFn<T>, kGeometryTypeCount> kPointDistanceTable = {
    call<T, SphereGeometry<T>, detail::pointDistanceSphere<T>>,
    unsupported<T>,
    call<T, CapsuleGeometry<T>, detail::pointDistanceCapsule<T>>,
    call<T, BoxGeometry<T>, detail::pointDistanceBox<T>>,
    call<T, ConvexMeshGeometry<T>, detail::pointDistanceConvex<T>>,
    call<T, TriangleMeshGeometry<T>, detail::pointDistanceTriangleMesh<T>>,
    unsupported<T>,
    unsupported<T>,
};
static_assert(kPointDistanceTable<float>.size() == kGeometryTypeCount, "one entry per GeometryType");

}  // namespace

namespace {

// The one path of both overloads once the point and the geometry are valid.
template <class T>
Status pointDistanceGeometry(const Vec3<T>& point, const Geometry<T>& geom, const Transform<T>& pose,
                             PointDistanceResult<T>& result) {
  if (Status s = detail::checkPose(pose, detail::kGeometryPoseField); !s.ok()) return s;
  PointDistanceResult<T> out;
  if (Status s = kPointDistanceTable<T>[static_cast<std::size_t>(geom.type())](geom, pose, point, out); !s.ok())
    return s;
  if (!std::isfinite(out.distance) || !isFinite(out.closestPoint))
    return Status::internal("pointDistance produced a non-finite result");
  result = out;
  return {};
}

}  // namespace

template <class T>
Status pointDistance(const Vec3<T>& point, const Geometry<T>& geom, const Transform<T>& pose,
                     PointDistanceResult<T>& result) noexcept {
  return detail::guarded([&]() -> Status {
    if (Status s = detail::checkFinite(point, detail::kPointField); !s.ok()) return s;
    if (const detail::Problem p = detail::geometryProblem(geom)) return p.status();
    return pointDistanceGeometry(point, geom, pose, result);
  });
}

template <class T>
Status pointDistance(const Vec3<T>& point, const Shape<T>& shape, const Transform<T>& pose,
                     PointDistanceResult<T>& result) noexcept {
  return detail::guarded([&]() -> Status {
    if (Status s = detail::checkFinite(point, detail::kPointField); !s.ok()) return s;
    if (!detail::ShapeAccess<T>::made(shape)) return Status::invalid(detail::emptyShapeText());
    return pointDistanceGeometry(point, shape.geometry(), pose, result);
  });
}

template Status pointDistance<float>(const Vec3<float>&, const Geometry<float>&, const Transform<float>&,
                                     PointDistanceResult<float>&);
template Status pointDistance<double>(const Vec3<double>&, const Geometry<double>&, const Transform<double>&,
                                      PointDistanceResult<double>&);
template Status pointDistance<float>(const Vec3<float>&, const Shape<float>&, const Transform<float>&,
                                     PointDistanceResult<float>&) noexcept;
template Status pointDistance<double>(const Vec3<double>&, const Shape<double>&, const Transform<double>&,
                                      PointDistanceResult<double>&) noexcept;

}  // namespace gq
