// The same scenes stepped 500 times (60 Hz) with stock Bullet and with gq: nothing falls through, the stack stands,
// bodies rest where the closed form puts them, and gq's final positions agree with stock Bullet's.
#include <gtest/gtest.h>

#include <cmath>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcherMt.h>
#include <LinearMath/btThreads.h>

#include "bullet_test_scene.h"

namespace gq::bullet::test {
namespace {

constexpr int kSteps = 500;
// Resting bodies sink by the solver's allowed penetration (a few mm): rest heights and positions hold within
// kRestTolerance (3% of the unit body size) of the closed form. Stock Bullet lets a landing capsule, hull or
// cylinder slide up to ~0.13 (one-point GJK contacts plus perturbation), which bounds the agreement tolerance.
// A ten-box stack creeps sideways in stock Bullet too (its top box ends ~0.05 off axis, in a direction set by
// round-off), so the stack's horizontal drift and its agreement have their own bounds.
constexpr btScalar kRestTolerance = btScalar(0.03);
constexpr btScalar kAgreementTolerance = btScalar(0.15);
constexpr btScalar kStackDrift = btScalar(0.12);
constexpr btScalar kStackAgreement = btScalar(0.2);

std::vector<btVector3> finalPositions(const std::vector<btRigidBody*>& bodies) {
  std::vector<btVector3> out;
  for (const btRigidBody* b : bodies) out.push_back(b->getWorldTransform().getOrigin());
  return out;
}

// Ten unit boxes stacked on a ground box, released touching.
std::vector<btVector3> boxStack(Backend backend, ShapeStore& store) {
  TestWorld w(backend);
  auto* ground = store.make<btBoxShape>(btVector3(20, 1, 20));
  auto* box = store.make<btBoxShape>(btVector3(0.5, 0.5, 0.5));
  w.add(ground, 0, btVector3(0, -1, 0));
  std::vector<btRigidBody*> boxes;
  for (int i = 0; i < 10; ++i) boxes.push_back(w.add(box, 1, btVector3(0, btScalar(0.5 + i), 0)));
  w.step(kSteps);
  return finalPositions(boxes);
}

TEST(BulletScenes, TenBoxStackStandsAndAgreesWithBullet) {
  ShapeStore store;
  const auto gq = boxStack(Backend::Gq, store);
  const auto bt = boxStack(Backend::Bullet, store);
  for (int i = 0; i < 10; ++i) {
    EXPECT_NEAR(gq[i].x(), 0, kStackDrift) << "box " << i;
    EXPECT_NEAR(gq[i].z(), 0, kStackDrift) << "box " << i;
    EXPECT_NEAR(gq[i].y(), 0.5 + i, kRestTolerance) << "box " << i;
    EXPECT_LT((gq[i] - bt[i]).length(), kStackAgreement) << "box " << i;
  }
}

enum class Surface { Mesh, HeightField };

// A sphere, a lying capsule, a hull cube and a cylinder dropped from 1 m onto a flat surface at y = 0.5 made of
// right triangles with 4 m legs. Each lands around the centre of a triangle's incircle (radius 1.17), clear of
// the internal edges: an edge struck first pushes sideways (Bullet's internal-edge effect, in both backends).
// Rest heights: 0.5 + radius (sphere, capsule), 0.5 + half size + margin (hull), 0.5 + half height (cylinder).
struct Drop {
  btVector3 start;
  btScalar restY;
};
std::vector<btVector3> dropScene(Backend backend, Surface surface, ShapeStore& store, std::vector<Drop>& drops) {
  TestWorld w(backend);
  if (surface == Surface::Mesh) {
    w.add(flatMesh(store, 6, 10, btScalar(0.5)), 0, btVector3(0, 0, 0));
  } else {
    // Heights 1 with the range [-1, 2]: Bullet centres the grid on height 0.5, so the surface lies at 0.5.
    btHeightfieldTerrainShape* field = heightField(store, 6, std::vector<float>(6 * 6, 1.0f), -1, 2);
    field->setLocalScaling(btVector3(4, 1, 4));
    w.add(field, 0, btVector3(0, 0, 0));
  }
  auto* sphere = store.make<btSphereShape>(btScalar(0.5));
  auto* capsule = store.make<btCapsuleShapeX>(btScalar(0.3), btScalar(1));
  auto* hull = cubeHull(store, btScalar(0.4));
  auto* cylinder = store.make<btCylinderShape>(btVector3(0.4, 0.6, 0.4));
  const btScalar r = btScalar(2 - std::sqrt(2.0)) * 2;  // incircle radius of the 4-4-4*sqrt(2) triangle
  drops = {{btVector3(-2 + r, 2, -2 + r), btScalar(1.0)},
           {btVector3(2 + r, 2, -2 + r), btScalar(0.8)},
           {btVector3(-6 + r, 2, 2 + r), btScalar(0.5 + 0.4 + 0.04)},
           {btVector3(2 + r, 2, 2 + r), btScalar(1.1)}};
  std::vector<btRigidBody*> bodies{w.add(sphere, 1, drops[0].start), w.add(capsule, 1, drops[1].start),
                                   w.add(hull, 1, drops[2].start), w.add(cylinder, 1, drops[3].start)};
  w.step(kSteps);
  return finalPositions(bodies);
}

void expectDropsRest(Surface surface) {
  ShapeStore store;
  std::vector<Drop> drops;
  const auto gq = dropScene(Backend::Gq, surface, store, drops);
  const auto bt = dropScene(Backend::Bullet, surface, store, drops);
  for (std::size_t i = 0; i < drops.size(); ++i) {
    EXPECT_GT(gq[i].y(), btScalar(0.5)) << "body " << i << " fell through";
    EXPECT_NEAR(gq[i].y(), drops[i].restY, kRestTolerance) << "body " << i;
    EXPECT_NEAR(gq[i].x(), drops[i].start.x(), kRestTolerance) << "body " << i;
    EXPECT_NEAR(gq[i].z(), drops[i].start.z(), kRestTolerance) << "body " << i;
    EXPECT_LT((gq[i] - bt[i]).length(), kAgreementTolerance)
        << "body " << i << " gq " << gq[i].x() << " " << gq[i].y() << " " << gq[i].z() << " bullet " << bt[i].x()
        << " " << bt[i].y() << " " << bt[i].z();
  }
}

TEST(BulletScenes, BodiesDroppedOnBvhMeshRestAndAgreeWithBullet) { expectDropsRest(Surface::Mesh); }
TEST(BulletScenes, BodiesDroppedOnHeightFieldRestAndAgreeWithBullet) { expectDropsRest(Surface::HeightField); }

// A sphere dropped next to the internal edges of a fine flat grid (1 m triangles, radius 0.5): the edges of the
// neighbouring triangles must not push it sideways (stock Bullet sends this sphere rolling ~5 m; not asserted).
TEST(BulletScenes, SphereLandingNearInternalEdgesStaysPut) {
  for (Surface surface : {Surface::Mesh, Surface::HeightField}) {
    ShapeStore store;
    TestWorld w(Backend::Gq);
    if (surface == Surface::Mesh) {
      w.add(flatMesh(store, 21, 10, btScalar(0.5)), 0, btVector3(0, 0, 0));
    } else {
      btHeightfieldTerrainShape* field = heightField(store, 21, std::vector<float>(21 * 21, 1.0f), -1, 2);
      w.add(field, 0, btVector3(0, 0, 0));
    }
    btRigidBody* ball = w.add(store.make<btSphereShape>(btScalar(0.5)), 1, btVector3(-3.1, 2.5, 0.3));
    w.step(kSteps);
    const btVector3 p = ball->getWorldTransform().getOrigin();
    EXPECT_NEAR(p.x(), -3.1, kRestTolerance) << (surface == Surface::Mesh ? "mesh" : "heightfield");
    EXPECT_NEAR(p.z(), 0.3, kRestTolerance);
    EXPECT_NEAR(p.y(), 1.0, kRestTolerance);
  }
}

// btCollisionDispatcherMt over the gq configuration: same stack, same answer.
TEST(BulletScenes, StackStandsUnderCollisionDispatcherMt) {
  btSetTaskScheduler(btGetSequentialTaskScheduler());  // btCollisionDispatcherMt sizes its batches from it
  CollisionConfiguration config;
  btCollisionDispatcherMt dispatcher(&config);
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  world.setGravity(btVector3(0, -10, 0));
  btBoxShape ground(btVector3(20, 1, 20)), box(btVector3(0.5, 0.5, 0.5));
  std::vector<std::unique_ptr<btDefaultMotionState>> states;
  std::vector<std::unique_ptr<btRigidBody>> bodies;
  auto add = [&](btCollisionShape* shape, btScalar mass, btScalar y) {
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(mass, inertia);
    states.push_back(std::make_unique<btDefaultMotionState>(btTransform(btQuaternion::getIdentity(),
                                                                        btVector3(0, y, 0))));
    bodies.push_back(std::make_unique<btRigidBody>(
        btRigidBody::btRigidBodyConstructionInfo(mass, states.back().get(), shape, inertia)));
    world.addRigidBody(bodies.back().get());
  };
  add(&ground, 0, -1);
  for (int i = 0; i < 5; ++i) add(&box, 1, btScalar(0.5 + i));
  for (int i = 0; i < kSteps; ++i) world.stepSimulation(btScalar(1) / 60, 10);
  for (int i = 0; i < 5; ++i)
    EXPECT_NEAR(bodies[std::size_t(i) + 1]->getWorldTransform().getOrigin().y(), 0.5 + i, kRestTolerance);
  for (auto& b : bodies) world.removeRigidBody(b.get());
}

}  // namespace
}  // namespace gq::bullet::test
