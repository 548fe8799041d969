// Overlap façade: validation, then one dispatch table indexed [type0][type1].
//
// Semantics: touching counts as overlapping (every kernel compares with <=); the plane is the solid half-space
// x <= 0 of its frame. Kernels run in the frame of the smaller shape (common/pair_frame.h), so that shapes far from
// the origin, or far from a much larger shape, keep their precision.
#include <array>
#include <string>

#include "common/pair_frame.h"
#include "common/validate.h"
#include "custom/callback_queries.h"
#include "gq/custom.h"
#include "gq/query.h"
#include "overlap/overlap.h"
#include "overlap/surface_overlap.h"

namespace gq {
namespace {

template <class T>
using OverlapFn = Status (*)(const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&, bool&);
template <class T> using OverlapTable = std::array<std::array<OverlapFn<T>, kGeometryTypeCount>, kGeometryTypeCount>;

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
  table[std::size_t(A)][std::size_t(B)] = Fn;
  if constexpr (A != B) table[std::size_t(B)][std::size_t(A)] = swapped<T, Fn>;
}

template <class T> constexpr OverlapTable<T> makeOverlapTable() {
  using GT = GeometryType;
  OverlapTable<T> t{};
  for (auto& row : t)
    for (auto& cell : row) cell = notYetImplemented<T>;  // overwritten below: every pair is registered
  setPair<T, GT::Sphere, GT::Sphere, pairKernel<T, SphereGeometry<T>, SphereGeometry<T>, detail::overlapSphereSphere<T>>>(t);
  setPair<T, GT::Sphere, GT::Plane, pairKernel<T, SphereGeometry<T>, PlaneGeometry<T>, detail::overlapSpherePlane<T>>>(t);
  setPair<T, GT::Sphere, GT::Capsule, pairKernel<T, SphereGeometry<T>, CapsuleGeometry<T>, detail::overlapSphereCapsule<T>>>(t);
  setPair<T, GT::Sphere, GT::Box, pairKernel<T, SphereGeometry<T>, BoxGeometry<T>, detail::overlapSphereBox<T>>>(t);
  setPair<T, GT::Sphere, GT::ConvexMesh, pairKernel<T, SphereGeometry<T>, ConvexMeshGeometry<T>, detail::overlapSphereConvex<T>>>(t);
  setPair<T, GT::Sphere, GT::Custom, customFirst<T, customKernel<T>>>(t);
  setPair<T, GT::Plane, GT::Plane, notDefinedBySpec<T>>(t);
  setPair<T, GT::Plane, GT::Capsule, pairKernel<T, PlaneGeometry<T>, CapsuleGeometry<T>, detail::overlapPlaneCapsule<T>>>(t);
  setPair<T, GT::Plane, GT::Box, pairKernel<T, PlaneGeometry<T>, BoxGeometry<T>, detail::overlapPlaneBox<T>>>(t);
  setPair<T, GT::Plane, GT::ConvexMesh, pairKernel<T, PlaneGeometry<T>, ConvexMeshGeometry<T>, detail::overlapPlaneConvex<T>>>(t);
  setPair<T, GT::Plane, GT::TriangleMesh, notDefinedBySpec<T>>(t);
  setPair<T, GT::Plane, GT::HeightField, notDefinedBySpec<T>>(t);
  setPair<T, GT::Plane, GT::Custom, customFirst<T, pairKernel<T, PlaneGeometry<T>, CustomGeometry<T>, detail::overlapPlaneCustom<T>>>>(t);
  setPair<T, GT::Capsule, GT::Capsule, pairKernel<T, CapsuleGeometry<T>, CapsuleGeometry<T>, detail::overlapCapsuleCapsule<T>>>(t);
  setPair<T, GT::Capsule, GT::Box, pairKernel<T, CapsuleGeometry<T>, BoxGeometry<T>, detail::overlapCapsuleBox<T>>>(t);
  setPair<T, GT::Capsule, GT::ConvexMesh, pairKernel<T, CapsuleGeometry<T>, ConvexMeshGeometry<T>, detail::overlapCapsuleConvex<T>>>(t);
  setPair<T, GT::Capsule, GT::Custom, customFirst<T, customKernel<T>>>(t);
  setPair<T, GT::Box, GT::Box, pairKernel<T, BoxGeometry<T>, BoxGeometry<T>, detail::overlapBoxBox<T>>>(t);
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

template <class T>
Status overlap(const Geometry<T>& geom0, const Transform<T>& pose0, const Geometry<T>& geom1,
               const Transform<T>& pose1, bool& overlapping) noexcept {
  return detail::guarded([&]() -> Status {
    if (Status s = detail::checkPairInputs(geom0, pose0, geom1, pose1); !s.ok()) return s;
    if (detail::isNonConvexCustom(geom0) || detail::isNonConvexCustom(geom1)) return nonConvexCustomStatus(geom0, geom1);
    const detail::PairFrame<T> frame = detail::pairFrame(geom0, pose0, geom1, pose1);
    bool result = false;
    const OverlapFn<T> fn = kOverlapTable<T>[std::size_t(geom0.type())][std::size_t(geom1.type())];
    if (Status s = fn(geom0, frame.pose0, geom1, frame.pose1, result); !s.ok()) return s;
    overlapping = result;
    return Status();
  });
}

template Status overlap<float>(const Geometry<float>&, const Transform<float>&, const Geometry<float>&,
                               const Transform<float>&, bool&);
template Status overlap<double>(const Geometry<double>&, const Transform<double>&, const Geometry<double>&,
                                const Transform<double>&, bool&);

}  // namespace gq
