// gq against the FCL reference checker (same model, forward kinematics and allowed-collision matrix; FCL's
// fcl::Convex for hulls, BVHModel<OBBRSS> for meshes, its own primitives and cylinders) on 10,000 random
// configurations per robot and mode. Every disagreeing link pair is settled by an independent long double referee
// (exact_polytope.h, exact_surfaces.h) and listed; gq must be right on each unless the pair is within a rounding
// tolerance of touching.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <iterator>

#include "exact_polytope.h"
#include "exact_surfaces.h"
#include "gq/urdf/fcl_checker.h"
#include "robot_paths.h"

namespace gq::urdf::test {
namespace {

// Pairs this close to touching (m, robots are ~1 m) may be called either way by rounding: float carries
// ~1e-7 relative, GJK stops at its own tolerance.
template <class T> constexpr double kTouchingTolerance = std::is_same_v<T, float> ? 1e-5 : 1e-9;

// Exact separation of two placed shapes: SAT for polytope pairs, triangle-pair SAT when a mesh is involved,
// projections for primitive solids.
Bracket exactShapeGap(const Shape<double>& a, const Transform<double>& pa, const Shape<double>& b,
                      const Transform<double>& pb) {
  const auto* meshA = a.geometry.getIf<TriangleMeshGeometry<double>>();
  const auto* meshB = b.geometry.getIf<TriangleMeshGeometry<double>>();
  if (meshA || meshB) {
    if (!meshA) return exactShapeGap(b, pb, a, pa);
    const WorldTriangles trianglesA = worldTriangles(*meshA->mesh, pa);
    std::vector<Polytope> piecesB;
    if (meshB) {
      piecesB = worldTriangles(*meshB->mesh, pb).triangles;
    } else {
      Polytope box;
      EXPECT_TRUE(worldPolytope(b, pb, box)) << "mesh mode pairs meshes with meshes or boxes";
      piecesB.push_back(box);
    }
    const LD gap = surfaceGap(trianglesA, piecesB);
    return {gap, gap};
  }
  Polytope polyA, polyB;
  if (worldPolytope(a, pa, polyA) && worldPolytope(b, pb, polyB)) {
    const LD gap = satGap(polyA, polyB);
    return {gap, gap};
  }
  Solid solidA, solidB;
  const bool ok = worldSolid(a, pa, solidA) && worldSolid(b, pb, solidB);
  EXPECT_TRUE(ok) << "no referee for " << toString(a.geometry.type()) << " - " << toString(b.geometry.type());
  return ok ? solidGap(solidA, solidB) : Bracket{};
}

// A link pair touches when any of its shape pairs does: the bracket of the closest shape pair.
Bracket exactLinkGap(const RobotModel<double>& m, const std::vector<double>& q, const LinkPair& pair) {
  std::vector<Transform<double>> poses;
  EXPECT_TRUE(forwardKinematics(m, q, poses).ok());
  Bracket best{std::numeric_limits<LD>::infinity(), std::numeric_limits<LD>::infinity()};
  for (std::uint32_t sa : m.links[pair.a].shapes)
    for (std::uint32_t sb : m.links[pair.b].shapes) {
      const Bracket g = exactShapeGap(m.shapes[sa], poses[pair.a] * m.shapes[sa].origin, m.shapes[sb],
                                      poses[pair.b] * m.shapes[sb].origin);
      best.lower = std::min(best.lower, g.lower);
      best.upper = std::min(best.upper, g.upper);
    }
  return best;
}

struct Disagreement {
  std::size_t configuration;
  LinkPair pair;
  bool gqSays;
  Bracket exact;
};

// On the real robots of the shared data folder (skipped when it does not hold them).
template <class T> class FclAgreementData : public RobotDataTest {};
TYPED_TEST_SUITE(FclAgreementData, Scalars);

template <class T> void compareOnRandomConfigurations(const RobotFiles& robot, Representation rep, std::size_t count) {
  const auto gqModel = loadCached<T>(robot, rep);
  ASSERT_TRUE(gqModel);
  const auto refModel = loadCached<double>(robot, rep);
  ASSERT_TRUE(refModel);
  std::unique_ptr<FclSelfCollisionChecker> fcl;
  const Status created = FclSelfCollisionChecker::create(refModel, fcl);
  ASSERT_TRUE(created.ok()) << created.toString();
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
  std::printf("[%s %s, %s] %zu configurations, %zu colliding (FCL), %zu disagreements\n", robot.name, toString(rep),
              std::is_same_v<T, float> ? "float" : "double", count, collidingConfigurations, disagreements.size());
  EXPECT_GT(collidingConfigurations, count / 100) << "the sample must exercise collisions";
  for (const auto& d : disagreements) {
    const bool decided = d.exact.provesContact() || d.exact.provesSeparation();
    const bool gqRight = decided && d.gqSays == d.exact.provesContact();
    std::printf("  config %zu %s - %s: gq %s, FCL %s, exact gap in [%.3Le, %.3Le] m -> %s\n", d.configuration,
                refModel->links[d.pair.a].name.c_str(), refModel->links[d.pair.b].name.c_str(),
                d.gqSays ? "collides" : "free", d.gqSays ? "free" : "collides", d.exact.lower, d.exact.upper,
                !decided ? "touching within rounding" : gqRight ? "gq right" : "FCL right");
    const bool nearTouching = std::max(std::abs(double(d.exact.lower)), std::abs(double(d.exact.upper))) <=
                                  kTouchingTolerance<T> ||
                              (!decided && double(d.exact.upper) <= kTouchingTolerance<T>);
    EXPECT_TRUE(gqRight || nearTouching) << "gq is wrong on configuration " << d.configuration;
  }
}

TYPED_TEST(FclAgreementData, PandaHullModeAgreesWithFclOnTenThousandRandomConfigurations) {
  compareOnRandomConfigurations<TypeParam>(kPanda, Representation::Hull, 10000);
}

TYPED_TEST(FclAgreementData, Ur5HullModeAgreesWithFclOnTenThousandRandomConfigurations) {
  compareOnRandomConfigurations<TypeParam>(kUr5, Representation::Hull, 10000);
}

// Exact triangle meshes (surfaces: a link inside another without crossing triangles is not a contact, in gq and FCL).
TYPED_TEST(FclAgreementData, PandaMeshModeAgreesWithFclOnTenThousandRandomConfigurations) {
  compareOnRandomConfigurations<TypeParam>(kPanda, Representation::Mesh, 10000);
}

TYPED_TEST(FclAgreementData, Ur5MeshModeAgreesWithFclOnTenThousandRandomConfigurations) {
  compareOnRandomConfigurations<TypeParam>(kUr5, Representation::Mesh, 10000);
}

// Panda's primitive URDF: spheres and exact cylinders (fcl::Cylinder on the FCL side).
TYPED_TEST(FclAgreementData, PandaPrimitiveUrdfAgreesWithFclOnTenThousandRandomConfigurations) {
  compareOnRandomConfigurations<TypeParam>(kPandaPrimitives, Representation::Hull, 10000);
}

TYPED_TEST(FclAgreementData, BestPrimitiveModeAgreesWithFclOnTenThousandRandomConfigurations) {
  compareOnRandomConfigurations<TypeParam>(kPanda, Representation::BestPrimitive, 10000);
  compareOnRandomConfigurations<TypeParam>(kUr5, Representation::BestPrimitive, 10000);
}

// The FCL checker's selfDistance (MoveIt's pre-seeded fcl::distance) and gq's agree on the clearance of
// collision-free configurations, hulls and meshes of Panda (the FCL checker is double only; FCL's GJK stops at its
// 1e-6 tolerance, so 1e-5 m). Where they disagree beyond it the test fails: no referee needed at that size.
class FclSelfDistanceData : public RobotDataTest {};

TEST_F(FclSelfDistanceData, ClearanceAgreesWithGqOnCollisionFreeConfigurations) {
  for (const Representation rep : {Representation::Hull, Representation::Mesh}) {
    const auto model = loadCached<double>(kPanda, rep);
    ASSERT_TRUE(model);
    std::unique_ptr<FclSelfCollisionChecker> fcl;
    ASSERT_TRUE(FclSelfCollisionChecker::create(model, fcl).ok());
    SelfCollisionChecker<double> gq(model);
    std::uint64_t rng = 23;
    int compared = 0;
    for (int i = 0; i < 60; ++i) {
      const std::vector<double> q = randomConfiguration(*model, rng);
      CollisionResult c;
      ASSERT_TRUE(gq.checkSelfCollision(q, c).ok());
      if (c.colliding) continue;
      SelfDistanceResult<double> a, b;
      ASSERT_TRUE(gq.selfDistance(q, a).ok());
      ASSERT_TRUE(fcl->selfDistance(q, b).ok());
      EXPECT_NEAR(a.distance, b.distance, 1e-5) << (rep == Representation::Hull ? "hull" : "mesh") << " configuration " << i;
      EXPECT_GT(b.distance, 0.0);
      ++compared;
    }
    EXPECT_GT(compared, 10);
  }
}

}  // namespace
}  // namespace gq::urdf::test
