#include <cmath>
#include <limits>

#include <dart/collision/DistanceFilter.hpp>
#include <dart/collision/DistanceResult.hpp>

#include "collision_object.h"
#include "gq/dart/collision_detector.h"
#include "group_cast.h"

namespace gq {
namespace dart {
namespace {

namespace dc = ::dart::collision;

struct NearestSearch {
  const CollisionGroup* group = nullptr;  // the group searched
  const CollisionObject* query = nullptr;
  InstanceId minId = 0;  // a self query asks each pair once: only instances with a larger id
  const dc::DistanceFilter* filter = nullptr;
};

bool acceptInstance(void* userData, InstanceId id) {
  const auto* search = static_cast<const NearestSearch*>(userData);
  if (id <= search->minId) return false;
  const CollisionObject* other = search->group->object(id);
  if (other == nullptr || other == search->query) return false;
  return search->filter == nullptr || search->filter->needDistance(search->query, other);
}

// The nearest pair (an object of `first`, an instance of `second`), each object asking `second`'s scene for the
// instance nearest to it below the best distance so far; stops at distanceLowerBound.
double nearestPair(const CollisionGroup& first, const CollisionGroup& second, bool self,
                   const dc::DistanceOption& option, dc::DistanceResult* result) {
  double best = std::numeric_limits<double>::infinity();
  const CollisionObject* best1 = nullptr;
  const CollisionObject* best2 = nullptr;
  DistanceResult<double> bestResult;
  for (CollisionObject* object : first.objects()) {
    if (!object->converted()) continue;
    NearestSearch search;
    search.group = &second;
    search.query = object;
    search.filter = option.distanceFilter.get();
    search.minId = self ? first.idOf(object) : 0;
    SceneFilter filter;
    filter.callback = &acceptInstance;
    filter.userData = &search;
    SceneDistanceResult<double> nearest;
    bool found = false;
    const double bound = std::isfinite(best) ? best : std::numeric_limits<double>::infinity();
    if (!second.scene().nearest(object->shape(), object->pose(), bound, nearest, found, filter).ok() || !found) {
      continue;
    }
    if (nearest.result.distance < best || best1 == nullptr) {
      best = nearest.result.distance;
      best1 = object;
      best2 = second.object(nearest.id);
      bestResult = nearest.result;
    }
    if (best <= option.distanceLowerBound) break;
  }
  if (best1 == nullptr) return 0.0;
  const double clamped = std::max(best, option.distanceLowerBound);
  if (result != nullptr) {
    result->minDistance = clamped;
    result->unclampedMinDistance = best;
    result->shapeFrame1 = best1->getShapeFrame();
    result->shapeFrame2 = best2 != nullptr ? best2->getShapeFrame() : nullptr;
    if (option.enableNearestPoints) {
      result->nearestPoint1 = bestResult.point0;
      result->nearestPoint2 = bestResult.point1;
    }
  }
  return clamped;
}

}  // namespace

double CollisionDetector::distance(dc::CollisionGroup* group, const dc::DistanceOption& option,
                                   dc::DistanceResult* result) {
  if (result != nullptr) result->clear();
  CollisionGroup *g = nullptr, *same = nullptr;
  if (!synchronizedGroups(group, group, g, same)) return 0.0;
  return nearestPair(*g, *g, true, option, result);
}

double CollisionDetector::distance(dc::CollisionGroup* group1, dc::CollisionGroup* group2,
                                   const dc::DistanceOption& option, dc::DistanceResult* result) {
  if (result != nullptr) result->clear();
  CollisionGroup *g1 = nullptr, *g2 = nullptr;
  if (!synchronizedGroups(group1, group2, g1, g2)) return 0.0;
  return nearestPair(*g1, *g2, false, option, result);
}

}  // namespace dart
}  // namespace gq
