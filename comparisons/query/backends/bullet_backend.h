#pragma once
// The Bullet 3.24 backend, built twice: gq-query-bullet links the float libraries and answers "float" cases,
// gq-query-bullet64 links the float64 libraries (BT_USE_DOUBLE_PRECISION) and answers "double" cases; the other
// precision gives kBulletPrecisionUnsupported so `gq-query --backend bullet` can merge the two outputs.
//   overlap, penetration, distance: btGjkPairDetector + btGjkEpaPenetrationDepthSolver (convex shapes only);
//   raycast: btCollisionWorld::rayTestSingle (closest hit; anyHit answers the closest hit);
//   sweep: btCollisionWorld::objectQuerySingle (convex swept shape).
// Shapes: btSphereShape, btCapsuleShapeX (height = 2 halfHeight), btBoxShape, btStaticPlaneShape, btConvexHullShape,
// btBvhTriangleMeshShape, btHeightfieldTerrainShape (no holes), btCylinderShapeX, btConeShapeX. Margins are zero
// except for spheres and capsules, whose margin is their radius by construction in Bullet (exact, not padding).
#include "backend.h"

namespace gq::cases {

inline constexpr const char* kBulletPrecisionUnsupported = "unsupported: precision ";

class BulletBackend final : public Backend {
 public:
  BulletBackend();
  ~BulletBackend() override;
  const char* name() const override { return "bullet"; }
  Result run(const Case& c, int repeat) override;

 private:
  struct Impl;
  Impl* impl_;
};

#ifdef GQ_HAVE_BULLET_ADAPTER
// "gq-bullet": the same Bullet shapes answered by gq through the Bullet adapter (gq::bullet / gq::bullet_double):
//   raycast: gq::bullet::CollisionWorld::rayTest; sweep: its convexSweepTest;
//   overlap, penetration, distance: contactPairTest with the adapter's closest-point algorithms (deepest point).
// Pairs the adapter leaves to Bullet (concave-concave, unmodelled shapes) are unsupported here.
class GqBulletBackend final : public Backend {
 public:
  GqBulletBackend();
  ~GqBulletBackend() override;
  const char* name() const override { return "gq-bullet"; }
  Result run(const Case& c, int repeat) override;

 private:
  struct Impl;
  Impl* impl_;
};
#endif

}  // namespace gq::cases
