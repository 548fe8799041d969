// A .skel file names its collision detector: `<collision_detector>gq</collision_detector>` loads gq's detector
// through DART's factory, and the world it describes simulates with it (a box dropped on a ground box comes to rest
// on it).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <dart/common/Uri.hpp>
#include <dart/constraint/ConstraintSolver.hpp>
#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/simulation/World.hpp>
#ifdef GQ_HAVE_DART_UTILS
#include <dart/utils/SkelParser.hpp>
#endif

namespace {

// A ground box (top face at z = 0, welded to the world) and a 0.2 cube whose centre starts at z = 0.5.
const char* const kSkel = R"(<?xml version="1.0" ?>
<skel version="1.0">
  <world name="drop">
    <physics>
      <time_step>0.001</time_step>
      <gravity>0 0 -9.81</gravity>
      <collision_detector>gq</collision_detector>
    </physics>
    <skeleton name="ground">
      <mobile>false</mobile>
      <body name="ground">
        <transformation>0 0 -0.05 0 0 0</transformation>
        <collision_shape>
          <transformation>0 0 0 0 0 0</transformation>
          <geometry><box><size>4 4 0.1</size></box></geometry>
        </collision_shape>
      </body>
      <joint type="weld" name="ground_joint"><parent>world</parent><child>ground</child></joint>
    </skeleton>
    <skeleton name="cube">
      <body name="cube">
        <transformation>0 0 0.5 0 0 0</transformation>
        <inertia><mass>1</mass><offset>0 0 0</offset></inertia>
        <collision_shape>
          <transformation>0 0 0 0 0 0</transformation>
          <geometry><box><size>0.2 0.2 0.2</size></box></geometry>
        </collision_shape>
      </body>
      <joint type="free" name="cube_joint"><parent>world</parent><child>cube</child></joint>
    </skeleton>
  </world>
</skel>
)";

TEST(DartSkel, CollisionDetectorElementSelectsGqAndTheWorldRestsOnIt) {
#ifndef GQ_HAVE_DART_UTILS
  GTEST_SKIP() << "DART's utils component (Debian libdart-utils-dev) was not found at configure time";
#else
  const std::string path = ::testing::TempDir() + "gq_dart_drop.skel";
  {
    std::ofstream out(path);
    out << kSkel;
    ASSERT_TRUE(out.good()) << "cannot write " << path;
  }
  const auto world = ::dart::utils::SkelParser::readWorld(::dart::common::Uri::createFromPath(path));
  ASSERT_NE(world, nullptr);
  const auto detector = world->getConstraintSolver()->getCollisionDetector();
  ASSERT_NE(detector, nullptr);
  EXPECT_EQ(detector->getType(), "gq");
  const auto cube = world->getSkeleton("cube");
  ASSERT_NE(cube, nullptr);
  for (int step = 0; step < 2000; ++step) world->step();
  const Eigen::Vector3d p = cube->getBodyNode(0)->getWorldTransform().translation();
  EXPECT_NEAR(p.z(), 0.1, 1e-3) << "the cube's centre rests half its side above the ground's top face";
  EXPECT_NEAR(p.x(), 0.0, 1e-6);
  EXPECT_NEAR(p.y(), 0.0, 1e-6);
  EXPECT_LT(cube->getBodyNode(0)->getLinearVelocity().norm(), 1e-2);
#endif
}

}  // namespace
