// The long double referees of the FCL comparison (exact_polytope.h, exact_surfaces.h) against closed forms, so
// that a disagreement they settle is settled right.
#include <gtest/gtest.h>

#include "exact_surfaces.h"

namespace gq::urdf::test {
namespace {

Solid cylinderAlongX(LD radius, LD halfHeight, const Vec3L& centre, const Mat3<LD>& r = Mat3<LD>::Identity()) {
  Solid s;
  s.kind = Solid::Kind::Cylinder;
  s.radius = radius;
  s.halfHeight = halfHeight;
  s.t = centre;
  s.r = r;
  return s;
}

TEST(Referees, ParallelCylindersSideBySideAreTheirAxisDistanceMinusBothRadiiApart) {
  const Solid a = cylinderAlongX(0.1L, 0.3L, Vec3L(0, 0, 0)), b = cylinderAlongX(0.05L, 0.2L, Vec3L(0.1L, 0.2L, 0));
  const Bracket g = solidGap(a, b);
  EXPECT_NEAR(double(g.lower), 0.05, 1e-12);  // 0.2 - 0.1 - 0.05
  EXPECT_NEAR(double(g.upper), 0.05, 1e-12);
  EXPECT_TRUE(g.provesSeparation());
}

TEST(Referees, CrossedCylindersThatInterpenetrateProveContact) {
  // b's axis along z through (0, 0.12, 0): it reaches y = 0.12 - 0.05 = 0.07 < a's radius 0.1.
  const Mat3<LD> turn = Eigen::AngleAxis<LD>(LD(M_PI / 2), Vec3L::UnitY()).toRotationMatrix();
  const Bracket g = solidGap(cylinderAlongX(0.1L, 0.3L, Vec3L::Zero()), cylinderAlongX(0.05L, 0.2L, Vec3L(0, 0.12L, 0), turn));
  EXPECT_TRUE(g.provesContact());
  EXPECT_FALSE(g.provesSeparation());
}

TEST(Referees, CylinderCapFacingASphereIsTheAxialGap) {
  Solid sphere;
  sphere.radius = 0.1L;
  sphere.t = Vec3L(0.3L + 0.1L + 0.02L, 0.05L, 0);  // beyond the cap (x = 0.3), within the radius sideways
  const Bracket g = solidGap(cylinderAlongX(0.1L, 0.3L, Vec3L::Zero()), sphere);
  EXPECT_NEAR(double(g.lower), 0.02, 1e-12);
  EXPECT_NEAR(double(g.upper), 0.02, 1e-12);
}

TEST(Referees, TrianglesAcrossAGapAndCoplanarNeighboursAreSeparatedExactlyBySat) {
  const Polytope a = trianglePolytope(Vec3L(0, 0, 0), Vec3L(1, 0, 0), Vec3L(0, 1, 0));
  const Polytope above = trianglePolytope(Vec3L(0, 0, 0.25L), Vec3L(1, 0, 0.25L), Vec3L(0, 1, 0.25L));
  EXPECT_NEAR(double(satGap(a, above)), 0.25, 1e-15);
  // Coplanar, across the hypotenuse x + y = 1: only an in-plane edge normal separates them.
  const Polytope beside = trianglePolytope(Vec3L(1, 0.1L, 0), Vec3L(1, 1, 0), Vec3L(0.1L, 1, 0));
  EXPECT_NEAR(double(satGap(a, beside)), 0.1 / std::sqrt(2.0), 1e-15);
  // Crossing: a vertical triangle through a's interior.
  const Polytope crossing = trianglePolytope(Vec3L(0.2L, 0.2L, -1), Vec3L(0.3L, 0.2L, 1), Vec3L(0.2L, 0.3L, 1));
  EXPECT_LT(satGap(a, crossing), 0);
}

}  // namespace
}  // namespace gq::urdf::test
