// Overlap façade: validation, then one dispatch table indexed [type0][type1].
//
// Semantics: touching counts as overlapping (every kernel compares with <=); the plane is the solid half-space
// x <= 0 of its frame. Kernels run in the frame of the smaller shape (common/pair_frame.h), so that shapes far from
// the origin, or far from a much larger shape, keep their precision. The sphere, capsule and box pairs run with both
// positions translated by the smaller shape's instead: the offset is still a subtraction of positions before anything
// else (what keeps that precision), and their kernels rotate into the frame they need themselves (the frame's
// quaternion products would be done twice; a sphere's rotation moves none of its points).
// The table's cells take the shapes (geometry and feature radius) and their world poses; the Geometry<T> and the
// prepared Shape<T> overloads differ only in what they validate before the one shared path (overlapShapes).
#include <array>
#include <string>
#include <type_traits>

#include "common/pair_frame.h"
#include "common/validate.h"
#include "custom/callback_queries.h"
#include "distance/plane_surface.h"
#include "gq/custom.h"
#include "gq/query.h"
#include "overlap/overlap.h"
#include "overlap/sphere_capsule.h"
#include "overlap/surface_overlap.h"
#include "prepared/shape_ref.h"

namespace gq {
namespace {

template <class T>
using OverlapFn = Status (*)(const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&, bool&);
// A table cell: the shapes with their world poses (validated, rotations within validation's tolerance of unit).
template <class T>
using OverlapCell = Status (*)(const detail::ShapeRef<T>&, const Transform<T>&, const detail::ShapeRef<T>&,
                               const Transform<T>&, bool&);
template <class T> using OverlapTable = std::array<std::array<OverlapCell<T>, kGeometryTypeCount>, kGeometryTypeCount>;

// A kernel that runs in the pair frame (common/pair_frame.h).
template <class T, OverlapFn<T> Fn>
Status framed(const detail::ShapeRef<T>& a, const Transform<T>& p0, const detail::ShapeRef<T>& b, const Transform<T>& p1,
              bool& overlapping) {
  const detail::PairFrame<T> frame = detail::pairFrame(a.radius, p0, b.radius, p1);
  return Fn(a.geom, frame.pose0, b.geom, frame.pose1, overlapping);
}

// A sphere, capsule or box pair: both positions translated by the smaller shape's, rotations kept (normalised as the
// frame does).
template <class T, class G0, class G1,
          bool (*Kernel)(const G0&, const Transform<T>&, const G1&, const Transform<T>&)>
Status translated(const detail::ShapeRef<T>& a, const Transform<T>& p0, const detail::ShapeRef<T>& b,
                  const Transform<T>& p1, bool& overlapping) {
  const Vec3<T> origin = detail::pairOrigin(a.radius, p0, b.radius, p1);
  // A sphere's rotation moves none of its points: its kernel does not read it, so it is not normalised.
  constexpr bool sphere0 = std::is_same_v<G0, SphereGeometry<T>>, sphere1 = std::is_same_v<G1, SphereGeometry<T>>;
  overlapping = Kernel(a.template get<G0>(), Transform<T>(Vec3<T>(p0.p - origin), sphere0 ? p0.q : detail::unitRotation(p0.q)),
                       b.template get<G1>(), Transform<T>(Vec3<T>(p1.p - origin), sphere1 ? p1.q : detail::unitRotation(p1.q)));
  return Status();
}

// Two spheres: the squared distance of the centres (their difference is the translated frame's offset).
template <class T>
[[gnu::always_inline]] inline Status sphereSphere(const detail::ShapeRef<T>& a, const Transform<T>& p0,
                                                  const detail::ShapeRef<T>& b, const Transform<T>& p1,
                                                  bool& overlapping) {
  overlapping = detail::overlapSphereSphere<T>(p0.p, a.radius, p1.p, b.radius);
  return Status();
}

// A cell whose kernel is defined inline (overlap/sphere_capsule.h), flattened: one body with the kernel and its helpers
// (closestPointOnSegment would be a call), without the poses' copies.
template <class T, OverlapCell<T> Cell>
[[gnu::flatten]] Status flattened(const detail::ShapeRef<T>& a, const Transform<T>& p0, const detail::ShapeRef<T>& b,
                                  const Transform<T>& p1, bool& overlapping) {
  return Cell(a, p0, b, p1, overlapping);
}

template <class T, OverlapCell<T> Cell>
Status swappedCell(const detail::ShapeRef<T>& a, const Transform<T>& p0, const detail::ShapeRef<T>& b,
                   const Transform<T>& p1, bool& overlapping) {
  return Cell(b, p1, a, p0, overlapping);
}

// Adapts a kernel on concrete geometry types to the table's signature.
template <class T, class G0, class G1,
          bool (*Kernel)(const G0&, const Transform<T>&, const G1&, const Transform<T>&)>
Status pairKernel(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                  bool& overlapping) {
  overlapping = Kernel(g0.template get<G0>(), p0, g1.template get<G1>(), p1);
  return Status();
}

// The one generic wrapper for swapped pairs: overlap is symmetric.
template <class T, OverlapFn<T> Fn>
Status swapped(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
               bool& overlapping) {
  return Fn(g1, p1, g0, p0, overlapping);
}

template <class T> const CustomGeometryCallbacks<T>& callbacksOf(const Geometry<T>& g) {
  return *g.template get<CustomGeometry<T>>().callbacks;
}

// Custom geometry on either side: GJK on the support mappings (convexity is checked by the façade).
template <class T>
Status customKernel(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                    bool& overlapping) {
  overlapping = detail::overlapCustomAny(g0, p0, g1, p1);
  return Status();
}

// A cell with custom geometry: the shape's own overlap callback when it answers, else `Fallback` (gq/custom.h).
template <class T, OverlapFn<T> Fallback>
Status customFirst(const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1, const Transform<T>& p1,
                   bool& overlapping) {
  if (detail::customOverlap(g0, p0, g1, p1, overlapping)) return Status();
  return Fallback(g0, p0, g1, p1, overlapping);
}

// The rejection of a pair in which a custom shape is not convex (only raycast and bounds answer those).
template <class T> Status nonConvexCustomStatus(const Geometry<T>& g0, const Geometry<T>& g1) {
  const Geometry<T>& g = detail::isNonConvexCustom(g0) ? g0 : g1;
  return Status::aboutCustom(StatusCode::Unsupported, CustomIssue::NonConvexOverlap, callbacksOf(g).name());
}

template <class T>
Status notDefinedBySpec(const Geometry<T>& g0, const Transform<T>&, const Geometry<T>& g1, const Transform<T>&, bool&) {
  return Status::unsupported("overlap of this pair of geometry types is not defined by the spec (PhysX does not "
                             "support it)")
      .withTypes(g0.type(), g1.type());
}

template <class T>
Status notYetImplemented(const Geometry<T>& g0, const Transform<T>&, const Geometry<T>& g1, const Transform<T>&, bool&) {
  return Status::unsupported("overlap of this pair of geometry types is not implemented yet")
      .withTypes(g0.type(), g1.type());
}

template <class T, GeometryType A, GeometryType B, OverlapFn<T> Fn> constexpr void setPair(OverlapTable<T>& table) {
  static_assert(A <= B, "pairs are registered once, in GeometryType order; the swapped cell is derived");
  table[std::size_t(A)][std::size_t(B)] = framed<T, Fn>;
  if constexpr (A != B) table[std::size_t(B)][std::size_t(A)] = framed<T, swapped<T, Fn>>;
}

// A cell that picks its own frame (the sphere, capsule and box pairs).
template <class T, GeometryType A, GeometryType B, OverlapCell<T> Cell> constexpr void setCell(OverlapTable<T>& table) {
  static_assert(A <= B, "pairs are registered once, in GeometryType order; the swapped cell is derived");
  table[std::size_t(A)][std::size_t(B)] = Cell;
  if constexpr (A != B) table[std::size_t(B)][std::size_t(A)] = swappedCell<T, Cell>;
}

template <class T> constexpr OverlapTable<T> makeOverlapTable() {
  using GT = GeometryType;
  OverlapTable<T> t{};
  for (auto& row : t)
    for (auto& cell : row) cell = framed<T, notYetImplemented<T>>;  // overwritten below: every pair is registered
  setCell<T, GT::Sphere, GT::Sphere, sphereSphere<T>>(t);
  setPair<T, GT::Sphere, GT::Plane, pairKernel<T, SphereGeometry<T>, PlaneGeometry<T>, detail::overlapSpherePlane<T>>>(t);
  setCell<T, GT::Sphere, GT::Capsule, flattened<T, translated<T, SphereGeometry<T>, CapsuleGeometry<T>, detail::sphereCapsuleOverlaps<T>>>>(t);
  setCell<T, GT::Sphere, GT::Box, translated<T, SphereGeometry<T>, BoxGeometry<T>, detail::overlapSphereBox<T>>>(t);
  setPair<T, GT::Sphere, GT::ConvexMesh, pairKernel<T, SphereGeometry<T>, ConvexMeshGeometry<T>, detail::overlapSphereConvex<T>>>(t);
  setPair<T, GT::Sphere, GT::Custom, customFirst<T, customKernel<T>>>(t);
  setPair<T, GT::Plane, GT::Plane, notDefinedBySpec<T>>(t);
  setPair<T, GT::Plane, GT::Capsule, pairKernel<T, PlaneGeometry<T>, CapsuleGeometry<T>, detail::overlapPlaneCapsule<T>>>(t);
  setPair<T, GT::Plane, GT::Box, pairKernel<T, PlaneGeometry<T>, BoxGeometry<T>, detail::overlapPlaneBox<T>>>(t);
  setPair<T, GT::Plane, GT::ConvexMesh, pairKernel<T, PlaneGeometry<T>, ConvexMeshGeometry<T>, detail::overlapPlaneConvex<T>>>(t);
  setPair<T, GT::Plane, GT::TriangleMesh, detail::overlapPlaneTriangleMesh<T>>(t);
  setPair<T, GT::Plane, GT::HeightField, detail::overlapPlaneHeightField<T>>(t);
  setPair<T, GT::Plane, GT::Custom, customFirst<T, pairKernel<T, PlaneGeometry<T>, CustomGeometry<T>, detail::overlapPlaneCustom<T>>>>(t);
  setCell<T, GT::Capsule, GT::Capsule, translated<T, CapsuleGeometry<T>, CapsuleGeometry<T>, detail::overlapCapsuleCapsule<T>>>(t);
  setCell<T, GT::Capsule, GT::Box, translated<T, CapsuleGeometry<T>, BoxGeometry<T>, detail::overlapCapsuleBox<T>>>(t);
  setPair<T, GT::Capsule, GT::ConvexMesh, pairKernel<T, CapsuleGeometry<T>, ConvexMeshGeometry<T>, detail::overlapCapsuleConvex<T>>>(t);
  setPair<T, GT::Capsule, GT::Custom, customFirst<T, customKernel<T>>>(t);
  setCell<T, GT::Box, GT::Box, translated<T, BoxGeometry<T>, BoxGeometry<T>, detail::overlapBoxBox<T>>>(t);
  setPair<T, GT::Box, GT::ConvexMesh, pairKernel<T, BoxGeometry<T>, ConvexMeshGeometry<T>, detail::overlapBoxConvex<T>>>(t);
  setPair<T, GT::Box, GT::Custom, customFirst<T, customKernel<T>>>(t);
  setPair<T, GT::ConvexMesh, GT::ConvexMesh, pairKernel<T, ConvexMeshGeometry<T>, ConvexMeshGeometry<T>, detail::overlapConvexConvex<T>>>(t);
  setPair<T, GT::ConvexMesh, GT::Custom, customFirst<T, customKernel<T>>>(t);
  setPair<T, GT::Custom, GT::Custom, customFirst<T, customKernel<T>>>(t);
  // Thin surfaces (triangle mesh, heightfield): overlap/<shape>_triangle_mesh.cpp etc., exact per-triangle tests.
  setPair<T, GT::Sphere, GT::TriangleMesh, detail::overlapConvexTriangleMesh<T>>(t);
  setPair<T, GT::Capsule, GT::TriangleMesh, detail::overlapConvexTriangleMesh<T>>(t);
  setPair<T, GT::Box, GT::TriangleMesh, detail::overlapConvexTriangleMesh<T>>(t);
  setPair<T, GT::ConvexMesh, GT::TriangleMesh, detail::overlapConvexTriangleMesh<T>>(t);
  setPair<T, GT::TriangleMesh, GT::Custom, customFirst<T, swapped<T, detail::overlapConvexTriangleMesh<T>>>>(t);
  setPair<T, GT::Sphere, GT::HeightField, detail::overlapConvexHeightField<T>>(t);
  setPair<T, GT::Capsule, GT::HeightField, detail::overlapConvexHeightField<T>>(t);
  setPair<T, GT::Box, GT::HeightField, detail::overlapConvexHeightField<T>>(t);
  setPair<T, GT::ConvexMesh, GT::HeightField, detail::overlapConvexHeightField<T>>(t);
  setPair<T, GT::HeightField, GT::Custom, customFirst<T, swapped<T, detail::overlapConvexHeightField<T>>>>(t);
  setPair<T, GT::TriangleMesh, GT::TriangleMesh, detail::overlapTriangleMeshTriangleMesh<T>>(t);
  setPair<T, GT::TriangleMesh, GT::HeightField, detail::overlapTriangleMeshHeightField<T>>(t);
  setPair<T, GT::HeightField, GT::HeightField, detail::overlapHeightFieldHeightField<T>>(t);
  return t;
}

template <class T> constexpr OverlapTable<T> kOverlapTable = makeOverlapTable<T>();
static_assert(std::tuple_size_v<OverlapTable<float>> == kGeometryTypeCount &&
                  std::tuple_size_v<OverlapTable<float>::value_type> == kGeometryTypeCount,
              "one row and one column per GeometryType");

}  // namespace

namespace detail {

// Two spheres, the cheapest pair (a few instructions): their cell called directly, before the table and without the
// exception guard (nothing in it allocates or throws).
template <class T> bool bothSpheres(const ShapeRef<T>& a, const ShapeRef<T>& b) {
  return a.type() == GeometryType::Sphere && b.type() == GeometryType::Sphere;
}

// The table, once every input is valid: the one code path of both overloads. Inline in both (a call more was ~15
// instructions a query).
template <class T>
[[gnu::always_inline]] inline Status overlapCell(const ShapeRef<T>& a, const Transform<T>& pose0, const ShapeRef<T>& b,
                                                 const Transform<T>& pose1, bool& overlapping) {
  bool result = false;
  const OverlapCell<T> fn = kOverlapTable<T>[std::size_t(a.type())][std::size_t(b.type())];
  if (Status s = fn(a, pose0, b, pose1, result); !s.ok()) [[unlikely]]
    return s;
  overlapping = result;
  return Status();
}

// Valid shapes: the poses, then the non-convex custom shapes, then the table.
template <class T>
Status overlapShapes(const ShapeRef<T>& a, const Transform<T>& pose0, const ShapeRef<T>& b, const Transform<T>& pose1,
                     bool nonConvexCustom, bool& overlapping) noexcept {
  return guarded([&]() -> Status {
    if (!pairPosesAreValid(pose0, pose1)) return pairPosesStatus(pose0, pose1);
    if (nonConvexCustom) return nonConvexCustomStatus(a.geom, b.geom);
    if (bothSpheres(a, b)) return sphereSphere<T>(a, pose0, b, pose1, overlapping);
    return overlapCell(a, pose0, b, pose1, overlapping);
  });
}

// A prepared pair that is not ready for the table (an empty or too large shape, a non-convex custom one, a bad pose):
// the rejection, in the order of the Geometry<T> overload.
template <class T>
[[gnu::noinline, gnu::cold]] Status overlapPreparedChecked(const Shape<T>& shape0, const Transform<T>& pose0,
                                                           const Shape<T>& shape1, const Transform<T>& pose1,
                                                           bool& overlapping) noexcept {
  using A = ShapeAccess<T>;
  if (const Problem p = A::pairProblem(shape0)) return guarded([&] { return p.status(); });
  if (const Problem p = A::pairProblem(shape1)) return guarded([&] { return p.status(); });
  return overlapShapes(A::ref(shape0), pose0, A::ref(shape1), pose1,
                       A::nonConvexCustom(shape0) || A::nonConvexCustom(shape1), overlapping);
}

}  // namespace detail

template <class T>
Status overlap(const Geometry<T>& geom0, const Transform<T>& pose0, const Geometry<T>& geom1,
               const Transform<T>& pose1, bool& overlapping) noexcept {
  return detail::guarded([&]() -> Status {
    if (detail::pairGeometryProblem(geom0) || detail::pairGeometryProblem(geom1)) [[unlikely]]
      return detail::checkPairInputs(geom0, pose0, geom1, pose1);
    return detail::overlapShapes(detail::shapeRef(geom0), pose0, detail::shapeRef(geom1), pose1,
                                 detail::isNonConvexCustom(geom0) || detail::isNonConvexCustom(geom1), overlapping);
  });
}

template <class T>
Status overlap(const Shape<T>& shape0, const Transform<T>& pose0, const Shape<T>& shape1, const Transform<T>& pose1,
               bool& overlapping) noexcept {
  using A = detail::ShapeAccess<T>;
  if (A::pairReady(shape0, shape1) && detail::pairPosesAreValid(pose0, pose1)) [[likely]] {
    if (detail::bothSpheres(A::ref(shape0), A::ref(shape1)))
      return sphereSphere<T>(A::ref(shape0), pose0, A::ref(shape1), pose1, overlapping);
    return detail::guarded([&] { return detail::overlapCell(A::ref(shape0), pose0, A::ref(shape1), pose1, overlapping); });
  }
  return detail::overlapPreparedChecked(shape0, pose0, shape1, pose1, overlapping);
}

template Status overlap<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                               const Transform<float>&, bool&);
template Status overlap<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                const Transform<double>&, bool&);
template Status overlap<float>(const Shape<float>&, const Transform<float>&, const Shape<float>&,
                               const Transform<float>&, bool&) noexcept;
template Status overlap<double>(const Shape<double>&, const Transform<double>&, const Shape<double>&,
                                const Transform<double>&, bool&) noexcept;

}  // namespace gq
