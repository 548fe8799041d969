// A DART simulation through the gq detector: boxes, spheres and capsules dropped on a mesh ground and on a heightmap
// come to rest, with the same final poses as with DART's Bullet detector within tolerance.
#include <gtest/gtest.h>

#include <dart/dynamics/CapsuleShape.hpp>

#include "dart_scene.h"

namespace {

using namespace gqtest;

enum class Ground { Mesh, Heightmap };

struct Rest {
  std::vector<Eigen::Vector3d> positions;
  double maxSpeed = 0.0;
};

// Nine bodies (three boxes, three spheres, three capsules lying flat) dropped from 0.3 above the ground, apart from
// each other, stepped for 3 s at 1 ms.
Rest dropAndSettle(const std::string& detectorName, Ground groundType) {
  auto world = ::dart::simulation::World::create();
  world->setTimeStep(0.001);
  world->getConstraintSolver()->setCollisionDetector(detector(detectorName));
  dd::ShapePtr groundShape;
  if (groundType == Ground::Mesh) {
    groundShape = groundMesh(3.0, 12);
  } else {
    groundShape = flatHeightmap(25, 0.25, 0.0);
  }
  world->addSkeleton(body("ground", groundShape, at(Eigen::Vector3d::Zero()), true));
  std::vector<dd::SkeletonPtr> bodies;
  const Eigen::Quaterniond lying(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  for (int i = 0; i < 9; ++i) {
    const double x = -1.2 + 1.2 * (i % 3), y = -1.2 + 1.2 * (i / 3);
    dd::ShapePtr shape;
    double halfHeight = 0.0;
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
    if (i % 3 == 0) {
      shape = std::make_shared<dd::BoxShape>(Eigen::Vector3d(0.3, 0.4, 0.2));
      halfHeight = 0.1;
    } else if (i % 3 == 1) {
      shape = std::make_shared<dd::SphereShape>(0.15);
      halfHeight = 0.15;
    } else {
      shape = std::make_shared<dd::CapsuleShape>(0.1, 0.4);
      halfHeight = 0.1;
      q = lying;
    }
    auto b = body("body" + std::to_string(i), shape, at(Eigen::Vector3d(x, y, halfHeight + 0.3), q), false);
    world->addSkeleton(b);
    bodies.push_back(b);
  }
  for (int step = 0; step < 3000; ++step) world->step();
  Rest rest;
  for (const auto& b : bodies) {
    rest.positions.push_back(b->getBodyNode(0)->getWorldTransform().translation());
    rest.maxSpeed = std::max(rest.maxSpeed, b->getBodyNode(0)->getLinearVelocity().norm());
  }
  return rest;
}

void expectRestsLikeBullet(Ground ground) {
  const Rest gq = dropAndSettle("gq", ground);
  EXPECT_LT(gq.maxSpeed, 1e-2);
  const double expectedZ[3] = {0.1, 0.15, 0.1};
  for (std::size_t i = 0; i < gq.positions.size(); ++i) {
    EXPECT_NEAR(gq.positions[i].z(), expectedZ[i % 3], 2e-3) << "body " << i;
  }
#ifdef GQ_HAVE_DART_BULLET
  const Rest bullet = dropAndSettle("bullet", ground);
  for (std::size_t i = 0; i < gq.positions.size(); ++i) {
    EXPECT_NEAR(gq.positions[i].z(), bullet.positions[i].z(), 5e-3) << "body " << i;
    EXPECT_LT((gq.positions[i] - bullet.positions[i]).head<2>().norm(), 0.05) << "body " << i;
  }
#endif
}

TEST(DartSimulation, DropOnMeshGroundRestsLikeBullet) { expectRestsLikeBullet(Ground::Mesh); }

TEST(DartSimulation, DropOnHeightmapRestsLikeBullet) { expectRestsLikeBullet(Ground::Heightmap); }

}  // namespace
