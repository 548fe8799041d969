#include <algorithm>
#include <vector>

#include <dart/collision/RaycastResult.hpp>

#include "collision_object.h"
#include "gq/dart/collision_detector.h"
#include "group_cast.h"

namespace gq {
namespace dart {

namespace dc = ::dart::collision;

bool CollisionDetector::raycast(dc::CollisionGroup* group, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                const dc::RaycastOption& option, dc::RaycastResult* result) {
  if (result != nullptr) result->clear();
  CollisionGroup* g = gqGroup(group);
  if (g == nullptr) return false;
  const Vec3<double> delta = to - from;
  const double length = delta.norm();
  if (!(length > 0.0) || !isFinite(Vec3<double>(from))) return false;
  const Vec3<double> dir = delta / length;
  g->synchronize();
  const auto toRayHit = [&](const SceneRaycastHit<double>& hit) {
    dc::RayHit ray;
    ray.mCollisionObject = g->object(hit.id);
    ray.mPoint = hit.hit.position;
    ray.mNormal = hit.hit.normal;
    ray.mFraction = hit.hit.distance / length;
    return ray;
  };
  const HitFlags flags = HitFlag::Position | HitFlag::Normal;
  if (!option.mEnableAllHits) {
    SceneRaycastHit<double> hit;
    bool hasHit = false;
    if (!g->scene().raycastClosest(from, dir, length, hit, hasHit, flags).ok() || !hasHit) return false;
    if (result != nullptr) result->mRayHits.push_back(toRayHit(hit));
    return true;
  }
  // Every object hit once, sorted by distance (one hit an instance: no HitFlag::MeshMultiple).
  std::vector<SceneRaycastHit<double>> hits(std::max<std::size_t>(1, g->scene().size()));
  std::uint32_t count = 0;
  if (!g->scene().raycastAll(from, dir, length, flags, std::uint32_t(hits.size()), hits.data(), count).ok()) {
    return false;
  }
  if (result != nullptr) {
    for (std::uint32_t i = 0; i < count; ++i) result->mRayHits.push_back(toRayHit(hits[i]));
  }
  return count > 0;
}

}  // namespace dart
}  // namespace gq
