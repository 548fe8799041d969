// generateTriangleContacts where the shape straddles the triangle's boundary: the contact polygon's corners include
// the crossings of the shape's edges with the triangle's edges (gq/contacts.h), float and double. Resting,
// penetrating and edge-on placements; expected points are closed forms of the placements.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "gq/contacts.h"
#include "gq/cooking.h"

namespace {

using namespace gq;

template <class T> struct ContactsEdgeCrossing : ::testing::Test {
  static constexpr double kTol = std::is_same_v<T, double> ? 1e-9 : 2e-5;
  // The triangle x <= 0 side of the edge x = 0 (from (0,-5) to (0,5)), apex at (-10, 0), in the plane z = 0.
  static Triangle<T> halfPlaneTriangle() {
    Triangle<T> t;
    t.verts[0] = Vec3<T>(T(0), T(-5), T(0));
    t.verts[1] = Vec3<T>(T(0), T(5), T(0));
    t.verts[2] = Vec3<T>(T(-10), T(0), T(0));
    return t;
  }
  // Every expected point matched by one contact (and as many contacts as points), each with `separation` along +z.
  static void expectPoints(const ContactBuffer<T>& c, const std::vector<Eigen::Vector3d>& expected, double separation) {
    ASSERT_EQ(c.count, expected.size());
    for (std::uint32_t i = 0; i < c.count; ++i) {
      EXPECT_NEAR(double(c.contacts[i].normal.z()), 1.0, kTol);
      EXPECT_NEAR(double(c.contacts[i].separation), separation, kTol);
    }
    for (const Eigen::Vector3d& e : expected) {
      double nearest = 1e9;
      for (std::uint32_t i = 0; i < c.count; ++i)
        nearest = std::min(nearest, (c.contacts[i].position.template cast<double>() - e).norm());
      EXPECT_NEAR(nearest, 0.0, kTol) << "expected contact at " << e.transpose();
    }
  }
  static std::shared_ptr<const ConvexMesh<T>> cubeHull() {
    std::vector<Vec3<T>> cube;
    for (int i = 0; i < 8; ++i) cube.emplace_back(T(i & 1 ? 0.5 : -0.5), T(i & 2 ? 0.5 : -0.5), T(i & 4 ? 0.5 : -0.5));
    std::shared_ptr<const ConvexMesh<T>> hull;
    EXPECT_TRUE(cookConvexMesh(cube, hull).ok());
    return hull;
  }
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(ContactsEdgeCrossing, Scalars);

TYPED_TEST(ContactsEdgeCrossing, RestingBoxAcrossTheTriangleEdgeGetsTwoCornersAndTwoCrossings) {
  using T = TypeParam;
  // A unit box centred over the edge x = 0 at height 0.51: its bottom face spans x in [-0.5, 0.5]; the part over the
  // triangle is x in [-0.5, 0]: corners at x = -0.5 and crossings of the edges y = +-0.5 with x = 0.
  ContactBuffer<T> c;
  ASSERT_TRUE(generateTriangleContacts(Geometry<T>(BoxGeometry<T>(T(0.5), T(0.5), T(0.5))),
                                       Transform<T>(Vec3<T>(T(0), T(1), T(0.51))), this->halfPlaneTriangle(), 3u, c,
                                       TriangleContactSettings<T>{T(0.02), T(0.01), T(1)})
                  .ok());
  ASSERT_GT(c.count, 0u);
  this->expectPoints(c, {{-0.5, 0.5, 0.01}, {-0.5, 1.5, 0.01}, {0, 0.5, 0.01}, {0, 1.5, 0.01}}, 0.01);
}

TYPED_TEST(ContactsEdgeCrossing, PenetratingHullAcrossTheTriangleEdgeKeepsTheCrossingsAtItsDepth) {
  using T = TypeParam;
  // The cube hull 0.05 deep, straddling the edge with 0.2 of its bottom over the triangle (x in [-0.2, 0]).
  ContactBuffer<T> c;
  ASSERT_TRUE(generateTriangleContacts(Geometry<T>(ConvexMeshGeometry<T>(this->cubeHull())),
                                       Transform<T>(Vec3<T>(T(0.3), T(0), T(0.45))), this->halfPlaneTriangle(), 0u, c,
                                       TriangleContactSettings<T>{T(0.01), T(0.1), T(1)})
                  .ok());
  ASSERT_GT(c.count, 0u);
  this->expectPoints(c, {{-0.2, -0.5, -0.05}, {-0.2, 0.5, -0.05}, {0, -0.5, -0.05}, {0, 0.5, -0.05}}, -0.05);
}

TYPED_TEST(ContactsEdgeCrossing, EdgeOnBoxAcrossTheTriangleEdgeGetsBothEndsOfItsContactSegment) {
  using T = TypeParam;
  // A unit box turned 45 degrees about X rests on its bottom edge (along X, at y = 0), 0.01 above the plane. The edge
  // spans x in [-0.5, 0.5]; over the triangle x in [-0.5, 0]: its end at x = -0.5 and its crossing with x = 0.
  const double lift = 0.5 * std::sqrt(2.0) + 0.01;
  const Transform<T> pose(Vec3<T>(T(0), T(0), T(lift)), Quat<T>(Eigen::AngleAxis<T>(T(M_PI / 4), Vec3<T>::UnitX())));
  ContactBuffer<T> c;
  ASSERT_TRUE(generateTriangleContacts(Geometry<T>(BoxGeometry<T>(T(0.5), T(0.5), T(0.5))), pose,
                                       this->halfPlaneTriangle(), 0u, c,
                                       TriangleContactSettings<T>{T(0.02), T(0.01), T(1)})
                  .ok());
  ASSERT_GT(c.count, 0u);
  this->expectPoints(c, {{-0.5, 0, 0.01}, {0, 0, 0.01}}, 0.01);
}

TYPED_TEST(ContactsEdgeCrossing, CapsuleAcrossTheTriangleEdgeGetsItsEndAndTheCrossing) {
  using T = TypeParam;
  // A capsule (radius 0.2, half height 0.6 along X) lying 0.01 above the plane across the edge x = 0: the lowest line
  // of its surface spans x in [-0.6, 0.6]; over the triangle: its end at x = -0.6 and the crossing at x = 0.
  ContactBuffer<T> c;
  ASSERT_TRUE(generateTriangleContacts(Geometry<T>(CapsuleGeometry<T>(T(0.2), T(0.6))),
                                       Transform<T>(Vec3<T>(T(0), T(0), T(0.21))), this->halfPlaneTriangle(), 0u, c,
                                       TriangleContactSettings<T>{T(0.02), T(0.01), T(1)})
                  .ok());
  ASSERT_GT(c.count, 0u);
  this->expectPoints(c, {{-0.6, 0, 0.01}, {0, 0, 0.01}}, 0.01);
}

}  // namespace
