// Two Convex decide overlap the same way through gq::fcl::collide (its cached hulls' ball certificate, inner-point
// certificate, GJK, exact band) and through core's gq::overlap (the same ball certificate, then GJK and the exact
// band): on seeded poses spanning apart, ball-decided, band and deep pairs.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

#include "gq/cooking.h"
#include "gq/fcl/fcl.h"
#include "gq/query.h"

namespace {

struct Hull {
  std::shared_ptr<const gq::ConvexMesh<double>> cooked;
  std::shared_ptr<::fcl::Convexd> fcl;
};

// The hull of `count` random points on an ellipsoid-ish shell, as gq cooks it and as an FCL Convex of its polygons.
Hull randomHull(int count, std::mt19937_64& gen) {
  std::normal_distribution<double> g;
  std::vector<gq::Vec3<double>> points;
  for (int i = 0; i < count; ++i)
    points.push_back(gq::Vec3<double>(0.7 * g(gen), 0.5 * g(gen), 0.3 * g(gen)).normalized() * 0.6);
  Hull h;
  EXPECT_TRUE(gq::cookConvexMesh(points, h.cooked).ok());
  auto vertices = std::make_shared<std::vector<::fcl::Vector3d>>(h.cooked->vertices.begin(), h.cooked->vertices.end());
  auto faces = std::make_shared<std::vector<int>>();
  for (const auto& p : h.cooked->polygons) {
    faces->push_back(int(p.indexCount));
    for (std::uint32_t k = 0; k < p.indexCount; ++k) faces->push_back(int(h.cooked->polygonVertices[p.indexBase + k]));
  }
  h.fcl = std::make_shared<::fcl::Convexd>(vertices, int(h.cooked->polygons.size()), faces);
  return h;
}

TEST(FclConvexDecisions, CollideDecidesAsCoreOverlapOnSeededPoses) {
  std::mt19937_64 gen(2026);
  std::normal_distribution<double> g;
  std::uniform_real_distribution<double> reach(0.0, 1.6);
  int overlapping = 0, total = 0;
  for (int pair = 0; pair < 8; ++pair) {
    const Hull a = randomHull(12 + 6 * pair, gen), b = randomHull(40 - 3 * pair, gen);
    ASSERT_TRUE(a.cooked && b.cooked);
    for (int i = 0; i < 250; ++i, ++total) {
      const Eigen::Quaterniond qa = Eigen::Quaterniond(g(gen), g(gen), g(gen), g(gen)).normalized();
      const Eigen::Quaterniond qb = Eigen::Quaterniond(g(gen), g(gen), g(gen), g(gen)).normalized();
      const gq::Vec3<double> pa(g(gen), g(gen), g(gen));
      const gq::Vec3<double> pb = pa + reach(gen) * gq::Vec3<double>(g(gen), g(gen), g(gen)).normalized();
      ::fcl::Transform3d ta = ::fcl::Transform3d::Identity(), tb = ta;
      ta.linear() = qa.toRotationMatrix();
      ta.translation() = pa;
      tb.linear() = qb.toRotationMatrix();
      tb.translation() = pb;
      ::fcl::CollisionRequestd request;
      ::fcl::CollisionResultd result;
      gq::fcl::collide<double>(a.fcl.get(), ta, b.fcl.get(), tb, request, result);
      bool core = false;
      ASSERT_TRUE(gq::overlap<double>(gq::ConvexMeshGeometry<double>(a.cooked), gq::Transform<double>(pa, qa),
                                      gq::ConvexMeshGeometry<double>(b.cooked), gq::Transform<double>(pb, qb), core)
                      .ok());
      EXPECT_EQ(result.isCollision(), core) << "pair " << pair << " pose " << i;
      overlapping += core;
    }
  }
  EXPECT_GT(overlapping, total / 5);  // both answers occur often
  EXPECT_LT(overlapping, total - total / 5);
}

}  // namespace
