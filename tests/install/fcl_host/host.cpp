// A program written against FCL 0.7. Switching it to gq is the alias line below (`= gq::fcl;`); nothing else changes.
// Checks: a sphere and a box touch or not as placed, their distance, and a broadphase's colliding pairs.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include <gq/fcl/fcl.h>  // FCL's headers plus gq::fcl

namespace fcl_api = ::fcl;

int main() {
  int failures = 0;
  const auto check = [&](bool ok, const char* what) {
    if (!ok) {
      std::fprintf(stderr, "wrong: %s\n", what);
      ++failures;
    }
  };

  // A unit sphere and a box of half extent 1, 2.5 apart along X: 0.5 between them; then 1.5 apart: overlapping.
  auto sphere = std::make_shared<fcl_api::Sphered>(1.0);
  auto box = std::make_shared<fcl_api::Boxd>(2.0, 2.0, 2.0);
  fcl_api::Transform3d tf = fcl_api::Transform3d::Identity();
  fcl_api::CollisionObjectd a(sphere, tf);
  tf.translation() = fcl_api::Vector3d(2.5, 0, 0);
  fcl_api::CollisionObjectd b(box, tf);

  fcl_api::DistanceRequestd distanceRequest;
  distanceRequest.enable_nearest_points = true;
  fcl_api::DistanceResultd distanceResult;
  fcl_api::distance(&a, &b, distanceRequest, distanceResult);
  check(std::abs(distanceResult.min_distance - 0.5) < 1e-6, "sphere-box distance 0.5");
  std::printf("distance %.6f\n", distanceResult.min_distance);

  fcl_api::CollisionRequestd request;
  fcl_api::CollisionResultd result;
  check(fcl_api::collide(&a, &b, request, result) == 0 && !result.isCollision(), "sphere and box 0.5 apart are free");
  tf.translation() = fcl_api::Vector3d(1.5, 0, 0);
  b.setTransform(tf);
  b.computeAABB();
  result.clear();
  fcl_api::collide(&a, &b, request, result);
  check(result.isCollision(), "sphere and box 1.5 apart collide");
  std::printf("collide at 1.5: %d\n", int(result.isCollision()));

  // A row of spheres of radius 0.6, 1 apart: neighbours overlap, the others do not.
  std::vector<std::unique_ptr<fcl_api::CollisionObjectd>> row;
  for (int i = 0; i < 6; ++i) {
    fcl_api::Transform3d t = fcl_api::Transform3d::Identity();
    t.translation() = fcl_api::Vector3d(i, 0, 10);
    row.push_back(std::make_unique<fcl_api::CollisionObjectd>(std::make_shared<fcl_api::Sphered>(0.6), t));
    row.back()->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(i)));
  }
  fcl_api::DynamicAABBTreeCollisionManagerd manager;
  for (auto& o : row) manager.registerObject(o.get());
  manager.setup();
  std::vector<std::pair<int, int>> pairs;
  manager.collide(&pairs, [](fcl_api::CollisionObjectd* p, fcl_api::CollisionObjectd* q, void* data) {
    fcl_api::CollisionRequestd r;
    fcl_api::CollisionResultd res;
    if (fcl_api::collide(p, q, r, res) > 0) {
      const int i = int(reinterpret_cast<std::intptr_t>(p->getUserData()));
      const int j = int(reinterpret_cast<std::intptr_t>(q->getUserData()));
      static_cast<std::vector<std::pair<int, int>>*>(data)->emplace_back(std::min(i, j), std::max(i, j));
    }
    return false;
  });
  std::sort(pairs.begin(), pairs.end());
  const std::vector<std::pair<int, int>> expected = {{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}};
  check(pairs == expected, "the broadphase finds the 5 neighbouring pairs");
  for (const auto& [i, j] : pairs) std::printf("pair %d %d\n", i, j);
  return failures == 0 ? 0 : 1;
}
