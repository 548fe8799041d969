// Raycast façade: validation, then one dispatch table indexed by GeometryType.
#include <algorithm>
#include <array>
#include <limits>

#include "common/validate.h"
#include "gq/query.h"
#include "prepared/shape_ref.h"
#include "raycast/raycast.h"

namespace gq {
namespace {

template <class T> using RaycastFn = std::uint32_t (*)(const Geometry<T>&, const Transform<T>&,
                                                        const detail::RayQuery<T>&, RaycastHit<T>*);

// Adapts a kernel on a concrete geometry type to the table's signature.
template <class T, class G,
          std::uint32_t (*Kernel)(const G&, const Transform<T>&, const detail::RayQuery<T>&, RaycastHit<T>*)>
std::uint32_t call(const Geometry<T>& g, const Transform<T>& pose, const detail::RayQuery<T>& ray, RaycastHit<T>* hits) {
  return Kernel(g.template get<G>(), pose, ray, hits);
}

template <class T> constexpr std::array<RaycastFn<T>, kGeometryTypeCount> kRaycastTable = {
    call<T, SphereGeometry<T>, detail::raycastSphere<T>>,
    call<T, PlaneGeometry<T>, detail::raycastPlane<T>>,
    call<T, CapsuleGeometry<T>, detail::raycastCapsule<T>>,
    call<T, BoxGeometry<T>, detail::raycastBox<T>>,
    call<T, ConvexMeshGeometry<T>, detail::raycastConvex<T>>,
    call<T, TriangleMeshGeometry<T>, detail::raycastTriangleMesh<T>>,
    call<T, HeightFieldGeometry<T>, detail::raycastHeightField<T>>,
    call<T, CustomGeometry<T>, detail::raycastCustom<T>>,
};

// Everything but the geometry's own checks (a prepared shape made them once), in the order the Geometry<T> overload
// reports them: the ray, the buffer and flags, [the geometry], the pose.
template <class T>
Status validateRay(const Vec3<T>& origin, const Vec3<T>& dir, T maxDist, HitFlags flags, std::uint32_t maxHits,
                   const RaycastHit<T>* hits) {
  if (Status s = detail::checkFinite(origin, detail::kRayOriginField); !s.ok()) return s;
  if (Status s = detail::checkUnitDirection(dir, detail::kRayDirectionField); !s.ok()) return s;
  if (Status s = detail::checkMaxDist(maxDist); !s.ok()) return s;
  if (maxHits == 0) return Status::invalid("maxHits must be >= 1");
  if (hits == nullptr) return Status::invalid("hit buffer is null");
  if (flags.has(HitFlag::Mtd) || flags.has(HitFlag::PreciseSweep) || flags.has(HitFlag::AssumeNoInitialOverlap))
    return Status::invalid("mtd, preciseSweep and assumeNoInitialOverlap are sweep flags, not raycast flags");
  return Status();
}

template <class T> Status validateRayPose(const Vec3<T>& origin, const Transform<T>& pose) {
  if (Status s = detail::checkPose(pose, detail::kGeometryPoseField); !s.ok()) return s;
  // Kernels work in the geometry's frame; an origin whose offset from the pose overflows T has no local position.
  if (!isFinite(Vec3<T>(origin - pose.p)))
    return Status::invalid("ray origin is too far from the geometry pose: their difference overflows the precision");
  return Status();
}

// validateRay and validateRayPose on the success path of a prepared shape (the façade's whole per-ray cost).
template <class T>
[[gnu::always_inline]] inline bool rayInputsAreValid(const Vec3<T>& origin, const Vec3<T>& dir,
                                                     const Transform<T>& pose, T maxDist, HitFlags flags,
                                                     std::uint32_t maxHits, const RaycastHit<T>* hits) {
  return detail::rayIsValid(origin, dir, pose.p) & detail::raySettingsAreValid(pose, maxDist, flags, maxHits, hits);
}

// The kernel call of both overloads once every input is valid.
template <class T>
[[gnu::always_inline]] inline std::uint32_t raycastValid(const Vec3<T>& origin, const Vec3<T>& unitDir,
                                                         const Geometry<T>& geom, const Transform<T>& pose, T maxDist,
                                                         HitFlags hitFlags, std::uint32_t maxHits,
                                                         RaycastHit<T>* hits) {
  const detail::RayQuery<T> ray = detail::rayQuery(origin, unitDir, maxDist, hitFlags, maxHits);
  return kRaycastTable<T>[static_cast<std::size_t>(geom.type())](geom, pose, ray, hits);
}

// The one path of both overloads once the ray and the geometry are valid.
template <class T>
Status raycastGeometry(const Vec3<T>& origin, const Vec3<T>& unitDir, const Geometry<T>& geom, const Transform<T>& pose,
                       T maxDist, HitFlags hitFlags, std::uint32_t maxHits, RaycastHit<T>* hits,
                       std::uint32_t& hitCount) {
  if (Status s = validateRayPose(origin, pose); !s.ok()) return s;
  hitCount = raycastValid(origin, unitDir, geom, pose, maxDist, hitFlags, maxHits, hits);
  return Status();
}

}  // namespace

template <class T>
Status raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, const Geometry<T>& geom, const Transform<T>& pose,
               T maxDist, HitFlags hitFlags, std::uint32_t maxHits, RaycastHit<T>* hits, std::uint32_t& hitCount) noexcept {
  return detail::guarded([&]() -> Status {
    if (Status s = validateRay(origin, unitDir, maxDist, hitFlags, maxHits, hits); !s.ok()) return s;
    if (const detail::Problem p = detail::geometryProblem(geom)) return p.status();
    return raycastGeometry(origin, unitDir, geom, pose, maxDist, hitFlags, maxHits, hits, hitCount);
  });
}

namespace detail {

template <class T>
[[gnu::noinline]] Status raycastShapeChecked(const Vec3<T>& origin, const Vec3<T>& unitDir, const Shape<T>& shape,
                                             const Transform<T>& pose, T maxDist, HitFlags hitFlags,
                                             std::uint32_t maxHits, RaycastHit<T>* hits,
                                             std::uint32_t& hitCount) noexcept {
  return guarded([&]() -> Status {
    if (rayInputsAreValid(origin, unitDir, pose, maxDist, hitFlags, maxHits, hits) && ShapeAccess<T>::made(shape)) {
      hitCount = raycastValid(origin, unitDir, shape.geometry(), pose, maxDist, hitFlags, maxHits, hits);
      return Status();
    }
    if (Status s = validateRay(origin, unitDir, maxDist, hitFlags, maxHits, hits); !s.ok()) return s;
    if (!ShapeAccess<T>::made(shape)) return Status::invalid(emptyShapeText());
    return raycastGeometry(origin, unitDir, shape.geometry(), pose, maxDist, hitFlags, maxHits, hits, hitCount);
  });
}

}  // namespace detail

// A mesh shape goes to the mesh kernel directly, which checks the inputs itself.
template <class T>
Status raycast(const Vec3<T>& origin, const Vec3<T>& unitDir, const Shape<T>& shape, const Transform<T>& pose,
               T maxDist, HitFlags hitFlags, std::uint32_t maxHits, RaycastHit<T>* hits,
               std::uint32_t& hitCount) noexcept {
  if (detail::ShapeAccess<T>::rayMesh(shape))
    return detail::raycastMeshShape(origin, unitDir, shape, pose, maxDist, hitFlags, maxHits, hits, hitCount);
  return detail::raycastShapeChecked(origin, unitDir, shape, pose, maxDist, hitFlags, maxHits, hits, hitCount);
}

template Status raycast<float>(const Vec3<float>&, const Vec3<float>&, const Geometry<float>&, const Transform<float>&,
                               float, HitFlags, std::uint32_t, RaycastHit<float>*, std::uint32_t&);
template Status raycast<double>(const Vec3<double>&, const Vec3<double>&, const Geometry<double>&,
                                const Transform<double>&, double, HitFlags, std::uint32_t, RaycastHit<double>*,
                                std::uint32_t&);
template Status raycast<float>(const Vec3<float>&, const Vec3<float>&, const Shape<float>&, const Transform<float>&,
                               float, HitFlags, std::uint32_t, RaycastHit<float>*, std::uint32_t&) noexcept;
template Status raycast<double>(const Vec3<double>&, const Vec3<double>&, const Shape<double>&,
                                const Transform<double>&, double, HitFlags, std::uint32_t, RaycastHit<double>*,
                                std::uint32_t&) noexcept;
template Status detail::raycastShapeChecked<float>(const Vec3<float>&, const Vec3<float>&, const Shape<float>&,
                                                   const Transform<float>&, float, HitFlags, std::uint32_t,
                                                   RaycastHit<float>*, std::uint32_t&) noexcept;
template Status detail::raycastShapeChecked<double>(const Vec3<double>&, const Vec3<double>&, const Shape<double>&,
                                                    const Transform<double>&, double, HitFlags, std::uint32_t,
                                                    RaycastHit<double>*, std::uint32_t&) noexcept;

}  // namespace gq
