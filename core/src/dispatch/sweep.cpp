// Sweep façade: validation, the flag rules of the spec, then one dispatch table indexed [swept][target].
//
// Rules (documented in the README's sweep section):
//  - the swept shape is a sphere, capsule, box or convex mesh (others: Unsupported); the target is any type (a
//    non-convex custom target: Unsupported);
//  - unitDir unit, maxDist >= 0 (NaN/negative: InvalidArgument); maxDist is clamped to tol::kMaxSweepDistance (1e8);
//    maxDist = 0 is an overlap test; inflation finite and >= 0;
//  - meshMultiple is rejected (InvalidArgument): a sweep returns at most one hit; anyHit is honoured for meshes;
//  - mtd with preciseSweep or assumeNoInitialOverlap, preciseSweep with inflation > 0, and assumeNoInitialOverlap
//    with maxDist = 0 return a Warning and the incompatible flag is ignored (the query runs);
//  - preciseSweep is accepted and changes nothing: every sweep is exact to the GJK tolerance by default;
//  - initial overlap (touching counts): hadInitialOverlap(); without mtd distance 0, normal -dir, no position; with
//    mtd distance = -depth (<= 0), normal = depenetration direction of the swept shape (translating it by
//    -normal * distance separates), position on the swept shape;
//  - faceIndex: triangle index (mesh, heightfield), polygon index (convex mesh, on hits), else 0xffffffff.
#include <array>
#include <string>

#include "common/validate.h"
#include "gq/custom.h"
#include "gq/query.h"
#include "prepared/shape_ref.h"
#include "sweep/sweep.h"

namespace gq {
namespace {

template <class T> using SweepFn = void (*)(const Geometry<T>&, const Transform<T>&, const Geometry<T>&,
                                            const Transform<T>&, const detail::SweepQuery<T>&, detail::SweepOutcome<T>&);

template <class T>
void unsupported(const Geometry<T>&, const Transform<T>&, const Geometry<T>&, const Transform<T>&,
                 const detail::SweepQuery<T>&, detail::SweepOutcome<T>&) {}

template <class T> using Row = std::array<SweepFn<T>, kGeometryTypeCount>;

// A row for a swept convex shape; the sphere row replaces its sphere cell by the closed form.
template <class T> constexpr Row<T> convexRow(SweepFn<T> sphereCell) {
  return {sphereCell,
          detail::sweepConvexPlane<T>,
          detail::sweepConvexConvex<T>,
          detail::sweepConvexConvex<T>,
          detail::sweepConvexConvex<T>,
          detail::sweepConvexTriangleMesh<T>,
          detail::sweepConvexHeightField<T>,
          detail::sweepConvexCustom<T>};
}
template <class T> constexpr Row<T> unsupportedRow() {
  return {unsupported<T>, unsupported<T>, unsupported<T>, unsupported<T>,
          unsupported<T>, unsupported<T>, unsupported<T>, unsupported<T>};
}

// Rows: swept type; columns: target type, both in GeometryType order.
template <class T> constexpr std::array<Row<T>, kGeometryTypeCount> kSweepTable = {{
    convexRow<T>(detail::sweepSphereSphere<T>),   // sphere
    unsupportedRow<T>(),                          // plane
    convexRow<T>(detail::sweepConvexConvex<T>),   // capsule
    convexRow<T>(detail::sweepConvexConvex<T>),   // box
    convexRow<T>(detail::sweepConvexConvex<T>),   // convex mesh
    unsupportedRow<T>(),                          // triangle mesh
    unsupportedRow<T>(),                          // heightfield
    unsupportedRow<T>(),                          // custom
}};
static_assert(kSweepTable<double>.size() == kGeometryTypeCount && kSweepTable<double>[0].size() == kGeometryTypeCount,
              "one row and one column per GeometryType");

bool isSweepable(GeometryType t) {
  return t == GeometryType::Sphere || t == GeometryType::Capsule || t == GeometryType::Box ||
         t == GeometryType::ConvexMesh;
}

// Everything but the geometries' own checks (a prepared shape made them once).
template <class T>
Status validateSweepQuery(const Vec3<T>& dir, T maxDist, HitFlags flags, T inflation) {
  if (Status s = detail::checkUnitDirection(dir, detail::kSweepDirectionField); !s.ok()) return s;
  if (Status s = detail::checkMaxDist(maxDist); !s.ok()) return s;
  if (!std::isfinite(inflation) || inflation < T(0)) return Status::invalid("inflation must be finite and >= 0");
  if (flags.has(HitFlag::MeshMultiple)) return Status::invalid("meshMultiple is not supported by sweeps (one hit)");
  return {};
}

template <class T> Status validateSweepTypes(const Geometry<T>& g0, const Geometry<T>& g1) {
  if (!isSweepable(g0.type()))
    return Status::unsupported("the swept geometry must be a sphere, capsule, box or convex mesh").withType(g0.type());
  if (const auto* c = g1.template getIf<CustomGeometry<T>>(); c && !c->callbacks->isConvex())
    return Status::unsupported("sweep against a non-convex custom geometry");
  return {};
}

// Applies the spec's incompatibilities: returns the flags to use and a warning message (nullptr if none). The mtd
// rule removes the flags of the other two, so only the last two can apply together: their message is composed here.
template <class T> HitFlags resolveFlags(HitFlags flags, T maxDist, T inflation, const char*& warning) {
  if (flags.has(HitFlag::Mtd) && (flags.has(HitFlag::PreciseSweep) || flags.has(HitFlag::AssumeNoInitialOverlap))) {
    warning = "mtd is incompatible with preciseSweep and assumeNoInitialOverlap: those are ignored.";
    flags = flags.without(HitFlag::PreciseSweep | HitFlag::AssumeNoInitialOverlap);
  }
  if (flags.has(HitFlag::PreciseSweep) && inflation > T(0)) {
    warning = "preciseSweep is incompatible with inflation: preciseSweep is ignored.";
    flags = flags.without(HitFlag::PreciseSweep);
  }
  if (flags.has(HitFlag::AssumeNoInitialOverlap) && maxDist == T(0)) {
    warning = warning ? "preciseSweep is incompatible with inflation: preciseSweep is ignored. assumeNoInitialOverlap "
                        "with a zero-length sweep: ignored, the overlap is tested."
                      : "assumeNoInitialOverlap with a zero-length sweep: ignored, the overlap is tested.";
    flags = flags.without(HitFlag::AssumeNoInitialOverlap);
  }
  return flags;
}

template <class T> bool targetDoubleSided(const Geometry<T>& g) {
  if (const auto* m = g.template getIf<TriangleMeshGeometry<T>>()) return m->doubleSided();
  if (const auto* h = g.template getIf<HeightFieldGeometry<T>>()) return h->doubleSided();
  return false;
}

template <class T> bool finiteOutcome(const detail::SweepOutcome<T>& o) {
  return std::isfinite(o.distance) && isFinite(o.normal) && isFinite(o.position) &&
         (!o.mtdValid || (std::isfinite(o.mtdDepth) && isFinite(o.mtdNormal) && isFinite(o.mtdPosition)));
}

// Writes the hit from a kernel outcome (positions back in world: the kernels ran with the origin at pose0.p).
template <class T>
void writeHit(const detail::SweepOutcome<T>& o, const detail::SweepQuery<T>& q, const Vec3<T>& origin, SweepHit<T>& hit) {
  hit = SweepHit<T>();
  hit.initialOverlap = o.initialOverlap;
  const bool asksFace = q.flags.has(HitFlag::FaceIndex);
  if (o.initialOverlap) {
    if (q.mtd && o.mtdValid) {
      hit.distance = -o.mtdDepth;
      hit.normal = o.mtdNormal;
      hit.position = o.mtdPosition + origin;
      hit.flags = HitFlag::Normal | HitFlag::Position;
    } else {
      hit.distance = T(0);
      hit.normal = -q.dir;
      hit.flags = HitFlag::Normal;
    }
  } else {
    hit.distance = o.distance;
    if (q.flags.has(HitFlag::Normal)) { hit.normal = o.normal; hit.flags |= HitFlag::Normal; }
    if (q.flags.has(HitFlag::Position)) { hit.position = o.position + origin; hit.flags |= HitFlag::Position; }
  }
  if (asksFace) { hit.faceIndex = o.faceIndex; hit.flags |= HitFlag::FaceIndex; }
}

}  // namespace

namespace detail {

// The one path of both overloads once the geometries are valid.
template <class T>
Status sweepShapes(const Vec3<T>& unitDir, T maxDist, const Geometry<T>& geom0, const Transform<T>& pose0,
                   const Geometry<T>& geom1, const Transform<T>& pose1, SweepHit<T>& hit, bool& hasHit,
                   HitFlags hitFlags, T inflation) noexcept {
  return guarded([&]() -> Status {
    if (!pairPosesAreValid(pose0, pose1)) return pairPosesStatus(pose0, pose1);
    if (Status s = validateSweepTypes(geom0, geom1); !s.ok()) return s;
    const char* warning = nullptr;
    const T reach = std::min(maxDist, T(tol::kMaxSweepDistance));
    const HitFlags flags = resolveFlags(hitFlags, reach, inflation, warning);

    SweepQuery<T> q;
    q.dir = unitDir.normalized();
    q.maxDist = reach;
    q.flags = flags;
    q.inflation = inflation;
    q.testInitialOverlap = !flags.has(HitFlag::AssumeNoInitialOverlap);
    q.mtd = flags.has(HitFlag::Mtd);
    q.cullBackFaces = !flags.has(HitFlag::MeshBothSides) && !targetDoubleSided(geom1);
    q.anyHit = flags.has(HitFlag::AnyHit);

    // Origin at the swept shape's start: kernels work on small coordinates; rotations are normalised.
    const Transform<T> local0(Vec3<T>::Zero(), pose0.q.normalized());
    const Transform<T> local1(Vec3<T>(pose1.p - pose0.p), pose1.q.normalized());
    SweepOutcome<T> o;
    kSweepTable<T>[static_cast<std::size_t>(geom0.type())][static_cast<std::size_t>(geom1.type())](
        geom0, local0, geom1, local1, q, o);
    if (!o.status.ok()) return o.status;
    if (!finiteOutcome(o)) return Status::internal("sweep produced a non-finite result");
    hasHit = o.hit;
    if (o.hit) writeHit(o, q, pose0.p, hit);
    return warning ? Status::warning(warning) : Status();
  });
}

}  // namespace detail

template <class T>
Status sweep(const Vec3<T>& unitDir, T maxDist, const Geometry<T>& geom0, const Transform<T>& pose0,
             const Geometry<T>& geom1, const Transform<T>& pose1, SweepHit<T>& hit, bool& hasHit, HitFlags hitFlags,
             T inflation) noexcept {
  return detail::guarded([&]() -> Status {
    if (Status s = validateSweepQuery(unitDir, maxDist, hitFlags, inflation); !s.ok()) return s;
    if (detail::pairGeometryProblem(geom0) || detail::pairGeometryProblem(geom1))
      return detail::checkPairInputs(geom0, pose0, geom1, pose1);
    return detail::sweepShapes(unitDir, maxDist, geom0, pose0, geom1, pose1, hit, hasHit, hitFlags, inflation);
  });
}

template <class T>
Status sweep(const Vec3<T>& unitDir, T maxDist, const Shape<T>& shape0, const Transform<T>& pose0,
             const Shape<T>& shape1, const Transform<T>& pose1, SweepHit<T>& hit, bool& hasHit, HitFlags hitFlags,
             T inflation) noexcept {
  using A = detail::ShapeAccess<T>;
  return detail::guarded([&]() -> Status {
    if (Status s = validateSweepQuery(unitDir, maxDist, hitFlags, inflation); !s.ok()) return s;
    if (const detail::Problem p = A::pairProblem(shape0)) return p.status();
    if (const detail::Problem p = A::pairProblem(shape1)) return p.status();
    return detail::sweepShapes(unitDir, maxDist, shape0.geometry(), pose0, shape1.geometry(), pose1, hit, hasHit,
                               hitFlags, inflation);
  });
}

template Status sweep<float>(const Vec3<float>&, float, const Geometry<float>&, const Transform<float>&,
                             const Geometry<float>&, const Transform<float>&, SweepHit<float>&, bool&, HitFlags, float);
template Status sweep<double>(const Vec3<double>&, double, const Geometry<double>&, const Transform<double>&,
                              const Geometry<double>&, const Transform<double>&, SweepHit<double>&, bool&, HitFlags,
                              double);
template Status sweep<float>(const Vec3<float>&, float, const Shape<float>&, const Transform<float>&,
                             const Shape<float>&, const Transform<float>&, SweepHit<float>&, bool&, HitFlags,
                             float) noexcept;
template Status sweep<double>(const Vec3<double>&, double, const Shape<double>&, const Transform<double>&,
                              const Shape<double>&, const Transform<double>&, SweepHit<double>&, bool&, HitFlags,
                              double) noexcept;

}  // namespace gq
