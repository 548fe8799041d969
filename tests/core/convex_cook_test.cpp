// Convex hull cooking (qhull): polygon faces, hull-only vertices, adjacency, bounds, centre and its balls, and
// rejected inputs.
#include <gtest/gtest.h>

#include <limits>
#include <set>

#include "gq/cooking.h"
#include "test_util.h"

namespace gq {
namespace {

template <class T> class ConvexCook : public ::testing::Test {};
TYPED_TEST_SUITE(ConvexCook, test::Scalars);

template <class T> std::vector<Vec3<T>> cubeCorners(T h) {
  std::vector<Vec3<T>> pts;
  for (int i = 0; i < 8; ++i) pts.emplace_back((i & 1) ? h : -h, (i & 2) ? h : -h, (i & 4) ? h : -h);
  return pts;
}

// Checks the invariants every cooked hull must satisfy: unit outward normals, planar counter-clockwise polygons,
// every input point behind every plane, CSR adjacency, bounds and an interior centre. Returns the edge count.
template <class T> std::size_t checkHull(const ConvexMesh<T>& hull, const std::vector<Vec3<T>>& input) {
  // qhull merges facets within its round-off, which scales with the largest coordinate, not the hull size.
  const double size = double((hull.localBounds.max - hull.localBounds.min).norm()) +
                      double(hull.localBounds.max.cwiseAbs().cwiseMax(hull.localBounds.min.cwiseAbs()).maxCoeff());
  const double eps = (std::is_same_v<T, float> ? 1e-5 : 1e-11) * size;
  for (const HullPolygon<T>& poly : hull.polygons) {
    EXPECT_NEAR(double(poly.normal.norm()), 1.0, 1e-6);
    EXPECT_GE(poly.indexCount, 3u);
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    for (std::uint32_t k = 0; k < poly.indexCount; ++k) {
      const Eigen::Vector3d a = hull.vertices[hull.polygonVertices[poly.indexBase + k]].template cast<double>();
      const Eigen::Vector3d b =
          hull.vertices[hull.polygonVertices[poly.indexBase + (k + 1) % poly.indexCount]].template cast<double>();
      newell += a.cross(b);
      EXPECT_NEAR(poly.normal.template cast<double>().dot(a) + double(poly.d), 0.0, eps);  // vertex on its plane
    }
    EXPECT_GT(newell.dot(poly.normal.template cast<double>()), 0.0) << "polygon not counter-clockwise from outside";
    for (const Vec3<T>& p : input) EXPECT_LE(double(poly.normal.dot(p) + poly.d), eps);
    EXPECT_LT(double(poly.normal.dot(hull.center) + poly.d), 0.0) << "centre not strictly inside";
  }
  for (const Vec3<T>& v : hull.vertices) {
    EXPECT_TRUE(std::find(input.begin(), input.end(), v) != input.end()) << "hull vertex is not an input point";
    EXPECT_TRUE(hull.localBounds.contains(v));
  }
  // The cooked balls: every vertex in the outer one, the inner one behind every plane.
  const Eigen::Vector3d c = hull.center.template cast<double>();
  for (const Vec3<T>& v : hull.vertices) EXPECT_LE((v.template cast<double>() - c).norm(), double(hull.outerRadius));
  for (const HullPolygon<T>& poly : hull.polygons)
    EXPECT_GE(-(poly.normal.template cast<double>().dot(c) + double(poly.d)), double(hull.innerRadius));
  EXPECT_GT(hull.innerRadius, T(0));
  EXPECT_EQ(hull.adjacencyOffsets.size(), hull.vertices.size() + 1);
  EXPECT_EQ(hull.adjacencyOffsets.back(), hull.adjacency.size());
  for (std::size_t i = 0; i < hull.vertices.size(); ++i) {  // symmetric, at least 3 neighbours (a 3-D vertex)
    EXPECT_GE(hull.adjacencyOffsets[i + 1] - hull.adjacencyOffsets[i], 3u);
    for (std::uint32_t k = hull.adjacencyOffsets[i]; k < hull.adjacencyOffsets[i + 1]; ++k) {
      const std::uint32_t j = hull.adjacency[k];
      const auto first = hull.adjacency.begin() + hull.adjacencyOffsets[j];
      const auto last = hull.adjacency.begin() + hull.adjacencyOffsets[j + 1];
      EXPECT_TRUE(std::find(first, last, std::uint32_t(i)) != last);
    }
  }
  return hull.adjacency.size() / 2;
}

TYPED_TEST(ConvexCook, CubeWithInteriorPointsHasEightVerticesAndSixQuads) {
  using T = TypeParam;
  std::vector<Vec3<T>> pts = cubeCorners(T(1));
  test::Rng rng(1);
  for (int i = 0; i < 50; ++i) pts.push_back(rng.inBox<T>(0.9));
  pts.push_back(Vec3<T>(0, 0, 1));  // on a face: coplanar, not a vertex
  std::shared_ptr<const ConvexMesh<T>> hull;
  ASSERT_TRUE(cookConvexMesh(pts, hull).ok());
  EXPECT_EQ(hull->vertices.size(), 8u);
  ASSERT_EQ(hull->polygons.size(), 6u);
  std::set<std::pair<int, int>> normals;
  for (const HullPolygon<T>& poly : hull->polygons) {
    EXPECT_EQ(poly.indexCount, 4u);
    int axis;
    poly.normal.cwiseAbs().maxCoeff(&axis);
    EXPECT_NEAR(std::abs(poly.normal[axis]), T(1), T(1e-6));
    EXPECT_NEAR(poly.d, T(-1), T(1e-6));
    normals.insert({axis, poly.normal[axis] > 0 ? 1 : -1});
  }
  EXPECT_EQ(normals.size(), 6u);
  EXPECT_EQ(checkHull(*hull, pts), 12u);
  EXPECT_EQ(hull->localBounds.min, Vec3<T>::Constant(T(-1)));
  EXPECT_EQ(hull->localBounds.max, Vec3<T>::Constant(T(1)));
  EXPECT_LT(hull->center.norm(), T(1e-6));
  // The balls are tight on a cube about its centre: the inscribed ball touches the faces, the outer one the corners.
  EXPECT_NEAR(hull->innerRadius, T(1), T(1e-5));
  EXPECT_NEAR(hull->outerRadius, std::sqrt(T(3)), T(1e-5));
}

TYPED_TEST(ConvexCook, RandomPointCloudsLieInsideEveryPlane) {
  using T = TypeParam;
  test::Rng rng(2);
  for (int cloud = 0; cloud < 20; ++cloud) {
    std::vector<Vec3<T>> pts;
    const int n = 4 + cloud * 25;
    const Vec3<T> offset = rng.inBox<T>(100);
    for (int i = 0; i < n; ++i) pts.push_back(offset + (cloud % 2 ? rng.unitVector<T>() * T(3) : rng.inBox<T>(2)));
    std::shared_ptr<const ConvexMesh<T>> hull;
    const Status s = cookConvexMesh(pts, hull);
    ASSERT_TRUE(s.ok()) << s.toString();
    const std::size_t edges = checkHull(*hull, pts);
    // Euler's formula for a convex polyhedron: V - E + F = 2.
    EXPECT_EQ(hull->vertices.size() + hull->polygons.size(), edges + 2);
  }
}

TYPED_TEST(ConvexCook, CoplanarTrianglesMergeIntoOnePolygon) {
  using T = TypeParam;
  // A square pyramid: the base is one quad even though qhull sees four coplanar base points.
  std::vector<Vec3<T>> pts = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 2}, {T(0.3), T(-0.2), 0}};
  std::shared_ptr<const ConvexMesh<T>> hull;
  ASSERT_TRUE(cookConvexMesh(pts, hull).ok());
  EXPECT_EQ(hull->vertices.size(), 5u);
  EXPECT_EQ(hull->polygons.size(), 5u);
  int quads = 0;
  for (const HullPolygon<T>& poly : hull->polygons) quads += poly.indexCount == 4;
  EXPECT_EQ(quads, 1);
  checkHull(*hull, pts);
}

TYPED_TEST(ConvexCook, DegenerateInputsAreRejectedWithAMessage) {
  using T = TypeParam;
  const T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
  struct Case {
    const char* what;
    std::vector<Vec3<T>> pts;
    StatusCode code;
  };
  const std::vector<Case> cases = {
      {"three points", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, StatusCode::DegenerateMesh},
      {"empty", {}, StatusCode::DegenerateMesh},
      {"coplanar", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {T(0.5), T(0.2), 0}}, StatusCode::DegenerateMesh},
      {"collinear", {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}}, StatusCode::DegenerateMesh},
      {"coincident", {{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}, StatusCode::DegenerateMesh},
      {"nan", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, nan}}, StatusCode::InvalidArgument},
      {"inf", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, inf}}, StatusCode::InvalidArgument},
  };
  for (const Case& c : cases) {
    std::shared_ptr<const ConvexMesh<T>> hull;
    const Status s = cookConvexMesh(c.pts, hull);
    EXPECT_EQ(s.code, c.code) << c.what << ": " << s.toString();
    EXPECT_STRNE(s.message(), "") << c.what;
    EXPECT_EQ(hull, nullptr) << c.what << ": output written on failure";
  }
}

TYPED_TEST(ConvexCook, QhullPrintsNothing) {
  using T = TypeParam;
  const std::vector<Vec3<T>> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  std::shared_ptr<const ConvexMesh<T>> hull, cube;
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  const Status s = cookConvexMesh(flat, hull);
  const Status ok = cookConvexMesh(cubeCorners(T(1)), cube);
  const std::string out = ::testing::internal::GetCapturedStdout();
  const std::string err = ::testing::internal::GetCapturedStderr();
  EXPECT_FALSE(s.ok());
  EXPECT_TRUE(ok.ok());
  EXPECT_NE(s.toString().find("qhull: QH"), std::string::npos) << "qhull's reason belongs in the status: " << s.toString();
  EXPECT_EQ(out, "");
  EXPECT_EQ(err, "");
}

}  // namespace
}  // namespace gq
