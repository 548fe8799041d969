// Hill climbing on hull adjacency is the support search of every hull with more than kHillClimbMinVertices
// vertices (now small hulls too): it must pick a vertex whose support value equals the exhaustive scan's exactly,
// from any start vertex, on qhull-cooked hulls, including ones with polygonal faces where the maximum is a face.
#include "gjk_test_shapes.h"

#include "gjk/gjk.h"
#include "gjk/support_map.h"
#include "gq/cooking.h"

namespace {

using namespace gjktest;

template <class T> class GjkHillClimb : public ::testing::Test {};
TYPED_TEST_SUITE(GjkHillClimb, Scalars);

// Exhaustive maximum of d.v computed the same way as the kernels (dot3), so equal values compare bitwise.
template <class T> T exhaustiveMaximum(const gq::ConvexMesh<T>& hull, const gq::Vec3<T>& d) {
  T best = -std::numeric_limits<T>::infinity();
  for (const auto& v : hull.vertices) best = std::max(best, gq::detail::dot3(v, d));
  return best;
}

// Hull as users get it: cooked by qhull (coplanar facets merged into polygons, adjacency along polygon edges).
template <class T> std::shared_ptr<const gq::ConvexMesh<T>> cooked(const std::vector<gq::Vec3<T>>& pts) {
  std::shared_ptr<const gq::ConvexMesh<T>> hull;
  EXPECT_TRUE(gq::cookConvexMesh(pts, hull).ok());
  return hull;
}

template <class T> void expectClimbIsExact(const gq::ConvexMesh<T>& hull, Rng& rng, int directions) {
  ASSERT_TRUE(gq::detail::hasAdjacency(hull));
  const auto n = static_cast<std::uint32_t>(hull.vertices.size());
  for (int i = 0; i < directions; ++i) {
    const gq::Vec3<T> d = rng.unit().cast<T>();
    const std::uint32_t start = static_cast<std::uint32_t>(i) % n;
    const std::uint32_t v = gq::detail::climbVertex(hull, d, start);
    ASSERT_LT(v, n);
    ASSERT_EQ(gq::detail::dot3(hull.vertices[v], d), exhaustiveMaximum(hull, d))
        << "direction " << i << " from vertex " << start << " on a hull of " << n << " vertices";
  }
}

TYPED_TEST(GjkHillClimb, ClimbFindsTheExhaustiveMaximumOnSmallRandomHulls) {
  using T = TypeParam;
  Rng rng(71);
  for (const int n : {9, 12, 16, 24, 30, 48, 64}) {
    const auto hull = cooked<T>(pointsOnEllipsoid<T>(rng, n, Eigen::Vector3d(1, 0.8, 0.6)));
    ASSERT_TRUE(hull);
    ASSERT_GT(hull->vertices.size(), gq::detail::kHillClimbMinVertices);
    expectClimbIsExact(*hull, rng, 3000);
  }
}

TYPED_TEST(GjkHillClimb, ClimbFindsTheExhaustiveMaximumOnHullsWithCoplanarFaces) {
  using T = TypeParam;
  Rng rng(72);
  // Hexagonal prism (12 vertices, two 6-gon faces) and a box with its face centres pushed out slightly (14).
  std::vector<gq::Vec3<T>> prism, studded;
  for (int k = 0; k < 6; ++k) {
    const double a = k * 3.14159265358979323846 / 3;
    for (const double z : {-0.5, 0.5}) prism.emplace_back(T(std::cos(a)), T(std::sin(a)), T(z));
  }
  for (int c = 0; c < 8; ++c) studded.emplace_back(T(c & 1 ? 1 : -1), T(c & 2 ? 1 : -1), T(c & 4 ? 1 : -1));
  for (int k = 0; k < 3; ++k)
    for (const double s : {-1.25, 1.25}) {
      gq::Vec3<T> p = gq::Vec3<T>::Zero();
      p[k] = T(s);
      studded.push_back(p);
    }
  for (const auto& pts : {prism, studded}) {
    const auto hull = cooked<T>(pts);
    ASSERT_TRUE(hull);
    ASSERT_EQ(hull->vertices.size(), pts.size());
    expectClimbIsExact(*hull, rng, 3000);
    // Axis directions make whole faces or edges maximal: ties must still give the maximum value.
    for (int k = 0; k < 3; ++k)
      for (const T s : {T(-1), T(1)}) {
        gq::Vec3<T> d = gq::Vec3<T>::Zero();
        d[k] = s;
        for (std::uint32_t start = 0; start < hull->vertices.size(); ++start)
          ASSERT_EQ(gq::detail::dot3(hull->vertices[gq::detail::climbVertex(*hull, d, start)], d), exhaustiveMaximum(*hull, d));
      }
  }
}

}  // namespace
