// generateTriangleContacts rules (gq/contacts.h), float and double. The triangle lies in the plane z = 0 (normal +z)
// unless said otherwise; expected separations and positions are closed forms of the placements below.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gq/contacts.h"
#include "gq/cooking.h"

namespace {

using namespace gq;

template <class T> struct TriangleContacts : ::testing::Test {
  static constexpr double kTol = std::is_same_v<T, double> ? 1e-9 : 2e-5;
  static Triangle<T> big() {  // covers [-4, 4]^2 around the origin
    Triangle<T> t;
    t.verts[0] = Vec3<T>(T(-10), T(-10), T(0));
    t.verts[1] = Vec3<T>(T(10), T(-10), T(0));
    t.verts[2] = Vec3<T>(T(0), T(20), T(0));
    return t;
  }
  static Transform<T> at(double x, double y, double z) { return Transform<T>(Vec3<T>(T(x), T(y), T(z))); }
  static Geometry<T> unitBox() { return BoxGeometry<T>(T(0.5), T(0.5), T(0.5)); }
  static void expectNormalUp(const ContactBuffer<T>& c) {
    for (std::uint32_t i = 0; i < c.count; ++i) EXPECT_NEAR(double(c.contacts[i].normal.z()), 1.0, kTol);
  }
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(TriangleContacts, Scalars);

TYPED_TEST(TriangleContacts, RestingBoxGivesFourCornerContactsWithTheGap) {
  using T = TypeParam;
  ContactBuffer<T> c;
  ASSERT_TRUE(generateTriangleContacts(this->unitBox(), this->at(0.2, -0.1, 0.51), this->big(), 7u, c,
                                       TriangleContactSettings<T>{T(0.02), T(0.01), T(1)})
                  .ok());
  ASSERT_GT(c.count, 0u);
  ASSERT_EQ(c.count, 4u);
  this->expectNormalUp(c);
  for (std::uint32_t i = 0; i < c.count; ++i) {
    EXPECT_NEAR(double(c.contacts[i].separation), 0.01, this->kTol);
    EXPECT_NEAR(double(c.contacts[i].position.z()), 0.01, this->kTol);
    EXPECT_NEAR(std::abs(double(c.contacts[i].position.x()) - 0.2), 0.5, this->kTol);  // a bottom corner
    EXPECT_NEAR(std::abs(double(c.contacts[i].position.y()) + 0.1), 0.5, this->kTol);
    EXPECT_EQ(c.contacts[i].triangleIndex, 7u);
  }
}

// Triangles are two-sided: a box under the triangle's back face gets the same four corners, mirrored, with the
// normal pointing down towards it.
TYPED_TEST(TriangleContacts, BoxUnderTheBackFaceGivesFourCornerContactsAsOnTheFront) {
  using T = TypeParam;
  ContactBuffer<T> c;
  ASSERT_TRUE(generateTriangleContacts(this->unitBox(), this->at(0.2, -0.1, -0.51), this->big(), 7u, c,
                                       TriangleContactSettings<T>{T(0.02), T(0.01), T(1)})
                  .ok());
  ASSERT_EQ(c.count, 4u);
  for (std::uint32_t i = 0; i < c.count; ++i) {
    EXPECT_NEAR(double(c.contacts[i].normal.z()), -1.0, this->kTol);
    EXPECT_NEAR(double(c.contacts[i].separation), 0.01, this->kTol);
    EXPECT_NEAR(double(c.contacts[i].position.z()), -0.01, this->kTol);
    EXPECT_NEAR(std::abs(double(c.contacts[i].position.x()) - 0.2), 0.5, this->kTol);  // a top corner
    EXPECT_NEAR(std::abs(double(c.contacts[i].position.y()) + 0.1), 0.5, this->kTol);
  }
}

TYPED_TEST(TriangleContacts, PenetratingBoxReportsNegativeSeparationAndKeepsTheDeepest) {
  using T = TypeParam;
  // Tilted about Y by a small angle: the corners at x = +0.5 go deepest.
  const double a = 0.1;
  const Transform<T> pose(Vec3<T>(T(0), T(0), T(0.45)), Quat<T>(Eigen::AngleAxis<T>(T(a), Vec3<T>::UnitY())));
  ContactBuffer<T> c;
  ASSERT_TRUE(generateTriangleContacts(this->unitBox(), pose, this->big(), 0u, c,
                                       TriangleContactSettings<T>{T(0.2), T(0.2), T(1)})
                  .ok());
  ASSERT_GT(c.count, 0u);
  ASSERT_EQ(c.count, 4u);
  this->expectNormalUp(c);
  // Bottom corners sit at z = 0.45 - 0.5 cos a -/+ 0.5 sin a.
  const double deepest = 0.45 - 0.5 * std::cos(a) - 0.5 * std::sin(a);
  const double shallow = 0.45 - 0.5 * std::cos(a) + 0.5 * std::sin(a);
  double minSep = 1e9;
  for (std::uint32_t i = 0; i < c.count; ++i) {
    const double s = double(c.contacts[i].separation);
    minSep = std::min(minSep, s);
    EXPECT_TRUE(std::abs(s - deepest) < this->kTol || std::abs(s - shallow) < this->kTol) << s;
  }
  EXPECT_NEAR(minSep, deepest, this->kTol);
  EXPECT_LT(minSep, 0.0);
}

TYPED_TEST(TriangleContacts, ContactsStopBeyondContactDistance) {
  using T = TypeParam;
  ContactBuffer<T> c;
  ASSERT_TRUE(generateTriangleContacts(this->unitBox(), this->at(0, 0, 0.6), this->big(), 0u, c,
                                       TriangleContactSettings<T>{T(0.05), T(0.01), T(1)})
                  .ok());
  EXPECT_EQ(c.count, 0u);
}

TYPED_TEST(TriangleContacts, CapsuleLyingFlatGivesTwoContactsUnderItsEnds) {
  using T = TypeParam;
  ContactBuffer<T> c;
  // Radius 0.25, half height 1 along X, axis at z = 0.24: both ends 0.01 deep.
  ASSERT_TRUE(generateTriangleContacts(Geometry<T>(CapsuleGeometry<T>(T(0.25), T(1))), this->at(0, 0, 0.24),
                                       this->big(), 0u, c, TriangleContactSettings<T>{T(0.01), T(0.01), T(1)})
                  .ok());
  ASSERT_GT(c.count, 0u);
  ASSERT_EQ(c.count, 2u);
  this->expectNormalUp(c);
  for (std::uint32_t i = 0; i < c.count; ++i) {
    EXPECT_NEAR(double(c.contacts[i].separation), -0.01, this->kTol);
    EXPECT_NEAR(std::abs(double(c.contacts[i].position.x())), 1.0, this->kTol);
    EXPECT_NEAR(double(c.contacts[i].position.z()), -0.01, this->kTol);
  }
}

TYPED_TEST(TriangleContacts, BigBoxOverSmallTriangleContactsAtTheTriangleVertices) {
  using T = TypeParam;
  Triangle<T> small;
  small.verts[0] = Vec3<T>(T(-0.3), T(-0.3), T(0));
  small.verts[1] = Vec3<T>(T(0.3), T(-0.3), T(0));
  small.verts[2] = Vec3<T>(T(0), T(0.3), T(0));
  ContactBuffer<T> c;
  ASSERT_TRUE(generateTriangleContacts(Geometry<T>(BoxGeometry<T>(T(2), T(2), T(0.5))), this->at(0, 0, 0.52), small, 0u,
                                       c, TriangleContactSettings<T>{T(0.05), T(0.01), T(1)})
                  .ok());
  ASSERT_GT(c.count, 0u);
  ASSERT_EQ(c.count, 3u);
  this->expectNormalUp(c);
  for (std::uint32_t i = 0; i < c.count; ++i) {
    EXPECT_NEAR(double(c.contacts[i].separation), 0.02, this->kTol);
    double nearest = 1e9;
    for (const Vec3<T>& v : small.verts) nearest = std::min(nearest, double((c.contacts[i].position - v).head(2).norm()));
    EXPECT_NEAR(nearest, 0.0, this->kTol);
  }
}

TYPED_TEST(TriangleContacts, EdgeOnBoxGivesOneContactAlongTheClosestFeatureNormal) {
  using T = TypeParam;
  // The box beside the triangle's edge y = -10 (|x| < 10 there), its face 0.03 away along -y, level with the plane.
  ContactBuffer<T> c;
  ASSERT_TRUE(generateTriangleContacts(this->unitBox(), this->at(0, -10.53, 0.2), this->big(), 0u, c,
                                       TriangleContactSettings<T>{T(0.05), T(0.01), T(1)})
                  .ok());
  ASSERT_GT(c.count, 0u);
  ASSERT_EQ(c.count, 1u);
  EXPECT_NEAR(double(c.contacts[0].separation), 0.03, this->kTol);
  EXPECT_NEAR(double(c.contacts[0].normal.y()), -1.0, this->kTol);
  EXPECT_NEAR(double(c.contacts[0].position.y()), -10.03, this->kTol);
}

TYPED_TEST(TriangleContacts, RestingConvexHullGivesFourContacts) {
  using T = TypeParam;
  std::vector<Vec3<T>> cube;
  for (int i = 0; i < 8; ++i) cube.emplace_back(T(i & 1 ? 0.5 : -0.5), T(i & 2 ? 0.5 : -0.5), T(i & 4 ? 0.5 : -0.5));
  std::shared_ptr<const ConvexMesh<T>> hull;
  ASSERT_TRUE(cookConvexMesh(cube, hull).ok());
  ContactBuffer<T> c;
  ASSERT_TRUE(generateTriangleContacts(Geometry<T>(ConvexMeshGeometry<T>(hull)), this->at(1, 1, 0.5), this->big(), 0u,
                                       c, TriangleContactSettings<T>{T(0.01), T(0.01), T(1)})
                  .ok());
  ASSERT_GT(c.count, 0u);
  EXPECT_EQ(c.count, 4u);
  this->expectNormalUp(c);
  for (std::uint32_t i = 0; i < c.count; ++i) EXPECT_NEAR(double(c.contacts[i].separation), 0.0, this->kTol);
}

TYPED_TEST(TriangleContacts, InvalidInputReturnsAStatusAndWritesNothing) {
  using T = TypeParam;
  ContactBuffer<T> c;
  c.count = 3;
  EXPECT_EQ(generateTriangleContacts(this->unitBox(), this->at(0, 0, 1), this->big(), 0u, c,
                                     TriangleContactSettings<T>{T(-1), T(0), T(1)})
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(generateTriangleContacts(this->unitBox(), this->at(0, 0, 1), this->big(), 0u, c,
                                     TriangleContactSettings<T>{T(0), T(0), T(0)})
                .code,
            StatusCode::InvalidArgument);
  EXPECT_EQ(generateTriangleContacts(Geometry<T>(SphereGeometry<T>(T(1))), this->at(0, 0, 1), this->big(), 0u, c,
                                     TriangleContactSettings<T>{T(0), T(0), T(1)})
                .code,
            StatusCode::Unsupported);
  EXPECT_EQ(c.count, 3u);
}

}  // namespace
