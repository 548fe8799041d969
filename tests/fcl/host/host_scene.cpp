// A host program written against FCL: a grid of shapes in a DynamicAABBTreeCollisionManager, self collision with
// FCL's default callback, one-vs-all distance, and a direct collide/distance. The build runs it twice: as written
// (FCL) and with the alias line below changed to `namespace coll = gq::fcl;` (tests/fcl/CMakeLists.txt); the
// outputs must be identical.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>
#include <vector>

#include "gq/fcl/fcl.h"  // FCL's headers plus gq::fcl

namespace coll = ::fcl;

namespace {

std::shared_ptr<coll::CollisionGeometryd> shapeAt(int i) {
  // Neighbours 1.0 apart: two big ones overlap by 0.12, big and small leave 0.04, diagonal neighbours >= 0.06.
  const double big = (i % 8) % 3 != 2 ? 0.56 : 0.4;
  switch (i % 4) {
    case 0: return std::make_shared<coll::Sphered>(big);
    case 1: return std::make_shared<coll::Boxd>(2 * big, 2 * big, 2 * big);
    case 2: return std::make_shared<coll::Capsuled>(big, 0.5);  // along Z: only the XY layout matters
    default: return std::make_shared<coll::Cylinderd>(big, 0.5);
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::unique_ptr<coll::CollisionObjectd>> objects;
  for (int i = 0; i < 64; ++i) {
    coll::Transform3d tf = coll::Transform3d::Identity();
    tf.translation() = coll::Vector3d(i % 8, i / 8, 0.0);
    objects.push_back(std::make_unique<coll::CollisionObjectd>(shapeAt(i), tf));
    objects.back()->setUserData(reinterpret_cast<void*>(static_cast<std::intptr_t>(i)));
  }
  coll::DynamicAABBTreeCollisionManagerd manager;
  for (auto& o : objects) manager.registerObject(o.get());
  manager.setup();

  // Self collision: every colliding pair (FCL's default callback stops at num_max_contacts, so collect per pair).
  struct Collect {
    std::vector<std::pair<int, int>> pairs;
  } collect;
  manager.collide(&collect, [](coll::CollisionObjectd* a, coll::CollisionObjectd* b, void* data) {
    coll::CollisionRequestd request;
    coll::CollisionResultd result;
    if (coll::collide(a, b, request, result) > 0) {
      int i = int(reinterpret_cast<std::intptr_t>(a->getUserData())), j = int(reinterpret_cast<std::intptr_t>(b->getUserData()));
      static_cast<Collect*>(data)->pairs.emplace_back(std::min(i, j), std::max(i, j));
    }
    return false;
  });
  std::sort(collect.pairs.begin(), collect.pairs.end());

  // The default callback: any collision at all.
  coll::DefaultCollisionData<double> any;
  manager.collide(&any, coll::DefaultCollisionFunction<double>);

  // One-vs-all distance with the default distance callback, from a sphere above the grid.
  coll::CollisionObjectd probe(std::make_shared<coll::Sphered>(0.25), coll::Transform3d(coll::Translation3d(3.3, 2.2, 2.0)));
  coll::DefaultDistanceData<double> nearest;
  manager.distance(&probe, &nearest, coll::DefaultDistanceFunction<double>);

  // Direct narrow phase.
  coll::DistanceRequestd request(true);
  coll::DistanceResultd result;
  coll::distance(objects[0].get(), objects[9].get(), request, result);

  FILE* out = argc > 1 ? std::fopen(argv[1], "w") : stdout;
  if (!out) return 1;
  std::fprintf(out, "colliding pairs: %zu\n", collect.pairs.size());
  for (const auto& [i, j] : collect.pairs) std::fprintf(out, "  %d %d\n", i, j);
  std::fprintf(out, "default callback found a collision: %d\n", int(any.result.isCollision()));
  std::fprintf(out, "probe distance: %.5f\n", nearest.result.min_distance);
  std::fprintf(out, "distance 0-9: %.5f\n", result.min_distance);
  if (out != stdout) std::fclose(out);
  return collect.pairs.empty() ? 1 : 0;
}
