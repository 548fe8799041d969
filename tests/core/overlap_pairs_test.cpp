// overlap(), pair by pair (spec "Overlaps"): touching counts as overlapping, the plane is a solid half-space,
// unsupported pairs answer Unsupported with a message saying why, invalid input writes no output.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gq/custom.h"
#include "gq/query.h"
#include "overlap_test_support.h"

namespace gq::test {
namespace {

template <class T> class Overlap : public ::testing::Test {};
TYPED_TEST_SUITE(Overlap, Scalars);

// A small relative gap that float and double both resolve at unit scale.
template <class T> T gap() { return std::is_same_v<T, float> ? T(1e-5) : T(1e-12); }

TYPED_TEST(Overlap, SphereSphereTouchingCountsAsOverlapping) {
  using T = TypeParam;
  const Geometry<T> s = SphereGeometry<T>(T(0.5));
  EXPECT_TRUE(overlaps<T>(s, Transform<T>(), s, Transform<T>(Vec3<T>(1, 0, 0))));
  EXPECT_FALSE(overlaps<T>(s, Transform<T>(), s, Transform<T>(Vec3<T>(1 + 8 * gap<T>(), 0, 0))));
}

// Radii whose squares underflow T: |d| <= r is still decided on the sizes themselves (squared, a distance 1e6 radii
// away and the radius both rounded to 0 and read as touching), by overlap and penetration of sphere against sphere,
// box and capsule (found by fuzz_pair_queries: spheres 7e-304 and 2e-323 wide, 1.8e-284 apart). (Radii whose squares
// overflow are beyond the supported magnitude, which validation rejects.)
TYPED_TEST(Overlap, SpheresWhoseSquaredSizesUnderflowAreApartOrOverlappingByTheirSizes) {
  using T = TypeParam;
  const bool isFloat = std::is_same_v<T, float>;
  for (const T r : {T(isFloat ? 1e-25 : 1e-200), T(isFloat ? 1e-30 : 1e-300)}) {
    const T far = r * T(1e6);  // far apart relative to the radii (the square of either side leaves the range)
    const std::vector<Geometry<T>> others = {SphereGeometry<T>(r), BoxGeometry<T>(r, r, r), CapsuleGeometry<T>(r, r)};
    for (const Geometry<T>& other : others) {
      const Geometry<T> sphere = SphereGeometry<T>(r);
      const Transform<T> apart(Vec3<T>(0, far, 0)), touching(Vec3<T>(0, r, 0));
      EXPECT_FALSE(overlaps<T>(sphere, Transform<T>(), other, apart)) << r << " " << int(other.type());
      EXPECT_TRUE(overlaps<T>(sphere, Transform<T>(), other, touching)) << r << " " << int(other.type());
      PenetrationResult<T> pen;
      ASSERT_TRUE(computePenetration(pen, sphere, Transform<T>(), other, apart).ok());
      EXPECT_FALSE(pen.penetrating) << r << " " << int(other.type());
      ASSERT_TRUE(computePenetration(pen, sphere, Transform<T>(), other, touching).ok());
      EXPECT_TRUE(pen.penetrating) << r << " " << int(other.type());
      EXPECT_GT(pen.depth, T(0));
      EXPECT_LE(pen.depth, T(2.5) * r);
    }
  }
}

TYPED_TEST(Overlap, PlaneIsASolidHalfSpace) {
  using T = TypeParam;
  const Geometry<T> plane = PlaneGeometry<T>();
  const Transform<T> pose(Vec3<T>(0, 1, 0), Quat<T>(Eigen::AngleAxis<T>(T(M_PI / 2), Vec3<T>::UnitZ())));  // normal +Y at y = 1
  EXPECT_TRUE(overlaps<T>(SphereGeometry<T>(1), Transform<T>(Vec3<T>(0, -50, 0)), plane, pose));  // deep behind
  EXPECT_TRUE(overlaps<T>(SphereGeometry<T>(1), Transform<T>(Vec3<T>(0, 2, 0)), plane, pose));    // touching
  EXPECT_FALSE(overlaps<T>(SphereGeometry<T>(1), Transform<T>(Vec3<T>(0, 2 + 8 * gap<T>(), 0)), plane, pose));
  EXPECT_TRUE(overlaps<T>(plane, pose, CapsuleGeometry<T>(T(0.5), 1), Transform<T>(Vec3<T>(0, 1.5, 0), pose.q)));
  EXPECT_FALSE(overlaps<T>(plane, pose, CapsuleGeometry<T>(T(0.5), 1), Transform<T>(Vec3<T>(5, 1.6, 0))));
  EXPECT_TRUE(overlaps<T>(BoxGeometry<T>(1, 1, 1), Transform<T>(Vec3<T>(0, 2, 0)), plane, pose));
  EXPECT_FALSE(overlaps<T>(BoxGeometry<T>(1, 1, 1), Transform<T>(Vec3<T>(0, 2.01, 0)), plane, pose));
  const Geometry<T> oct = ConvexMeshGeometry<T>(octahedronHull<T>(1));
  EXPECT_TRUE(overlaps<T>(oct, Transform<T>(Vec3<T>(0, 1.99, 0)), plane, pose));
  EXPECT_FALSE(overlaps<T>(oct, Transform<T>(Vec3<T>(0, 2.01, 0)), plane, pose));
}

TYPED_TEST(Overlap, SphereCapsuleUsesDistanceToTheSegment) {
  using T = TypeParam;
  const Geometry<T> cap = CapsuleGeometry<T>(T(0.5), T(2));
  EXPECT_TRUE(overlaps<T>(SphereGeometry<T>(T(0.5)), Transform<T>(Vec3<T>(1.9, 0.99, 0)), cap, Transform<T>()));
  EXPECT_FALSE(overlaps<T>(SphereGeometry<T>(T(0.5)), Transform<T>(Vec3<T>(2.8, 0.7, 0)), cap, Transform<T>()));
}

TYPED_TEST(Overlap, SphereBoxCornerRegionUsesEuclideanDistance) {
  using T = TypeParam;
  const Geometry<T> box = BoxGeometry<T>(1, 1, 1);
  // Corner at (1,1,1): a sphere of radius 0.5 at (1.3,1.3,1.3) is sqrt(0.27) ~ 0.52 away: no overlap, although
  // its bounds overlap the box.
  EXPECT_FALSE(overlaps<T>(SphereGeometry<T>(T(0.5)), Transform<T>(Vec3<T>(1.3, 1.3, 1.3)), box, Transform<T>()));
  EXPECT_TRUE(overlaps<T>(SphereGeometry<T>(T(0.5)), Transform<T>(Vec3<T>(1.28, 1.28, 1.28)), box, Transform<T>()));
}

TYPED_TEST(Overlap, CapsuleCapsuleSkewAxes) {
  using T = TypeParam;
  const Geometry<T> cap = CapsuleGeometry<T>(T(0.25), T(1));
  const Quat<T> rz(Eigen::AngleAxis<T>(T(M_PI / 2), Vec3<T>::UnitZ()));
  EXPECT_TRUE(overlaps<T>(cap, Transform<T>(), cap, Transform<T>(Vec3<T>(0, 0, 0.5), rz)));   // touching
  EXPECT_FALSE(overlaps<T>(cap, Transform<T>(), cap, Transform<T>(Vec3<T>(0, 0, 0.51), rz)));
  // Beyond the end cap: distance from (1,0,0) to the other segment end region.
  EXPECT_FALSE(overlaps<T>(cap, Transform<T>(), cap, Transform<T>(Vec3<T>(1.6, 0, 0), rz)));
  EXPECT_TRUE(overlaps<T>(cap, Transform<T>(), cap, Transform<T>(Vec3<T>(1.5, 0, 0), rz)));
}

TYPED_TEST(Overlap, CapsuleBoxNearEdgeNeedsExactSegmentBoxDistance) {
  using T = TypeParam;
  const Geometry<T> box = BoxGeometry<T>(1, 1, 1);
  // Capsule parallel to the box's x edge at (y,z) = (1+d, 1+d): distance d*sqrt(2).
  EXPECT_TRUE(overlaps<T>(CapsuleGeometry<T>(T(0.3), 2), Transform<T>(Vec3<T>(0, 1.2, 1.2)), box, Transform<T>()));
  EXPECT_FALSE(overlaps<T>(CapsuleGeometry<T>(T(0.28), 2), Transform<T>(Vec3<T>(0, 1.2, 1.2)), box, Transform<T>()));
}

TYPED_TEST(Overlap, BoxBoxEdgeEdgeSeparationNeedsCrossProductAxis) {
  using T = TypeParam;
  const Quat<T> aboutY(Eigen::AngleAxis<T>(T(M_PI / 4), Vec3<T>::UnitY()));
  const Quat<T> aboutX(Eigen::AngleAxis<T>(T(M_PI / 4), Vec3<T>::UnitX()));
  const T c = T(2 * std::sqrt(2.0));
  const Geometry<T> box = BoxGeometry<T>(1, 1, 1);
  // Face axes alone do not separate these; only Y x X = -Z does.
  EXPECT_FALSE(overlaps<T>(box, Transform<T>(Vec3<T>(0, 0, 0), aboutY), box, Transform<T>(Vec3<T>(0, 0, c + T(0.01)), aboutX)));
  EXPECT_TRUE(overlaps<T>(box, Transform<T>(Vec3<T>(0, 0, 0), aboutY), box, Transform<T>(Vec3<T>(0, 0, c - T(0.01)), aboutX)));
}

TYPED_TEST(Overlap, ConvexPairsAgreeWithClosedFormHalfSpaces) {
  using T = TypeParam;
  const Geometry<T> oct = ConvexMeshGeometry<T>(octahedronHull<T>(1));
  const Geometry<T> tet = ConvexMeshGeometry<T>(cornerTetrahedron<T>(1));
  // Octahedron face x+y+z <= 1; the tetrahedron's corner 0 at t*(1,1,1)/sqrt3 is its closest point to it.
  const Vec3<T> n = Vec3<T>::Ones().normalized();
  const T plane = T(1 / std::sqrt(3.0));
  EXPECT_TRUE(overlaps<T>(oct, Transform<T>(), tet, Transform<T>(Vec3<T>(n * (plane - T(0.01))))));
  EXPECT_FALSE(overlaps<T>(oct, Transform<T>(), tet, Transform<T>(Vec3<T>(n * (plane + T(0.01))))));
  EXPECT_TRUE(overlaps<T>(SphereGeometry<T>(T(0.1)), Transform<T>(Vec3<T>(n * (plane + T(0.09)))), oct, Transform<T>()));
  EXPECT_FALSE(overlaps<T>(SphereGeometry<T>(T(0.1)), Transform<T>(Vec3<T>(n * (plane + T(0.11)))), oct, Transform<T>()));
  EXPECT_TRUE(overlaps<T>(BoxGeometry<T>(T(0.1), T(0.1), T(0.1)), Transform<T>(Vec3<T>(1.09, 0, 0)), oct, Transform<T>()));
  EXPECT_FALSE(overlaps<T>(BoxGeometry<T>(T(0.1), T(0.1), T(0.1)), Transform<T>(Vec3<T>(1.11, 0, 0)), oct, Transform<T>()));
  // Capsule along X beyond the tip (1,0,0) of the octahedron.
  EXPECT_TRUE(overlaps<T>(CapsuleGeometry<T>(T(0.2), 1), Transform<T>(Vec3<T>(2.19, 0, 0)), oct, Transform<T>()));
  EXPECT_FALSE(overlaps<T>(CapsuleGeometry<T>(T(0.2), 1), Transform<T>(Vec3<T>(2.21, 0, 0)), oct, Transform<T>()));
}

TYPED_TEST(Overlap, PlaneWithPlaneMeshOrHeightFieldIsNotDefinedBySpec) {
  using T = TypeParam;
  bool out = true;
  const Status s = overlap<T>(PlaneGeometry<T>(), Transform<T>(), PlaneGeometry<T>(), Transform<T>(), out);
  EXPECT_EQ(s.code, StatusCode::Unsupported);
  EXPECT_NE(s.toString().find("not defined by the spec"), std::string::npos) << s.toString();
  EXPECT_TRUE(out);  // untouched
}

TYPED_TEST(Overlap, InvalidInputWritesNoOutput) {
  using T = TypeParam;
  bool out = true;
  Status s = overlap<T>(SphereGeometry<T>(0), Transform<T>(), SphereGeometry<T>(1), Transform<T>(Vec3<T>(5, 0, 0)), out);
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  Transform<T> bad;
  bad.q = Quat<T>(2, 0, 0, 0);
  s = overlap<T>(SphereGeometry<T>(1), bad, SphereGeometry<T>(1), Transform<T>(Vec3<T>(5, 0, 0)), out);
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_TRUE(out);
}

// A convex custom shape (a sphere by support mapping) goes through GJK; a non-convex one is refused.
template <class T> class SupportSphere : public CustomGeometryCallbacks<T> {
 public:
  SupportSphere(T r, bool convex) : r_(r), convex_(convex) {}
  const char* name() const override { return "support sphere"; }
  Bounds3<T> localBounds() const override { return Bounds3<T>::fromCenterExtents(Vec3<T>::Zero(), Vec3<T>::Constant(r_)); }
  Vec3<T> support(const Vec3<T>& d) const override {
    const T n = d.norm();
    return n > T(0) ? Vec3<T>(d * (r_ / n)) : Vec3<T>(r_, 0, 0);
  }
  bool raycast(const Vec3<T>&, const Vec3<T>&, T, HitFlags, RaycastHit<T>&) const override { return false; }
  bool isConvex() const override { return convex_; }

 private:
  T r_;
  bool convex_;
};

// A box of half extent h by support mapping.
template <class T> class SupportBox : public CustomGeometryCallbacks<T> {
 public:
  explicit SupportBox(T h) : h_(h) {}
  const char* name() const override { return "support box"; }
  Bounds3<T> localBounds() const override { return Bounds3<T>::fromCenterExtents(Vec3<T>::Zero(), Vec3<T>::Constant(h_)); }
  Vec3<T> support(const Vec3<T>& d) const override {
    return Vec3<T>(d.x() < T(0) ? -h_ : h_, d.y() < T(0) ? -h_ : h_, d.z() < T(0) ? -h_ : h_);
  }
  bool raycast(const Vec3<T>&, const Vec3<T>&, T, HitFlags, RaycastHit<T>&) const override { return false; }

 private:
  T h_;
};

TYPED_TEST(Overlap, ConvexCustomGeometryUsesItsSupportMapping) {
  using T = TypeParam;
  const Geometry<T> custom = CustomGeometry<T>(std::make_shared<SupportSphere<T>>(T(1), true));
  EXPECT_TRUE(overlaps<T>(custom, Transform<T>(), BoxGeometry<T>(1, 1, 1), Transform<T>(Vec3<T>(1.9, 0, 0))));
  EXPECT_FALSE(overlaps<T>(custom, Transform<T>(), BoxGeometry<T>(1, 1, 1), Transform<T>(Vec3<T>(2.1, 0, 0))));
  EXPECT_TRUE(overlaps<T>(SphereGeometry<T>(1), Transform<T>(Vec3<T>(0, 1.9, 0)), custom, Transform<T>()));
  EXPECT_FALSE(overlaps<T>(SphereGeometry<T>(1), Transform<T>(Vec3<T>(0, 2.1, 0)), custom, Transform<T>()));
  EXPECT_TRUE(overlaps<T>(PlaneGeometry<T>(), Transform<T>(), custom, Transform<T>(Vec3<T>(0.9, 0, 0))));
  EXPECT_FALSE(overlaps<T>(PlaneGeometry<T>(), Transform<T>(), custom, Transform<T>(Vec3<T>(1.1, 0, 0))));
  const auto pen = penetration<T>(custom, Transform<T>(Vec3<T>(1.5, 0, 0)), BoxGeometry<T>(1, 1, 1), Transform<T>());
  ASSERT_TRUE(pen.penetrating);
  const double tol = std::is_same_v<T, float> ? 1e-3 : 1e-6;
  EXPECT_NEAR(double(pen.depth), 0.5, tol);
  EXPECT_NEAR(double(pen.direction.x()), 1.0, tol);
  const Geometry<T> nonConvex = CustomGeometry<T>(std::make_shared<SupportSphere<T>>(T(1), false));
  bool out = false;
  EXPECT_EQ(overlap<T>(nonConvex, Transform<T>(), BoxGeometry<T>(1, 1, 1), Transform<T>(), out).code, StatusCode::Unsupported);
  EXPECT_EQ(overlap<T>(PlaneGeometry<T>(), Transform<T>(), nonConvex, Transform<T>(), out).code, StatusCode::Unsupported);
  PenetrationResult<T> r;
  EXPECT_EQ(computePenetration<T>(r, nonConvex, Transform<T>(), SphereGeometry<T>(1), Transform<T>()).code, StatusCode::Unsupported);
  // Custom against custom and against a plane.
  const Geometry<T> customBox = CustomGeometry<T>(std::make_shared<SupportBox<T>>(T(1)));
  const auto cc = penetration<T>(customBox, Transform<T>(Vec3<T>(0.2, 0.1, 1.5)), customBox, Transform<T>());
  ASSERT_TRUE(cc.penetrating);
  EXPECT_NEAR(double(cc.depth), 0.5, tol);
  EXPECT_NEAR(double(cc.direction.z()), 1.0, tol);
  const auto pc = penetration<T>(PlaneGeometry<T>(), Transform<T>(), custom, Transform<T>(Vec3<T>(0.75, 0, 0)));
  ASSERT_TRUE(pc.penetrating);
  EXPECT_NEAR(double(pc.depth), 0.25, tol);
  EXPECT_NEAR(double(pc.direction.x()), -1.0, tol);
}

TYPED_TEST(Overlap, ConvexVsMeshPenetrationUsesTheSpecsIterativeAlgorithmAndSpecExclusionsSaySo) {
  using T = TypeParam;
  std::shared_ptr<const TriangleMesh<T>> mesh;
  ASSERT_TRUE(cookTriangleMesh<T>({Vec3<T>(0, 0, 0), Vec3<T>(1, 0, 0), Vec3<T>(0, 1, 0)}, {{0, 1, 2}}, mesh).ok());
  const Geometry<T> tri = TriangleMeshGeometry<T>(mesh);
  bool out = false;
  // A unit sphere whose centre is 0.5 above the triangle (normal +Z): pushed out along +Z by 0.5.
  const Transform<T> above(Vec3<T>(T(0.2), T(0.2), T(0.5)));
  PenetrationResult<T> pen;
  ASSERT_TRUE(computePenetration<T>(pen, SphereGeometry<T>(1), above, tri, Transform<T>()).ok());
  ASSERT_TRUE(pen.penetrating);
  EXPECT_NEAR(double(pen.depth), 0.5, 1e-4);
  EXPECT_NEAR(double(pen.direction.z()), 1.0, 1e-4);
  PenetrationResult<T> swappedPen;
  ASSERT_TRUE(computePenetration<T>(swappedPen, tri, Transform<T>(), SphereGeometry<T>(1), above).ok());
  EXPECT_NEAR(double(swappedPen.depth), double(pen.depth), 1e-6);
  EXPECT_NEAR(double(swappedPen.direction.z()), -1.0, 1e-4);
  out = false;
  ASSERT_TRUE(overlap<T>(tri, Transform<T>(), PlaneGeometry<T>(), Transform<T>(), out).ok());
  EXPECT_TRUE(out);  // vertices at x = 0 touch the half-space x <= 0
  PenetrationResult<T> r;
  const Status m = computePenetration<T>(r, tri, Transform<T>(), tri, Transform<T>());
  EXPECT_NE(m.toString().find("not defined by the spec"), std::string::npos) << m.toString();
}

}  // namespace
}  // namespace gq::test
