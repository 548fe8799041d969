// Penetration (MTD) façade: validation, then one dispatch table indexed [type0][type1].
//
// Sign convention (the one place it is written): when `penetrating`, translating geom0 by direction * depth
// separates the shapes; direction is unit and depth >= 0 (0 when touching, which counts as penetrating, so that
// overlap() and computePenetration() agree). The plane is the solid half-space x <= 0 of its frame.
// Kernels run in the frame of the smaller shape (common/pair_frame.h: shapes far from the origin, or far from a much
// larger shape, keep their precision); the direction is rotated back to world space by the cell. The sphere pairs,
// capsule-box and box-box run with both positions translated by the smaller shape's instead: the offset is still a
// subtraction of positions before anything else (what keeps that precision), their kernels rotate into the frame they
// need themselves, and their direction is a world one.
// The table's cells take the shapes (geometry and feature radius) and their world poses; the Geometry<T> and the
// prepared Shape<T> overloads differ only in what they validate before the one shared path (penetrationShapes).
#include <array>
#include <string>
#include <type_traits>

#include "common/pair_frame.h"
#include "common/validate.h"
#include "custom/callback_queries.h"
#include "gq/custom.h"
#include "gq/mesh_query.h"
#include "gq/query.h"
#include "penetration/penetration.h"
#include "penetration/sphere_box.h"
#include "penetration/sphere_capsule.h"
#include "prepared/shape_ref.h"

namespace gq {
namespace {

template <class T>
using PenetrationFn = Status (*)(const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&, PenetrationResult<T>&);
template <class T>
using PenetrationCell = Status (*)(const detail::ShapeRef<T>&, const Transform<T>&, const detail::ShapeRef<T>&,
                                   const Transform<T>&, PenetrationResult<T>&);
template <class T> using PenetrationTable = std::array<std::array<PenetrationCell<T>, kGeometryTypeCount>, kGeometryTypeCount>;

// A kernel that runs in the pair frame (common/pair_frame.h); the direction comes back in world space.
template <class T, PenetrationFn<T> Fn>
Status framed(const detail::ShapeRef<T>& a, const Transform<T>& p0, const detail::ShapeRef<T>& b, const Transform<T>& p1,
              PenetrationResult<T>& result) {
  const detail::PairFrame<T> frame = detail::pairFrame(a.radius, p0, b.radius, p1);
  const Status s = Fn(a.geom, frame.pose0, b.geom, frame.pose1, result);  // Ok, or a Warning with an answer
  if (!s.ok()) return s;
  if (result.penetrating) result.direction = frame.world.rotate(result.direction);
  return s;
}

// A sphere, capsule or box pair: both positions translated by the smaller shape's, rotations kept (normalised as the
// frame does).
template <class T, class G0, class G1,
          bool (*Kernel)(const G0&, const Transform<T>&, const G1&, const Transform<T>&, Vec3<T>&, T&)>
[[gnu::always_inline]] inline Status translated(const detail::ShapeRef<T>& a, const Transform<T>& p0,
                                                const detail::ShapeRef<T>& b, const Transform<T>& p1,
                                                PenetrationResult<T>& result) {
  const Vec3<T> origin = detail::pairOrigin(a.radius, p0, b.radius, p1);
  // A sphere's rotation moves none of its points: its kernel does not read it, so it is not normalised.
  constexpr bool sphere0 = std::is_same_v<G0, SphereGeometry<T>>, sphere1 = std::is_same_v<G1, SphereGeometry<T>>;
  result.penetrating =
      Kernel(a.template get<G0>(), Transform<T>(Vec3<T>(p0.p - origin), sphere0 ? p0.q : detail::unitRotation(p0.q)),
             b.template get<G1>(), Transform<T>(Vec3<T>(p1.p - origin), sphere1 ? p1.q : detail::unitRotation(p1.q)), result.direction,
             result.depth);
  return Status();
}

// A cell whose kernel is defined inline (penetration/sphere_capsule.h, sphere_box.h), flattened: one body with the kernel and its
// helpers (closestPointOnSegment would be a call), without the poses' copies. (Flattening every translated cell cost
// the cells with out-of-line kernels ~5 instructions a query.)
template <class T, PenetrationCell<T> Cell>
[[gnu::flatten]] Status flattened(const detail::ShapeRef<T>& a, const Transform<T>& p0, const detail::ShapeRef<T>& b,
                                  const Transform<T>& p1, PenetrationResult<T>& result) {
  return Cell(a, p0, b, p1, result);
}

template <class T, PenetrationCell<T> Cell>
Status swappedCell(const detail::ShapeRef<T>& a, const Transform<T>& p0, const detail::ShapeRef<T>& b,
                   const Transform<T>& p1, PenetrationResult<T>& result) {
  const Status s = Cell(b, p1, a, p0, result);
  if (!s.ok()) return s;
  result.direction = -result.direction;
  return s;
}

// Adapts a kernel on concrete geometry types to the table's signature.
template <class T, class G0, class G1,
          bool (*Kernel)(const G0&, const Transform<T>&, const G1&, const Transform<T>&, Vec3<T>&, T&)>
Status pairKernel(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                  PenetrationResult<T>& result) {
  result.penetrating = Kernel(g0.template get<G0>(), p0, g1.template get<G1>(), p1, result.direction, result.depth);
  return Status();
}

// The one generic wrapper for swapped pairs: moving geom1 by +v separates as moving geom0 by -v does.
template <class T, PenetrationFn<T> Fn>
Status swapped(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
               PenetrationResult<T>& result) {
  const Status s = Fn(g1, p1, g0, p0, result);
  if (!s.ok()) return s;
  result.direction = -result.direction;
  return s;
}

template <class T> const CustomGeometryCallbacks<T>& callbacksOf(const Geometry<T>& g) {
  return *g.template get<CustomGeometry<T>>().callbacks;
}

// Custom geometry on either side: GJK on the support mappings (convexity is checked by the façade).
template <class T>
Status customKernel(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                    PenetrationResult<T>& result) {
  return detail::penetrationCustomAny(g0, p0, g1, p1, result.penetrating, result.direction, result.depth);
}

// A cell with custom geometry: the shape's own penetration callback when it answers, else `Fallback` (gq/custom.h).
template <class T, PenetrationFn<T> Fallback>
Status customFirst(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                   PenetrationResult<T>& result) {
  bool answered = false;
  if (Status s = detail::customPenetration(g0, p0, g1, p1, answered, result.penetrating, result.direction, result.depth);
      !s.ok() || answered)
    return s;
  return Fallback(g0, p0, g1, p1, result);
}

// The rejection of a pair in which a custom shape is not convex (only raycast and bounds answer those).
template <class T> Status nonConvexCustomStatus(const Geometry<T>& g0, const Geometry<T>& g1) {
  const Geometry<T>& g = detail::isNonConvexCustom(g0) ? g0 : g1;
  return Status::aboutCustom(StatusCode::Unsupported, CustomIssue::NonConvexPenetration, callbacksOf(g).name());
}

// A convex shape against a triangle mesh or heightfield: the spec's iterative algorithm with its usual 4 iterations.
inline constexpr std::uint32_t kSurfacePenetrationIterations = 4;
template <class T>
Status surfaceKernel(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                     PenetrationResult<T>& result) {
  if (const auto* mesh = g1.template getIf<TriangleMeshGeometry<T>>())
    return computeTriangleMeshPenetration(result, g0, p0, *mesh, p1, kSurfacePenetrationIterations);
  return computeHeightFieldPenetration(result, g0, p0, g1.template get<HeightFieldGeometry<T>>(), p1,
                                       kSurfacePenetrationIterations);
}

template <class T>
Status notDefinedBySpec(const Geometry<T>& g0, const Transform<T>&, const Geometry<T>& g1, const Transform<T>&, PenetrationResult<T>&) {
  return Status::unsupported("penetration of this pair of geometry types is not defined by the spec (PhysX does not "
                             "support it)")
      .withTypes(g0.type(), g1.type());
}

template <class T, GeometryType A, GeometryType B, PenetrationFn<T> Fn> constexpr void setPair(PenetrationTable<T>& table) {
  static_assert(A <= B, "pairs are registered once, in GeometryType order; the swapped cell is derived");
  table[std::size_t(A)][std::size_t(B)] = framed<T, Fn>;
  if constexpr (A != B) table[std::size_t(B)][std::size_t(A)] = framed<T, swapped<T, Fn>>;
}

// A cell that picks its own frame (the sphere, capsule and box pairs).
template <class T, GeometryType A, GeometryType B, PenetrationCell<T> Cell>
constexpr void setCell(PenetrationTable<T>& table) {
  static_assert(A <= B, "pairs are registered once, in GeometryType order; the swapped cell is derived");
  table[std::size_t(A)][std::size_t(B)] = Cell;
  if constexpr (A != B) table[std::size_t(B)][std::size_t(A)] = swappedCell<T, Cell>;
}

template <class T> constexpr PenetrationTable<T> makePenetrationTable() {
  using GT = GeometryType;
  PenetrationTable<T> t{};
  setCell<T, GT::Sphere, GT::Sphere, translated<T, SphereGeometry<T>, SphereGeometry<T>, detail::penetrationSphereSphere<T>>>(t);
  setPair<T, GT::Sphere, GT::Plane, pairKernel<T, SphereGeometry<T>, PlaneGeometry<T>, detail::penetrationSpherePlane<T>>>(t);
  setCell<T, GT::Sphere, GT::Capsule, flattened<T, translated<T, SphereGeometry<T>, CapsuleGeometry<T>, detail::sphereCapsulePenetration<T>>>>(t);
  setCell<T, GT::Sphere, GT::Box, flattened<T, translated<T, SphereGeometry<T>, BoxGeometry<T>, detail::sphereBoxPenetration<T>>>>(t);
  setPair<T, GT::Sphere, GT::ConvexMesh, pairKernel<T, SphereGeometry<T>, ConvexMeshGeometry<T>, detail::penetrationSphereConvex<T>>>(t);
  setPair<T, GT::Sphere, GT::Custom, customFirst<T, customKernel<T>>>(t);
  setPair<T, GT::Plane, GT::Plane, notDefinedBySpec<T>>(t);
  setPair<T, GT::Plane, GT::Capsule, pairKernel<T, PlaneGeometry<T>, CapsuleGeometry<T>, detail::penetrationPlaneCapsule<T>>>(t);
  setPair<T, GT::Plane, GT::Box, pairKernel<T, PlaneGeometry<T>, BoxGeometry<T>, detail::penetrationPlaneBox<T>>>(t);
  setPair<T, GT::Plane, GT::ConvexMesh, pairKernel<T, PlaneGeometry<T>, ConvexMeshGeometry<T>, detail::penetrationPlaneConvex<T>>>(t);
  setPair<T, GT::Plane, GT::TriangleMesh, notDefinedBySpec<T>>(t);
  setPair<T, GT::Plane, GT::HeightField, notDefinedBySpec<T>>(t);
  setPair<T, GT::Plane, GT::Custom, customFirst<T, pairKernel<T, PlaneGeometry<T>, CustomGeometry<T>, detail::penetrationPlaneCustom<T>>>>(t);
  // Capsules in the pair frame: there the smaller one's axis is exactly +X, so parallel axes give an exact zero
  // offset and the push falls back to a direction normal to both (in world space rounding chose a random one).
  setPair<T, GT::Capsule, GT::Capsule, pairKernel<T, CapsuleGeometry<T>, CapsuleGeometry<T>, detail::penetrationCapsuleCapsule<T>>>(t);
  setCell<T, GT::Capsule, GT::Box, translated<T, CapsuleGeometry<T>, BoxGeometry<T>, detail::penetrationCapsuleBox<T>>>(t);
  setPair<T, GT::Capsule, GT::ConvexMesh, pairKernel<T, CapsuleGeometry<T>, ConvexMeshGeometry<T>, detail::penetrationCapsuleConvex<T>>>(t);
  setPair<T, GT::Capsule, GT::Custom, customFirst<T, customKernel<T>>>(t);
  setCell<T, GT::Box, GT::Box, translated<T, BoxGeometry<T>, BoxGeometry<T>, detail::penetrationBoxBox<T>>>(t);
  setPair<T, GT::Box, GT::ConvexMesh, pairKernel<T, BoxGeometry<T>, ConvexMeshGeometry<T>, detail::penetrationBoxConvex<T>>>(t);
  setPair<T, GT::Box, GT::Custom, customFirst<T, customKernel<T>>>(t);
  setPair<T, GT::ConvexMesh, GT::ConvexMesh, pairKernel<T, ConvexMeshGeometry<T>, ConvexMeshGeometry<T>, detail::penetrationConvexConvex<T>>>(t);
  setPair<T, GT::ConvexMesh, GT::Custom, customFirst<T, customKernel<T>>>(t);
  setPair<T, GT::Custom, GT::Custom, customFirst<T, customKernel<T>>>(t);
  setPair<T, GT::Sphere, GT::TriangleMesh, surfaceKernel<T>>(t);
  setPair<T, GT::Capsule, GT::TriangleMesh, surfaceKernel<T>>(t);
  setPair<T, GT::Box, GT::TriangleMesh, surfaceKernel<T>>(t);
  setPair<T, GT::ConvexMesh, GT::TriangleMesh, surfaceKernel<T>>(t);
  setPair<T, GT::TriangleMesh, GT::Custom, customFirst<T, swapped<T, surfaceKernel<T>>>>(t);
  setPair<T, GT::Sphere, GT::HeightField, surfaceKernel<T>>(t);
  setPair<T, GT::Capsule, GT::HeightField, surfaceKernel<T>>(t);
  setPair<T, GT::Box, GT::HeightField, surfaceKernel<T>>(t);
  setPair<T, GT::ConvexMesh, GT::HeightField, surfaceKernel<T>>(t);
  setPair<T, GT::HeightField, GT::Custom, customFirst<T, swapped<T, surfaceKernel<T>>>>(t);
  setPair<T, GT::TriangleMesh, GT::TriangleMesh, notDefinedBySpec<T>>(t);
  setPair<T, GT::TriangleMesh, GT::HeightField, notDefinedBySpec<T>>(t);
  setPair<T, GT::HeightField, GT::HeightField, notDefinedBySpec<T>>(t);
  return t;
}

template <class T> constexpr PenetrationTable<T> kPenetrationTable = makePenetrationTable<T>();
static_assert(std::tuple_size_v<PenetrationTable<float>> == kGeometryTypeCount &&
                  std::tuple_size_v<PenetrationTable<float>::value_type> == kGeometryTypeCount,
              "one row and one column per GeometryType");
template <class T> constexpr bool everyCellFilled(const PenetrationTable<T>& t) {
  for (const auto& row : t)
    for (const auto cell : row)
      if (cell == nullptr) return false;
  return true;
}
static_assert(everyCellFilled(kPenetrationTable<float>) && everyCellFilled(kPenetrationTable<double>),
              "every pair is registered (answered, or unsupported with a reason)");

}  // namespace

namespace detail {

// Two spheres, the cheapest pair: their cell called directly, before the table and without the exception guard
// (nothing in it allocates or throws). The answer is finite by construction: validated centres and radii are finite
// and within kMaxMagnitude, and the kernel takes the range-safe unit vector where |c0 - c1|^2 would over- or underflow.
template <class T> bool bothSpheres(const ShapeRef<T>& a, const ShapeRef<T>& b) {
  return a.type() == GeometryType::Sphere && b.type() == GeometryType::Sphere;
}
template <class T>
[[gnu::always_inline]] inline void penetrationSpheres(PenetrationResult<T>& result, const ShapeRef<T>& a,
                                                      const Transform<T>& pose0, const ShapeRef<T>& b,
                                                      const Transform<T>& pose1) noexcept {
  PenetrationResult<T> local;
  (void)translated<T, SphereGeometry<T>, SphereGeometry<T>, penetrationSphereSphere<T>>(a, pose0, b, pose1, local);
  result = local.penetrating ? local : PenetrationResult<T>();
}

// The table, once every input is valid: the one code path of both overloads. Inline in both (a call more was ~15
// instructions a query).
template <class T>
[[gnu::always_inline]] inline Status penetrationCell(PenetrationResult<T>& result, const ShapeRef<T>& a,
                                                     const Transform<T>& pose0, const ShapeRef<T>& b,
                                                     const Transform<T>& pose1) {
  PenetrationResult<T> local;
  const PenetrationCell<T> fn = kPenetrationTable<T>[std::size_t(a.type())][std::size_t(b.type())];
  const Status s = fn(a, pose0, b, pose1, local);  // Ok, or a Warning with an answer
  if (!s.ok()) [[unlikely]]
    return s;
  if (!local.penetrating) {
    result = PenetrationResult<T>();
    return s;
  }
  if (!isFinite(local.direction) || !std::isfinite(local.depth)) [[unlikely]]
    return Status::internal("computePenetration produced a non-finite result");
  result = local;
  return s;
}

// Valid shapes: the poses, then the non-convex custom shapes, then the table.
template <class T>
Status penetrationShapes(PenetrationResult<T>& result, const ShapeRef<T>& a, const Transform<T>& pose0,
                         const ShapeRef<T>& b, const Transform<T>& pose1, bool nonConvexCustom) noexcept {
  return guarded([&]() -> Status {
    if (!pairPosesAreValid(pose0, pose1)) return pairPosesStatus(pose0, pose1);
    if (nonConvexCustom) return nonConvexCustomStatus(a.geom, b.geom);
    if (bothSpheres(a, b)) {
      penetrationSpheres(result, a, pose0, b, pose1);
      return Status();
    }
    return penetrationCell(result, a, pose0, b, pose1);
  });
}

// A prepared pair that is not ready for the table: the rejection, in the order of the Geometry<T> overload.
template <class T>
[[gnu::noinline, gnu::cold]] Status penetrationPreparedChecked(PenetrationResult<T>& result, const Shape<T>& shape0,
                                                               const Transform<T>& pose0, const Shape<T>& shape1,
                                                               const Transform<T>& pose1) noexcept {
  using A = ShapeAccess<T>;
  if (const Problem p = A::pairProblem(shape0)) return guarded([&] { return p.status(); });
  if (const Problem p = A::pairProblem(shape1)) return guarded([&] { return p.status(); });
  return penetrationShapes(result, A::ref(shape0), pose0, A::ref(shape1), pose1,
                           A::nonConvexCustom(shape0) || A::nonConvexCustom(shape1));
}

}  // namespace detail

template <class T>
Status computePenetration(PenetrationResult<T>& result, const Geometry<T>& geom0, const Transform<T>& pose0,
                          const Geometry<T>& geom1, const Transform<T>& pose1) noexcept {
  return detail::guarded([&]() -> Status {
    if (detail::pairGeometryProblem(geom0) || detail::pairGeometryProblem(geom1)) [[unlikely]]
      return detail::checkPairInputs(geom0, pose0, geom1, pose1);
    return detail::penetrationShapes(result, detail::shapeRef(geom0), pose0, detail::shapeRef(geom1), pose1,
                                     detail::isNonConvexCustom(geom0) || detail::isNonConvexCustom(geom1));
  });
}

template <class T>
Status computePenetration(PenetrationResult<T>& result, const Shape<T>& shape0, const Transform<T>& pose0,
                          const Shape<T>& shape1, const Transform<T>& pose1) noexcept {
  using A = detail::ShapeAccess<T>;
  if (A::pairReady(shape0, shape1) && detail::pairPosesAreValid(pose0, pose1)) [[likely]] {
    if (detail::bothSpheres(A::ref(shape0), A::ref(shape1))) {
      detail::penetrationSpheres(result, A::ref(shape0), pose0, A::ref(shape1), pose1);
      return Status();
    }
    return detail::guarded([&] { return detail::penetrationCell(result, A::ref(shape0), pose0, A::ref(shape1), pose1); });
  }
  return detail::penetrationPreparedChecked(result, shape0, pose0, shape1, pose1);
}

template Status computePenetration<float>(PenetrationResult<float>&, const Geometry<float>&, const Transform<float>&,
                                          const Geometry<float>&, const Transform<float>&);
template Status computePenetration<double>(PenetrationResult<double>&, const Geometry<double>&,
                                           const Transform<double>&, const Geometry<double>&, const Transform<double>&);
template Status computePenetration<float>(PenetrationResult<float>&, const Shape<float>&, const Transform<float>&,
                                          const Shape<float>&, const Transform<float>&) noexcept;
template Status computePenetration<double>(PenetrationResult<double>&, const Shape<double>&, const Transform<double>&,
                                           const Shape<double>&, const Transform<double>&) noexcept;

}  // namespace gq
