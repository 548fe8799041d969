// Normals and directions are unit vectors (the spec's PxGeometryQuery outputs) also when they come from float
// offsets of ~1e-20, whose squared length is subnormal and keeps only a few bits: d / sqrt(|d|^2) was off by
// percents there (fuzz_pair_queries found it in ball distances, then in sphere/capsule penetration). Each test puts
// one kernel's normalised difference in that range.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "gq/cooking.h"
#include "gq/query.h"

namespace {

using V = gq::Vec3<float>;
using Pose = gq::Transform<float>;
constexpr float kTiny = 2e-22f;  // kTiny^2 = 4e-44: 28 units of the smallest float subnormal

void expectUnit(const V& n) { EXPECT_NEAR(n.norm(), 1.0f, 1e-5f) << n.transpose(); }

gq::PenetrationResult<float> penetration(const gq::Geometry<float>& g0, const Pose& p0, const gq::Geometry<float>& g1,
                                         const Pose& p1) {
  gq::PenetrationResult<float> r;
  EXPECT_TRUE(gq::computePenetration(r, g0, p0, g1, p1).ok());
  EXPECT_TRUE(r.penetrating);
  return r;
}

TEST(UnitNormalsFromTinyOffsets, SphereCentreNextToACapsuleAxisPushesAlongAUnitDirection) {
  const gq::SphereGeometry<float> sphere(0.2f);
  const gq::CapsuleGeometry<float> capsule(0.3f, 1.0f);
  const auto r = penetration(sphere, Pose(V(0.1f, kTiny, 0.0f)), capsule, Pose());
  expectUnit(r.direction);
  EXPECT_GT(r.direction.y(), 0.99f);  // away from the axis
}

TEST(UnitNormalsFromTinyOffsets, ParallelCapsuleAxesApartByATinyOffsetPushAlongAUnitDirection) {
  const gq::CapsuleGeometry<float> capsule(0.3f, 1.0f);
  const auto r = penetration(capsule, Pose(V(0.0f, kTiny, 0.0f)), capsule, Pose());
  expectUnit(r.direction);
}

TEST(UnitNormalsFromTinyOffsets, SphereCentreJustOutsideABoxFacePushesAlongAUnitDirection) {
  const gq::SphereGeometry<float> sphere(0.5f);
  const gq::BoxGeometry<float> slab(1e-19f, 1.0f, 1.0f);  // centre at x = 1e-19 + kTiny lies kTiny outside
  const auto r = penetration(sphere, Pose(V(1e-19f + kTiny, 0.0f, 0.0f)), slab, Pose());
  expectUnit(r.direction);
  EXPECT_GT(r.direction.x(), 0.99f);
}

TEST(UnitNormalsFromTinyOffsets, CapsuleJustAboveATriangleMeshPushesAlongAUnitDirection) {
  const std::vector<V> points = {V(-1, -1, 0), V(1, -1, 0), V(1, 1, 0), V(-1, 1, 0)};
  const std::vector<std::array<std::uint32_t, 3>> triangles = {{0, 1, 2}, {0, 2, 3}};
  std::shared_ptr<const gq::TriangleMesh<float>> mesh;
  ASSERT_TRUE(gq::cookTriangleMesh(points, triangles, mesh).ok());
  const gq::CapsuleGeometry<float> capsule(0.25f, 0.5f);
  const auto r = penetration(capsule, Pose(V(0.1f, 0.2f, kTiny)), gq::TriangleMeshGeometry<float>(mesh), Pose());
  expectUnit(r.direction);
  EXPECT_GT(r.direction.z(), 0.99f);  // out of the front face
  EXPECT_NEAR(r.depth, 0.25f, 1e-6f);
}

TEST(UnitNormalsFromTinyOffsets, ClosestPointOnATinySphereLiesOnItsSurface) {
  const float radius = 1e-22f;
  gq::PointDistanceResult<float> d;
  ASSERT_TRUE(gq::pointDistance(V(2.5e-22f, 0.0f, 0.0f), gq::Geometry<float>(gq::SphereGeometry<float>(radius)), Pose(), d).ok());
  EXPECT_NEAR(d.closestPoint.x(), radius, 1e-5f * radius);
}

TEST(UnitNormalsFromTinyOffsets, ClosestPointOnATinyCapsuleLiesOnItsSurface) {
  const float radius = 1e-22f;
  gq::PointDistanceResult<float> d;
  ASSERT_TRUE(gq::pointDistance(V(0.0f, 2.5e-22f, 0.0f), gq::Geometry<float>(gq::CapsuleGeometry<float>(radius, 1.0f)), Pose(), d).ok());
  EXPECT_NEAR(d.closestPoint.y(), radius, 1e-5f * radius);
}

TEST(UnitNormalsFromTinyOffsets, RayHitsOnTinySpheresAndCapsulesHaveUnitNormals) {
  const float radius = 1e-22f;
  const V origin(-5e-22f, 0.0f, 0.0f);
  for (const gq::Geometry<float>& g :
       {gq::Geometry<float>(gq::SphereGeometry<float>(radius)), gq::Geometry<float>(gq::CapsuleGeometry<float>(radius, 1e-22f))}) {
    gq::RaycastHit<float> hit;
    std::uint32_t count = 0;
    ASSERT_TRUE(gq::raycast(origin, V(1, 0, 0), g, Pose(), 1.0f, gq::kDefaultHitFlags, 1, &hit, count).ok());
    ASSERT_EQ(count, 1u);
    expectUnit(hit.normal);
  }
}

TEST(UnitNormalsFromTinyOffsets, InitiallyOverlappingSphereSweepHasAUnitMtdNormal) {
  const gq::Geometry<float> sphere = gq::SphereGeometry<float>(0.5f);
  gq::SweepHit<float> hit;
  bool hasHit = false;
  ASSERT_TRUE(gq::sweep(V(1, 0, 0), 1.0f, sphere, Pose(V(0.0f, kTiny, 0.0f)), sphere, Pose(), hit, hasHit,
                        gq::kDefaultHitFlags | gq::HitFlag::Mtd)
                  .ok());
  ASSERT_TRUE(hasHit);
  expectUnit(hit.normal);
}

}  // namespace
