// Distance façade: validation, then one dispatch table indexed [type0][type1]. Closed forms are written for
// a <= b in GeometryType order; the mirrored cells go through `swapped`, which exchanges the inputs and flips the
// result (point0 <-> point1, normal -> -normal). Convex pairs without a closed form use GJK/EPA in either order;
// custom shapes are asked their own distance callback first.
// Every cell runs with both poses translated by the smaller shape's position (common/pair_frame.h), rotations kept
// (the GjkCache lives in geom0's frame): a float pair near x = 3e7 lost 0.28 of depth to world coordinates. The
// Geometry<T> and the prepared Shape<T> overloads differ only in what they validate before the one shared path
// (distanceShapes).
// Triangle meshes and heightfields are thin surfaces (distance >= 0, see distance/surface_distance.h). Unsupported:
// plane-plane, mesh-heightfield, heightfield-heightfield, and non-convex custom shapes.
#include <array>

#include "common/pair_frame.h"
#include "common/validate.h"
#include "custom/callback_queries.h"
#include "distance/distance.h"
#include "distance/plane_surface.h"
#include "distance/surface_distance.h"
#include "gq/custom.h"
#include "gq/query.h"
#include "prepared/shape_ref.h"

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
  const auto flip = [&out](const DistanceResult<T>& flipped) {
    out.distance = flipped.distance;
    out.point0 = flipped.point1;
    out.point1 = flipped.point0;
    out.normal = -flipped.normal;
  };
  DistanceResult<T> flipped;
  if (!cache) {  // no cache to mirror (nor one to zero on every call)
    const Status s = Fn(g1, p1, g0, p0, nullptr, flipped, farEnough);
    if (s.ok()) flip(flipped);
    return s;
  }
  GjkCache<T> inner;
  inner.direction = mirror(p0, p1, cache->direction);
  inner.simplexSize = std::min<std::uint32_t>(cache->simplexSize, 4);
  for (std::uint32_t k = 0; k < inner.simplexSize; ++k) inner.simplexDirections[k] = mirror(p0, p1, cache->simplexDirections[k]);
  const Status s = Fn(g1, p1, g0, p0, &inner, flipped, farEnough);
  if (!s.ok()) return s;
  flip(flipped);
  cache->direction = mirror(p1, p0, inner.direction);
  cache->iterations = inner.iterations;
  cache->simplexSize = inner.simplexSize;
  for (std::uint32_t k = 0; k < inner.simplexSize; ++k) cache->simplexDirections[k] = mirror(p1, p0, inner.simplexDirections[k]);
  return s;
}

// A table cell: the shapes with their world poses (validated).
template <class T>
using DistanceCell = Status (*)(const detail::ShapeRef<T>&, const Transform<T>&, const detail::ShapeRef<T>&,
                                const Transform<T>&, GjkCache<T>*, DistanceResult<T>&, T);

// Runs Fn with both poses translated by the smaller shape's position and their rotations normalised (validation
// accepts |q| within 1e-3 of 1; one unit to rounding is used as given), then moves the witnesses back.
template <class T, DistanceFn<T> Fn>
Status translated(const detail::ShapeRef<T>& a, const Transform<T>& p0, const detail::ShapeRef<T>& b,
                  const Transform<T>& p1, GjkCache<T>* cache, DistanceResult<T>& out, T farEnough) {
  const Vec3<T> origin = detail::pairOrigin(a.radius, p0, b.radius, p1);
  const Transform<T> q0(Vec3<T>(p0.p - origin), detail::unitRotation(p0.q));
  const Transform<T> q1(Vec3<T>(p1.p - origin), detail::unitRotation(p1.q));
  const Status s = Fn(a.geom, q0, b.geom, q1, cache, out, farEnough);
  out.point0 += origin;
  out.point1 += origin;
  return s;
}

// Two spheres: the balls' closed form in the translated frame, inline (rotations are not read).
template <class T>
[[gnu::always_inline]] inline void ballsPair(const detail::ShapeRef<T>& a, const Transform<T>& p0,
                                             const detail::ShapeRef<T>& b, const Transform<T>& p1,
                                             DistanceResult<T>& out) {
  const Vec3<T> origin = detail::pairOrigin(a.radius, p0, b.radius, p1);
  detail::ballsDistance(Vec3<T>(p0.p - origin), a.radius, Vec3<T>(p1.p - origin), b.radius, out);
  out.point0 += origin;
  out.point1 += origin;
}

template <class T>
Status sphereSphere(const detail::ShapeRef<T>& a, const Transform<T>& p0, const detail::ShapeRef<T>& b,
                    const Transform<T>& p1, GjkCache<T>* cache, DistanceResult<T>& out, T) {
  ballsPair(a, p0, b, p1, out);
  if (cache) cache->iterations = 0;
  return {};
}

template <class T> using Row = std::array<DistanceCell<T>, kGeometryTypeCount>;
template <class T> using FnRow = std::array<DistanceFn<T>, kGeometryTypeCount>;
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
// Plane vs the thin surfaces: the lowest vertex's signed height (distance/plane_surface.h).
template <class T> constexpr DistanceFn<T> kPlaneMesh = detail::distancePlaneTriangleMesh<T>;
template <class T> constexpr DistanceFn<T> kPlaneHeightField = detail::distancePlaneHeightField<T>;

// Rows geom0, columns geom1, in GeometryType order: Sphere, Plane, Capsule, Box, Convex, Mesh, HeightField, Custom.
template <class T> constexpr std::array<FnRow<T>, kGeometryTypeCount> kDistanceKernels = {{
    {kSphereSphere<T>, kSpherePlane<T>, kSphereCapsule<T>, kSphereBox<T>, gjk<T>, kConvexSurface<T>, kConvexSurface<T>,
     customFirst<T>},
    {swapped<T, kSpherePlane<T>>, unsupported<T>, kPlaneCapsule<T>, kPlaneBox<T>, planeConvex<T>, kPlaneMesh<T>,
     kPlaneHeightField<T>, planeConvex<T>},
    {swapped<T, kSphereCapsule<T>>, swapped<T, kPlaneCapsule<T>>, kCapsuleCapsule<T>, kCapsuleBox<T>, gjk<T>,
     kConvexSurface<T>, kConvexSurface<T>, customFirst<T>},
    {swapped<T, kSphereBox<T>>, swapped<T, kPlaneBox<T>>, swapped<T, kCapsuleBox<T>>, boxBox<T>, gjk<T>,
     kConvexSurface<T>, kConvexSurface<T>, customFirst<T>},
    {gjk<T>, swapped<T, planeConvex<T>>, gjk<T>, gjk<T>, gjk<T>, kConvexSurface<T>, kConvexSurface<T>, customFirst<T>},
    {kSurfaceConvex<T>, swapped<T, kPlaneMesh<T>>, kSurfaceConvex<T>, kSurfaceConvex<T>, kSurfaceConvex<T>,
     kMeshMesh<T>, unsupported<T>, kSurfaceConvex<T>},
    {kSurfaceConvex<T>, swapped<T, kPlaneHeightField<T>>, kSurfaceConvex<T>, kSurfaceConvex<T>, kSurfaceConvex<T>, unsupported<T>,
     unsupported<T>, kSurfaceConvex<T>},
    {customFirst<T>, swapped<T, planeConvex<T>>, customFirst<T>, customFirst<T>, customFirst<T>, kConvexSurface<T>,
     kConvexSurface<T>, customFirst<T>},
}};
static_assert(kDistanceKernels<double>.size() == kGeometryTypeCount &&
                  kDistanceKernels<double>[0].size() == kGeometryTypeCount,
              "one row and one column per GeometryType");

// The table the façade reads: every kernel above in the translated frame.
template <class T, std::size_t I, std::size_t... J> constexpr Row<T> cellRow(std::index_sequence<J...>) {
  return {translated<T, kDistanceKernels<T>[I][J]>...};
}
template <class T, std::size_t... I>
constexpr std::array<Row<T>, kGeometryTypeCount> cellTable(std::index_sequence<I...>) {
  return {cellRow<T, I>(std::make_index_sequence<kGeometryTypeCount>())...};
}
template <class T> constexpr std::array<Row<T>, kGeometryTypeCount> withSphereSphere(std::array<Row<T>, kGeometryTypeCount> t) {
  t[0][0] = sphereSphere<T>;
  return t;
}
template <class T>
constexpr std::array<Row<T>, kGeometryTypeCount> kDistanceTable =
    withSphereSphere<T>(cellTable<T>(std::make_index_sequence<kGeometryTypeCount>()));


// x * 0 is 0 for a finite x and NaN for an infinite or NaN one: the sum of the ten products is 0 exactly when every
// value is finite (one branch instead of ten).
template <class T> bool finiteResult(const DistanceResult<T>& r) {
  const auto zero = [](const Vec3<T>& v) { return v.x() * T(0) + v.y() * T(0) + v.z() * T(0); };
  return r.distance * T(0) + zero(r.point0) + zero(r.point1) + zero(r.normal) == T(0);
}

}  // namespace

namespace detail {

// Writes a kernel's answer `r` to `result`: the distance alone when it is proven beyond the bound (a search may have
// stopped there), else the whole answer. `checkFinite`: false (result untouched) when the answer is not finite.
template <class T>
[[gnu::always_inline]] inline bool publishDistance(DistanceResult<T>& result, const DistanceResult<T>& r, T maxDistance,
                                                   bool* beyond, bool checkFinite) {
  if (beyond && r.distance > maxDistance) {
    result = DistanceResult<T>();
    result.distance = r.distance;
    *beyond = true;
    return true;
  }
  if (checkFinite && !finiteResult(r)) [[unlikely]]
    return false;
  result = r;
  if (beyond) *beyond = false;
  return true;
}

// Two spheres, the cheapest pair, answered before the table: no call through it, the answer in registers, and nothing
// that allocates or throws (so no exception guard). The answer is finite by construction: validated positions and
// radii are finite and within kMaxMagnitude, and ballsDistance takes the range-safe norm where |c1 - c0|^2 would
// overflow. The table's sphere-sphere cell computes the same (ballsPair).
template <class T> bool bothSpheres(const ShapeRef<T>& a, const ShapeRef<T>& b) {
  return a.type() == GeometryType::Sphere && b.type() == GeometryType::Sphere;
}
template <class T>
[[gnu::always_inline]] inline void distanceSpheres(DistanceResult<T>& result, const ShapeRef<T>& a,
                                                   const Transform<T>& pose0, const ShapeRef<T>& b,
                                                   const Transform<T>& pose1, GjkCache<T>* cache, T maxDistance,
                                                   bool* beyond) noexcept {
  DistanceResult<T> balls;
  ballsPair(a, pose0, b, pose1, balls);
  if (cache) cache->iterations = 0;
  publishDistance(result, balls, maxDistance, beyond, false);
}

// The table, once every input is valid: the one code path of both overloads (distance and distanceWithin:
// maxDistance +inf for the former, `beyond` null). Out of line: inlined into the prepared entry it cost that entry
// ~17 instructions a query more in spills than the call does.
template <class T>
Status distanceCell(DistanceResult<T>& result, const ShapeRef<T>& a, const Transform<T>& pose0, const ShapeRef<T>& b,
                    const Transform<T>& pose1, GjkCache<T>* cache, T maxDistance, bool* beyond) {
  DistanceResult<T> r;
  const auto fn = kDistanceTable<T>[static_cast<std::size_t>(a.type())][static_cast<std::size_t>(b.type())];
  Status s = fn(a, pose0, b, pose1, cache, r, maxDistance);
  if (!s.ok()) [[unlikely]]
    return s;
  if (!publishDistance(result, r, maxDistance, beyond, true)) [[unlikely]]
    return Status::internal("distance produced a non-finite result");
  if (s.code == StatusCode::Ok) [[likely]]
    return Status();  // built in place: no move of the kernel's Status
  return s;
}

// Valid shapes: the poses, the bound, then the non-convex custom shapes, then the table.
template <class T>
Status distanceShapes(DistanceResult<T>& result, const ShapeRef<T>& a, const Transform<T>& pose0, const ShapeRef<T>& b,
                      const Transform<T>& pose1, bool nonConvexCustom, GjkCache<T>* cache, T maxDistance,
                      bool* beyond) noexcept {
  return guarded([&]() -> Status {
    if (!pairPosesAreValid(pose0, pose1)) return pairPosesStatus(pose0, pose1);
    if (std::isnan(maxDistance)) return Status::invalid("distanceWithin: maxDistance is NaN");
    if (nonConvexCustom) return Status::unsupported("distance needs a convex custom geometry (isConvex() is false)");
    if (bothSpheres(a, b)) {
      distanceSpheres(result, a, pose0, b, pose1, cache, maxDistance, beyond);
      return Status();
    }
    return distanceCell(result, a, pose0, b, pose1, cache, maxDistance, beyond);
  });
}

template <class T>
Status distanceGeometries(DistanceResult<T>& result, const Geometry<T>& geom0, const Transform<T>& pose0,
                          const Geometry<T>& geom1, const Transform<T>& pose1, GjkCache<T>* cache, T maxDistance,
                          bool* beyond) noexcept {
  return guarded([&]() -> Status {
    if (pairGeometryProblem(geom0) || pairGeometryProblem(geom1)) [[unlikely]]
      return checkPairInputs(geom0, pose0, geom1, pose1);
    return distanceShapes(result, shapeRef(geom0), pose0, shapeRef(geom1), pose1,
                          isNonConvexCustom(geom0) || isNonConvexCustom(geom1), cache, maxDistance, beyond);
  });
}

// A prepared pair that is not ready for the table: the rejection, in the order of the Geometry<T> overload.
template <class T>
[[gnu::noinline, gnu::cold]] Status distancePreparedChecked(DistanceResult<T>& result, const Shape<T>& shape0,
                                                            const Transform<T>& pose0, const Shape<T>& shape1,
                                                            const Transform<T>& pose1, GjkCache<T>* cache,
                                                            T maxDistance, bool* beyond) noexcept {
  using A = ShapeAccess<T>;
  if (const Problem p = A::pairProblem(shape0)) return guarded([&] { return p.status(); });
  if (const Problem p = A::pairProblem(shape1)) return guarded([&] { return p.status(); });
  return distanceShapes(result, A::ref(shape0), pose0, A::ref(shape1), pose1,
                        A::nonConvexCustom(shape0) || A::nonConvexCustom(shape1), cache, maxDistance, beyond);
}

template <class T>
[[gnu::always_inline]] inline Status distancePrepared(DistanceResult<T>& result, const Shape<T>& shape0,
                                                      const Transform<T>& pose0, const Shape<T>& shape1,
                                                      const Transform<T>& pose1, GjkCache<T>* cache, T maxDistance,
                                                      bool* beyond) noexcept {
  using A = ShapeAccess<T>;
  if (A::pairReady(shape0, shape1) && pairPosesAreValid(pose0, pose1) && !std::isnan(maxDistance)) [[likely]] {
    if (bothSpheres(A::ref(shape0), A::ref(shape1))) {
      distanceSpheres(result, A::ref(shape0), pose0, A::ref(shape1), pose1, cache, maxDistance, beyond);
      return Status();
    }
    return guarded([&] {
      return distanceCell(result, A::ref(shape0), pose0, A::ref(shape1), pose1, cache, maxDistance, beyond);
    });
  }
  return distancePreparedChecked(result, shape0, pose0, shape1, pose1, cache, maxDistance, beyond);
}

}  // namespace detail

template <class T>
Status distance(DistanceResult<T>& result, const Geometry<T>& geom0, const Transform<T>& pose0,
                const Geometry<T>& geom1, const Transform<T>& pose1, GjkCache<T>* cache) noexcept {
  return detail::distanceGeometries(result, geom0, pose0, geom1, pose1, cache, std::numeric_limits<T>::infinity(),
                                    static_cast<bool*>(nullptr));
}

template <class T>
Status distanceWithin(DistanceResult<T>& result, bool& beyond, T maxDistance, const Geometry<T>& geom0,
                      const Transform<T>& pose0, const Geometry<T>& geom1, const Transform<T>& pose1,
                      GjkCache<T>* cache) noexcept {
  return detail::distanceGeometries(result, geom0, pose0, geom1, pose1, cache, maxDistance, &beyond);
}

template <class T>
Status distance(DistanceResult<T>& result, const Shape<T>& shape0, const Transform<T>& pose0, const Shape<T>& shape1,
                const Transform<T>& pose1, GjkCache<T>* cache) noexcept {
  return detail::distancePrepared(result, shape0, pose0, shape1, pose1, cache, std::numeric_limits<T>::infinity(),
                                  static_cast<bool*>(nullptr));
}

template <class T>
Status distanceWithin(DistanceResult<T>& result, bool& beyond, T maxDistance, const Shape<T>& shape0,
                      const Transform<T>& pose0, const Shape<T>& shape1, const Transform<T>& pose1,
                      GjkCache<T>* cache) noexcept {
  return detail::distancePrepared(result, shape0, pose0, shape1, pose1, cache, maxDistance, &beyond);
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
template Status distance<float>(DistanceResult<float>&, const Shape<float>&, const Transform<float>&,
                                const Shape<float>&, const Transform<float>&, GjkCache<float>*) noexcept;
template Status distance<double>(DistanceResult<double>&, const Shape<double>&, const Transform<double>&,
                                 const Shape<double>&, const Transform<double>&, GjkCache<double>*) noexcept;
template Status distanceWithin<float>(DistanceResult<float>&, bool&, float, const Shape<float>&,
                                      const Transform<float>&, const Shape<float>&, const Transform<float>&,
                                      GjkCache<float>*) noexcept;
template Status distanceWithin<double>(DistanceResult<double>&, bool&, double, const Shape<double>&,
                                       const Transform<double>&, const Shape<double>&, const Transform<double>&,
                                       GjkCache<double>*) noexcept;

}  // namespace gq
