// gq against the FCL reference checker (fcl::Convex on the same hulls, same allowed-collision matrix) on 10,000
// random configurations per robot in hull mode. Every disagreeing link pair is settled by the exact long double
// separating-axis test and listed; gq must be right on each unless the pair is within a rounding tolerance of
// touching.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <iterator>

#include "exact_polytope.h"
#include "gq/urdf/fcl_checker.h"
#include "robot_paths.h"

namespace gq::urdf::test {
namespace {

// Pairs this close to touching (m, robots are ~1 m) may be called either way by rounding: float carries
// ~1e-7 relative, GJK stops at its own tolerance.
template <class T> constexpr double kTouchingTolerance = std::is_same_v<T, float> ? 1e-5 : 1e-9;

// Exact gap of a link pair: the smallest SAT gap over its shape pairs (<= 0: the links collide).
LD exactLinkGap(const RobotModel<double>& m, const std::vector<double>& q, const LinkPair& pair) {
  std::vector<Transform<double>> poses;
  EXPECT_TRUE(forwardKinematics(m, q, poses).ok());
  LD gap = std::numeric_limits<LD>::infinity();
  for (std::uint32_t sa : m.links[pair.a].shapes)
    for (std::uint32_t sb : m.links[pair.b].shapes) {
      Polytope pa, pb;
      const bool ok = worldPolytope(m.shapes[sa], poses[pair.a] * m.shapes[sa].origin, pa) &&
                      worldPolytope(m.shapes[sb], poses[pair.b] * m.shapes[sb].origin, pb);
      EXPECT_TRUE(ok) << "hull mode of this robot has only polytopes";
      if (ok) gap = std::min(gap, satGap(pa, pb));
    }
  return gap;
}

struct Disagreement {
  std::size_t configuration;
  LinkPair pair;
  bool gqSays;
  LD exactGap;
};

template <class T> class FclAgreement : public ::testing::Test {};
TYPED_TEST_SUITE(FclAgreement, Scalars);

template <class T> void compareOnRandomConfigurations(const RobotFiles& robot, std::size_t count) {
  const auto gqModel = loadCached<T>(robot, Representation::Hull);
  const auto refModel = loadCached<double>(robot, Representation::Hull);
  std::unique_ptr<FclSelfCollisionChecker> fcl;
  ASSERT_TRUE(FclSelfCollisionChecker::create(refModel, fcl).ok());
  SelfCollisionChecker<T> gq(gqModel);
  std::uint64_t rng = 2024;
  std::vector<Disagreement> disagreements;
  std::size_t collidingConfigurations = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const std::vector<double> q = randomConfiguration(*refModel, rng);
    CollisionResult a, b;
    ASSERT_TRUE(gq.checkSelfCollision(castConfiguration<T>(q), a).ok());
    ASSERT_TRUE(fcl->checkSelfCollision(q, b).ok());
    collidingConfigurations += b.colliding;
    std::vector<LinkPair> onlyGq, onlyFcl;
    std::set_difference(a.pairs.begin(), a.pairs.end(), b.pairs.begin(), b.pairs.end(), std::back_inserter(onlyGq));
    std::set_difference(b.pairs.begin(), b.pairs.end(), a.pairs.begin(), a.pairs.end(), std::back_inserter(onlyFcl));
    for (const auto& p : onlyGq) disagreements.push_back({k, p, true, exactLinkGap(*refModel, q, p)});
    for (const auto& p : onlyFcl) disagreements.push_back({k, p, false, exactLinkGap(*refModel, q, p)});
  }
  std::printf("[%s, %s] %zu configurations, %zu colliding (FCL), %zu disagreements\n", robot.name,
              std::is_same_v<T, float> ? "float" : "double", count, collidingConfigurations, disagreements.size());
  EXPECT_GT(collidingConfigurations, count / 100) << "the sample must exercise collisions";
  for (const auto& d : disagreements) {
    const bool exactSays = d.exactGap <= 0;
    std::printf("  config %zu %s - %s: gq %s, FCL %s, exact SAT gap %.3Le m -> %s right\n", d.configuration,
                refModel->links[d.pair.a].name.c_str(), refModel->links[d.pair.b].name.c_str(),
                d.gqSays ? "collides" : "free", d.gqSays ? "free" : "collides", d.exactGap,
                d.gqSays == exactSays ? "gq" : "FCL");
    EXPECT_TRUE(d.gqSays == exactSays || std::abs(double(d.exactGap)) <= kTouchingTolerance<T>)
        << "gq is wrong by " << double(d.exactGap) << " m on configuration " << d.configuration;
  }
}

TYPED_TEST(FclAgreement, PandaHullModeAgreesWithFclOnTenThousandRandomConfigurations) {
  compareOnRandomConfigurations<TypeParam>(kPanda, 10000);
}

TYPED_TEST(FclAgreement, Ur5HullModeAgreesWithFclOnTenThousandRandomConfigurations) {
  compareOnRandomConfigurations<TypeParam>(kUr5, 10000);
}

}  // namespace
}  // namespace gq::urdf::test
