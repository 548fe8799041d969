// The ball certificate of hull pairs (overlap/convex_convex.cpp) also runs before GJK for sphere, capsule and box
// against a hull: on seeded poses the public overlap answers as GJK with its exact band does alone, and the
// certificate decides a good share of the poses both ways.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "gq/cooking.h"
#include "gq/query.h"
#include "overlap/overlap.h"
#include "overlap/polytope.h"

namespace {

using namespace gq;

template <class T> struct OverlapConvexBalls : ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(OverlapConvexBalls, Scalars);

template <class T, class G>
void expectSameAsWithoutBalls(const G& shape, const ConvexMeshGeometry<T>& hull, std::mt19937_64& gen, int& apart,
                              int& overlapping) {
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> reach(0.0, 2.5);
  for (int i = 0; i < 400; ++i) {
    const Quat<T> q0 = Eigen::Quaterniond(n(gen), n(gen), n(gen), n(gen)).normalized().cast<T>();
    const Quat<T> q1 = Eigen::Quaterniond(n(gen), n(gen), n(gen), n(gen)).normalized().cast<T>();
    const Vec3<T> p0(T(n(gen)), T(n(gen)), T(n(gen)));
    const Vec3<T> p1 = p0 + T(reach(gen)) * Vec3<T>(T(n(gen)), T(n(gen)), T(n(gen))).normalized();
    const Transform<T> pose0(p0, q0), pose1(p1, q1);
    bool got = false;
    ASSERT_TRUE(overlap<T>(shape, pose0, hull, pose1, got).ok());
    const bool alone = detail::overlapConvexShapes(Geometry<T>(shape), pose0, Geometry<T>(hull), pose1);
    EXPECT_EQ(got, alone) << i;
    switch (detail::hullBallsCertificate(detail::hullBalls(shape, pose0), detail::hullBalls(hull, pose1))) {
      case detail::OverlapCertificate::Apart: ++apart; break;
      case detail::OverlapCertificate::Overlapping: ++overlapping; break;
      case detail::OverlapCertificate::Unknown: break;
    }
  }
}

TYPED_TEST(OverlapConvexBalls, SphereCapsuleAndBoxPairsDecideAsGjkAloneDoes) {
  using T = TypeParam;
  std::mt19937_64 gen(17);
  std::normal_distribution<double> n;
  std::vector<Vec3<T>> points;
  for (int i = 0; i < 30; ++i)
    points.push_back(Vec3<T>(T(0.8 * n(gen)), T(0.6 * n(gen)), T(0.5 * n(gen))).normalized() * T(0.7));
  std::shared_ptr<const ConvexMesh<T>> cooked;
  ASSERT_TRUE(cookConvexMesh(points, cooked).ok());
  const ConvexMeshGeometry<T> hull(cooked, MeshScale<T>(Vec3<T>(T(1.2), T(0.9), T(1)), Quat<T>(Eigen::AngleAxis<T>(T(0.4), Vec3<T>::UnitZ()))));
  int apart = 0, overlapping = 0;
  expectSameAsWithoutBalls<T>(SphereGeometry<T>(T(0.4)), hull, gen, apart, overlapping);
  expectSameAsWithoutBalls<T>(CapsuleGeometry<T>(T(0.3), T(0.5)), hull, gen, apart, overlapping);
  expectSameAsWithoutBalls<T>(BoxGeometry<T>(T(0.3), T(0.4), T(0.5)), hull, gen, apart, overlapping);
  EXPECT_GT(apart, 200);  // of 1,200 poses
  EXPECT_GT(overlapping, 100);
}

}  // namespace
