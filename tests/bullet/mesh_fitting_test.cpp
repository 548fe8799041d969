// CollisionConfiguration::meshFitting: a btGImpactMeshShape body answered by its gq::fitShape fit rests like the
// exact shape it is a mesh of.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include <BulletCollision/Gimpact/btGImpactShape.h>

#include "gq/bullet/collision_configuration.h"
#include "gq/bullet/collision_world.h"
#include "gq/cooking.h"
#include "shape_cache.h"

namespace gq::bullet::test {
namespace {

const btVector3 kHalf(0.5, 0.25, 0.4);

// The 12 triangles of a box of half extents kHalf, outward-facing.
struct BoxMesh {
  std::vector<btScalar> vertices;
  std::vector<int> indices{0, 2, 1, 1, 2, 3, 4, 5, 6, 5, 7, 6, 0, 1, 4, 1, 5, 4,
                           2, 6, 3, 3, 6, 7, 0, 4, 2, 2, 4, 6, 1, 3, 5, 3, 7, 5};
  btTriangleIndexVertexArray array;
  BoxMesh() {
    for (int i = 0; i < 8; ++i) {
      vertices.push_back((i & 1 ? 1 : -1) * kHalf.x());
      vertices.push_back((i & 2 ? 1 : -1) * kHalf.y());
      vertices.push_back((i & 4 ? 1 : -1) * kHalf.z());
    }
    array.addIndexedMesh(btIndexedMesh());
    btIndexedMesh& m = array.getIndexedMeshArray()[0];
    m.m_numTriangles = 12;
    m.m_triangleIndexBase = reinterpret_cast<const unsigned char*>(indices.data());
    m.m_triangleIndexStride = 3 * sizeof(int);
    m.m_numVertices = 8;
    m.m_vertexBase = reinterpret_cast<const unsigned char*>(vertices.data());
    m.m_vertexStride = 3 * sizeof(btScalar);
    m.m_vertexType = sizeof(btScalar) == sizeof(double) ? PHY_DOUBLE : PHY_FLOAT;
  }
};

// A gq world with the fitting settings given to its configuration, a static ground box with its top at y = 0,
// and one dynamic body of `shape` (inertia of the exact box) dropped from y = 1 turned about the vertical.
struct DropWorld {
  CollisionConfiguration config;
  CollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  DiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &config};
  btBoxShape groundShape{btVector3(5, 1, 5)};
  std::unique_ptr<btDefaultMotionState> groundState, bodyState;
  std::unique_ptr<btRigidBody> ground, body;

  DropWorld(btCollisionShape* shape, const FitOptions<double>* fitting) {
    config.meshFitting = fitting;
    world.setGravity(btVector3(0, -10, 0));
    groundState = std::make_unique<btDefaultMotionState>(btTransform(btQuaternion::getIdentity(), btVector3(0, -1, 0)));
    ground = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(0, groundState.get(), &groundShape));
    world.addRigidBody(ground.get());
    btVector3 inertia;
    btBoxShape(kHalf).calculateLocalInertia(1, inertia);
    bodyState = std::make_unique<btDefaultMotionState>(
        btTransform(btQuaternion(btVector3(0, 1, 0), btScalar(0.4)), btVector3(0, 1, 0)));
    body = std::make_unique<btRigidBody>(btRigidBody::btRigidBodyConstructionInfo(1, bodyState.get(), shape, inertia));
    world.addRigidBody(body.get());
  }
  ~DropWorld() {
    world.removeRigidBody(body.get());
    world.removeRigidBody(ground.get());
  }
  btTransform restAfter(int steps) {
    for (int i = 0; i < steps; ++i) world.stepSimulation(btScalar(1) / 60, 10);
    return body->getWorldTransform();
  }
};

TEST(BulletMeshFitting, GImpactBoxMeshRestsLikeTheExactBox) {
  btBoxShape exact(kHalf);
  DropWorld reference(&exact, nullptr);
  const btTransform expected = reference.restAfter(120);

  BoxMesh mesh;
  btGImpactMeshShape gimpact(&mesh.array);
  gimpact.updateBound();
  FitOptions<double> fitting;
  fitting.tolerance = 1e-3;
  fitting.contain = true;
  DropWorld fitted(&gimpact, &fitting);
  const btTransform rest = fitted.restAfter(120);

  // Resting on its face at the exact box's height (the solver's resting penetration is the same for both).
  EXPECT_NEAR(rest.getOrigin().y(), expected.getOrigin().y(), 1e-3);
  EXPECT_NEAR(rest.getOrigin().y(), kHalf.y(), 5e-3);
  EXPECT_NEAR(rest.getOrigin().x(), expected.getOrigin().x(), 1e-3);
  EXPECT_NEAR(rest.getOrigin().z(), expected.getOrigin().z(), 1e-3);
  EXPECT_GT(rest.getBasis().getColumn(1).y(), btScalar(0.9999));  // upright
  EXPECT_LT(fitted.body->getLinearVelocity().length(), btScalar(1e-2));
}

// Two GImpact meshes: Bullet's default configuration has no algorithm for a concave pair, so without the option
// (off by default) the box falls through the ground; with it both are fitted and the box rests on the ground.
TEST(BulletMeshFitting, GImpactPairCollidesOnlyWhenFittingIsOn) {
  BoxMesh mesh;
  btGImpactMeshShape box(&mesh.array);
  box.updateBound();
  BoxMesh groundMesh;
  btGImpactMeshShape ground(&groundMesh.array);
  ground.setLocalScaling(btVector3(10, 4, 10));  // half extents (5, 1, 5), like the ground box
  ground.updateBound();
  FitOptions<double> fitting;
  fitting.tolerance = 1e-3;
  fitting.contain = true;
  for (const FitOptions<double>* settings : {static_cast<const FitOptions<double>*>(nullptr), static_cast<const FitOptions<double>*>(&fitting)}) {
    DropWorld w(&box, settings);
    w.world.removeRigidBody(w.ground.get());
    w.ground->setCollisionShape(&ground);
    w.world.addRigidBody(w.ground.get());
    const btScalar y = w.restAfter(120).getOrigin().y();
    if (settings)
      EXPECT_NEAR(y, kHalf.y(), 5e-3);
    else
      EXPECT_LT(y, btScalar(-1));
  }
}

// A fit's hull part is handed to the hull cache as its btConvexHullShape's hull: the cache answers that very hull
// (no second qhull run) while the shape's points stay those vertices, and cooks its own once they change.
TEST(BulletHullCache, ASharedHullIsAnsweredUntilTheShapesPointsChange) {
  std::vector<V3> points;
  for (int i = 0; i < 8; ++i) points.emplace_back(i & 1 ? 1 : -1, i & 2 ? 2 : -2, i & 4 ? 3 : -3);
  points.emplace_back(0, 0, 0);  // inside: not a hull vertex
  std::shared_ptr<const ConvexMesh<Real>> cooked;
  ASSERT_TRUE(cookConvexMesh(points, cooked).ok());
  btConvexHullShape shape;
  for (const V3& v : cooked->vertices) shape.addPoint(toBt(v), false);
  shape.recalcLocalAabb();
  ASSERT_TRUE(shareHull(shape, cooked));
  std::shared_ptr<const ConvexMesh<Real>> answered;
  ASSERT_EQ(cachedHull(shape, answered), Support::Gq);
  EXPECT_EQ(answered, cooked);
  shape.addPoint(btVector3(0, 0, 4));
  ASSERT_EQ(cachedHull(shape, answered), Support::Gq);
  EXPECT_NE(answered, cooked);
  EXPECT_EQ(answered->vertices.size(), cooked->vertices.size() + 1);
  btConvexHullShape empty;
  EXPECT_FALSE(shareHull(empty, cooked));
  EXPECT_FALSE(shareHull(shape, nullptr));
}

}  // namespace
}  // namespace gq::bullet::test
