// generateContacts rules (gq/contacts.h), float and double: the contact set of a convex pair. The ground is a box
// with its top face at z = 0.5 (or a plane at z = 0); expected separations and positions are closed forms of the
// placements below.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "gq/contacts.h"
#include "gq/cooking.h"
#include "gq/custom_shapes.h"
#include "gq/query.h"
#include "gq/shape.h"

namespace {

using namespace gq;

template <class T> struct ContactSets : ::testing::Test {
  static constexpr double kTol = std::is_same_v<T, double> ? 1e-9 : 5e-5;
  static Geometry<T> ground() { return BoxGeometry<T>(T(2), T(2), T(0.5)); }
  static Geometry<T> unitBox() { return BoxGeometry<T>(T(0.5), T(0.5), T(0.5)); }
  static Transform<T> at(double x, double y, double z, double yaw = 0) {
    return Transform<T>(Vec3<T>(T(x), T(y), T(z)), Quat<T>(Eigen::AngleAxis<T>(T(yaw), Vec3<T>::UnitZ())));
  }
  // The plane x = 0 of its frame turned so its normal is +z.
  static Transform<T> planeUp() {
    return Transform<T>(Vec3<T>::Zero(), Quat<T>(Eigen::AngleAxis<T>(T(-EIGEN_PI / 2), Vec3<T>::UnitY())));
  }
  static ContactSetSettings<T> within(double d, std::uint32_t maxContacts = 4) {
    ContactSetSettings<T> s;
    s.contactDistance = T(d);
    s.maxContacts = maxContacts;
    return s;
  }
  static void expectNormal(const ContactSet<T>& c, double x, double y, double z) {
    EXPECT_NEAR(double(c.normal.x()), x, kTol);
    EXPECT_NEAR(double(c.normal.y()), y, kTol);
    EXPECT_NEAR(double(c.normal.z()), z, kTol);
  }
  // Whether (x, y, z) is one of the set's positions.
  static bool hasPoint(const ContactSet<T>& c, double x, double y, double z) {
    for (std::uint32_t i = 0; i < c.count; ++i)
      if ((c.points[i].position.template cast<double>() - Eigen::Vector3d(x, y, z)).norm() < 10 * kTol) return true;
    return false;
  }
  static std::shared_ptr<const ConvexMesh<T>> hexagonalPrism(double r, double h) {
    std::vector<Vec3<T>> pts;
    for (int k = 0; k < 6; ++k)
      for (double z : {-h, h})
        pts.emplace_back(T(r * std::cos(k * EIGEN_PI / 3)), T(r * std::sin(k * EIGEN_PI / 3)), T(z));
    std::shared_ptr<const ConvexMesh<T>> mesh;
    EXPECT_TRUE(cookConvexMesh(pts, mesh).ok());
    return mesh;
  }
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(ContactSets, Scalars);

// A unit box turned about z, 0.02 into the ground's top face: the 4 corners of its footprint at the exact depth, on
// the ground's surface, normal from the ground (geom1) to the box (geom0).
TYPED_TEST(ContactSets, BoxOnBoxFaceGivesTheFourFootprintCornersAtTheExactDepth) {
  using T = TypeParam;
  const double yaw = 0.3, cx = 0.3, cy = -0.2;
  ContactSet<T> c;
  ASSERT_TRUE(generateContacts(this->unitBox(), this->at(cx, cy, 0.98, yaw), this->ground(), this->at(0, 0, 0), c).ok());
  ASSERT_EQ(c.count, 4u);
  this->expectNormal(c, 0, 0, 1);
  for (std::uint32_t i = 0; i < c.count; ++i) EXPECT_NEAR(double(c.points[i].separation), -0.02, this->kTol);
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) {
      const double x = cx + 0.5 * (sx * std::cos(yaw) - sy * std::sin(yaw));
      const double y = cy + 0.5 * (sx * std::sin(yaw) + sy * std::cos(yaw));
      EXPECT_TRUE(this->hasPoint(c, x, y, 0.5)) << x << " " << y;
    }
}

// Overhanging the ground's edge at x = 2: the corners of the overlap rectangle [1.3, 2] x [-0.7, 0.3].
TYPED_TEST(ContactSets, OverhangingBoxGivesTheCornersOfTheOverlapRectangle) {
  using T = TypeParam;
  ContactSet<T> c;
  ASSERT_TRUE(generateContacts(this->unitBox(), this->at(1.8, -0.2, 0.99), this->ground(), this->at(0, 0, 0), c).ok());
  ASSERT_EQ(c.count, 4u);
  this->expectNormal(c, 0, 0, 1);
  for (double x : {1.3, 2.0})
    for (double y : {-0.7, 0.3}) EXPECT_TRUE(this->hasPoint(c, x, y, 0.5)) << x << " " << y;
  for (std::uint32_t i = 0; i < c.count; ++i) EXPECT_NEAR(double(c.points[i].separation), -0.01, this->kTol);
  // Swapped: the normal flips and the points move to the new geom1 (the box's bottom face, z = 0.49).
  ContactSet<T> s;
  ASSERT_TRUE(generateContacts(this->ground(), this->at(0, 0, 0), this->unitBox(), this->at(1.8, -0.2, 0.99), s).ok());
  ASSERT_EQ(s.count, 4u);
  this->expectNormal(s, 0, 0, -1);
  for (double x : {1.3, 2.0})
    for (double y : {-0.7, 0.3}) EXPECT_TRUE(this->hasPoint(s, x, y, 0.49)) << x << " " << y;
}

// A gap within contactDistance gives the same 4 points with a positive separation; beyond it, none.
TYPED_TEST(ContactSets, GapWithinTheContactDistanceOnlyIsReported) {
  using T = TypeParam;
  ContactSet<T> c;
  ASSERT_TRUE(generateContacts(this->unitBox(), this->at(0, 0, 1.01), this->ground(), this->at(0, 0, 0), c,
                               this->within(0.05))
                  .ok());
  ASSERT_EQ(c.count, 4u);
  for (std::uint32_t i = 0; i < c.count; ++i) EXPECT_NEAR(double(c.points[i].separation), 0.01, this->kTol);
  ASSERT_TRUE(generateContacts(this->unitBox(), this->at(0, 0, 1.1), this->ground(), this->at(0, 0, 0), c,
                               this->within(0.05))
                  .ok());
  EXPECT_EQ(c.count, 0u);
  this->expectNormal(c, 0, 0, 0);
}

// A tilted box: the deepest point carries the exact penetration depth and none is deeper, whatever the pose.
TYPED_TEST(ContactSets, NoPointIsDeeperThanTheExactPenetration) {
  using T = TypeParam;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Vector3d axis = Eigen::Vector3d(u(rng), u(rng), u(rng)).normalized();
    const Transform<T> pose(Vec3<T>(T(u(rng)), T(u(rng)), T(0.95 + 0.05 * u(rng))),
                            Quat<T>(Eigen::AngleAxis<T>(T(0.1 * u(rng)), axis.cast<T>())));
    PenetrationResult<T> mtd;
    ASSERT_TRUE(computePenetration(mtd, this->unitBox(), pose, this->ground(), this->at(0, 0, 0)).ok());
    ContactSet<T> c;
    ASSERT_TRUE(generateContacts(this->unitBox(), pose, this->ground(), this->at(0, 0, 0), c, this->within(0.01)).ok());
    ASSERT_GE(c.count, 1u) << "trial " << trial;
    ASSERT_LE(c.count, 4u);
    double deepest = std::numeric_limits<double>::max();
    for (std::uint32_t i = 0; i < c.count; ++i) {
      deepest = std::min(deepest, double(c.points[i].separation));
      EXPECT_GE(double(c.points[i].separation), -double(mtd.depth) - this->kTol) << "trial " << trial;
    }
    EXPECT_NEAR(deepest, -double(mtd.depth), this->kTol) << "trial " << trial;
    EXPECT_NEAR(double(c.normal.norm()), 1.0, this->kTol);
  }
}

// Crossed edges: box 0 turned 45 degrees about y, its bottom edge (along y) 0.01 into the top edge (along x) of a
// box turned 45 degrees about x. One point (no face within ~8 degrees of the normal): the crossing on geom1's edge,
// normal +z, at the exact depth.
TYPED_TEST(ContactSets, CrossedEdgesGiveTheirCrossingAtTheExactDepth) {
  using T = TypeParam;
  const double r = 0.5 * std::sqrt(2.0);
  const Transform<T> pose0(Vec3<T>(T(0.1), T(-0.05), T(2 * r - 0.01)),
                           Quat<T>(Eigen::AngleAxis<T>(T(EIGEN_PI / 4), Vec3<T>::UnitY())));
  const Transform<T> pose1(Vec3<T>(T(0.1), T(-0.05), T(0)), Quat<T>(Eigen::AngleAxis<T>(T(EIGEN_PI / 4), Vec3<T>::UnitX())));
  ContactSet<T> c;
  ASSERT_TRUE(generateContacts(this->unitBox(), pose0, this->unitBox(), pose1, c).ok());
  ASSERT_EQ(c.count, 1u);
  this->expectNormal(c, 0, 0, 1);
  EXPECT_NEAR(double(c.points[0].separation), -0.01, this->kTol);
  EXPECT_TRUE(this->hasPoint(c, 0.1, -0.05, r));
}

// A box on its edge (turned 45 degrees about x), 0.01 into the ground's top face: one point on the edge's line on the
// face, at the exact depth.
TYPED_TEST(ContactSets, BoxOnItsEdgeGivesOnePointOfTheEdgeAtTheExactDepth) {
  using T = TypeParam;
  const double r = 0.5 * std::sqrt(2.0);
  const Transform<T> pose(Vec3<T>(T(0.2), T(0.3), T(0.5 + r - 0.01)),
                          Quat<T>(Eigen::AngleAxis<T>(T(EIGEN_PI / 4), Vec3<T>::UnitX())));
  ContactSet<T> c;
  ASSERT_TRUE(generateContacts(this->unitBox(), pose, this->ground(), this->at(0, 0, 0), c).ok());
  ASSERT_EQ(c.count, 1u);
  this->expectNormal(c, 0, 0, 1);
  EXPECT_NEAR(double(c.points[0].separation), -0.01, this->kTol);
  const Eigen::Vector3d p = c.points[0].position.template cast<double>();
  EXPECT_NEAR(p.y(), 0.3, 10 * this->kTol);
  EXPECT_NEAR(p.z(), 0.5, 10 * this->kTol);
  EXPECT_LE(std::abs(p.x() - 0.2), 0.5 + 10 * this->kTol);
}

// A hexagonal hull standing on its face: 4 of the 6 bottom corners by default, all 6 when maxContacts allows; 1 (the
// deepest, exact) with maxContacts = 1.
TYPED_TEST(ContactSets, HullOnBoxKeepsMaxContactsOfItsBottomFace) {
  using T = TypeParam;
  const Geometry<T> hull = ConvexMeshGeometry<T>(this->hexagonalPrism(0.5, 0.25));
  const Transform<T> pose = this->at(0.1, 0.2, 0.74);
  ContactSet<T> c;
  ASSERT_TRUE(generateContacts(hull, pose, this->ground(), this->at(0, 0, 0), c).ok());
  ASSERT_EQ(c.count, 4u);
  this->expectNormal(c, 0, 0, 1);
  for (std::uint32_t i = 0; i < c.count; ++i) EXPECT_NEAR(double(c.points[i].separation), -0.01, this->kTol);
  ASSERT_TRUE(generateContacts(hull, pose, this->ground(), this->at(0, 0, 0), c, this->within(0, 8)).ok());
  ASSERT_EQ(c.count, 6u);
  for (int k = 0; k < 6; ++k)
    EXPECT_TRUE(this->hasPoint(c, 0.1 + 0.5 * std::cos(k * EIGEN_PI / 3), 0.2 + 0.5 * std::sin(k * EIGEN_PI / 3), 0.5));
  ASSERT_TRUE(generateContacts(hull, pose, this->ground(), this->at(0, 0, 0), c, this->within(0, 1)).ok());
  ASSERT_EQ(c.count, 1u);
  EXPECT_NEAR(double(c.points[0].separation), -0.01, this->kTol);
}

// A capsule lying on the face: its two end points; a sphere: one point under its centre.
TYPED_TEST(ContactSets, CapsuleLyingGivesTwoAndSphereOne) {
  using T = TypeParam;
  ContactSet<T> c;
  ASSERT_TRUE(generateContacts(Geometry<T>(CapsuleGeometry<T>(T(0.25), T(0.5))), this->at(0.2, 0.1, 0.74, 0.4),
                               this->ground(), this->at(0, 0, 0), c)
                  .ok());
  ASSERT_EQ(c.count, 2u);
  this->expectNormal(c, 0, 0, 1);
  for (int s : {-1, 1})
    EXPECT_TRUE(this->hasPoint(c, 0.2 + s * 0.5 * std::cos(0.4), 0.1 + s * 0.5 * std::sin(0.4), 0.5));
  for (std::uint32_t i = 0; i < c.count; ++i) EXPECT_NEAR(double(c.points[i].separation), -0.01, this->kTol);

  ASSERT_TRUE(generateContacts(Geometry<T>(SphereGeometry<T>(T(0.25))), this->at(0.3, -0.4, 0.74), this->ground(),
                               this->at(0, 0, 0), c)
                  .ok());
  ASSERT_EQ(c.count, 1u);
  this->expectNormal(c, 0, 0, 1);
  EXPECT_NEAR(double(c.points[0].separation), -0.01, this->kTol);
  EXPECT_TRUE(this->hasPoint(c, 0.3, -0.4, 0.5));
}

// A standing cylinder: its cap's rim sampled at 4 points.
TYPED_TEST(ContactSets, StandingCylinderGivesItsCapRim) {
  using T = TypeParam;
  const Geometry<T> cylinder = CustomGeometry<T>(std::make_shared<CylinderCallbacks<T>>(T(0.3), T(0.4)));
  // The cylinder's axis is its local x: turned to stand on z.
  const Transform<T> pose(Vec3<T>(T(0), T(0), T(0.89)),
                          Quat<T>(Eigen::AngleAxis<T>(T(-EIGEN_PI / 2), Vec3<T>::UnitY())));
  ContactSet<T> c;
  ASSERT_TRUE(generateContacts(cylinder, pose, this->ground(), this->at(0, 0, 0), c).ok());
  ASSERT_EQ(c.count, 4u);
  this->expectNormal(c, 0, 0, 1);
  for (std::uint32_t i = 0; i < c.count; ++i) {
    EXPECT_NEAR(double(c.points[i].separation), -0.01, 10 * this->kTol);
    EXPECT_NEAR(double(c.points[i].position.template head<2>().norm()), 0.3, 10 * this->kTol);
  }
}

// A plane in either order; positions on geom1 (the plane, or the box's bottom face).
TYPED_TEST(ContactSets, BoxOnPlaneInEitherOrder) {
  using T = TypeParam;
  const Geometry<T> plane = PlaneGeometry<T>();
  ContactSet<T> c;
  ASSERT_TRUE(generateContacts(this->unitBox(), this->at(0.5, 0.5, 0.49), plane, this->planeUp(), c).ok());
  ASSERT_EQ(c.count, 4u);
  this->expectNormal(c, 0, 0, 1);
  for (double x : {0.0, 1.0})
    for (double y : {0.0, 1.0}) EXPECT_TRUE(this->hasPoint(c, x, y, 0.0));
  ASSERT_TRUE(generateContacts(plane, this->planeUp(), this->unitBox(), this->at(0.5, 0.5, 0.49), c).ok());
  ASSERT_EQ(c.count, 4u);
  this->expectNormal(c, 0, 0, -1);
  for (double x : {0.0, 1.0})
    for (double y : {0.0, 1.0}) EXPECT_TRUE(this->hasPoint(c, x, y, -0.01));
  for (std::uint32_t i = 0; i < c.count; ++i) EXPECT_NEAR(double(c.points[i].separation), -0.01, this->kTol);
}

// Rounded shapes: the margins count in the separation (cores 0.05 apart, geom0 grown by 0.1: 0.05 deep).
TYPED_TEST(ContactSets, MarginsRoundTheShapes) {
  using T = TypeParam;
  ContactSetSettings<T> s;
  s.margin0 = T(0.1);
  ContactSet<T> c;
  ASSERT_TRUE(generateContacts(this->unitBox(), this->at(0, 0, 1.05), this->ground(), this->at(0, 0, 0), c, s).ok());
  ASSERT_EQ(c.count, 4u);
  for (std::uint32_t i = 0; i < c.count; ++i) {
    EXPECT_NEAR(double(c.points[i].separation), -0.05, this->kTol);
    EXPECT_NEAR(double(c.points[i].position.z()), 0.5, this->kTol);
  }
}

// Prepared shapes give the Geometry overload's answer bit for bit.
TYPED_TEST(ContactSets, PreparedShapesGiveTheSameSet) {
  using T = TypeParam;
  Shape<T> box, ground;
  ASSERT_TRUE(makeShape(this->unitBox(), box).ok());
  ASSERT_TRUE(makeShape(this->ground(), ground).ok());
  const Transform<T> pose(Vec3<T>(T(0.2), T(0.1), T(0.97)),
                          Quat<T>(Eigen::AngleAxis<T>(T(0.05), Vec3<T>(T(0.6), T(0.8), T(0)))));
  ContactSet<T> a, b;
  ASSERT_TRUE(generateContacts(this->unitBox(), pose, this->ground(), this->at(0, 0, 0), a).ok());
  ASSERT_TRUE(generateContacts(box, pose, ground, this->at(0, 0, 0), b).ok());
  ASSERT_EQ(a.count, b.count);
  EXPECT_EQ(a.normal, b.normal);
  for (std::uint32_t i = 0; i < a.count; ++i) {
    EXPECT_EQ(a.points[i].position, b.points[i].position);
    EXPECT_EQ(a.points[i].separation, b.points[i].separation);
  }
}

// Bad input: InvalidArgument and nothing written; pairs without a contact set: Unsupported.
TYPED_TEST(ContactSets, BadInputAndUnsupportedPairsWriteNothing) {
  using T = TypeParam;
  ContactSet<T> c;
  c.count = 3;
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const auto code = [&](const Geometry<T>& g0, const Transform<T>& p0, const Geometry<T>& g1,
                        const ContactSetSettings<T>& s) {
    return generateContacts(g0, p0, g1, this->at(0, 0, 0), c, s).code;
  };
  const ContactSetSettings<T> ok;
  EXPECT_EQ(code(this->unitBox(), Transform<T>(Vec3<T>(nan, T(0), T(0))), this->ground(), ok),
            StatusCode::InvalidArgument);
  EXPECT_EQ(code(Geometry<T>(BoxGeometry<T>(T(-1), T(1), T(1))), this->at(0, 0, 1), this->ground(), ok),
            StatusCode::InvalidArgument);
  ContactSetSettings<T> bad = ok;
  bad.maxContacts = 0;
  EXPECT_EQ(code(this->unitBox(), this->at(0, 0, 1), this->ground(), bad), StatusCode::InvalidArgument);
  bad = ok;
  bad.maxContacts = kMaxContactSetPoints + 1;
  EXPECT_EQ(code(this->unitBox(), this->at(0, 0, 1), this->ground(), bad), StatusCode::InvalidArgument);
  bad = ok;
  bad.contactDistance = T(-1);
  EXPECT_EQ(code(this->unitBox(), this->at(0, 0, 1), this->ground(), bad), StatusCode::InvalidArgument);
  bad = ok;
  bad.margin1 = nan;
  EXPECT_EQ(code(this->unitBox(), this->at(0, 0, 1), this->ground(), bad), StatusCode::InvalidArgument);
  bad = ok;
  bad.toleranceLength = T(0);
  EXPECT_EQ(code(this->unitBox(), this->at(0, 0, 1), this->ground(), bad), StatusCode::InvalidArgument);
  const Geometry<T> plane = PlaneGeometry<T>();
  EXPECT_EQ(code(plane, this->at(0, 0, 0), plane, ok), StatusCode::Unsupported);
  std::shared_ptr<const TriangleMesh<T>> mesh;
  const std::vector<Vec3<T>> verts{Vec3<T>(T(0), T(0), T(0)), Vec3<T>(T(1), T(0), T(0)), Vec3<T>(T(0), T(1), T(0))};
  const std::vector<TriangleIndices> tris{{0u, 1u, 2u}};
  ASSERT_TRUE(cookTriangleMesh(verts, tris, mesh).ok());
  EXPECT_EQ(code(this->unitBox(), this->at(0, 0, 0.4), Geometry<T>(TriangleMeshGeometry<T>(mesh)), ok),
            StatusCode::Unsupported);
  Shape<T> empty, box;
  ASSERT_TRUE(makeShape(this->unitBox(), box).ok());
  EXPECT_EQ(generateContacts(empty, this->at(0, 0, 1), box, this->at(0, 0, 0), c).code, StatusCode::InvalidArgument);
  EXPECT_EQ(c.count, 3u);
}

}  // namespace
