// gq::fcl::DynamicAABBTreeCollisionManager against ::fcl::DynamicAABBTreeCollisionManager on a 1000-object scene.
// Both managers run the same narrow phase (::fcl::collide) in their callbacks, so the colliding pair sets must be
// identical (the broadphase only prunes); gq's candidate pairs are a subset of FCL's (its boxes are tighter).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "fcl_scenes.h"
#include "gq/fcl/fcl.h"

namespace gq::fcltest {
namespace {

constexpr int kObjects = 1000;
constexpr double kSceneExtent = 6.0;  // objects placed in [-6, 6]^3

using PairSet = std::set<std::pair<const void*, const void*>>;

std::pair<const void*, const void*> key(const ::fcl::CollisionObjectd* a, const ::fcl::CollisionObjectd* b) {
  return a < b ? std::make_pair<const void*, const void*>(a, b) : std::make_pair<const void*, const void*>(b, a);
}

struct Collected {
  PairSet candidates, colliding;
  bool useGq = false;
};

bool collectPair(::fcl::CollisionObjectd* a, ::fcl::CollisionObjectd* b, void* data) {
  auto* c = static_cast<Collected*>(data);
  c->candidates.insert(key(a, b));
  ::fcl::CollisionRequestd request;
  ::fcl::CollisionResultd result;
  const std::size_t n = c->useGq ? gq::fcl::collide(a, b, request, result) : ::fcl::collide(a, b, request, result);
  if (n > 0) c->colliding.insert(key(a, b));
  return false;
}

struct Scene {
  std::vector<TestShape> shapes;
  std::vector<std::unique_ptr<::fcl::CollisionObjectd>> objects;
  std::vector<::fcl::CollisionObjectd*> pointers;

  explicit Scene(std::uint32_t seed) {
    std::mt19937 rng(seed);
    const Kind kinds[] = {Kind::Sphere, Kind::Box, Kind::Capsule, Kind::Cylinder, Kind::Convex, Kind::Ellipsoid};
    for (int i = 0; i < kObjects; ++i) {
      shapes.push_back(makeShape(kinds[i % 6], rng));
      objects.push_back(std::make_unique<::fcl::CollisionObjectd>(shapes.back().geometry, randomPose(rng, kSceneExtent)));
      pointers.push_back(objects.back().get());
    }
  }

  void moveHalf(std::mt19937& rng) {
    for (std::size_t i = 0; i < objects.size(); i += 2) {
      objects[i]->setTransform(randomPose(rng, kSceneExtent));
      objects[i]->computeAABB();  // FCL's manager reads the object's AABB; gq's reads the transform
    }
  }
};

Collected selfCollide(const ::fcl::BroadPhaseCollisionManagerd& manager, bool useGq = false) {
  Collected c;
  c.useGq = useGq;
  manager.collide(&c, collectPair);
  return c;
}

TEST(FclBroadphase, SelfCollisionFindsTheSamePairsAsFclStaticAndAfterMoving) {
  Scene scene(42);
  ::fcl::DynamicAABBTreeCollisionManagerd fclManager;
  gq::fcl::DynamicAABBTreeCollisionManagerd gqManager;
  fclManager.registerObjects(scene.pointers);
  gqManager.registerObjects(scene.pointers);
  fclManager.setup();
  gqManager.setup();
  EXPECT_EQ(gqManager.size(), std::size_t(kObjects));

  const Collected f0 = selfCollide(fclManager), g0 = selfCollide(gqManager);
  EXPECT_GT(f0.colliding.size(), 50u);
  EXPECT_EQ(g0.colliding, f0.colliding);
  EXPECT_TRUE(std::includes(f0.candidates.begin(), f0.candidates.end(), g0.candidates.begin(), g0.candidates.end()))
      << "gq's exact boxes must prune at least what FCL's cubes prune";
  EXPECT_LT(g0.candidates.size(), f0.candidates.size());

  std::mt19937 rng(7);
  scene.moveHalf(rng);
  fclManager.update();
  gqManager.update();
  const Collected f1 = selfCollide(fclManager), g1 = selfCollide(gqManager);
  EXPECT_NE(f1.colliding, f0.colliding);
  EXPECT_EQ(g1.colliding, f1.colliding);
}

TEST(FclBroadphase, UnregisterAndSingleObjectUpdateKeepTheAnswers) {
  Scene scene(5);
  ::fcl::DynamicAABBTreeCollisionManagerd fclManager;
  gq::fcl::DynamicAABBTreeCollisionManagerd gqManager;
  fclManager.registerObjects(scene.pointers);
  gqManager.registerObjects(scene.pointers);
  for (int i = 0; i < 100; ++i) {
    fclManager.unregisterObject(scene.pointers[std::size_t(3 * i)]);
    gqManager.unregisterObject(scene.pointers[std::size_t(3 * i)]);
  }
  std::mt19937 rng(11);
  for (int i = 1; i < 60; i += 3) {
    scene.objects[std::size_t(i)]->setTransform(randomPose(rng, kSceneExtent));
    scene.objects[std::size_t(i)]->computeAABB();
    fclManager.update(scene.pointers[std::size_t(i)]);
    gqManager.update(scene.pointers[std::size_t(i)]);
  }
  EXPECT_EQ(gqManager.size(), fclManager.size());
  EXPECT_EQ(selfCollide(gqManager).colliding, selfCollide(fclManager).colliding);
}

TEST(FclBroadphase, OneVsAllAndManagerVsManagerFindFclsPairs) {
  Scene scene(9);
  std::vector<::fcl::CollisionObjectd*> left(scene.pointers.begin(), scene.pointers.begin() + 500),
      right(scene.pointers.begin() + 500, scene.pointers.end());
  ::fcl::DynamicAABBTreeCollisionManagerd fclLeft, fclRight;
  gq::fcl::DynamicAABBTreeCollisionManagerd gqLeft, gqRight;
  fclLeft.registerObjects(left), fclRight.registerObjects(right);
  gqLeft.registerObjects(left), gqRight.registerObjects(right);
  Collected f, g, gMixed;
  fclLeft.collide(&fclRight, &f, collectPair);
  gqLeft.collide(&gqRight, &g, collectPair);
  gqLeft.collide(&fclRight, &gMixed, collectPair);  // another manager type on the other side
  EXPECT_GT(f.colliding.size(), 10u);
  EXPECT_EQ(g.colliding, f.colliding);
  EXPECT_EQ(gMixed.colliding, f.colliding);
  for (int i = 0; i < 20; ++i) {
    Collected fo, go;
    fclLeft.collide(right[std::size_t(i)], &fo, collectPair);
    gqLeft.collide(right[std::size_t(i)], &go, collectPair);
    EXPECT_EQ(go.colliding, fo.colliding) << "query object " << i;
  }
}

TEST(FclBroadphase, SelfDistanceEqualsTheBruteForceMinimum) {
  Scene scene(3);
  std::vector<::fcl::CollisionObjectd*> few(scene.pointers.begin(), scene.pointers.begin() + 120);
  for (auto* o : few) {  // spread out: a positive minimum that the pruning must not miss
    ::fcl::Transform3d tf = o->getTransform();
    tf.translation() *= 4;
    o->setTransform(tf);
    o->computeAABB();
  }
  gq::fcl::DynamicAABBTreeCollisionManagerd manager;
  manager.registerObjects(few);
  ::fcl::DefaultDistanceData<double> data;
  manager.distance(&data, gq::fcl::DefaultDistanceFunction<double>);
  // Brute force over all pairs with the same narrow phase.
  double best = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < few.size(); ++i)
    for (std::size_t j = i + 1; j < few.size(); ++j) {
      ::fcl::DistanceResultd r;
      gq::fcl::distance(few[i], few[j], ::fcl::DistanceRequestd(), r);
      best = std::min(best, r.min_distance);
    }
  ASSERT_GT(best, 0);
  EXPECT_DOUBLE_EQ(data.result.min_distance, best);
}

TEST(FclBroadphase, DefaultCollisionCallbackStopsEarly) {
  Scene scene(42);
  gq::fcl::DynamicAABBTreeCollisionManagerd manager;
  manager.registerObjects(scene.pointers);
  ::fcl::DefaultCollisionData<double> data;  // num_max_contacts = 1: stop at the first collision
  manager.collide(&data, gq::fcl::DefaultCollisionFunction<double>);
  EXPECT_TRUE(data.done);
  EXPECT_EQ(data.result.numContacts(), 1u);
}

}  // namespace
}  // namespace gq::fcltest
