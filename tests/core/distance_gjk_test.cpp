// gq::distance on the GJK/EPA pairs against exact brute-force references over polytope feature pairs (long double).
#include "gjk_test_shapes.h"

#include "gjk/gjk.h"
#include "gq/custom.h"

namespace {

using namespace gjktest;

template <class T> class DistanceGjk : public ::testing::Test {};
TYPED_TEST_SUITE(DistanceGjk, Scalars);

constexpr int kPoses = 1000;

// A core polytope (box, hull, segment or point) with the radius that rounds it.
struct RoundedPolytope {
  Polytope core;
  L margin = 0;
};

// Exact signed distance of two rounded polytopes: separated cores -> feature distance - margins; intersecting
// cores -> -(SAT depth + margins).
inline L exactSignedDistance(const RoundedPolytope& a, const RoundedPolytope& b) {
  const L sat = polytopePenetration(a.core, b.core);
  if (sat < 0) return polytopeDistance(a.core, b.core) - a.margin - b.margin;
  return -(sat + a.margin + b.margin);
}

// Signed distance of x from a rounded polytope's surface, valid near the surface.
inline L surfaceResidual(const VL& x, const RoundedPolytope& p) {
  if (p.core.tris.empty()) {  // point or segment: distance to the core minus the radius
    const VL& a = p.core.v.front();
    const VL& b = p.core.v.back();
    return pointSegment(x, a, b) - p.margin;
  }
  return signedDistanceToPolytope(x, p.core) - p.margin;
}

template <class T> RoundedPolytope roundedBox(const Eigen::Vector3d& h, const gq::Transform<T>& pose) {
  return {boxPolytope<T>(h.cast<T>(), pose), 0};
}
template <class T> RoundedPolytope roundedCapsule(const gq::CapsuleGeometry<T>& c, const gq::Transform<T>& pose) {
  const auto [a, b] = capsuleSegment(c, pose);
  RoundedPolytope p;
  p.core.v = {a, b};
  p.core.edges = {{0, 1}};
  p.margin = L(c.radius);
  return p;
}
template <class T> RoundedPolytope roundedSphere(T radius, const gq::Transform<T>& pose) {
  RoundedPolytope p;
  p.core.v = {toL(pose).p};
  p.margin = L(radius);
  return p;
}
template <class T> RoundedPolytope roundedHull(const gq::ConvexMesh<T>& mesh, const gq::MeshScale<T>& scale,
                                               const gq::Transform<T>& pose) {
  RoundedPolytope p{hullPolytope(mesh, gq::Transform<T>()), 0};
  const Eigen::Matrix<L, 3, 3> S = scale.toMatrix().template cast<L>();
  const PoseL t = toL(pose);
  for (auto& v : p.core.v) v = t.apply(S * v);
  return p;
}

// One vertex on each half-axis at a random distance: the FCL adapter tests' convex shape, with long flat faces.
template <class T> std::vector<gq::Vec3<T>> randomOctahedron(Rng& rng) {
  std::vector<gq::Vec3<T>> pts;
  for (int axis = 0; axis < 3; ++axis)
    for (const double side : {1.0, -1.0}) {
      gq::Vec3<T> p = gq::Vec3<T>::Zero();
      p[axis] = T(side * rng.uniform(0.35, 0.8));
      pts.push_back(p);
    }
  return pts;
}

// Separation of the two rounded polytopes along unit n (from r0 towards r1): what a plane normal to n proves.
inline L gapAlong(const VL& n, const RoundedPolytope& r0, const RoundedPolytope& r1) {
  L hi0 = -std::numeric_limits<L>::infinity(), lo1 = std::numeric_limits<L>::infinity();
  for (const VL& v : r0.core.v) hi0 = std::max(hi0, n.dot(v));
  for (const VL& v : r1.core.v) lo1 = std::min(lo1, n.dot(v));
  return lo1 - hi0 - r0.margin - r1.margin;
}

// A separated result's normal is the separating direction: the gap along it is the distance. Witnesses rounded to T
// (coordinates of a few units: |error of point1 - point0| of a few eps) tilt the normal by that over the distance,
// and a tilt costs up to the shapes' extent times the angle: the bound widens as 1/distance near touching.
template <class T> constexpr double kWitnessRounding = 12 * double(std::numeric_limits<T>::epsilon());
template <class T> double normalCertificateTolerance(double distance) {
  return kGjkTol<T> + kWitnessRounding<T> / distance;
}

// Runs distance both ways and checks value, witnesses on the surfaces, the normal as a separating direction, and
// the result's own consistency.
template <class T>
void checkPair(const gq::Geometry<T>& g0, const gq::Transform<T>& p0, const RoundedPolytope& r0,
               const gq::Geometry<T>& g1, const gq::Transform<T>& p1, const RoundedPolytope& r1, int i) {
  const double tol = kGjkTol<T>;
  const L exact = exactSignedDistance(r0, r1);
  gq::DistanceResult<T> r, m;
  ASSERT_TRUE(gq::distance(r, g0, p0, g1, p1).ok());
  ASSERT_TRUE(gq::distance(m, g1, p1, g0, p0).ok());
  ASSERT_NEAR(double(r.distance), double(exact), tol) << "pose " << i;
  ASSERT_NEAR(double(m.distance), double(exact), tol) << "pose " << i;
  EXPECT_NEAR(double(surfaceResidual(toL(r.point0), r0)), 0.0, tol) << "pose " << i;
  EXPECT_NEAR(double(surfaceResidual(toL(r.point1), r1)), 0.0, tol) << "pose " << i;
  if (exact > L(tol)) {
    EXPECT_NEAR(double(gapAlong(toL(r.normal).normalized(), r0, r1)), double(exact),
                normalCertificateTolerance<T>(double(exact))) << "pose " << i;
    EXPECT_NEAR(double(gapAlong(toL(m.normal).normalized(), r1, r0)), double(exact),
                normalCertificateTolerance<T>(double(exact))) << "pose " << i;
  }
  expectConsistent(r, tol);
  expectConsistent(m, tol);
}

TYPED_TEST(DistanceGjk, BoxBoxSeparatedAlongFaceAxisIsTheGap) {
  using T = TypeParam;
  Rng rng(21);
  const Eigen::Vector3d hA(1, 1, 1);
  for (int i = 0; i < kPoses; ++i) {
    // B's lowest point along -X sits `gap` above A's +X face and projects inside it.
    const Eigen::Vector3d hB = rng.vec(0.1, 0.5);
    const Eigen::Quaterniond q = rng.rotation();
    const double gap = rng.uniform(1e-3, 1.0);
    const double reach = (q.conjugate() * Eigen::Vector3d::UnitX()).cwiseAbs().dot(hB);
    const Eigen::Vector3d c{1 + gap + reach, rng.uniform(-0.1, 0.1), rng.uniform(-0.1, 0.1)};
    const gq::Transform<T> pA, pB(c.cast<T>(), q.cast<T>());
    gq::DistanceResult<T> r;
    ASSERT_TRUE(gq::distance(r, box<T>(hA), pA, box<T>(hB), pB).ok());
    ASSERT_NEAR(double(r.distance), gap, kGjkTol<T>) << "pose " << i;
    EXPECT_NEAR(double(r.normal.x()), 1.0, kGjkTol<T>);
    EXPECT_NEAR(double(r.point0.x()), 1.0, kGjkTol<T>);
    expectConsistent(r, kGjkTol<T>);
  }
}

TYPED_TEST(DistanceGjk, BoxBoxSeparatedAlongEdgeEdgeAxisIsTheGap) {
  using T = TypeParam;
  Rng rng(22);
  const Eigen::Vector3d n = Eigen::Vector3d(1, 1, 0).normalized(), u = Eigen::Vector3d(1, -1, 0).normalized();
  for (int i = 0; i < kPoses; ++i) {
    // B's edge along u faces A's edge (x = y = 1, along z) across the axis n = (1,1,0)/sqrt2.
    const double s = rng.uniform(0.2, 0.6), gap = rng.uniform(1e-3, 1.0), z0 = rng.uniform(-0.5, 0.5);
    Eigen::Matrix3d R;
    Eigen::Vector3d m = Eigen::Vector3d::UnitZ();
    R.col(0) = u;
    R.col(1) = (n + m) / std::sqrt(2.0);
    R.col(2) = (n - m) / std::sqrt(2.0);
    if (R.determinant() < 0) R.col(1).swap(R.col(2));
    ASSERT_NEAR((R * Eigen::Vector3d(0, 1, 1)).normalized().dot(n), 1.0, 1e-12);
    const Eigen::Vector3d c = Eigen::Vector3d(1, 1, z0) + (gap + s * std::sqrt(2.0)) * n;
    const gq::Transform<T> pA, pB(c.cast<T>(), Eigen::Quaterniond(R).cast<T>());
    gq::DistanceResult<T> r;
    ASSERT_TRUE(gq::distance(r, box<T>(Eigen::Vector3d(1, 1, 1)), pA, box<T>(Eigen::Vector3d::Constant(s)), pB).ok());
    ASSERT_NEAR(double(r.distance), gap, kGjkTol<T>) << "pose " << i;
    EXPECT_NEAR(double(r.normal.template cast<double>().dot(n)), 1.0, kGjkTol<T>);
    EXPECT_NEAR(double((r.point0.template cast<double>() - Eigen::Vector3d(1, 1, z0)).norm()), 0.0, 10 * kGjkTol<T>);
    expectConsistent(r, kGjkTol<T>);
  }
}

TYPED_TEST(DistanceGjk, BoxBoxMatchesBruteForceFeaturePairs) {
  using T = TypeParam;
  Rng rng(23);
  int penetrating = 0;
  for (int i = 0; i < kPoses; ++i) {
    const Eigen::Vector3d h0 = rng.vec(0.2, 1), h1 = rng.vec(0.2, 1);
    const auto p0 = randomPose<T>(rng, 1.2), p1 = randomPose<T>(rng, 1.2);
    const RoundedPolytope r0 = roundedBox(h0, p0), r1 = roundedBox(h1, p1);
    penetrating += polytopePenetration(r0.core, r1.core) >= 0;
    checkPair<T>(box<T>(h0), p0, r0, box<T>(h1), p1, r1, i);
  }
  EXPECT_GT(penetrating, kPoses / 10);  // both regimes are exercised
  EXPECT_LT(penetrating, kPoses - kPoses / 10);
}

// Plates and rods (each half-extent log-uniform in [1e-3, 2]): long parallel edges and faces, the closed form's
// near-ties between vertex and edge candidates (distance/box_box.cpp). Exact: the brute-force feature pairs.
TYPED_TEST(DistanceGjk, PlateAndRodBoxesMatchBruteForceFeaturePairs) {
  using T = TypeParam;
  Rng rng(36);
  const auto logUniform = [&] {
    return Eigen::Vector3d(std::pow(10.0, rng.uniform(-3, 0.3)), std::pow(10.0, rng.uniform(-3, 0.3)),
                           std::pow(10.0, rng.uniform(-3, 0.3)));
  };
  for (int i = 0; i < kPoses; ++i) {
    const Eigen::Vector3d h0 = logUniform(), h1 = logUniform();
    const auto p0 = randomPose<T>(rng, 1.5), p1 = randomPose<T>(rng, 1.5);
    checkPair<T>(box<T>(h0), p0, roundedBox(h0, p0), box<T>(h1), p1, roundedBox(h1, p1), i);
  }
}

// Boxes scaled by a power of two answer the scaled answer, bitwise, down to sizes whose squares leave T's range
// (2^-70 in float, 2^-540 in double: squared distances of 2^-140 and 2^-1080 are subnormal or zero). The closed form
// squares lengths; such pairs run rescaled (distance/box_box.cpp).
TYPED_TEST(DistanceGjk, BoxPairsScaledByAPowerOfTwoAnswerTheScaledAnswer) {
  using T = TypeParam;
  const int exponent = std::is_same_v<T, float> ? -70 : -540;
  Rng rng(35);
  int separated = 0;
  for (int i = 0; i < kPoses; ++i) {
    const Eigen::Vector3d h0 = rng.vec(0.2, 1), h1 = rng.vec(0.2, 1);
    const auto p0 = randomPose<T>(rng, 1.2), p1 = randomPose<T>(rng, 1.2);
    const auto scaled = [&](const gq::Transform<T>& p) {
      return gq::Transform<T>(gq::Vec3<T>(p.p * std::ldexp(T(1), exponent)), p.q);
    };
    const auto tiny = [&](const Eigen::Vector3d& h) { return box<T>(h * std::ldexp(1.0, exponent)); };
    gq::DistanceResult<T> r, s;
    ASSERT_TRUE(gq::distance(r, box<T>(h0), p0, box<T>(h1), p1).ok());
    ASSERT_TRUE(gq::distance(s, tiny(h0), scaled(p0), tiny(h1), scaled(p1)).ok());
    separated += r.distance > T(0);
    ASSERT_EQ(s.distance, std::ldexp(r.distance, exponent)) << "pose " << i;
    EXPECT_EQ(s.point0, gq::Vec3<T>(r.point0 * std::ldexp(T(1), exponent))) << "pose " << i;
    EXPECT_EQ(s.point1, gq::Vec3<T>(r.point1 * std::ldexp(T(1), exponent))) << "pose " << i;
    EXPECT_EQ(s.normal, r.normal) << "pose " << i;
  }
  EXPECT_GT(separated, kPoses / 10);
}

// Far from the origin the answer depends on the boxes' relative placement only: the kernels run at the smaller
// shape's position (fuzz_pair_queries: a float cylinder and box near x = 2.8e7, where a coordinate's ulp is 2, lost
// 0.28 of their depth of 3.17 in world coordinates). Float near 3e7, double near 1e11 (ulp 1.5e-5); the exact answer
// in long double from the rounded poses.
TYPED_TEST(DistanceGjk, BoxPairsFarFromTheOriginKeepTheirDistance) {
  using T = TypeParam;
  constexpr bool isFloat = std::is_same_v<T, float>;
  const Eigen::Vector3d far = isFloat ? Eigen::Vector3d(2.8e7, -1.3e7, 6e6) : Eigen::Vector3d(1e11, -3e10, 2e10);
  const double tol = isFloat ? 1e-3 : 1e-6;  // boxes of size 2-16
  Rng rng(33);
  int penetrating = 0;
  for (int i = 0; i < kPoses; ++i) {
    const Eigen::Vector3d h0 = rng.vec(1, 8), h1 = rng.vec(1, 8);
    const auto n0 = randomPose<T>(rng, 6), n1 = randomPose<T>(rng, 6);
    const gq::Transform<T> p0(gq::Vec3<T>((n0.p.template cast<double>() + far).template cast<T>()), n0.q);
    const gq::Transform<T> p1(gq::Vec3<T>((n1.p.template cast<double>() + far).template cast<T>()), n1.q);
    const L exact = exactSignedDistance(roundedBox(h0, p0), roundedBox(h1, p1));
    penetrating += exact < 0;
    gq::DistanceResult<T> r;
    ASSERT_TRUE(gq::distance(r, box<T>(h0), p0, box<T>(h1), p1).ok());
    ASSERT_NEAR(double(r.distance), double(exact), tol) << "pose " << i;
  }
  EXPECT_GT(penetrating, kPoses / 10);  // both regimes are exercised
  EXPECT_LT(penetrating, kPoses - kPoses / 10);
}

TYPED_TEST(DistanceGjk, ConvexConvexMatchesBruteForceFeaturePairs) {
  using T = TypeParam;
  Rng rng(24);
  for (int i = 0; i < kPoses; ++i) {
    const auto h0 = makeHull<T>(pointsOnEllipsoid<T>(rng, 12 + i % 9, rng.vec(0.3, 1)));
    const auto h1 = makeHull<T>(pointsOnEllipsoid<T>(rng, 12 + i % 7, rng.vec(0.3, 1)));
    const auto p0 = randomPose<T>(rng, 1), p1 = randomPose<T>(rng, 1);
    const gq::MeshScale<T> s0, s1 = randomScale<T>(rng, 0.5, 1.5);
    checkPair<T>(gq::ConvexMeshGeometry<T>(h0, s0), p0, roundedHull(*h0, s0, p0), gq::ConvexMeshGeometry<T>(h1, s1),
                 p1, roundedHull(*h1, s1, p1), i);
  }
}

// GJK can stall on a rounding tie and still converge later; the simplex it converged on gives the normal. (Falling
// back to an earlier simplex whose |v| was smaller by rounding cost float normals up to 3.7e-4 of gap in ~1 of 5,000
// of these poses; this seed draws 5 such poses.)
TYPED_TEST(DistanceGjk, ConvexConvexNormalIsTheSeparatingDirectionAfterAStall) {
  using T = TypeParam;
  Rng rng(32);
  for (int i = 0; i < 20 * kPoses; ++i) {
    const auto h0 = makeHull<T>(randomOctahedron<T>(rng)), h1 = makeHull<T>(randomOctahedron<T>(rng));
    const auto p0 = randomPose<T>(rng, 1), p1 = randomPose<T>(rng, 1);
    const gq::MeshScale<T> unit;
    checkPair<T>(gq::ConvexMeshGeometry<T>(h0), p0, roundedHull(*h0, unit, p0), gq::ConvexMeshGeometry<T>(h1), p1,
                 roundedHull(*h1, unit, p1), i);
  }
}

TYPED_TEST(DistanceGjk, CapsuleBoxMatchesBruteForceSegmentFeatures) {
  using T = TypeParam;
  Rng rng(25);
  for (int i = 0; i < kPoses; ++i) {
    const double rad = rng.uniform(0.05, 0.5), hh = rng.uniform(0.1, 1.2);
    const gq::CapsuleGeometry<T> cap{T(rad), T(hh)};
    const Eigen::Vector3d h = rng.vec(0.2, 1);
    const auto p0 = randomPose<T>(rng, 1.5), p1 = randomPose<T>(rng, 1.5);
    checkPair<T>(cap, p0, roundedCapsule(cap, p0), box<T>(h), p1, roundedBox(h, p1), i);
  }
}

TYPED_TEST(DistanceGjk, SphereConvexMatchesBruteForcePointFeatures) {
  using T = TypeParam;
  Rng rng(26);
  const auto hull = makeHull<T>(pointsOnEllipsoid<T>(rng, 24, Eigen::Vector3d(1, 0.7, 0.5)));
  for (int i = 0; i < kPoses; ++i) {
    const T rad = T(rng.uniform(0.05, 0.8));
    const auto p0 = randomPose<T>(rng, 1.5), p1 = randomPose<T>(rng, 0.5);
    checkPair<T>(gq::SphereGeometry<T>(rad), p0, roundedSphere(rad, p0), gq::ConvexMeshGeometry<T>(hull), p1,
                 roundedHull(*hull, gq::MeshScale<T>(), p1), i);
  }
}

// A convex custom shape: a box given only by its support mapping.
template <class T> class CustomBox : public gq::CustomGeometryCallbacks<T> {
 public:
  explicit CustomBox(const gq::Vec3<T>& h) : h_(h) {}
  const char* name() const override { return "custom box"; }
  gq::Bounds3<T> localBounds() const override { return gq::Bounds3<T>::fromMinMax(-h_, h_); }
  gq::Vec3<T> support(const gq::Vec3<T>& d) const override {
    return {d.x() < 0 ? -h_.x() : h_.x(), d.y() < 0 ? -h_.y() : h_.y(), d.z() < 0 ? -h_.z() : h_.z()};
  }
  bool raycast(const gq::Vec3<T>&, const gq::Vec3<T>&, T, gq::HitFlags, gq::RaycastHit<T>&) const override { return false; }

 private:
  gq::Vec3<T> h_;
};

TYPED_TEST(DistanceGjk, CustomConvexMatchesBruteForceThroughSupportMapping) {
  using T = TypeParam;
  Rng rng(27);
  for (int i = 0; i < kPoses; ++i) {
    const Eigen::Vector3d h0 = rng.vec(0.2, 1), h1 = rng.vec(0.2, 1);
    const auto p0 = randomPose<T>(rng, 1.2), p1 = randomPose<T>(rng, 1.2);
    const gq::Geometry<T> custom = gq::CustomGeometry<T>(std::make_shared<CustomBox<T>>(h0.cast<T>()));
    checkPair<T>(custom, p0, roundedBox(h0, p0), box<T>(h1), p1, roundedBox(h1, p1), i);
  }
}

TYPED_TEST(DistanceGjk, WarmStartedCallTakesNoMoreIterations) {
  using T = TypeParam;
  Rng rng(28);
  const auto hull = makeHull<T>(pointsOnEllipsoid<T>(rng, 40, Eigen::Vector3d(1, 0.8, 0.6)));
  const gq::Geometry<T> g0 = gq::ConvexMeshGeometry<T>(hull), g1 = box<T>(Eigen::Vector3d(0.5, 0.3, 0.4));
  int fewer = 0;
  for (int i = 0; i < 200; ++i) {
    const auto p0 = randomPose<T>(rng, 0.2);
    const gq::Vec3<T> centre = rng.unit().cast<T>() * T(2.5);
    const gq::Transform<T> p1(centre, rng.rotation().cast<T>());
    gq::GjkCache<T> cache;
    gq::DistanceResult<T> cold, warm;
    ASSERT_TRUE(gq::distance(cold, g0, p0, g1, p1, &cache).ok());
    const std::uint32_t coldIterations = cache.iterations;
    ASSERT_GT(cache.direction.norm(), T(0));
    ASSERT_TRUE(gq::distance(warm, g0, p0, g1, p1, &cache).ok());
    EXPECT_LE(cache.iterations, coldIterations) << "pose " << i;
    fewer += cache.iterations < coldIterations;
    EXPECT_NEAR(double(warm.distance), double(cold.distance), kGjkTol<T>);
  }
  EXPECT_GT(fewer, 100);  // the warm start actually helps
}

// gjkDistance's `farEnough` (a mesh's nearest triangle so far): GJK stops early only when the exact distance
// exceeds it, with a lower bound of the exact distance; otherwise the answer is the full one. A cache carried from
// pose to pose exercises the seeded simplex's bounds too; hull vs capsule adds margins to the bound.
TYPED_TEST(DistanceGjk, FarEnoughStopsOnlyBeyondItWithALowerBound) {
  using T = TypeParam;
  Rng rng(29);
  const double tol = kGjkTol<T>;
  const auto hull = makeHull<T>(pointsOnEllipsoid<T>(rng, 30, Eigen::Vector3d(0.6, 0.5, 0.4)));
  const gq::CapsuleGeometry<T> cap{T(0.2), T(0.5)};
  gq::GjkCache<T> cache;
  int stopped = 0, answered = 0, penetrating = 0;
  for (int i = 0; i < kPoses; ++i) {
    const auto p0 = randomPose<T>(rng, 1.5), p1 = randomPose<T>(rng, 1.5);
    const bool withCapsule = i % 2 == 1;
    const gq::Geometry<T> g0 = gq::ConvexMeshGeometry<T>(hull);
    const gq::Geometry<T> g1 = withCapsule ? gq::Geometry<T>(cap) : gq::Geometry<T>(gq::ConvexMeshGeometry<T>(hull));
    const RoundedPolytope r1 = withCapsule ? roundedCapsule(cap, p1) : roundedHull(*hull, gq::MeshScale<T>(), p1);
    const L exact = exactSignedDistance(roundedHull(*hull, gq::MeshScale<T>(), p0), r1);
    const auto a = gq::detail::makeConvexShape(g0, p0), b = gq::detail::makeConvexShape(g1, p1);
    // Signed: a penetrating pair's bound is negative too (0.25 x a depth is above the distance, 1.1 x below).
    for (const double factor : {0.25, 0.9, 1.1}) {
      const T farEnough = T(double(exact) * factor);
      const gq::detail::GjkResult<T> g =
          gq::detail::gjkDistance(a, b, &cache, T(0), static_cast<const gq::Vec3<T>*>(nullptr), farEnough);
      SCOPED_TRACE(testing::Message() << "pose " << i << ", factor " << factor << ", exact " << double(exact));
      if (g.beyond) {
        EXPECT_GT(double(exact), double(farEnough) - tol);
        EXPECT_GT(double(g.distance), double(farEnough));
        EXPECT_LE(double(g.distance), double(exact) + tol);
        ++stopped;
      } else {
        ASSERT_TRUE(g.status.ok());
        if (!g.coresOverlap) EXPECT_NEAR(double(g.distance), double(exact), tol);
        else EXPECT_LT(double(exact), tol);
        penetrating += exact < -tol;
        ++answered;
      }
      if (double(farEnough) > double(exact) + tol) EXPECT_FALSE(g.beyond);  // a lower bound never exceeds the distance
    }
  }
  EXPECT_GT(stopped, kPoses / 2);  // both outcomes are exercised
  EXPECT_GT(answered, kPoses / 2);
  EXPECT_GT(penetrating, kPoses / 10);  // negative bounds too
}

}  // namespace
