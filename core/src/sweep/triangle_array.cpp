// Sweep of a sphere, capsule or box against an array of world-space triangles (the spec's PxGeometryQuery::sweep
// over a PxTriangle buffer). Rules:
//  - the swept shape is a sphere, capsule or box (others: Unsupported); unitDir unit, maxDist >= 0 (clamped to
//    tol::kMaxSweepDistance), inflation finite and >= 0, triangles finite, `triangles` non-null when count > 0,
//    *cachedIndex < count (InvalidArgument otherwise; nothing written);
//  - supported flags: the defaults, assumeNoInitialOverlap, preciseSweep, meshBothSides, anyHit; meshMultiple and
//    mtd are rejected (InvalidArgument);
//  - winding gives the front face (counter-clockwise seen from the front); back faces are culled unless
//    doubleSided or meshBothSides; a hit normal always faces against the sweep;
//  - *cachedIndex is tested first; with anyHit the first hit found is returned, else the closest one (ties to the
//    triangle facing the sweep most, then the smaller index); faceIndex is the triangle's index in the array;
//  - an initial overlap reports hadInitialOverlap, distance 0, normal -dir and the smallest overlapping index.
#include <string>
#include <vector>

#include "common/validate.h"
#include "gq/mesh_query.h"
#include "sweep/sweep.h"

namespace gq {
namespace {

template <class T>
Status validateTriangleSweep(const Vec3<T>& dir, T maxDist, const Geometry<T>& geom, const Transform<T>& pose,
                             const Triangle<T>* triangles, std::uint32_t count, HitFlags flags,
                             const std::uint32_t* cachedIndex, T inflation) {
  if (Status s = detail::checkUnitDirection(dir, detail::kSweepDirectionField); !s.ok()) return s;
  if (Status s = detail::checkMaxDist(maxDist); !s.ok()) return s;
  if (!std::isfinite(inflation) || inflation < T(0)) return Status::invalid("inflation must be finite and >= 0");
  if (flags.has(HitFlag::MeshMultiple)) return Status::invalid("meshMultiple is not supported by sweepTriangles (one hit)");
  if (flags.has(HitFlag::Mtd)) return Status::invalid("mtd is not supported by sweepTriangles");
  if (const detail::Problem p = detail::pairGeometryProblem(geom)) return p.status();  // a pair query's sizes
  if (Status s = detail::checkPose(pose, detail::kPoseField); !s.ok()) return s;
  const GeometryType t = geom.type();
  if (t != GeometryType::Sphere && t != GeometryType::Capsule && t != GeometryType::Box)
    return Status::unsupported("sweepTriangles takes a sphere, capsule or box as the swept geometry").withType(t);
  if (count > 0 && triangles == nullptr) return Status::invalid("triangles is null with a non-zero count");
  for (std::uint32_t i = 0; i < count; ++i)
    if (const char* problem = detail::rawTriangleProblem(triangles[i], pose))
      return Status::invalid(problem).withIndex(i);
  if (cachedIndex && *cachedIndex >= count)
    return Status::invalid("cachedIndex is out of range of the triangles").withIndex(*cachedIndex);
  return {};
}

// The triangle moved to the query's local frame (origin at the swept shape's start).
template <class T> Triangle<T> shifted(const Triangle<T>& tri, const Vec3<T>& origin) {
  Triangle<T> out;
  for (int k = 0; k < 3; ++k) out.verts[k] = tri.verts[k] - origin;
  return out;
}

}  // namespace

template <class T>
Status sweepTriangles(const Vec3<T>& unitDir, T maxDist, const Geometry<T>& geom, const Transform<T>& pose,
                      const Triangle<T>* triangles, std::uint32_t triangleCount, SweepHit<T>& hit, bool& hasHit,
                      const TriangleSweepSettings<T>& settings) noexcept {
  return detail::guarded([&]() -> Status {
    const HitFlags hitFlags = settings.flags;
    const std::uint32_t* cachedIndex = settings.cachedIndex;
    const T inflation = settings.inflation;
    const bool doubleSided = settings.doubleSided;
    if (Status s = validateTriangleSweep(unitDir, maxDist, geom, pose, triangles, triangleCount, hitFlags, cachedIndex,
                                         inflation);
        !s.ok())
      return s;
    detail::SweepQuery<T> q;
    q.dir = unitDir.normalized();
    q.maxDist = std::min(maxDist, T(tol::kMaxSweepDistance));
    q.flags = hitFlags;
    q.inflation = inflation;
    q.testInitialOverlap = !hitFlags.has(HitFlag::AssumeNoInitialOverlap) || q.maxDist == T(0);
    q.mtd = false;
    q.cullBackFaces = !doubleSided && !hitFlags.has(HitFlag::MeshBothSides);
    q.anyHit = hitFlags.has(HitFlag::AnyHit);

    const detail::ConvexShape<T> a =
        detail::makeSweptShape(geom, Transform<T>(Vec3<T>::Zero(), pose.q.normalized()), inflation);
    const Bounds3<T> reachBox = detail::sweptBoundsInFrame(a, Transform<T>(), q.dir, q.maxDist);
    detail::TriangleHitPicker<T> picker;
    picker.tieTolerance = detail::triangleTieTolerance(a, reachBox);
    detail::SweepQuery<T> local = q;
    // The cached triangle first, then the others in order.
    auto visit = [&](std::uint32_t i) {
      const Triangle<T> tri = shifted(triangles[i], pose.p);
      Bounds3<T> box;
      for (const Vec3<T>& v : tri.verts) box.include(v);
      if (!box.overlaps(reachBox)) return false;
      local.maxDist = picker.earlyOut(q.maxDist);
      detail::ToiResult<T> toi;
      T facing;
      if (!detail::sweepOneTriangle(a, tri, local, doubleSided, toi, facing)) return false;
      return picker.offer(toi, facing, i, q.anyHit);
    };
    bool done = cachedIndex && visit(*cachedIndex);
    for (std::uint32_t i = 0; i < triangleCount && !done; ++i)
      if (!cachedIndex || i != *cachedIndex) done = visit(i);

    hasHit = picker.found;
    if (!picker.found) return Status();
    detail::SweepOutcome<T> o;
    detail::outcomeFromToi(picker.best, o);
    if (!std::isfinite(o.distance) || !isFinite(o.normal) || !isFinite(o.position))
      return Status::internal("sweepTriangles produced a non-finite result");
    hit = SweepHit<T>();
    hit.initialOverlap = o.initialOverlap;
    hit.distance = o.initialOverlap ? T(0) : o.distance;
    if (o.initialOverlap) {
      hit.normal = -q.dir;
      hit.flags = HitFlag::Normal;
    } else {
      if (hitFlags.has(HitFlag::Normal)) { hit.normal = o.normal; hit.flags |= HitFlag::Normal; }
      if (hitFlags.has(HitFlag::Position)) { hit.position = o.position + pose.p; hit.flags |= HitFlag::Position; }
    }
    if (hitFlags.has(HitFlag::FaceIndex)) { hit.faceIndex = picker.bestIndex; hit.flags |= HitFlag::FaceIndex; }
    return Status();
  });
}

template Status sweepTriangles<float>(const Vec3<float>&, float, const Geometry<float>&, const Transform<float>&,
                                      const Triangle<float>*, std::uint32_t, SweepHit<float>&, bool&,
                                      const TriangleSweepSettings<float>&);
template Status sweepTriangles<double>(const Vec3<double>&, double, const Geometry<double>&, const Transform<double>&,
                                       const Triangle<double>*, std::uint32_t, SweepHit<double>&, bool&,
                                       const TriangleSweepSettings<double>&);

}  // namespace gq
