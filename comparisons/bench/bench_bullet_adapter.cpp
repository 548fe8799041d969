// Stock Bullet vs gq through the Bullet adapter, side by side: stepping the test scenes (10-box stack; sphere,
// capsule, hull and cylinder dropped on a BVH mesh and on a heightfield; Bullet's BasicDemo 5x5x5 box grid; a
// 200-body mixed pile on a triangle-mesh ground; 500 steps each), contact generation per pair type (the algorithm
// each configuration installs, called directly on a resting pair that wobbles slightly from call to call), 10k
// rayTests and 10k convexSweepTests (sphere radius 0.25) against a scene of sphere, rotated box, capsule, mesh floor
// and heightfield. Each benchmark is registered once per backend (bullet / gq); the scenes are the tests'
// (tests/bullet). Stepping benchmarks report how the scene came to rest next to the time (counters): the largest
// body speed after 5 s (max_speed_5s), the depth of the lowest body below the ground after 500 steps (below_ground)
// and, for the stack, the largest error of a box's height from the exact one (height_error).
// Run: bench_bullet_adapter --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>

#include "bullet_test_scene.h"
#include "pile_scenes.h"

// Instruction counts per pair call: run under `valgrind --tool=callgrind --collect-atstart=no`; the pair loops
// switch collection on and off around themselves (no-ops outside valgrind).
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define GQ_CALLGRIND_TOGGLE() CALLGRIND_TOGGLE_COLLECT
#else
#define GQ_CALLGRIND_TOGGLE() (void)0
#endif

namespace {

using gq::bullet::test::Backend;
using gq::bullet::test::ShapeStore;
using gq::bullet::test::TestWorld;
using namespace gq::bullet::test;

constexpr int kSceneSteps = 500;
constexpr int kQueries = 10000;

void boxStack(TestWorld& w, ShapeStore& store) {
  w.add(store.make<btBoxShape>(btVector3(20, 1, 20)), 0, btVector3(0, -1, 0));
  auto* box = store.make<btBoxShape>(btVector3(0.5, 0.5, 0.5));
  for (int i = 0; i < 10; ++i) w.add(box, 1, btVector3(0, btScalar(0.5 + i), 0));
}

void drops(TestWorld& w, ShapeStore& store, bool mesh) {
  if (mesh) {
    w.add(gq::bullet::test::flatMesh(store, 6, 10, btScalar(0.5)), 0, btVector3(0, 0, 0));
  } else {
    auto* field = gq::bullet::test::heightField(store, 6, std::vector<float>(36, 1.0f), -1, 2);
    field->setLocalScaling(btVector3(4, 1, 4));
    w.add(field, 0, btVector3(0, 0, 0));
  }
  const btScalar r = btScalar(2 - std::sqrt(2.0)) * 2;
  w.add(store.make<btSphereShape>(btScalar(0.5)), 1, btVector3(-2 + r, 2, -2 + r));
  w.add(store.make<btCapsuleShapeX>(btScalar(0.3), btScalar(1)), 1, btVector3(2 + r, 2, -2 + r));
  w.add(gq::bullet::test::cubeHull(store, btScalar(0.4)), 1, btVector3(-6 + r, 2, 2 + r));
  w.add(store.make<btCylinderShape>(btVector3(0.4, 0.6, 0.4)), 1, btVector3(2 + r, 2, 2 + r));
}

enum class Scene { Stack, DropsOnMesh, DropsOnHeightField, Grid, MixedPile };

// Builds the scene; the stack, grid and pile also list their dynamic bodies for the rest measures.
PileScene build(Scene scene, TestWorld& w, ShapeStore& store) {
  switch (scene) {
    case Scene::Stack: {
      boxStack(w, store);
      PileScene s;
      for (int i = 1; i < w.world().getNumCollisionObjects(); ++i)
        s.bodies.push_back(btRigidBody::upcast(w.world().getCollisionObjectArray()[i]));
      return s;
    }
    case Scene::DropsOnMesh: drops(w, store, true); break;
    case Scene::DropsOnHeightField: drops(w, store, false); break;
    case Scene::Grid: return basicDemoGrid(w, store);
    case Scene::MixedPile: return mixedPile(w, store);
  }
  return PileScene();
}

// The rest measures of one untimed run: max speed after 5 s (300 steps), then after 500 steps the depth below the
// ground and (stack) the largest height error.
void restCounters(benchmark::State& state, Scene scene, Backend backend) {
  ShapeStore store;
  TestWorld w(backend);
  const PileScene s = build(scene, w, store);
  if (s.bodies.empty()) return;
  w.step(300);
  state.counters["max_speed_5s"] = maxSpeed(s);
  w.step(kSceneSteps - 300);
  state.counters["below_ground"] = deepestBelowGround(s);
  if (scene == Scene::Stack) {
    btScalar err = 0;
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
      err = std::max(err, std::abs(s.bodies[i]->getWorldTransform().getOrigin().y() - btScalar(0.5 + double(i))));
    state.counters["height_error"] = err;
  }
}

void BM_Step(benchmark::State& state, Scene scene, Backend backend) {
  for (auto _ : state) {
    ShapeStore store;
    TestWorld w(backend);
    build(scene, w, store);
    w.step(kSceneSteps);
    benchmark::DoNotOptimize(w.world().getNumCollisionObjects());
  }
  state.SetItemsProcessed(state.iterations() * kSceneSteps);
  restCounters(state, scene, backend);
}

// ---- Contact generation per pair type ----------------------------------------------------------------------

enum class Pair { SphereBox, BoxBox, CapsuleBox, HullHull, BoxMesh };
constexpr int kPairCalls = 1000;

// The point of a convex shape rotated by q (origin at 0) farthest along +y (sign 1) or -y (sign -1).
btVector3 extreme(btCollisionShape* shape, const btQuaternion& q, btScalar sign) {
  const btVector3 dir = btVector3(0, sign, 0) * btMatrix3x3(q);
  return btMatrix3x3(q) * static_cast<btConvexShape*>(shape)->localGetSupportingVertex(dir);
}

// Two objects in resting contact (slightly penetrating, A above B), as the pile's pairs are.
struct PairScene {
  ShapeStore store;
  btCollisionObject a, b;
  explicit PairScene(Pair pair) {
    btCollisionShape* box = store.make<btBoxShape>(btVector3(0.5, 0.5, 0.5));
    btCollisionShape *sa = nullptr, *sb = box;
    btVector3 at(0, 0, 0);
    const btQuaternion tilt(btVector3(1, 0, 1).normalized(), btScalar(0.05));
    btQuaternion qa = btQuaternion::getIdentity();
    switch (pair) {
      case Pair::SphereBox: sa = store.make<btSphereShape>(btScalar(0.5)); at.setY(btScalar(0.995)); break;
      case Pair::BoxBox: sa = box; at.setY(btScalar(0.995)); qa = btQuaternion(btVector3(0, 1, 0), btScalar(0.3)); break;
      case Pair::CapsuleBox: sa = store.make<btCapsuleShapeX>(btScalar(0.25), btScalar(0.6)); at.setY(btScalar(0.745)); break;
      case Pair::HullHull:
        sa = randomHull(store, 30, btVector3(btScalar(0.5), btScalar(0.4), btScalar(0.45)), 3);
        sb = randomHull(store, 30, btVector3(btScalar(0.5), btScalar(0.4), btScalar(0.45)), 4);
        qa = tilt;
        // A's lowest point 5 mm into B's highest (curved hulls touch at one point).
        at = extreme(sb, btQuaternion::getIdentity(), 1) - extreme(sa, qa, -1) - btVector3(0, btScalar(0.005), 0);
        break;
      case Pair::BoxMesh: sa = box; sb = flatMesh(store, 5, 2, 0); at.setY(btScalar(0.495)); qa = tilt; break;
    }
    a.setCollisionShape(sa);
    b.setCollisionShape(sb);
    a.setWorldTransform(btTransform(qa, at));
    b.setWorldTransform(btTransform::getIdentity());
  }
};

// Calls the pair's contact algorithm kPairCalls times per iteration, A's pose wobbling by up to 1 mm and 0.06
// degrees (a resting pair), a manifold result per call as Bullet's dispatcher makes it.
void BM_PairContacts(benchmark::State& state, Pair pair, Backend backend) {
  PairScene scene(pair);
  TestWorld w(backend);  // only its configuration and dispatcher
  btCollisionDispatcher* dispatcher = static_cast<btCollisionDispatcher*>(w.world().getDispatcher());
  const btTransform base = scene.a.getWorldTransform();
  btCollisionObjectWrapper wa(nullptr, scene.a.getCollisionShape(), &scene.a, scene.a.getWorldTransform(), -1, -1);
  btCollisionObjectWrapper wb(nullptr, scene.b.getCollisionShape(), &scene.b, scene.b.getWorldTransform(), -1, -1);
  btCollisionAlgorithm* algorithm = dispatcher->findAlgorithm(&wa, &wb, nullptr, BT_CONTACT_POINT_ALGORITHMS);
  btDispatcherInfo& info = w.world().getDispatchInfo();
  int points = 0;
  {
    btManifoldResult warmUp(&wa, &wb);  // cooks the shapes once, as the first frame of a world does
    algorithm->processCollision(&wa, &wb, info, &warmUp);
  }
  for (auto _ : state) {
    GQ_CALLGRIND_TOGGLE();
    for (int i = 0; i < kPairCalls; ++i) {
      const btScalar t = btScalar(std::sin(0.37 * i));
      scene.a.setWorldTransform(base * btTransform(btQuaternion(btVector3(1, 0, 0), btScalar(1e-3) * t),
                                                   btVector3(0, btScalar(1e-3) * t, 0)));
      btManifoldResult result(&wa, &wb);
      algorithm->processCollision(&wa, &wb, info, &result);
      if (result.getPersistentManifold()) points += result.getPersistentManifold()->getNumContacts();
    }
    GQ_CALLGRIND_TOGGLE();
  }
  state.counters["contacts"] = double(points) / double(std::max<std::int64_t>(1, state.iterations() * kPairCalls));
  algorithm->~btCollisionAlgorithm();
  dispatcher->freeCollisionAlgorithm(algorithm);
  state.SetItemsProcessed(state.iterations() * kPairCalls);
}

struct QueryScene {
  ShapeStore store;
  TestWorld world;
  std::vector<btVector3> from, to;
  explicit QueryScene(Backend backend) : world(backend) {
    world.add(store.make<btSphereShape>(btScalar(1)), 0, btVector3(0, 0, 0));
    world.add(store.make<btBoxShape>(btVector3(1, 0.5, 2)), 0, btVector3(5, 0, 0),
              btQuaternion(btVector3(0, 1, 0), btScalar(0.5)));
    world.add(store.make<btCapsuleShape>(btScalar(0.5), btScalar(2)), 0, btVector3(-5, 0, 0));
    world.add(gq::bullet::test::flatMesh(store, 9, 12, -3), 0, btVector3(0, 0, 0));
    std::vector<float> h(25);
    for (int j = 0; j < 5; ++j)
      for (int x = 0; x < 5; ++x) h[std::size_t(j * 5 + x)] = 0.25f * float(x);
    world.add(gq::bullet::test::heightField(store, 5, h, 0, 1), 0, btVector3(0, 0, 20));
    // Rays from above, aimed at random points of the scene's floor (same seed for both backends).
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> ux(-8, 8), uz(-3, 3), tilt(-0.3f, 0.3f);
    for (int i = 0; i < kQueries; ++i) {
      const btVector3 target(ux(rng), -4, uz(rng));
      from.push_back(target + btVector3(tilt(rng) * 14, 14, tilt(rng) * 14));
      to.push_back(target);
    }
    world.world().updateAabbs();
  }
};

void BM_RayTest(benchmark::State& state, Backend backend) {
  QueryScene scene(backend);
  int hits = 0;
  for (auto _ : state) {
    for (int i = 0; i < kQueries; ++i) {
      btCollisionWorld::ClosestRayResultCallback cb(scene.from[i], scene.to[i]);
      scene.world.world().rayTest(scene.from[i], scene.to[i], cb);
      hits += cb.hasHit();
    }
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * kQueries);
}

void BM_ConvexSweepTest(benchmark::State& state, Backend backend) {
  QueryScene scene(backend);
  btSphereShape ball(btScalar(0.25));
  int hits = 0;
  for (auto _ : state) {
    for (int i = 0; i < kQueries; ++i) {
      const btTransform from(btQuaternion::getIdentity(), scene.from[i]);
      const btTransform to(btQuaternion::getIdentity(), scene.to[i]);
      btCollisionWorld::ClosestConvexResultCallback cb(scene.from[i], scene.to[i]);
      scene.world.convexSweepTest(&ball, from, to, cb);
      hits += cb.hasHit();
    }
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * kQueries);
}

#define GQ_STEP_BENCH(name, scene)                                                                        \
  BENCHMARK_CAPTURE(BM_Step, name##_bullet, scene, Backend::Bullet)->Unit(benchmark::kMillisecond); \
  BENCHMARK_CAPTURE(BM_Step, name##_gq, scene, Backend::Gq)->Unit(benchmark::kMillisecond)
GQ_STEP_BENCH(stack, Scene::Stack);
GQ_STEP_BENCH(drops_mesh, Scene::DropsOnMesh);
GQ_STEP_BENCH(drops_heightfield, Scene::DropsOnHeightField);
GQ_STEP_BENCH(grid, Scene::Grid);
GQ_STEP_BENCH(mixed_pile, Scene::MixedPile);
#define GQ_PAIR_BENCH(name, pair)                                                                                \
  BENCHMARK_CAPTURE(BM_PairContacts, name##_bullet, pair, Backend::Bullet)->Unit(benchmark::kMicrosecond); \
  BENCHMARK_CAPTURE(BM_PairContacts, name##_gq, pair, Backend::Gq)->Unit(benchmark::kMicrosecond)
GQ_PAIR_BENCH(sphere_box, Pair::SphereBox);
GQ_PAIR_BENCH(box_box, Pair::BoxBox);
GQ_PAIR_BENCH(capsule_box, Pair::CapsuleBox);
GQ_PAIR_BENCH(hull_hull, Pair::HullHull);
GQ_PAIR_BENCH(box_mesh, Pair::BoxMesh);
BENCHMARK_CAPTURE(BM_RayTest, bullet, Backend::Bullet)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RayTest, gq, Backend::Gq)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ConvexSweepTest, bullet, Backend::Bullet)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ConvexSweepTest, gq, Backend::Gq)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
