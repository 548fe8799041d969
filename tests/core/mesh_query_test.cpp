// World bounds of triangle-mesh instances: exactly the AABB of the scaled, posed vertices.
#include <gtest/gtest.h>

#include "bounds/bounds.h"
#include "mesh_test_helpers.h"

namespace gq {
namespace {

using meshtest::Scalars;
using LD = long double;

template <class T> class MeshBounds : public ::testing::Test {};
TYPED_TEST_SUITE(MeshBounds, Scalars);

// Long-double AABB of every vertex mapped by pose and scale, and the check against the kernel.
template <class T> void expectExactBounds(const MeshData<T>& m, const MeshScale<T>& scale, const Transform<T>& pose) {
  const auto mesh = meshtest::cook(m.vertices, m.triangles);
  const Bounds3<T> b = detail::boundsTriangleMesh(TriangleMeshGeometry<T>(mesh, scale), pose);
  const Eigen::Matrix<LD, 3, 3> S = scale.toMatrix().template cast<LD>();
  const Eigen::Matrix<LD, 3, 3> R = pose.q.toRotationMatrix().template cast<LD>();
  Eigen::AlignedBox<LD, 3> ref;
  for (const auto& v : m.vertices) ref.extend(R * (S * v.template cast<LD>()) + pose.p.template cast<LD>());
  const LD tol = (std::is_same_v<T, float> ? LD(1e-6) : LD(1e-14)) * (ref.diagonal().norm() + pose.p.norm());
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(LD(b.min[k]), ref.min()[k], tol);
    EXPECT_NEAR(LD(b.max[k]), ref.max()[k], tol);
  }
}

TYPED_TEST(MeshBounds, BoundsAreTheExactAabbOfScaledPosedVertices) {
  using T = TypeParam;
  const MeshScale<T> scale(Vec3<T>(T(1.7), T(-0.6), T(2.5)),
                           Quat<T>(Eigen::AngleAxis<T>(T(0.9), Vec3<T>(1, -2, 1).normalized())));
  const Transform<T> pose(Vec3<T>(3, -1, 2), Quat<T>(Eigen::AngleAxis<T>(T(2.3), Vec3<T>(2, 1, 1).normalized())));
  expectExactBounds(meshtest::icosphere<T>(2), scale, pose);
  expectExactBounds(meshtest::quadStack<T>(1), scale, pose);  // flat: no 3D hull, every vertex counts
}

// The same on the bunny from the shared data folder (skipped when it is missing).
template <class T> class MeshBoundsData : public ::testing::Test {};
TYPED_TEST_SUITE(MeshBoundsData, Scalars);

TYPED_TEST(MeshBoundsData, BoundsAreTheExactAabbOfTheScaledPosedBunny) {
  using T = TypeParam;
  GQ_REQUIRE_BUNNY();
  const MeshScale<T> scale(Vec3<T>(T(1.7), T(-0.6), T(2.5)),
                           Quat<T>(Eigen::AngleAxis<T>(T(0.9), Vec3<T>(1, -2, 1).normalized())));
  const Transform<T> pose(Vec3<T>(3, -1, 2), Quat<T>(Eigen::AngleAxis<T>(T(2.3), Vec3<T>(2, 1, 1).normalized())));
  expectExactBounds(meshtest::bunny<T>(), scale, pose);
}

}  // namespace
}  // namespace gq
