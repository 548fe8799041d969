// Stock Bullet vs gq through the Bullet adapter, side by side: stepping the test scenes (10-box stack; sphere,
// capsule, hull and cylinder dropped on a BVH mesh and on a heightfield; 500 steps each), 10k rayTests and 10k
// convexSweepTests (sphere radius 0.25) against a scene of sphere, rotated box, capsule, mesh floor and heightfield.
// Each benchmark is registered once per backend (bullet / gq); the scenes are the tests' (tests/bullet).
// Run: bench_bullet_adapter --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "bullet_test_scene.h"

namespace {

using gq::bullet::test::Backend;
using gq::bullet::test::ShapeStore;
using gq::bullet::test::TestWorld;

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

enum class Scene { Stack, DropsOnMesh, DropsOnHeightField };

void BM_Step(benchmark::State& state, Scene scene, Backend backend) {
  for (auto _ : state) {
    ShapeStore store;
    TestWorld w(backend);
    if (scene == Scene::Stack)
      boxStack(w, store);
    else
      drops(w, store, scene == Scene::DropsOnMesh);
    w.step(kSceneSteps);
    benchmark::DoNotOptimize(w.world().getNumCollisionObjects());
  }
  state.SetItemsProcessed(state.iterations() * kSceneSteps);
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

BENCHMARK_CAPTURE(BM_Step, stack_bullet, Scene::Stack, Backend::Bullet)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Step, stack_gq, Scene::Stack, Backend::Gq)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Step, drops_mesh_bullet, Scene::DropsOnMesh, Backend::Bullet)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Step, drops_mesh_gq, Scene::DropsOnMesh, Backend::Gq)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Step, drops_heightfield_bullet, Scene::DropsOnHeightField, Backend::Bullet)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Step, drops_heightfield_gq, Scene::DropsOnHeightField, Backend::Gq)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RayTest, bullet, Backend::Bullet)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_RayTest, gq, Backend::Gq)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ConvexSweepTest, bullet, Backend::Bullet)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ConvexSweepTest, gq, Backend::Gq)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
