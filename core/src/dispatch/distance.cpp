// Distance façade: validation, then one dispatch table indexed [type0][type1]. Closed forms are written for
// a <= b in GeometryType order; the mirrored cells go through `swapped`, which exchanges the inputs and flips the
// result (point0 <-> point1, normal -> -normal). Convex pairs without a closed form use GJK/EPA in either order;
// custom shapes are asked their own distance callback first.
// Triangle meshes and heightfields are thin surfaces (distance >= 0, see distance/surface_distance.h). Unsupported:
// plane-plane, plane-mesh/heightfield, mesh-heightfield, heightfield-heightfield, and non-convex custom shapes.
#include <array>

#include "common/pair_frame.h"
#include "common/validate.h"
#include "custom/callback_queries.h"
#include "distance/distance.h"
#include "distance/surface_distance.h"
#include "gq/custom.h"
#include "gq/query.h"

namespace gq {
namespace {

// The last argument is distanceWithin's bound (+inf for distance): the searched pairs (GJK, a mesh's traversal) may
// stop once the pair is proven farther, writing only a distance above it; closed forms ignore it.
template <class T> using DistanceFn = Status (*)(const Geometry<T>&, const Transform<T>&, const Geometry<T>&,
                                                 const Transform<T>&, GjkCache<T>*, DistanceResult<T>&, T);

// Adapts a closed-form kernel on concrete types to the table's signature.
template <class T, class G0, class G1,
          void (*Kernel)(const G0&, const Transform<T>&, const G1&, const Transform<T>&, DistanceResult<T>&)>
Status closedForm(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                  GjkCache<T>* cache, DistanceResult<T>& out, T) {
  Kernel(g0.template get<G0>(), p0, g1.template get<G1>(), p1, out);
  if (cache) cache->iterations = 0;
  return {};
}

// Plane against a support-mapped shape (the kernel takes the Geometry).
template <class T>
Status planeConvex(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                   GjkCache<T>* cache, DistanceResult<T>& out, T) {
  detail::distancePlaneConvex(g0.template get<PlaneGeometry<T>>(), p0, g1, p1, out);
  if (cache) cache->iterations = 0;
  return {};
}

template <class T>
Status gjk(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
           GjkCache<T>* cache, DistanceResult<T>& out, T farEnough) {
  return detail::distanceGjk(g0, p0, g1, p1, cache, out, T(0), farEnough);
}

// A cell with custom geometry: the shape's own distance callback when it answers (gq/custom.h), else GJK/EPA.
template <class T>
Status customFirst(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                   GjkCache<T>* cache, DistanceResult<T>& out, T farEnough) {
  bool answered = false;
  if (Status s = detail::customDistance(g0, p0, g1, p1, answered, out); !s.ok() || answered) {
    if (cache && answered) cache->iterations = 0;
    return s;
  }
  return detail::distanceGjk(g0, p0, g1, p1, cache, out, T(0), farEnough);
}

// Boxes: the closed form in box 0's frame (distance/box_box.cpp); GJK/EPA in its rare overlapping parallel-face case.
template <class T>
Status boxBox(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
              GjkCache<T>* cache, DistanceResult<T>& out, T) {
  const Vec3<T>& h0 = g0.template get<BoxGeometry<T>>().halfExtents;
  const Vec3<T>& h1 = g1.template get<BoxGeometry<T>>().halfExtents;
  DistanceResult<T> local;
  if (!detail::distanceBoxBoxLocal(h0, h1, Mat3<T>((p0.q.conjugate() * p1.q).toRotationMatrix()), p0.transformInv(p1.p),
                                   local))
    return detail::distanceGjk(g0, p0, g1, p1, cache, out);
  out.distance = local.distance;
  out.normal = p0.rotate(local.normal);
  out.point0 = p0.transform(local.point0);
  out.point1 = p0.transform(local.point1);
  if (cache) cache->iterations = 0;
  return {};
}

template <class T>
Status unsupported(const Geometry<T>& g0, const Transform<T>&, const Geometry<T>& g1, const Transform<T>&,
                   GjkCache<T>*, DistanceResult<T>&, T) {
  return Status::unsupported("distance is not available between this pair of geometry types")
      .withTypes(g0.type(), g1.type());
}

// The mirrored pair: runs Fn(geom1, geom0) and flips the answer. The cache direction lives in the caller's geom0
// frame and points from geom0 to geom1's side of the Minkowski difference, so it is re-expressed for the swap.
template <class T, DistanceFn<T> Fn>
Status swapped(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
               GjkCache<T>* cache, DistanceResult<T>& out, T farEnough) {
  // A direction d in geom0's frame (geom0 supports along d, geom1 along -d) is -d in geom1's frame.
  const auto mirror = [](const Transform<T>& from, const Transform<T>& to, const Vec3<T>& d) {
    return Vec3<T>(to.rotateInv(-from.rotate(d)));
  };
  GjkCache<T> inner;
  if (cache) {
    inner.direction = mirror(p0, p1, cache->direction);
    inner.simplexSize = std::min<std::uint32_t>(cache->simplexSize, 4);
    for (std::uint32_t k = 0; k < inner.simplexSize; ++k) inner.simplexDirections[k] = mirror(p0, p1, cache->simplexDirections[k]);
  }
  DistanceResult<T> flipped;
  const Status s = Fn(g1, p1, g0, p0, cache ? &inner : nullptr, flipped, farEnough);
  if (!s.ok()) return s;
  out.distance = flipped.distance;
  out.point0 = flipped.point1;
  out.point1 = flipped.point0;
  out.normal = -flipped.normal;
  if (cache) {
    cache->direction = mirror(p1, p0, inner.direction);
    cache->iterations = inner.iterations;
    cache->simplexSize = inner.simplexSize;
    for (std::uint32_t k = 0; k < inner.simplexSize; ++k) cache->simplexDirections[k] = mirror(p1, p0, inner.simplexDirections[k]);
  }
  return s;
}

template <class T> using Row = std::array<DistanceFn<T>, kGeometryTypeCount>;
template <class T> using S = SphereGeometry<T>;
template <class T> using P = PlaneGeometry<T>;
template <class T> using C = CapsuleGeometry<T>;
template <class T> using B = BoxGeometry<T>;

template <class T> constexpr DistanceFn<T> kSphereSphere = closedForm<T, S<T>, S<T>, detail::distanceSphereSphere<T>>;
template <class T> constexpr DistanceFn<T> kSpherePlane = closedForm<T, S<T>, P<T>, detail::distanceSpherePlane<T>>;
template <class T> constexpr DistanceFn<T> kSphereCapsule = closedForm<T, S<T>, C<T>, detail::distanceSphereCapsule<T>>;
template <class T> constexpr DistanceFn<T> kSphereBox = closedForm<T, S<T>, B<T>, detail::distanceSphereBox<T>>;
template <class T> constexpr DistanceFn<T> kPlaneCapsule = closedForm<T, P<T>, C<T>, detail::distancePlaneCapsule<T>>;
template <class T> constexpr DistanceFn<T> kPlaneBox = closedForm<T, P<T>, B<T>, detail::distancePlaneBox<T>>;
template <class T> constexpr DistanceFn<T> kCapsuleCapsule = closedForm<T, C<T>, C<T>, detail::distanceCapsuleCapsule<T>>;
template <class T> constexpr DistanceFn<T> kCapsuleBox = closedForm<T, C<T>, B<T>, detail::distanceCapsuleBox<T>>;

// Convex shapes vs triangle meshes and heightfields (distance/convex_surface.cpp), mesh vs mesh (BVH vs BVH).
template <class T> constexpr DistanceFn<T> kConvexSurface = detail::distanceConvexSurface<T>;
template <class T> constexpr DistanceFn<T> kSurfaceConvex = swapped<T, detail::distanceConvexSurface<T>>;
template <class T> constexpr DistanceFn<T> kMeshMesh = detail::distanceTriangleMeshTriangleMesh<T>;

// Rows geom0, columns geom1, in GeometryType order: Sphere, Plane, Capsule, Box, Convex, Mesh, HeightField, Custom.
template <class T> constexpr std::array<Row<T>, kGeometryTypeCount> kDistanceTable = {{
    {kSphereSphere<T>, kSpherePlane<T>, kSphereCapsule<T>, kSphereBox<T>, gjk<T>, kConvexSurface<T>, kConvexSurface<T>,
     customFirst<T>},
    {swapped<T, kSpherePlane<T>>, unsupported<T>, kPlaneCapsule<T>, kPlaneBox<T>, planeConvex<T>, unsupported<T>,
     unsupported<T>, planeConvex<T>},
    {swapped<T, kSphereCapsule<T>>, swapped<T, kPlaneCapsule<T>>, kCapsuleCapsule<T>, kCapsuleBox<T>, gjk<T>,
     kConvexSurface<T>, kConvexSurface<T>, customFirst<T>},
    {swapped<T, kSphereBox<T>>, swapped<T, kPlaneBox<T>>, swapped<T, kCapsuleBox<T>>, boxBox<T>, gjk<T>,
     kConvexSurface<T>, kConvexSurface<T>, customFirst<T>},
    {gjk<T>, swapped<T, planeConvex<T>>, gjk<T>, gjk<T>, gjk<T>, kConvexSurface<T>, kConvexSurface<T>, customFirst<T>},
    {kSurfaceConvex<T>, unsupported<T>, kSurfaceConvex<T>, kSurfaceConvex<T>, kSurfaceConvex<T>, kMeshMesh<T>,
     unsupported<T>, kSurfaceConvex<T>},
    {kSurfaceConvex<T>, unsupported<T>, kSurfaceConvex<T>, kSurfaceConvex<T>, kSurfaceConvex<T>, unsupported<T>,
     unsupported<T>, kSurfaceConvex<T>},
    {customFirst<T>, swapped<T, planeConvex<T>>, customFirst<T>, customFirst<T>, customFirst<T>, kConvexSurface<T>,
     kConvexSurface<T>, customFirst<T>},
}};
static_assert(kDistanceTable<double>.size() == kGeometryTypeCount && kDistanceTable<double>[0].size() == kGeometryTypeCount,
              "one row and one column per GeometryType");

template <class T> bool finiteResult(const DistanceResult<T>& r) {
  return std::isfinite(r.distance) && isFinite(r.point0) && isFinite(r.point1) && isFinite(r.normal);
}

// distance and distanceWithin (maxDistance +inf for the former; `beyond` null).
template <class T>
Status boundedDistance(DistanceResult<T>& result, const Geometry<T>& geom0, const Transform<T>& pose0,
                       const Geometry<T>& geom1, const Transform<T>& pose1, GjkCache<T>* cache, T maxDistance,
                       bool* beyond) {
  return detail::guarded([&]() -> Status {
    if (Status s = detail::checkPairInputs(geom0, pose0, geom1, pose1); !s.ok()) return s;
    if (std::isnan(maxDistance)) return Status::invalid("distanceWithin: maxDistance is NaN");
    if (detail::isNonConvexCustom(geom0) || detail::isNonConvexCustom(geom1))
      return Status::unsupported("distance needs a convex custom geometry (isConvex() is false)");
    // Normalise the poses' rotations (validation accepts |q| within 1e-3 of 1). Kernels run with both poses
    // translated by the smaller shape's position (common/pair_frame.h), rotations kept (the GjkCache lives in
    // geom0's frame): a float pair near x = 3e7 lost 0.28 of depth to world coordinates.
    const Vec3<T> origin = detail::pairOrigin(geom0, pose0, geom1, pose1);
    const Transform<T> q0(Vec3<T>(pose0.p - origin), pose0.q.normalized());
    const Transform<T> q1(Vec3<T>(pose1.p - origin), pose1.q.normalized());
    DistanceResult<T> r;
    const auto fn = kDistanceTable<T>[static_cast<std::size_t>(geom0.type())][static_cast<std::size_t>(geom1.type())];
    const Status s = fn(geom0, q0, geom1, q1, cache, r, maxDistance);
    if (!s.ok()) return s;
    if (beyond && r.distance > maxDistance) {  // proven beyond the bound (a search may have stopped): the distance alone
      result = DistanceResult<T>();
      result.distance = r.distance;
      *beyond = true;
      return s;
    }
    r.point0 += origin;
    r.point1 += origin;
    if (!finiteResult(r)) return Status::internal("distance produced a non-finite result");
    result = r;
    if (beyond) *beyond = false;
    return s;
  });
}

}  // namespace

template <class T>
Status distance(DistanceResult<T>& result, const Geometry<T>& geom0, const Transform<T>& pose0,
                const Geometry<T>& geom1, const Transform<T>& pose1, GjkCache<T>* cache) noexcept {
  return boundedDistance(result, geom0, pose0, geom1, pose1, cache, std::numeric_limits<T>::infinity(),
                         static_cast<bool*>(nullptr));
}

template <class T>
Status distanceWithin(DistanceResult<T>& result, bool& beyond, T maxDistance, const Geometry<T>& geom0,
                      const Transform<T>& pose0, const Geometry<T>& geom1, const Transform<T>& pose1,
                      GjkCache<T>* cache) noexcept {
  return boundedDistance(result, geom0, pose0, geom1, pose1, cache, maxDistance, &beyond);
}

template Status distance<float>(DistanceResult<float>&, const Geometry<float>&, const Transform<float>&,
                                const Geometry<float>&, const Transform<float>&, GjkCache<float>*);
template Status distance<double>(DistanceResult<double>&, const Geometry<double>&, const Transform<double>&,
                                 const Geometry<double>&, const Transform<double>&, GjkCache<double>*);
template Status distanceWithin<float>(DistanceResult<float>&, bool&, float, const Geometry<float>&,
                                      const Transform<float>&, const Geometry<float>&, const Transform<float>&,
                                      GjkCache<float>*);
template Status distanceWithin<double>(DistanceResult<double>&, bool&, double, const Geometry<double>&,
                                       const Transform<double>&, const Geometry<double>&, const Transform<double>&,
                                       GjkCache<double>*);

}  // namespace gq
