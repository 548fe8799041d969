// The mesh surface the pair and mesh queries walk (mesh_pairs/surface.h) and the query shape they test triangles
// with (mesh_pairs/shape_triangle.h): the float culling box rounds outward exactly as std::nextafter, a surface
// without rotation or scale hands out the same world triangles as getTriangle, and a hull's world bounds (computed on
// the first ask) are its bounds.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>

#include "gq/cooking.h"
#include "gq/mesh_query.h"
#include "mesh_test_helpers.h"

#include "bounds/bounds.h"
#include "mesh_pairs/shape_triangle.h"
#include "mesh_pairs/surface.h"

namespace gq::meshtest {
namespace {

bool sameFloat(float a, float b) {
  return std::isnan(a) ? std::isnan(b) : std::memcmp(&a, &b, sizeof a) == 0;  // +0 and -0 differ
}

void expectStepsAsNextafter(float f) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  EXPECT_TRUE(sameFloat(detail::floatBelow(f), std::nextafter(f, -inf))) << f;
  EXPECT_TRUE(sameFloat(detail::floatAbove(f), std::nextafter(f, inf))) << f;
}

TEST(MeshSurfaceFloatBounds, CullingBoxRoundsOutwardAsNextafter) {
  constexpr float inf = std::numeric_limits<float>::infinity();
  for (float f : {0.0f, -0.0f, 1.0f, -1.0f, std::numeric_limits<float>::denorm_min(),
                  -std::numeric_limits<float>::denorm_min(), std::numeric_limits<float>::min(),
                  -std::numeric_limits<float>::min(), std::numeric_limits<float>::max(),
                  -std::numeric_limits<float>::max(), inf, -inf, std::numeric_limits<float>::quiet_NaN()})
    expectStepsAsNextafter(f);
  std::mt19937 rng(7);
  for (int k = 0; k < 100000; ++k) {  // every exponent and sign: random bit patterns
    const std::uint32_t bits = rng();
    float f;
    std::memcpy(&f, &bits, sizeof f);
    expectStepsAsNextafter(f);
  }
}

template <class T> class MeshSurfaceTriangles : public ::testing::Test {};
TYPED_TEST_SUITE(MeshSurfaceTriangles, Scalars);

// Translated only, the surface's triangles skip the product with the identity: they must still be getTriangle's,
// bit for bit (getTriangle rotates by the identity quaternion and adds the translation). Rotated, the general product
// gives them up to rounding.
TYPED_TEST(MeshSurfaceTriangles, ATranslatedSurfacesTrianglesAreGetTrianglesWorldTriangles) {
  using T = TypeParam;
  const MeshData<T> data = icosphere<T>(2);
  const TriangleMeshGeometry<T> mesh(cook<T>(data.vertices, data.triangles));
  const T tol = T(16) * std::numeric_limits<T>::epsilon() * T(10);  // |world vertex| <= |t| + 1 < 10
  const Transform<T> translated(Vec3<T>(T(3.25), T(-1.5), T(7)));
  const Transform<T> rotated(Vec3<T>(T(3.25), T(-1.5), T(7)), Quat<T>(T(0.8), T(0.2), T(-0.4), T(0.4)).normalized());
  for (const Transform<T>& pose : {translated, rotated}) {
    const detail::MeshSurface<T> surface(mesh, pose);
    for (std::uint32_t cooked = 0; cooked < mesh.mesh->triangles.size(); ++cooked) {
      Triangle<T> expected;
      ASSERT_TRUE(getTriangle(mesh, pose, surface.inputIndex(cooked), expected).ok());
      const Triangle<T> got = surface.triangle(cooked);
      for (int k = 0; k < 3; ++k) {
        if (&pose == &translated) EXPECT_EQ(got.verts[k], expected.verts[k]) << cooked << " vertex " << k;
        else EXPECT_LE((got.verts[k] - expected.verts[k]).norm(), tol) << cooked << " vertex " << k;
      }
    }
  }
}

// A hull's world bounds wait for the first ask (overlap tests never need them); asked, they are boundsConvex's, and
// the culling box holds them.
TYPED_TEST(MeshSurfaceTriangles, AHullQueryShapesBoundsOnFirstAskAreItsWorldBounds) {
  using T = TypeParam;
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  std::vector<Vec3<T>> points;
  for (int k = 0; k < 40; ++k) points.push_back(Vec3<double>(normal(rng), normal(rng), normal(rng)).cast<T>());
  std::shared_ptr<const ConvexMesh<T>> hull;
  ASSERT_TRUE(cookConvexMesh(points, hull).ok());
  const ConvexMeshGeometry<T> g(hull, MeshScale<T>(Vec3<T>(T(2), T(0.5), T(1))));
  const Transform<T> pose(Vec3<T>(T(1), T(2), T(-3)), Quat<T>(T(0.6), T(0.0), T(0.8), T(0.0)));
  const Geometry<T> geometry(g);  // outlives the query shape, which reads the hull from it
  const detail::TriangleQueryShape<T> shape(geometry, pose);
  const Bounds3<T> expected = detail::boundsConvex(g, pose);
  EXPECT_EQ(shape.worldBounds().min, expected.min);
  EXPECT_EQ(shape.worldBounds().max, expected.max);
  const Bounds3<T> cull = shape.cullBounds();
  EXPECT_TRUE((cull.min.array() <= expected.min.array()).all() && (cull.max.array() >= expected.max.array()).all());
}

}  // namespace
}  // namespace gq::meshtest
