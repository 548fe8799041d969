// A DART program that picks its collision detector by name only: `switch_by_name [gq|bullet|fcl|dart]` (default
// DETECTOR_NAME, "gq" unless the build defines it).
// It drops a sphere and a box on a ground box, steps the world for two seconds, then casts a ray down through the
// sphere. It names no gq symbol: linking gq::dart is what makes the factory know "gq".
// Exit status 0 when both bodies rest on the ground and (for detectors that raycast) the ray hits the sphere's top.
#include <cmath>
#include <cstdio>
#include <string>

#include <dart/collision/CollisionDetector.hpp>
#include <dart/collision/CollisionGroup.hpp>
#include <dart/collision/RaycastResult.hpp>
#include <dart/constraint/ConstraintSolver.hpp>
#include <dart/dynamics/BoxShape.hpp>
#include <dart/dynamics/FreeJoint.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/dynamics/SphereShape.hpp>
#include <dart/dynamics/WeldJoint.hpp>
#include <dart/simulation/World.hpp>

#ifndef DETECTOR_NAME
#define DETECTOR_NAME "gq"
#endif

namespace dd = dart::dynamics;

static dd::SkeletonPtr body(const std::string& name, const dd::ShapePtr& shape, const Eigen::Vector3d& at,
                            bool fixed) {
  auto skeleton = dd::Skeleton::create(name);
  dd::BodyNode* node = nullptr;
  if (fixed) {
    node = skeleton->createJointAndBodyNodePair<dd::WeldJoint>().second;
    Eigen::Isometry3d tf = Eigen::Isometry3d::Identity();
    tf.translation() = at;
    node->getParentJoint()->setTransformFromParentBodyNode(tf);
  } else {
    node = skeleton->createJointAndBodyNodePair<dd::FreeJoint>().second;
    Eigen::Isometry3d tf = Eigen::Isometry3d::Identity();
    tf.translation() = at;
    dd::FreeJoint::setTransformOf(node, tf);
  }
  node->createShapeNodeWith<dd::CollisionAspect, dd::DynamicsAspect>(shape);
  dd::Inertia inertia;
  inertia.setMass(1.0);
  inertia.setMoment(shape->computeInertia(1.0));
  node->setInertia(inertia);
  return skeleton;
}

int main(int argc, char** argv) {
  const std::string name = argc > 1 ? argv[1] : DETECTOR_NAME;
  auto detector = dart::collision::CollisionDetector::getFactory()->create(name);
  if (!detector) {
    std::printf("no collision detector named '%s'\n", name.c_str());
    return 1;
  }
  auto world = dart::simulation::World::create();
  world->setTimeStep(0.001);
  world->getConstraintSolver()->setCollisionDetector(detector);
  world->addSkeleton(body("ground", std::make_shared<dd::BoxShape>(Eigen::Vector3d(4, 4, 0.2)),
                          Eigen::Vector3d(0, 0, -0.1), true));
  auto ball = body("ball", std::make_shared<dd::SphereShape>(0.1), Eigen::Vector3d(0, 0, 0.5), false);
  auto crate = body("crate", std::make_shared<dd::BoxShape>(Eigen::Vector3d(0.2, 0.2, 0.2)),
                    Eigen::Vector3d(0.5, 0, 0.4), false);
  world->addSkeleton(ball);
  world->addSkeleton(crate);
  for (int i = 0; i < 2000; ++i) world->step();

  const double ballZ = ball->getBodyNode(0)->getWorldTransform().translation().z();
  const double crateZ = crate->getBodyNode(0)->getWorldTransform().translation().z();
  std::printf("detector %s: ball z %.4f, crate z %.4f\n", detector->getType().c_str(), ballZ, crateZ);
  bool ok = std::abs(ballZ - 0.1) < 0.01 && std::abs(crateZ - 0.1) < 0.01;

  auto group = world->getConstraintSolver()->getCollisionGroup();
  dart::collision::RaycastResult ray;
  const Eigen::Vector3d from(0, 0, 2), to(0, 0, -1);
  if (detector->raycast(group.get(), from, to, dart::collision::RaycastOption(), &ray) && ray.hasHit()) {
    const Eigen::Vector3d hit = ray.mRayHits.front().mPoint;
    std::printf("ray hit at z %.4f (fraction %.4f)\n", hit.z(), ray.mRayHits.front().mFraction);
    ok = ok && std::abs(hit.z() - (ballZ + 0.1)) < 0.01;
  } else if (name == "gq" || name == "bullet") {
    std::printf("the ray missed\n");
    ok = false;
  } else {
    std::printf("no raycast with detector %s\n", name.c_str());
  }
  return ok ? 0 : 1;
}
