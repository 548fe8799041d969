// A DART world stepped with its collision detector chosen by name: gq (gq::dart), bullet (dart-collision-bullet) and
// fcl (DART's default), in one run. The scene: 27 bodies (boxes, spheres and capsules in a 3 x 3 x 3 pile, 5 cm
// apart) dropped on a ground box; each benchmark iteration builds the world (not timed) and steps it 600 times at
// 1 ms (the pile falls, collides and settles). Counter ms_per_step: CPU time of one step.
// bench_dart.to_csv.py writes comparisons/results/dart.csv from several runs.
#include <benchmark/benchmark.h>

#include <string>

#include <dart/collision/CollisionDetector.hpp>
#include <dart/constraint/ConstraintSolver.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/CapsuleShape.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/SphereShape.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/simulation/World.hpp>

namespace {

namespace dd = ::dart::dynamics;

constexpr int kSteps = 600;

dd::SkeletonPtr body(const std::string& name, const dd::ShapePtr& shape, const Eigen::Isometry3d& tf, bool fixed) {
  auto skeleton = dd::Skeleton::create(name);
  dd::BodyNode* node = nullptr;
  if (fixed) {
    node = skeleton->createJointAndBodyNodePair<dd::WeldJoint>().second;
    node->getParentJoint()->setTransformFromParentBodyNode(tf);
  } else {
    node = skeleton->createJointAndBodyNodePair<dd::FreeJoint>().second;
    dd::FreeJoint::setTransformOf(node, tf);
  }
  node->createShapeNodeWith<dd::CollisionAspect, dd::DynamicsAspect>(shape);
  dd::Inertia inertia;
  inertia.setMass(1.0);
  inertia.setMoment(shape->computeInertia(1.0));
  node->setInertia(inertia);
  return skeleton;
}

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
  for (auto _ : state) {
    state.PauseTiming();
    auto world = pile(detector);
    state.ResumeTiming();
    for (int i = 0; i < kSteps; ++i) world->step();
    benchmark::DoNotOptimize(world->getTime());
  }
  state.counters["ms_per_step"] = benchmark::Counter(1e3 * kSteps, benchmark::Counter::kIsIterationInvariantRate |
                                                                      benchmark::Counter::kInvert);
}

}  // namespace

BENCHMARK_CAPTURE(stepPile, gq, std::string("gq"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stepPile, bullet, std::string("bullet"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(stepPile, fcl, std::string("fcl"))->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
