// A DART world stepped with its collision detector chosen by name: gq (gq::dart), bullet (dart-collision-bullet) and
// fcl (DART's default), in one run. The scene: 27 bodies (boxes, spheres and capsules in a 3 x 3 x 3 pile, 5 cm
// apart) dropped on a ground box; each benchmark iteration builds the world (not timed) and steps it 600 times at
// 1 ms (the pile falls, collides and settles).
// bench_dart.to_csv.py writes comparisons/results/dart.csv from several runs.
#include <benchmark/benchmark.h>

#include <string>

#include "dart_scene.h"  // tests/dart: bodies built in code

namespace {

using gqtest::body;
namespace dd = ::dart::dynamics;

constexpr int kSteps = 600;

::dart::simulation::WorldPtr pile(const std::string& detector) {
  auto world = ::dart::simulation::World::create();
  world->setTimeStep(0.001);
  world->getConstraintSolver()->setCollisionDetector(
      ::dart::collision::CollisionDetector::getFactory()->create(detector));
  Eigen::Isometry3d tf = Eigen::Isometry3d::Identity();
  tf.translation() = Eigen::Vector3d(0, 0, -0.5);
  world->addSkeleton(body("ground", std::make_shared<dd::BoxShape>(Eigen::Vector3d(10, 10, 1)), tf, true));
  const Eigen::Quaterniond lying(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitY()));
  for (int i = 0; i < 27; ++i) {
    const int x = i % 3, y = (i / 3) % 3, z = i / 9;
    tf = Eigen::Isometry3d::Identity();
    tf.translation() = Eigen::Vector3d(0.35 * x + 0.01 * z, 0.35 * y - 0.01 * z, 0.2 + 0.35 * z);
    dd::ShapePtr shape;
    switch (i % 3) {
      case 0: shape = std::make_shared<dd::BoxShape>(Eigen::Vector3d(0.3, 0.3, 0.3)); break;
      case 1: shape = std::make_shared<dd::SphereShape>(0.15); break;
      default:
        shape = std::make_shared<dd::CapsuleShape>(0.1, 0.1);
        tf.linear() = lying.toRotationMatrix();
        break;
    }
    world->addSkeleton(body("body" + std::to_string(i), shape, tf, false));
  }
  return world;
}

void stepPile(benchmark::State& state, const std::string& detector) {
  double maxSpeed = 0.0, lowest = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    auto world = pile(detector);
    state.ResumeTiming();
    for (int i = 0; i < kSteps; ++i) world->step();
    benchmark::DoNotOptimize(world->getTime());
    state.PauseTiming();
    maxSpeed = 0.0;
    lowest = 1e9;
    for (std::size_t k = 1; k < world->getNumSkeletons(); ++k) {
      const dd::BodyNode* node = world->getSkeleton(k)->getBodyNode(0);
      maxSpeed = std::max(maxSpeed, node->getLinearVelocity().norm());
      lowest = std::min(lowest, node->getWorldTransform().translation().z());
    }
    state.ResumeTiming();
  }
  // How the pile ends: the largest body speed after the last step, and the lowest body centre (the ground is z = 0).
  state.counters["max_speed_end"] = maxSpeed;
  state.counters["lowest_z_end"] = lowest;
}

}  // namespace

BENCHMARK_CAPTURE(stepPile, gq, std::string("gq"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stepPile, bullet, std::string("bullet"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stepPile, fcl, std::string("fcl"))->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
