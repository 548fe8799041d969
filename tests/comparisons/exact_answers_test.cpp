// The referee of gq-compare: the suites' exact answers (comparisons/suites/exact.h) against closed forms.
#include <cmath>

#include <gtest/gtest.h>

#include "exact.h"
#include "suite.h"

namespace gq::suites {
namespace {

Core boxCore(const V3& c, const V3& h) {
  Core core;
  for (int i = 0; i < 8; ++i)
    core.points.push_back(c + V3((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(), (i & 4) ? h.z() : -h.z()));
  return core;
}

TEST(ExactAnswers, SphereSphereSignedDistanceIsCentreDistanceMinusRadii) {
  const Core a{{V3(0, 0, 0)}, 0.5L}, b{{V3(1, 2, 2)}, 1.0L};
  EXPECT_NEAR(double(signedDistance(a, b)), 3.0 - 1.5, 1e-15);
  const Core c{{V3(0.1L, 0, 0)}, 1.0L};
  EXPECT_NEAR(double(signedDistance(a, c)), 0.1 - 1.5, 1e-15);
}

TEST(ExactAnswers, AlignedBoxPenetrationDepthIsTheSmallestAxisOverlap) {
  const Core a = boxCore(V3::Zero(), V3(1, 1, 1)), b = boxCore(V3(1.5L, 0.3L, 1.9L), V3(1, 1, 1));
  EXPECT_NEAR(double(signedDistance(a, b)), -0.1, 1e-15);  // overlaps 0.5, 1.7, 0.1: the z overlap is least
}

TEST(ExactAnswers, BoxesOnTheirDiagonalAreSeparatedByTheCornerGap) {
  // FCL bug fcl#545: unit boxes offset by (d, d, d) touch at corners; the gap is sqrt(3) (d - 2) once apart.
  const Core a = boxCore(V3::Zero(), V3(1, 1, 1)), b = boxCore(V3(2.5L, 2.5L, 2.5L), V3(1, 1, 1));
  EXPECT_NEAR(double(signedDistance(a, b)), std::sqrt(3.0) * 0.5, 1e-15);
  const Core c = boxCore(V3(1.5L, 1.5L, 1.5L), V3(1, 1, 1));
  EXPECT_NEAR(double(signedDistance(a, c)), -0.5, 1e-15);
}

TEST(ExactAnswers, RotatedBoxEdgeAgainstFaceUsesTheEdgeDepth) {
  // A unit cube turned 45 degrees about z, its edge pointing down at x = 0 onto a unit cube's top face.
  Core b;
  const Ld s = std::sqrt(Ld(2));
  for (const V3& p : boxCore(V3::Zero(), V3(1, 1, 1)).points) {
    const V3 r(p.x() / s - p.y() / s, p.x() / s + p.y() / s, p.z());
    b.points.push_back(V3(r.z(), r.y(), r.x()) + V3(0, 0, 1 + s - 0.25L));
  }
  EXPECT_NEAR(double(signedDistance(boxCore(V3::Zero(), V3(1, 1, 1)), b)), -0.25, 1e-15);
}

TEST(ExactAnswers, CapsulesCrossingAtRightAnglesAreApartByTheAxisGapMinusRadii) {
  const Core a{{V3(-1, 0, 0), V3(1, 0, 0)}, 0.2L}, b{{V3(0, -1, 1), V3(0, 1, 1)}, 0.3L};
  EXPECT_NEAR(double(signedDistance(a, b)), 0.5, 1e-15);
  const Core c{{V3(0, -1, 0.1L), V3(0, 1, 0.1L)}, 0.3L};  // axes 0.1 apart: the segments do not meet
  EXPECT_NEAR(double(signedDistance(a, c)), 0.1 - 0.5, 1e-15);
}

TEST(ExactAnswers, LibccdCylinderPairDepthIsFortyFiveHundredths) {
  std::vector<nlohmann::json> overlap, penetration, distance;
  addPairSuites(embeddedOptions(), overlap, penetration, distance);
  int found = 0;
  for (const auto& c : penetration)
    if (c["expect"]["group"] == "cylinders") {
      EXPECT_NEAR(c["expect"]["depth"].get<double>(), 0.45, 1e-15);
      ++found;
    }
  EXPECT_EQ(found, 2);  // float and double
}

TEST(ExactAnswers, RaysHitSolidsAtTheirClosedFormEntry) {
  const V3 o(-5, 0.6L, 0), d(1, 0, 0);
  EXPECT_NEAR(double(*rayHit(Core{{V3::Zero()}, 1}, o, d, 100)), 5 - std::sqrt(1 - 0.36), 1e-15);
  EXPECT_NEAR(double(*rayHit(boxCore(V3::Zero(), V3(1, 1, 1)), o, d, 100)), 4.0, 1e-15);
  EXPECT_FALSE(rayHit(boxCore(V3::Zero(), V3(1, 0.5L, 1)), o, d, 100).has_value());
  EXPECT_EQ(double(*rayHit(Core{{V3::Zero()}, 1}, V3(0.1L, 0, 0), d, 100)), 0.0);  // starts inside
  const Core capsule{{V3(0, -1, 0), V3(0, 1, 0)}, 0.5L};
  EXPECT_NEAR(double(*rayHit(capsule, V3(-5, 0.3L, 0), d, 100)), 4.5, 1e-15);
}

TEST(ExactAnswers, MeshRaysAreWatertightOnSharedEdgesAndCullBackFaces) {
  Placed mesh{ellipsoidMesh(V3d(1, 1, 1), 1), Pose{}};
  const TriangleSoup soup = soupOf(mesh);
  // Through the vertex (1,0,0) shared by four faces, and through the edge midpoint between two of them.
  EXPECT_NEAR(double(*rayHit(soup, V3(5, 0, 0), V3(-1, 0, 0), 100)), 4.0, 1e-15);
  const V3 mid = (V3(1, 0, 0) + V3(1, 0, 1).normalized()) / 2;  // a level-1 edge from the vertex (1,0,0)
  EXPECT_TRUE(rayHit(soup, 3 * mid, -mid.normalized(), 100).has_value());
  // From the centre outwards every triangle is a back face.
  EXPECT_FALSE(rayHit(soup, V3::Zero(), V3(1, 0, 0), 100).has_value());
}

// ---- sweeps ----------------------------------------------------------------------------------------------------

Placed placedAt(Shape shape, const V3d& p, const Eigen::Vector4d& q = Eigen::Vector4d(0, 0, 0, 1)) {
  Placed out;
  out.shape = std::move(shape);
  out.pose.p = p;
  out.pose.q = q;
  return out;
}

Shape sphereShape(double r) {
  Shape s;
  s.kind = Kind::Sphere;
  s.radius = r;
  return s;
}

Shape boxShape(const V3d& h) {
  Shape s;
  s.kind = Kind::Box;
  s.halfExtents = h;
  return s;
}

TEST(ExactSweeps, SphereSweptAtASphereHitsWhereTheCentresAreTheRadiiApart) {
  // |p0 + t d - p1| = r0 + r1 at the smaller root: t = b - sqrt(b^2 - |m|^2 + R^2), b = d.m, m = p1 - p0.
  const V3d p0(0, 0, 0), p1(5, 0.7, -0.4), d = V3d(1, 0.1, 0).normalized();
  const double r0 = 0.5, r1 = 0.8, big = r0 + r1;
  const V3d m = p1 - p0;
  const double b = d.dot(m), t = b - std::sqrt(b * b - m.squaredNorm() + big * big);
  const SweepToi toi = exactSweepToi(placedAt(sphereShape(r0), p0), placedAt(sphereShape(r1), p1), d, 10);
  ASSERT_TRUE(toi.hit);
  EXPECT_NEAR(double(toi.distance), t, 1e-13);
  EXPECT_FALSE(exactSweepToi(placedAt(sphereShape(r0), p0), placedAt(sphereShape(r1), p1), d, 0.9 * t).hit);
  // Aimed sideways: passes by at distance |m x d| - R.
  const V3d side = V3d(1, 0.6, 0).normalized();
  const SweepToi miss = exactSweepToi(placedAt(sphereShape(r0), p0), placedAt(sphereShape(r1), p1), side, 10);
  EXPECT_FALSE(miss.hit);
  EXPECT_NEAR(double(miss.margin), m.cross(side).norm() - big, 1e-12);
}

TEST(ExactSweeps, BoxSweptAtABoxOnTheirCommonAxisHitsAtTheFaceGap) {
  const SweepToi toi = exactSweepToi(placedAt(boxShape(V3d(0.5, 0.5, 0.5)), V3d(0, 0, 0)),
                                     placedAt(boxShape(V3d(1, 2, 3)), V3d(4, 0.3, -0.2)), V3d(1, 0, 0), 10);
  ASSERT_TRUE(toi.hit);
  EXPECT_NEAR(double(toi.distance), 4 - 1 - 0.5, 1e-15);
  EXPECT_NEAR(double(toi.cosine), 1.0, 1e-15);
}

TEST(ExactSweeps, BoxTurnedOnItsEdgeHitsAFaceWhenTheEdgeArrives) {
  // A unit half-extent cube turned 45 degrees about z moves along +x towards a box whose face is at x = 3:
  // its leading edge is sqrt(2) ahead of its centre.
  const Eigen::Vector4d turn = axisAngle(V3d::UnitZ(), M_PI / 4);
  const SweepToi toi = exactSweepToi(placedAt(boxShape(V3d(1, 1, 1)), V3d(0, 0, 0), turn),
                                     placedAt(boxShape(V3d(1, 5, 5)), V3d(4, 0, 0)), V3d(1, 0, 0), 10);
  ASSERT_TRUE(toi.hit);
  EXPECT_NEAR(double(toi.distance), 3 - std::sqrt(2.0), 1e-14);
}

TEST(ExactSweeps, StartingInsideIsAHitAtZeroWithTheDepthAsMargin) {
  const SweepToi toi = exactSweepToi(placedAt(boxShape(V3d(1, 1, 1)), V3d(0, 0, 0)),
                                     placedAt(boxShape(V3d(1, 1, 1)), V3d(1.75, 0, 0)), V3d(0, 1, 0), 1);
  ASSERT_TRUE(toi.hit);
  EXPECT_EQ(double(toi.distance), 0.0);
  EXPECT_NEAR(double(toi.margin), 0.25, 1e-15);
}

TEST(ExactSweeps, SphereSweptDownOntoAPlaneHitsAtItsHeightMinusRadiusOverTheCosine) {
  Shape plane;
  plane.kind = Kind::Plane;
  // The plane x = 0 (normal +x) turned to normal +z: a rotation of -90 degrees about y.
  const Placed ground = placedAt(plane, V3d(0, 0, 0.5), axisAngle(V3d::UnitY(), -M_PI / 2));
  const V3d d = V3d(0.6, 0, -0.8);
  const SweepToi toi = exactSweepToi(placedAt(sphereShape(0.25), V3d(0, 0, 2.5)), ground, d, 10);
  ASSERT_TRUE(toi.hit);
  EXPECT_NEAR(double(toi.distance), (2.5 - 0.5 - 0.25) / 0.8, 1e-14);
  EXPECT_NEAR(double(toi.cosine), 0.8, 1e-15);
}

TEST(ExactAnswers, EverySuiteCaseCarriesAnExpectAndAFiniteScale) {
  for (const auto& suite : makeSuites(embeddedOptions())) {
    EXPECT_GT(suite.cases.size(), 20u) << suite.family;
    for (const auto& c : suite.cases) {
      ASSERT_TRUE(c.contains("expect")) << c["id"];
      EXPECT_TRUE(std::isfinite(c["expect"]["scale"].get<double>()));
      EXPECT_GT(c["expect"]["scale"].get<double>(), 0.0);
    }
  }
}

}  // namespace
}  // namespace gq::suites
