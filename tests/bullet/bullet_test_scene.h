#pragma once
// Test worlds built the same way with stock Bullet and with gq (only the construction lines differ).
#include <memory>
#include <vector>

#include <btBulletDynamicsCommon.h>
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>

#include "gq/bullet/collision_configuration.h"
#include "gq/bullet/collision_world.h"

namespace gq::bullet::test {

enum class Backend { Bullet, Gq };
inline const char* name(Backend b) { return b == Backend::Bullet ? "bullet" : "gq"; }

class TestWorld {
 public:
  explicit TestWorld(Backend backend) : backend_(backend) {
    if (backend == Backend::Gq) {
      config_ = std::make_unique<CollisionConfiguration>();
      dispatcher_ = std::make_unique<CollisionDispatcher>(config_.get());
    } else {
      config_ = std::make_unique<btDefaultCollisionConfiguration>();
      dispatcher_ = std::make_unique<btCollisionDispatcher>(config_.get());
    }
    broadphase_ = std::make_unique<btDbvtBroadphase>();
    solver_ = std::make_unique<btSequentialImpulseConstraintSolver>();
    if (backend == Backend::Gq)
      world_ = std::make_unique<DiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                        config_.get());
    else
      world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(), solver_.get(),
                                                          config_.get());
    world_->setGravity(btVector3(0, -10, 0));
  }
  ~TestWorld() {
    for (auto& b : bodies_) world_->removeRigidBody(b.get());
  }
  TestWorld(const TestWorld&) = delete;
  TestWorld& operator=(const TestWorld&) = delete;

  // Adds a body (mass 0: static) at `origin` with rotation `rotation`; the shape stays owned by the caller.
  btRigidBody* add(btCollisionShape* shape, btScalar mass, const btVector3& origin,
                   const btQuaternion& rotation = btQuaternion::getIdentity()) {
    btVector3 inertia(0, 0, 0);
    if (mass > 0) shape->calculateLocalInertia(mass, inertia);
    states_.push_back(std::make_unique<btDefaultMotionState>(btTransform(rotation, origin)));
    btRigidBody::btRigidBodyConstructionInfo info(mass, states_.back().get(), shape, inertia);
    bodies_.push_back(std::make_unique<btRigidBody>(info));
    world_->addRigidBody(bodies_.back().get());
    return bodies_.back().get();
  }
  void step(int steps) {
    for (int i = 0; i < steps; ++i) world_->stepSimulation(btScalar(1) / 60, 10);
  }
  btDiscreteDynamicsWorld& world() { return *world_; }
  Backend backend() const { return backend_; }
  // The gq world's query entry points (convexSweepTest is not virtual in Bullet).
  void convexSweepTest(const btConvexShape* shape, const btTransform& from, const btTransform& to,
                       btCollisionWorld::ConvexResultCallback& cb) {
    if (backend_ == Backend::Gq)
      static_cast<DiscreteDynamicsWorld&>(*world_).convexSweepTest(shape, from, to, cb);
    else
      world_->convexSweepTest(shape, from, to, cb);
  }

 private:
  Backend backend_;
  std::unique_ptr<btCollisionConfiguration> config_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btBroadphaseInterface> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::vector<std::unique_ptr<btDefaultMotionState>> states_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
};

// Shapes shared by the stock and gq worlds of a test.
struct ShapeStore {
  std::vector<std::unique_ptr<btTriangleMesh>> meshes;          // declared first: outlive the shapes
  std::vector<std::unique_ptr<std::vector<float>>> heights;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  template <class S, class... A> S* make(A&&... args) {
    auto s = std::make_unique<S>(std::forward<A>(args)...);
    S* raw = s.get();
    shapes.push_back(std::move(s));
    return raw;
  }
};

// A flat grid of (n-1)^2 quads over [-half, half]^2 at height y, as a BVH triangle mesh.
inline btBvhTriangleMeshShape* flatMesh(ShapeStore& store, int n, btScalar half, btScalar y) {
  auto mesh = std::make_unique<btTriangleMesh>();
  const btScalar step = 2 * half / btScalar(n - 1);
  auto at = [&](int i, int j) { return btVector3(-half + step * btScalar(i), y, -half + step * btScalar(j)); };
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      mesh->addTriangle(at(i, j), at(i, j + 1), at(i + 1, j));
      mesh->addTriangle(at(i + 1, j), at(i, j + 1), at(i + 1, j + 1));
    }
  btTriangleMesh* raw = mesh.get();
  store.meshes.push_back(std::move(mesh));
  return store.make<btBvhTriangleMeshShape>(raw, true);
}

// An n x n heightfield (Y up, unit spacing) of the given heights with Bullet's centring range [minH, maxH].
inline btHeightfieldTerrainShape* heightField(ShapeStore& store, int n, std::vector<float> h, btScalar minH,
                                              btScalar maxH) {
  store.heights.push_back(std::make_unique<std::vector<float>>(std::move(h)));
  return store.make<btHeightfieldTerrainShape>(n, n, store.heights.back()->data(), minH, maxH, 1, false);
}

// A convex hull with the 8 corners of the cube [-a, a]^3 (margin outside, Bullet's default 0.04).
inline btConvexHullShape* cubeHull(ShapeStore& store, btScalar a) {
  auto* hull = store.make<btConvexHullShape>();
  for (int i = 0; i < 8; ++i)
    hull->addPoint(btVector3(i & 1 ? a : -a, i & 2 ? a : -a, i & 4 ? a : -a), i == 7);
  return hull;
}

}  // namespace gq::bullet::test
