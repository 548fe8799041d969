// Box/cylinder distance certificates (distance/box_cylinder.cpp): a cap or the side of the cylinder, or a face,
// corner or edge of the box, as the closest feature is answered exactly, each answer proven here by a separating
// plane whose gap is the answer; common points are Overlapping; touching pairs are left to GJK.
#include "gjk_test_shapes.h"

#include <cmath>
#include <limits>

#include "distance/distance.h"
#include "gjk/gjk.h"
#include "gq/custom_shapes.h"
#include "overlap/overlap.h"

namespace {

using namespace gjktest;
using gq::detail::BoxCylinderDistance;

template <class T> class BoxCylinderDistanceTest : public ::testing::Test {};
TYPED_TEST_SUITE(BoxCylinderDistanceTest, Scalars);

// A cylinder in the box's frame.
template <class T> struct Cylinder {
  gq::Vec3<T> c, a;
  T r, hh;
};

// The gap between box and cylinder along the unit n (from the box towards the cylinder): the least of n.y over the
// cylinder minus the most of n.x over the box. It never exceeds their distance.
template <class T> long double gapAlong(const gq::Vec3<T>& h, const Cylinder<T>& s, const gq::Vec3<T>& n) {
  using L = long double;
  const L na = L(n.x()) * s.a.x() + L(n.y()) * s.a.y() + L(n.z()) * s.a.z();
  const L nc = L(n.x()) * s.c.x() + L(n.y()) * s.c.y() + L(n.z()) * s.c.z();
  // The rim's reach |n x a| from the cross product itself: sqrt(1 - (n.a)^2) has an infinite slope at n = a.
  const L cx = L(n.y()) * s.a.z() - L(n.z()) * s.a.y(), cy = L(n.z()) * s.a.x() - L(n.x()) * s.a.z(),
          cz = L(n.x()) * s.a.y() - L(n.y()) * s.a.x();
  const L cylinderLeast = nc - L(s.hh) * std::abs(na) - L(s.r) * std::sqrt(cx * cx + cy * cy + cz * cz);
  const L boxMost = L(h.x()) * std::abs(L(n.x())) + L(h.y()) * std::abs(L(n.y())) + L(h.z()) * std::abs(L(n.z()));
  return cylinderLeast - boxMost;
}

template <class T> bool inCylinder(const Cylinder<T>& s, const gq::Vec3<T>& p, T slack) {
  const gq::Vec3<T> d = p - s.c;
  const T t = d.dot(s.a);
  return std::abs(t) <= s.hh + slack && std::sqrt(std::max(T(0), d.squaredNorm() - t * t)) <= s.r + slack;
}

template <class T> T tolerance(const gq::Vec3<T>& h, const Cylinder<T>& s) {
  return gq::detail::cylinderBoxTolerance(h, s.c, s.r, s.hh);
}

// GJK's boolean on the pair (the cylinder as core's custom cylinder at `pose`, the box at the origin).
template <class T> bool gjkOverlap(const gq::Vec3<T>& h, const Cylinder<T>& s, const gq::Transform<T>& pose) {
  gq::CustomGeometry<T> cylinder;
  EXPECT_TRUE(gq::makeCylinder(s.r, s.hh, cylinder).ok());
  const gq::Geometry<T> box{gq::BoxGeometry<T>(h)};
  return gq::detail::gjkOverlap(gq::detail::makeConvexShape(gq::Geometry<T>(cylinder), pose),
                                gq::detail::makeConvexShape(box, gq::Transform<T>()));
}

template <class T> BoxCylinderDistance answer(const gq::Vec3<T>& h, const Cylinder<T>& s, gq::DistanceResult<T>& d) {
  return gq::detail::distanceBoxCylinderLocal<T>(h, s.c, s.a, s.r, s.hh, d);
}

TYPED_TEST(BoxCylinderDistanceTest, CapAndSideAnswersArePairsOfSurfacePointsAtTheGapOfASeparatingPlane) {
  using T = TypeParam;
  const T eps = std::is_same_v<T, float> ? T(2e-5) : T(1e-12);
  Rng rng(2026);
  int separated = 0, overlapping = 0, unknown = 0, unknownApart = 0;
  for (int i = 0; i < 4000; ++i) {
    const gq::Vec3<T> h = rng.vec(0.05, 1.0).cast<T>();
    const gq::Transform<T> pose = randomPose<T>(rng, 1.5);
    const Cylinder<T> s{pose.p, pose.rotate(gq::Vec3<T>::UnitX()), T(rng.uniform(0.1, 1.0)), T(rng.uniform(0.05, 1.5))};
    gq::DistanceResult<T> d;
    switch (answer(h, s, d)) {
      case BoxCylinderDistance::Separated: {
        ++separated;
        ASSERT_GT(d.distance, T(0)) << "pose " << i;
        EXPECT_LE((d.point0.cwiseAbs() - h).maxCoeff(), eps) << "point0 on the box, pose " << i;
        EXPECT_TRUE(inCylinder(s, d.point1, eps)) << "point1 on the cylinder, pose " << i;
        EXPECT_NEAR((d.point1 - d.point0).norm(), d.distance, eps) << "pose " << i;
        EXPECT_LE((d.point1 - d.point0 - d.distance * d.normal).norm(), eps) << "pose " << i;
        // The plane along the normal separates them by the answer: no closer pair exists. The normal is the
        // witnesses' difference over the distance: off by ~eps_T |p| / distance, which lowers the box's gap at its
        // edges to first order (slack of that angle times the shapes' size).
        const T reach = d.point0.norm() + d.point1.norm() + T(1);
        const T angle = T(8) * std::numeric_limits<T>::epsilon() * reach / d.distance;
        const T slack = eps + angle * (h.norm() + s.r + s.hh);
        EXPECT_GE(gapAlong(h, s, d.normal), (long double)(d.distance) - slack) << "pose " << i;
        break;
      }
      case BoxCylinderDistance::Overlapping:
        ++overlapping;
        EXPECT_TRUE(gjkOverlap(h, s, pose)) << "pose " << i;
        break;
      case BoxCylinderDistance::Unknown:
        ++unknown;
        if (!gjkOverlap(h, s, pose)) ++unknownApart;
        break;
    }
  }
  EXPECT_GT(separated, 800);
  EXPECT_GT(overlapping, 300);
  EXPECT_LE(unknownApart, 4) << "GJK is left separated pairs only where a search ends short of the tolerance";
  EXPECT_LT(unknown, 300) << "and overlapping pairs whose common point the certificates do not reach";
}

// Box [-0.2, 0.2]^3, cylinder of radius 0.5 and half height 0.25 with its axis along z.
template <class T> Cylinder<T> uprightCylinder(const gq::Vec3<T>& centre) {
  return {centre, gq::Vec3<T>::UnitZ(), T(0.5), T(0.25)};
}

TYPED_TEST(BoxCylinderDistanceTest, BoxAboveTheCapIsItsHeightAboveTheCap) {
  using T = TypeParam;
  const gq::Vec3<T> h = gq::Vec3<T>::Constant(T(0.2));
  gq::DistanceResult<T> d;
  ASSERT_EQ(answer(h, uprightCylinder<T>(gq::Vec3<T>(T(0.1), T(-0.2), T(-1))), d), BoxCylinderDistance::Separated);
  EXPECT_NEAR(d.distance, T(0.55), T(1e-6));  // box bottom z = -0.2, cap z = -0.75
  EXPECT_NEAR(d.normal.z(), T(-1), T(1e-6));
  EXPECT_NEAR(d.point1.z(), T(-0.75), T(1e-6));
}

TYPED_TEST(BoxCylinderDistanceTest, BoxBesideTheSideIsTheAxisDistanceLessTheRadius) {
  using T = TypeParam;
  const gq::Vec3<T> h = gq::Vec3<T>::Constant(T(0.2));
  gq::DistanceResult<T> d;
  ASSERT_EQ(answer(h, uprightCylinder<T>(gq::Vec3<T>(T(1), T(0.1), T(0))), d), BoxCylinderDistance::Separated);
  EXPECT_NEAR(d.distance, T(0.3), T(1e-6));  // box face x = 0.2, side at x = 0.5
  EXPECT_NEAR(d.normal.x(), T(1), T(1e-6));
}

TYPED_TEST(BoxCylinderDistanceTest, RimAboveABoxFaceIsTheGapOfThatFace) {
  using T = TypeParam;
  const gq::Vec3<T> h = gq::Vec3<T>::Constant(T(0.2));
  const T s = T(std::sqrt(0.5));
  const Cylinder<T> tilted{gq::Vec3<T>(T(0), T(0), T(-1.5)), gq::Vec3<T>(s, T(0), s), T(0.5), T(0.25)};
  gq::DistanceResult<T> d;
  ASSERT_EQ(answer(h, tilted, d), BoxCylinderDistance::Separated);
  // The highest cylinder point is on the upper rim, (hh + r) sqrt(1/2) above the centre.
  EXPECT_NEAR(d.distance, T(1.3) - T(0.75) * s, T(1e-6));
  EXPECT_NEAR(d.normal.z(), T(-1), T(1e-6));
}

TYPED_TEST(BoxCylinderDistanceTest, RimNearestABoxCornerIsTheCornersDistanceToTheCylinder) {
  using T = TypeParam;
  const gq::Vec3<T> h = gq::Vec3<T>::Constant(T(0.2));
  gq::DistanceResult<T> d;
  ASSERT_EQ(answer(h, uprightCylinder<T>(gq::Vec3<T>(T(1), T(1), T(1))), d), BoxCylinderDistance::Separated);
  // Nearest the corner (0.2, 0.2, 0.2): the lower rim's point towards it, (1, 1, 0.75) - 0.5 (1, 1, 0) / sqrt(2).
  const T across = T(0.8) - T(0.5) * T(std::sqrt(0.5));
  EXPECT_NEAR(d.distance, std::sqrt(T(2) * across * across + T(0.55) * T(0.55)), T(1e-6));
  EXPECT_NEAR(d.point0.x(), T(0.2), T(1e-6));
}

TYPED_TEST(BoxCylinderDistanceTest, RimAgainstABoxEdgeIsFoundAlongTheEdge) {
  using T = TypeParam;
  const gq::Vec3<T> h = gq::Vec3<T>::Constant(T(0.2));
  gq::DistanceResult<T> d;
  // The rim point (-0.5, 0, -0.75) is nearest the box edge x = z = -0.2, at its middle; no corner is nearest.
  ASSERT_EQ(answer(h, uprightCylinder<T>(gq::Vec3<T>(T(-1), T(0), T(-1))), d), BoxCylinderDistance::Separated);
  EXPECT_NEAR(d.distance, std::sqrt(T(0.3) * T(0.3) + T(0.55) * T(0.55)), T(1e-6));
  EXPECT_NEAR(d.point0.y(), T(0), T(1e-5));
  EXPECT_NEAR(d.point1.x(), T(-0.5), T(1e-5));
}

TYPED_TEST(BoxCylinderDistanceTest, TouchingWithinTheToleranceIsLeftToGjk) {
  using T = TypeParam;
  const gq::Vec3<T> h = gq::Vec3<T>::Constant(T(0.2));
  gq::DistanceResult<T> d;
  d.distance = T(7);
  // The side a quarter of the tolerance from the face x = 0.2 (at gap 0 the touching point is a common point).
  const Cylinder<T> near = uprightCylinder<T>(gq::Vec3<T>(T(0.7), T(0), T(0)));
  const Cylinder<T> touching = uprightCylinder<T>(gq::Vec3<T>(T(0.7) + tolerance(h, near) / T(4), T(0), T(0)));
  EXPECT_EQ(answer(h, touching, d), BoxCylinderDistance::Unknown);
  EXPECT_EQ(d.distance, T(7)) << "nothing written";
}

// Squared lengths of such pairs may leave T's range; GJK runs them rescaled (gjk/pair_scale.h) and the façade's
// answer is then the scaled answer.
TYPED_TEST(BoxCylinderDistanceTest, PairsBeyondGjksUnscaledRangeAreLeftToItsRescaling) {
  using T = TypeParam;
  const gq::Vec3<T> h = gq::Vec3<T>::Constant(T(0.2));
  const Cylinder<T> beside = uprightCylinder<T>(gq::Vec3<T>(T(1), T(0.1), T(0)));
  const bool single = std::is_same_v<T, float>;
  for (const T factor : {single ? T(0x1p-24) : T(0x1p-110), single ? T(0x1p24) : T(0x1p110)}) {
    const Cylinder<T> scaled{factor * beside.c, beside.a, factor * beside.r, factor * beside.hh};
    gq::DistanceResult<T> d;
    d.distance = T(7);
    EXPECT_EQ(answer(gq::Vec3<T>(factor * h), scaled, d), BoxCylinderDistance::Unknown) << factor;
    EXPECT_EQ(d.distance, T(7)) << "nothing written";
    gq::CustomGeometry<T> cylinder;
    ASSERT_TRUE(gq::makeCylinder(scaled.r, scaled.hh, cylinder).ok());
    const gq::Transform<T> pose(scaled.c, gq::Quat<T>::FromTwoVectors(gq::Vec3<T>::UnitX(), gq::Vec3<T>::UnitZ()));
    gq::DistanceResult<T> facade;
    ASSERT_TRUE(gq::distance(facade, gq::Geometry<T>(gq::BoxGeometry<T>(gq::Vec3<T>(factor * h))), gq::Transform<T>(),
                             gq::Geometry<T>(cylinder), pose).ok());
    EXPECT_NEAR(double(facade.distance / factor), 0.3, 1e-5) << factor;
  }
}

TYPED_TEST(BoxCylinderDistanceTest, BoxCornerInsideTheCylinderIsOverlapping) {
  using T = TypeParam;
  const gq::Vec3<T> h = gq::Vec3<T>::Constant(T(0.2));
  gq::DistanceResult<T> d;
  EXPECT_EQ(answer(h, uprightCylinder<T>(gq::Vec3<T>(T(0.6), T(0), T(0))), d), BoxCylinderDistance::Overlapping);
}

// gq::distance asks core's custom cylinder its distance callback against a box, which answers separated pairs by
// the certified pair (no GJK iteration: the cache reports 0), in either order; GJK agrees within its tolerance.
TYPED_TEST(BoxCylinderDistanceTest, FacadeAnswersACustomCylinderAndABoxByTheCertifiedPairInEitherOrder) {
  using T = TypeParam;
  const double tol = std::is_same_v<T, float> ? 2e-4 : 1e-9;
  Rng rng(77);
  int certified = 0;
  for (int i = 0; i < 1000; ++i) {
    const gq::Vec3<T> h = rng.vec(0.05, 1.0).cast<T>();
    const T radius = T(rng.uniform(0.1, 1.0)), halfHeight = T(rng.uniform(0.05, 1.5));
    const gq::Transform<T> pc = randomPose<T>(rng, 1.5), pb = randomPose<T>(rng, 1.5);
    gq::CustomGeometry<T> cylinder;
    ASSERT_TRUE(gq::makeCylinder(radius, halfHeight, cylinder).ok());
    const gq::Geometry<T> gc(cylinder), gb{gq::BoxGeometry<T>(h)};
    gq::GjkCache<T> c0, c1;
    gq::DistanceResult<T> r0, r1, gjk;
    ASSERT_TRUE(gq::distance(r0, gc, pc, gb, pb, &c0).ok()) << "pose " << i;
    ASSERT_TRUE(gq::distance(r1, gb, pb, gc, pc, &c1).ok()) << "pose " << i;
    ASSERT_TRUE(gq::detail::distanceGjk(gc, pc, gb, pb, static_cast<gq::GjkCache<T>*>(nullptr), gjk).ok())
        << "pose " << i;
    EXPECT_NEAR(double(r0.distance), double(gjk.distance), tol) << "pose " << i;
    EXPECT_NEAR(double(r1.distance), double(r0.distance), tol) << "pose " << i;
    if (c0.iterations > 0 || !(r0.distance > T(0))) continue;
    ++certified;
    EXPECT_EQ(c1.iterations, 0u) << "the box first asks the cylinder too, pose " << i;
    EXPECT_LE((r1.normal + r0.normal).norm(), T(tol)) << "pose " << i;
    EXPECT_LE((r1.point0 - r0.point1).norm(), T(tol)) << "pose " << i;
    EXPECT_LE((r0.point1 - r0.point0 - r0.distance * r0.normal).norm(), T(tol)) << "pose " << i;
  }
  EXPECT_GT(certified, 300);
}

}  // namespace
