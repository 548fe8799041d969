// Penetration of spheres and capsules into hulls scaled flat or thin past T's precision (MeshScale factors spanning
// more than 1/eps, penetration/degenerate_hull.h): a unit cube scaled by S = R diag(s) R^T with one tiny factor is a
// flat polygon in the plane normal to R e_tiny, of thickness ~ that factor; with two tiny factors it is a segment
// along R e_long of half-length s_long |R e_long|_1. Exact answers from that geometry (long double):
//  - a sphere or a level capsule centred in the sheet's plane, well inside its polygon: depth = radius (plus half
//    the thickness, below T's rounding of the radius) along the sheet's normal;
//  - a sphere beside the needle's interior at distance d: apart when d > r, else depth r - d along the
//    perpendicular.
// Before: SAT over face normals that the scale rotation's rounding decides (two open fuzz findings: a sphere centred
// on a sheet pushed out through its rim, 1.94 deep for 2.06; a sphere 4.5 beside a needle "2.0 deep").
#include "gjk_test_shapes.h"

namespace {

using namespace gjktest;
using gq::Transform;
using gq::Vec3;
using ML = Eigen::Matrix<L, 3, 3>;

template <class T> class DegenerateHullPenetration : public ::testing::Test {};
TYPED_TEST_SUITE(DegenerateHullPenetration, Scalars);

template <class T> std::shared_ptr<const gq::ConvexMesh<T>> unitCube() {
  return makeHull<T>(
      {{-1, -1, -1}, {1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {-1, 1, 1}, {1, 1, 1}});
}

template <class T> T tiny() { return std::is_same_v<T, float> ? T(1e-30) : T(1e-200); }
template <class T> double tolerance() { return std::is_same_v<T, float> ? 1e-4 : 1e-9; }

// A scale rotation: near the identity (as in the finding, 1e-65 off it) or anywhere.
template <class T> Eigen::Quaternion<T> scaleRotation(Rng& rng, int trial) {
  if (trial % 2 == 0) return rng.rotation().cast<T>();
  const Eigen::Vector3d axis = rng.unit();
  return Eigen::Quaterniond(Eigen::AngleAxisd(1e-3 * rng.uniform(0, 1), axis)).cast<T>();
}

// The world direction of the scale's axis k: pose rotation times scale rotation times e_k (long double).
template <class T> VL worldAxis(const Transform<T>& pose, const Eigen::Quaternion<T>& scaleRot, int k) {
  const ML r = pose.q.template cast<L>().normalized().toRotationMatrix() *
               scaleRot.template cast<L>().normalized().toRotationMatrix();
  return r.col(k);
}

// The unit cube scaled to a sheet (a, tiny, c) or to a needle (tiny, 1e18 tiny, length) about the rotation sr.
template <class T>
gq::Geometry<T> sheetOf(const std::shared_ptr<const gq::ConvexMesh<T>>& cube, T a, T c,
                        const Eigen::Quaternion<T>& sr) {
  return gq::ConvexMeshGeometry<T>(cube, gq::MeshScale<T>(Vec3<T>(a, tiny<T>(), c), sr));
}
template <class T>
gq::Geometry<T> needleOf(const std::shared_ptr<const gq::ConvexMesh<T>>& cube, T length,
                         const Eigen::Quaternion<T>& sr) {
  return gq::ConvexMeshGeometry<T>(cube, gq::MeshScale<T>(Vec3<T>(tiny<T>(), T(1e18) * tiny<T>(), length), sr));
}
// The needle's half-length along the world image of the scale's Z: length * |R e_z|_1 (the cube's corner in the
// mesh frame, scaled).
template <class T> L needleHalfLength(T length, const Eigen::Quaternion<T>& sr) {
  return L(length) * sr.template cast<L>().normalized().toRotationMatrix().col(2).cwiseAbs().sum();
}

TYPED_TEST(DegenerateHullPenetration, SphereAndCapsuleCentredInASheetArePushedOutAlongItsNormal) {
  using T = TypeParam;
  Rng rng(20261124);
  const auto cube = unitCube<T>();
  ASSERT_TRUE(cube);
  for (int trial = 0; trial < 40; ++trial) {
    const T a = T(rng.uniform(3, 8)), c = T(rng.uniform(3, 8)), radius = T(rng.uniform(0.5, 1.5));
    const Eigen::Quaternion<T> sr = scaleRotation<T>(rng, trial);
    const gq::Geometry<T> sheet = sheetOf(cube, a, c, sr);
    const Transform<T> ps(rng.vec(-4, 4).cast<T>(), rng.rotation().cast<T>());
    const VL normal = worldAxis(ps, sr, 1), e0 = worldAxis(ps, sr, 0), e2 = worldAxis(ps, sr, 2);
    // In the sheet's plane, within its inscribed ellipse (semi-axes a and c) less the radius and a margin.
    const L room = L(std::min(a, c)) - L(radius) - L(1);
    // Every fourth at the sheet's centre itself, as in the finding (both faces' offsets then cancel exactly).
    const bool atCentre = trial % 4 == 0;
    const L u = atCentre ? L(0) : L(rng.uniform(-0.7, 0.7)) * room;
    const L w = atCentre ? L(0) : L(rng.uniform(-0.7, 0.7)) * room;
    const VL centre = toL(ps.p) + u * e0 + w * e2;
    const Vec3<T> centreT = centre.template cast<T>();
    const double tol = tolerance<T>() * (double(std::max(a, c)) + 4);
    SCOPED_TRACE(testing::Message() << "trial " << trial << " radius " << radius);
    for (const bool capsule : {false, true}) {
      // The capsule lies level in the plane (its axis local X along e0).
      const gq::Geometry<T> round = capsule ? gq::Geometry<T>(gq::CapsuleGeometry<T>(radius, T(0.5)))
                                            : gq::Geometry<T>(gq::SphereGeometry<T>(radius));
      const Eigen::Quaternion<L> toE0 = Eigen::Quaternion<L>::FromTwoVectors(VL::UnitX(), e0);
      const Transform<T> pr(centreT, capsule ? toE0.template cast<T>() : Eigen::Quaternion<T>::Identity());
      SCOPED_TRACE(capsule ? "capsule" : "sphere");
      gq::PenetrationResult<T> pen;
      ASSERT_TRUE(gq::computePenetration(pen, round, pr, sheet, ps).ok());
      ASSERT_TRUE(pen.penetrating);
      EXPECT_NEAR(double(pen.depth), double(radius), tol);
      EXPECT_NEAR(std::abs(double(pen.direction.template cast<L>().dot(normal))), 1.0, 1e-4);
      gq::DistanceResult<T> d;
      ASSERT_TRUE(gq::distance(d, round, pr, sheet, ps).ok());
      EXPECT_NEAR(double(d.distance), -double(radius), tol);
    }
  }
}

TYPED_TEST(DegenerateHullPenetration, SphereBesideANeedleIsApartOrPushedOffItsAxis) {
  using T = TypeParam;
  Rng rng(1124);
  const auto cube = unitCube<T>();
  ASSERT_TRUE(cube);
  for (int trial = 0; trial < 40; ++trial) {
    const T length = T(rng.uniform(4, 8)), radius = T(rng.uniform(1, 4));
    const Eigen::Quaternion<T> sr = scaleRotation<T>(rng, trial);
    const gq::Geometry<T> needle = needleOf(cube, length, sr);
    const Transform<T> pn(rng.vec(-4, 4).cast<T>(), rng.rotation().cast<T>());
    // The needle: the segment along the world image of the scale's Z (needleHalfLength).
    const VL axis = worldAxis(pn, sr, 2);
    const L half = needleHalfLength(length, sr);
    // The sphere's centre beside the needle's middle half, at distance d from its axis.
    const VL side = axis.unitOrthogonal();
    const L d = L(rng.uniform(0.2, 2.5)) * L(radius), t = L(rng.uniform(-0.5, 0.5)) * half;
    const Vec3<T> centre = (toL(pn.p) + t * axis + d * side).template cast<T>();
    const gq::Geometry<T> ball = gq::SphereGeometry<T>(radius);
    const Transform<T> pb(centre, Eigen::Quaternion<T>::Identity());
    // The exact distance of the stored centre from the segment.
    const VL rel = toL(centre) - toL(pn.p);
    const L along = std::clamp(rel.dot(axis), -half, half);
    const L exact = (rel - along * axis).norm();
    SCOPED_TRACE(testing::Message() << "trial " << trial << " radius " << radius << " axis distance "
                                    << double(exact));
    if (std::abs(double(exact - L(radius))) < 1e-2) continue;  // touching within rounding: either answer
    const double tol = tolerance<T>() * 10;
    gq::PenetrationResult<T> pen;
    ASSERT_TRUE(gq::computePenetration(pen, ball, pb, needle, pn).ok());
    EXPECT_EQ(pen.penetrating, exact < L(radius));
    if (pen.penetrating) {
      EXPECT_NEAR(double(pen.depth), double(L(radius) - exact), tol);
      EXPECT_NEAR(std::abs(double(pen.direction.template cast<L>().dot(axis))), 0.0, 1e-3);
    }
    gq::DistanceResult<T> dist;
    ASSERT_TRUE(gq::distance(dist, ball, pb, needle, pn).ok());
    EXPECT_NEAR(double(dist.distance), double(exact - L(radius)), tol);
  }
}

// `check(pen, solid)` on the penetration of a box of half-extents `half`, then of the cube hull scaled to it,
// against the degenerate hull, in both orders (the degenerate hull as geom0, then as geom1).
template <class T, class Check>
void forBoxAndHullInBothOrders(const std::shared_ptr<const gq::ConvexMesh<T>>& cube, const Vec3<T>& half,
                               const gq::Geometry<T>& degenerate, const Transform<T>& pd, const Transform<T>& pb,
                               Check check) {
  for (const bool hull : {false, true}) {
    const gq::Geometry<T> solid = hull ? gq::Geometry<T>(gq::ConvexMeshGeometry<T>(cube, gq::MeshScale<T>(half)))
                                       : gq::Geometry<T>(gq::BoxGeometry<T>(half));
    SCOPED_TRACE(hull ? "hull" : "box");
    for (const bool degenerateFirst : {false, true}) {
      SCOPED_TRACE(degenerateFirst ? "degenerate hull first" : "solid first");
      gq::PenetrationResult<T> pen;
      ASSERT_TRUE((degenerateFirst ? gq::computePenetration(pen, degenerate, pd, solid, pb)
                                   : gq::computePenetration(pen, solid, pb, degenerate, pd)).ok());
      check(pen, solid);
    }
  }
}

// A box, or a hull of the same cube, in any orientation with its centre in a sheet's plane (within 0.4 min(a, c) of
// the sheet's centre; half-extents h in [0.2, 0.5]): depth = its support D = sum h_i |n . b_i| along the sheet's
// normal n. A direction tilted by theta towards the plane costs at least D cos(theta) + (1.8 - |h|) sin(theta) >= D
// (the sheet reaches 0.6 min(a, c) >= 1.8 beyond the centre in-plane, the box at most |h| <= 0.87 < 0.93). Its
// face normals are not the sheet's: SAT must find n among the sheet's. Both orders (the sheet on either side).
TYPED_TEST(DegenerateHullPenetration, BoxAndHullCentredInASheetArePushedOutAlongItsNormal) {
  using T = TypeParam;
  Rng rng(2411);
  const auto cube = unitCube<T>();
  ASSERT_TRUE(cube);
  for (int trial = 0; trial < 40; ++trial) {
    const T a = T(rng.uniform(3, 8)), c = T(rng.uniform(3, 8));
    const Vec3<T> half(T(rng.uniform(0.2, 0.5)), T(rng.uniform(0.2, 0.5)), T(rng.uniform(0.2, 0.5)));
    const Eigen::Quaternion<T> sr = scaleRotation<T>(rng, trial);
    const gq::Geometry<T> sheet = sheetOf(cube, a, c, sr);
    const Transform<T> ps(rng.vec(-4, 4).cast<T>(), rng.rotation().cast<T>());
    const VL normal = worldAxis(ps, sr, 1), e0 = worldAxis(ps, sr, 0), e2 = worldAxis(ps, sr, 2);
    const L reach = L(0.4) * L(std::min(a, c));
    const bool atCentre = trial % 4 == 0;
    const L u = atCentre ? L(0) : L(rng.uniform(-0.7, 0.7)) * reach;
    const L w = atCentre ? L(0) : L(rng.uniform(-0.7, 0.7)) * reach;
    const Vec3<T> centre = (toL(ps.p) + u * e0 + w * e2).template cast<T>();
    const Transform<T> pb(centre, rng.rotation().cast<T>());
    const ML boxAxes = pb.q.template cast<L>().normalized().toRotationMatrix();
    const L depth = half.template cast<L>().dot((boxAxes.transpose() * normal).cwiseAbs());
    const double tol = tolerance<T>() * (double(std::max(a, c)) + 4);
    SCOPED_TRACE(testing::Message() << "trial " << trial << " half " << half.transpose());
    forBoxAndHullInBothOrders<T>(cube, half, sheet, ps, pb, [&](const gq::PenetrationResult<T>& pen, const auto&) {
      ASSERT_TRUE(pen.penetrating);
      EXPECT_NEAR(double(pen.depth), double(depth), tol);
      EXPECT_NEAR(std::abs(double(pen.direction.template cast<L>().dot(normal))), 1.0, 1e-4);
    });
  }
}

// A box (or the same cube as a hull) in any orientation beside a needle's middle: the pair's exact MTD by SAT in long
// double over the complete axis set of a box against a segment (the box's 3 face normals and the 3 crosses of its
// edges with the segment; the needle's thickness, ~1e-12 of T's rounding, is left out). Both orders.
TYPED_TEST(DegenerateHullPenetration, BoxAndHullBesideANeedleAreApartOrPushedOffIt) {
  using T = TypeParam;
  Rng rng(2412);
  const auto cube = unitCube<T>();
  ASSERT_TRUE(cube);
  int penetrating = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const T length = T(rng.uniform(4, 8));
    const Vec3<T> half(T(rng.uniform(0.3, 1)), T(rng.uniform(0.3, 1)), T(rng.uniform(0.3, 1)));
    const Eigen::Quaternion<T> sr = scaleRotation<T>(rng, trial);
    const gq::Geometry<T> needle = needleOf(cube, length, sr);
    const Transform<T> pn(rng.vec(-4, 4).cast<T>(), rng.rotation().cast<T>());
    const VL axis = worldAxis(pn, sr, 2);
    const L needleHalf = needleHalfLength(length, sr);
    const VL side = axis.unitOrthogonal();
    const L d = L(rng.uniform(0.1, 1.5)) * half.template cast<L>().norm(), t = L(rng.uniform(-0.3, 0.3)) * needleHalf;
    const Transform<T> pb((toL(pn.p) + t * axis + d * side).template cast<T>(), rng.rotation().cast<T>());
    const VL centre = toL(pb.p), n0 = toL(pn.p) - needleHalf * axis, n1 = toL(pn.p) + needleHalf * axis;
    const ML boxAxes = pb.q.template cast<L>().normalized().toRotationMatrix();
    // Overlap along unit u: the smaller push that separates the projections (negative: apart along u).
    const auto overlapAlong = [&](VL u) {
      u.normalize();
      const L r = half.template cast<L>().dot((boxAxes.transpose() * u).cwiseAbs()), c = centre.dot(u);
      const L lo = std::min(n0.dot(u), n1.dot(u)), hi = std::max(n0.dot(u), n1.dot(u));
      return std::min(c + r - lo, hi - (c - r));
    };
    L exact = std::numeric_limits<L>::max();
    for (int k = 0; k < 3; ++k) {
      exact = std::min(exact, overlapAlong(boxAxes.col(k)));
      const VL cross = boxAxes.col(k).cross(axis);
      if (cross.norm() > L(1e-9)) exact = std::min(exact, overlapAlong(cross));
    }
    SCOPED_TRACE(testing::Message() << "trial " << trial << " half " << half.transpose() << " exact "
                                    << double(exact));
    if (std::abs(double(exact)) < 1e-2) continue;  // touching within rounding: either answer
    penetrating += exact > 0;
    const double tol = tolerance<T>() * 10;
    const auto check = [&](const gq::PenetrationResult<T>& pen, const gq::Geometry<T>& solid) {
      EXPECT_EQ(pen.penetrating, exact > 0);
      if (pen.penetrating) EXPECT_NEAR(double(pen.depth), double(exact), tol);
      bool overlapping = false;
      ASSERT_TRUE(gq::overlap(solid, pb, needle, pn, overlapping).ok());
      EXPECT_EQ(overlapping, exact > 0);
    };
    forBoxAndHullInBothOrders<T>(cube, half, needle, pn, pb, check);
  }
  EXPECT_GT(penetrating, 5);
}

}  // namespace
