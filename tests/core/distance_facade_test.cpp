// gq::distance façade: validation, unsupported cells, and the mirrored-pair wrapper.
#include "gjk_test_shapes.h"

#include "gq/custom.h"

namespace {

using namespace gjktest;

template <class T> class DistanceFacade : public ::testing::Test {};
TYPED_TEST_SUITE(DistanceFacade, Scalars);

template <class T> gq::DistanceResult<T> sentinel() {
  gq::DistanceResult<T> r;
  r.distance = T(42);
  r.normal = gq::Vec3<T>(T(7), T(7), T(7));
  return r;
}
template <class T> void expectUntouched(const gq::DistanceResult<T>& r) {
  EXPECT_EQ(r.distance, T(42));
  EXPECT_EQ(r.normal, gq::Vec3<T>(T(7), T(7), T(7)));
}

TYPED_TEST(DistanceFacade, InvalidInputIsRejectedAndWritesNothing) {
  using T = TypeParam;
  auto r = sentinel<T>();
  gq::Transform<T> bad;
  bad.p.x() = std::numeric_limits<T>::quiet_NaN();
  EXPECT_EQ(gq::distance(r, sphere<T>(1), bad, sphere<T>(1), gq::Transform<T>()).code, gq::StatusCode::InvalidArgument);
  gq::Transform<T> unnormalised;
  unnormalised.q = gq::Quat<T>(T(2), T(0), T(0), T(0));
  EXPECT_EQ(gq::distance(r, sphere<T>(1), gq::Transform<T>(), box<T>(Eigen::Vector3d(1, 1, 1)), unnormalised).code,
            gq::StatusCode::InvalidArgument);
  EXPECT_EQ(gq::distance(r, sphere<T>(-1), gq::Transform<T>(), sphere<T>(1), gq::Transform<T>()).code,
            gq::StatusCode::InvalidArgument);
  expectUntouched(r);
}

TYPED_TEST(DistanceFacade, PlanePlaneAndSurfaceSurfacePairsWithAHeightFieldAreUnsupported) {
  using T = TypeParam;
  auto r = sentinel<T>();
  const gq::Geometry<T> plane = gq::PlaneGeometry<T>();
  EXPECT_EQ(gq::distance(r, plane, gq::Transform<T>(), plane, gq::Transform<T>()).code, gq::StatusCode::Unsupported);
  std::shared_ptr<const gq::TriangleMesh<T>> cooked;
  ASSERT_TRUE(gq::cookTriangleMesh<T>({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, cooked).ok());
  const gq::Geometry<T> mesh = gq::TriangleMeshGeometry<T>(cooked);
  gq::HeightFieldDesc<T> desc;
  desc.rows = desc.columns = 2;
  desc.heights = {T(0), T(0), T(0), T(0)};
  std::shared_ptr<const gq::HeightField<T>> field;
  ASSERT_TRUE(gq::cookHeightField(desc, field).ok());
  const gq::Geometry<T> hf = gq::HeightFieldGeometry<T>(field, T(1), T(1), T(1));
  EXPECT_EQ(gq::distance(r, mesh, gq::Transform<T>(), hf, gq::Transform<T>()).code, gq::StatusCode::Unsupported);
  EXPECT_EQ(gq::distance(r, hf, gq::Transform<T>(), hf, gq::Transform<T>()).code, gq::StatusCode::Unsupported);
  expectUntouched(r);
  // Convex shapes against surfaces are answered (mesh-pair task).
  EXPECT_TRUE(gq::distance(r, sphere<T>(1), gq::Transform<T>(), mesh, gq::Transform<T>()).ok());
  EXPECT_TRUE(gq::distance(r, hf, gq::Transform<T>(), sphere<T>(1), gq::Transform<T>()).ok());
}

template <class T> class Bumpy : public gq::CustomGeometryCallbacks<T> {
 public:
  const char* name() const override { return "bumpy"; }
  gq::Bounds3<T> localBounds() const override { return gq::Bounds3<T>::fromCenterExtents(gq::Vec3<T>::Zero(), gq::Vec3<T>::Ones()); }
  gq::Vec3<T> support(const gq::Vec3<T>& d) const override { return d.normalized(); }
  bool raycast(const gq::Vec3<T>&, const gq::Vec3<T>&, T, gq::HitFlags, gq::RaycastHit<T>&) const override { return false; }
  bool isConvex() const override { return false; }
};

TYPED_TEST(DistanceFacade, NonConvexCustomGeometryIsUnsupported) {
  using T = TypeParam;
  auto r = sentinel<T>();
  const gq::Geometry<T> custom = gq::CustomGeometry<T>(std::make_shared<Bumpy<T>>());
  EXPECT_EQ(gq::distance(r, custom, gq::Transform<T>(), sphere<T>(1), gq::Transform<T>()).code, gq::StatusCode::Unsupported);
  expectUntouched(r);
}

// Every supported pair in both orders: same distance, exchanged witnesses, opposite normals.
TYPED_TEST(DistanceFacade, SwappedPairFlipsWitnessesAndNormal) {
  using T = TypeParam;
  Rng rng(31);
  const auto hull = makeHull<T>(pointsOnEllipsoid<T>(rng, 16, Eigen::Vector3d(0.6, 0.5, 0.4)));
  const std::vector<gq::Geometry<T>> shapes = {sphere<T>(0.4), gq::PlaneGeometry<T>(), capsule<T>(0.3, 0.5),
                                               box<T>(Eigen::Vector3d(0.4, 0.3, 0.5)), gq::ConvexMeshGeometry<T>(hull)};
  for (std::size_t i = 0; i < shapes.size(); ++i)
    for (std::size_t j = 0; j < shapes.size(); ++j) {
      if (i == 1 && j == 1) continue;  // plane-plane: unsupported
      for (int k = 0; k < 20; ++k) {
        const auto p0 = randomPose<T>(rng, 1.5), p1 = randomPose<T>(rng, 1.5);
        gq::DistanceResult<T> a, b;
        ASSERT_TRUE(gq::distance(a, shapes[i], p0, shapes[j], p1).ok()) << i << " " << j;
        ASSERT_TRUE(gq::distance(b, shapes[j], p1, shapes[i], p0).ok()) << i << " " << j;
        EXPECT_NEAR(double(a.distance), double(b.distance), kGjkTol<T>) << i << " " << j;
        if (std::abs(double(a.distance)) < 1e-3) continue;  // touching: witnesses need not be unique
        EXPECT_LE(double((toL(a.point0) - toL(b.point1)).norm()), 1e3 * kGjkTol<T>) << i << " " << j;
        EXPECT_LE(double((toL(a.normal) + toL(b.normal)).norm()), 1e3 * kGjkTol<T>) << i << " " << j;
        expectConsistent(a, kGjkTol<T>);
      }
    }
}

}  // namespace
