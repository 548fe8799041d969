// The bad-input contract of the query façades (docs/hardening.md, table "queries"): one test per row. Every rejected
// call returns the row's status with a message and leaves its outputs bitwise untouched (query_families.h).
#include <gtest/gtest.h>

#include "query_families.h"

namespace gq::hardening {
namespace {

template <class T> class BadInputQueries : public ::testing::Test {};

// The documented bound on sizes and pair offsets (README, bad-input table).
template <class T> T supportedMagnitude() { return std::is_same_v<T, float> ? T(1e9) : T(1e75); }
TYPED_TEST_SUITE(BadInputQueries, Scalars);

TYPED_TEST(BadInputQueries, ValidBaselineIsAcceptedByEveryFamily) {
  using T = TypeParam;
  for (const FamilyOutcome& o : runEveryFamily(FamilyInputs<T>()))
    EXPECT_TRUE(o.status.ok()) << o.family << ": " << o.status.toString();
}

TYPED_TEST(BadInputQueries, NaNOrInfInAPoseIsInvalidArgumentInEveryFamily) {
  using T = TypeParam;
  for (int field = 0; field < 7; ++field) {
    for (const T bad : {kNaN<T>, kInf<T>, -kInf<T>}) {
      FamilyInputs<T> in;
      Transform<T> pose;
      if (field < 3) pose.p[field] = bad;
      else pose.q.coeffs()[field - 3] = bad;
      in.pose0 = in.pose1 = pose;
      expectEveryFamilyReturns(in, StatusCode::InvalidArgument);
    }
  }
}

TYPED_TEST(BadInputQueries, NonUnitQuaternionIsInvalidArgumentInEveryFamily) {
  using T = TypeParam;
  for (const T w : {T(1.01), T(0), T(0.5), T(1e30)}) {
    FamilyInputs<T> in;
    in.pose0.q = in.pose1.q = Quat<T>(w, T(0), T(0), T(0));
    expectEveryFamilyReturns(in, StatusCode::InvalidArgument);
  }
}

TYPED_TEST(BadInputQueries, PosesWhoseOffsetOverflowsIsInvalidArgumentInEveryPairFamily) {
  // Pair kernels work in pose0's frame: pose1.p - pose0.p must be representable (opposite poses near the scalar's
  // limit overflow it to Inf). Rays, point distance and bounds take one pose each and stay valid.
  using T = TypeParam;
  const T far = std::numeric_limits<T>::max() * T(0.75);
  for (const Geometry<T>& g : everyGeometry<T>()) {
    FamilyInputs<T> in;
    in.geom0 = SphereGeometry<T>(T(0.5));
    in.geom1 = g;
    in.pose0.p.x() = -far;
    in.pose1.p.x() = far;
    expectEveryFamilyReturns(in, StatusCode::InvalidArgument, {"raycast", "pointDistance", "bounds"});
  }
}

TYPED_TEST(BadInputQueries, NaNOrInfRayOriginIsInvalidArgument) {
  using T = TypeParam;
  for (const Geometry<T>& g : everyGeometry<T>())
    for (const T bad : {kNaN<T>, kInf<T>}) {
      FamilyInputs<T> in;
      in.geom1 = g;
      in.origin.y() = bad;
      EXPECT_EQ(runEveryFamily(in)[0].status.code, StatusCode::InvalidArgument) << toString(g.type());
    }
}

TYPED_TEST(BadInputQueries, NonUnitZeroOrNaNDirectionIsInvalidArgumentForRaysAndSweeps) {
  using T = TypeParam;
  for (const Vec3<T>& dir : {Vec3<T>(T(1.001), T(0), T(0)), Vec3<T>(T(0.5), T(0), T(0)), Vec3<T>::Zero().eval(),
                             Vec3<T>(kNaN<T>, T(0), T(0)), Vec3<T>(kInf<T>, T(0), T(0))}) {
    FamilyInputs<T> in;
    in.dir = dir;
    expectEveryFamilyReturns(in, StatusCode::InvalidArgument,
                             {"overlap", "penetration", "distance", "distanceWithin", "pointDistance", "bounds"});
  }
}

TYPED_TEST(BadInputQueries, NegativeOrNaNMaxDistIsInvalidArgumentForRaysAndSweeps) {
  using T = TypeParam;
  for (const T maxDist : {T(-1), T(-1e-30), kNaN<T>, -kInf<T>}) {
    FamilyInputs<T> in;
    in.maxDist = maxDist;
    expectEveryFamilyReturns(in, StatusCode::InvalidArgument,
                             {"overlap", "penetration", "distance", "distanceWithin", "pointDistance", "bounds"});
  }
}

TYPED_TEST(BadInputQueries, NaNMaxDistanceIsInvalidArgumentForDistanceWithin) {
  using T = TypeParam;
  FamilyInputs<T> in;
  in.maxDistance = kNaN<T>;
  const std::vector<FamilyOutcome> out = runEveryFamily(in);
  EXPECT_EQ(out.back().family, "distanceWithin");
  EXPECT_EQ(out.back().status.code, StatusCode::InvalidArgument);
  for (const T bound : {-kInf<T>, T(-1), T(0), kInf<T>}) {  // any other bound is a bound
    in.maxDistance = bound;
    EXPECT_TRUE(runEveryFamily(in).back().status.ok()) << double(bound);
  }
}

TYPED_TEST(BadInputQueries, InfiniteMaxDistIsAcceptedAndSweepsClampItTo1e8) {
  using T = TypeParam;
  FamilyInputs<T> in;
  in.maxDist = kInf<T>;
  in.pose1 = Transform<T>(Vec3<T>(T(5), T(0), T(0)));  // spheres of radius 0.5: contact after 4
  in.origin = Vec3<T>(T(-5), T(0), T(0));
  for (const FamilyOutcome& o : runEveryFamily(in)) EXPECT_TRUE(o.status.ok()) << o.family << o.status.toString();
  SweepHit<T> hit;
  bool hasHit = false;
  ASSERT_TRUE(sweep(in.dir, in.maxDist, in.geom0, in.pose0, in.geom1, in.pose1, hit, hasHit).ok());
  ASSERT_TRUE(hasHit);
  EXPECT_NEAR(double(hit.distance), 4.0, 1e-5);
}

TYPED_TEST(BadInputQueries, ZeroMaxHitsOrNullHitBufferIsInvalidArgument) {
  using T = TypeParam;
  for (const Geometry<T>& g : everyGeometry<T>()) {
    RaycastHit<T> hit = sentinelRaycastHit<T>();
    std::uint32_t count = 4242;
    Status s = raycast<T>(Vec3<T>(T(-5), T(0), T(0)), Vec3<T>::UnitX(), g, Transform<T>(), T(10), kDefaultHitFlags, 0u,
                       &hit, count);
    EXPECT_EQ(s.code, StatusCode::InvalidArgument) << toString(g.type());
    s = raycast<T>(Vec3<T>(T(-5), T(0), T(0)), Vec3<T>::UnitX(), g, Transform<T>(), T(10), kDefaultHitFlags, 4u,
                static_cast<RaycastHit<T>*>(nullptr), count);
    EXPECT_EQ(s.code, StatusCode::InvalidArgument) << toString(g.type());
    EXPECT_EQ(count, 4242u);
    EXPECT_TRUE(sameBits(hit, sentinelRaycastHit<T>()));
  }
}

TYPED_TEST(BadInputQueries, SweepOnlyFlagsOnARaycastAndMeshMultipleOnASweepAreInvalidArgument) {
  using T = TypeParam;
  for (const HitFlag f : {HitFlag::Mtd, HitFlag::PreciseSweep, HitFlag::AssumeNoInitialOverlap}) {
    RaycastHit<T> hit = sentinelRaycastHit<T>();
    std::uint32_t count = 4242;
    const Status s = raycast<T>(Vec3<T>(T(-5), T(0), T(0)), Vec3<T>::UnitX(), Geometry<T>(SphereGeometry<T>(T(1))),
                             Transform<T>(), T(10), kDefaultHitFlags | f, 1u, &hit, count);
    EXPECT_EQ(s.code, StatusCode::InvalidArgument);
    EXPECT_EQ(count, 4242u);
  }
  SweepHit<T> hit = sentinelSweepHit<T>();
  bool hasHit = true;
  const Status s = sweep<T>(Vec3<T>::UnitX(), T(10), Geometry<T>(SphereGeometry<T>(T(1))), Transform<T>(),
                         Geometry<T>(SphereGeometry<T>(T(1))), Transform<T>(Vec3<T>(T(5), T(0), T(0))), hit, hasHit,
                         kDefaultHitFlags | HitFlag::MeshMultiple);
  EXPECT_EQ(s.code, StatusCode::InvalidArgument);
  EXPECT_TRUE(hasHit && sameBits(hit, sentinelSweepHit<T>()));
}

TYPED_TEST(BadInputQueries, NonPositiveOrNonFiniteSizesAreInvalidArgumentInEveryFamily) {
  using T = TypeParam;
  const std::vector<Geometry<T>> bad = {
      SphereGeometry<T>(T(0)),          SphereGeometry<T>(T(-1)),        SphereGeometry<T>(kNaN<T>),
      SphereGeometry<T>(kInf<T>),       Geometry<T>(),                   CapsuleGeometry<T>(T(0), T(1)),
      CapsuleGeometry<T>(T(1), T(-1)),  CapsuleGeometry<T>(T(1), kInf<T>), BoxGeometry<T>(T(1), T(0), T(1)),
      BoxGeometry<T>(T(1), T(1), T(-1)), BoxGeometry<T>(kNaN<T>, T(1), T(1))};
  for (const Geometry<T>& g : bad) {
    FamilyInputs<T> in;
    in.geom0 = in.geom1 = g;
    expectEveryFamilyReturns(in, StatusCode::InvalidArgument);
  }
}

TYPED_TEST(BadInputQueries, SizesBeyondTheSupportedMagnitudeAreInvalidArgumentInPairFamilies) {
  // Pair kernels square products of two lengths; sizes above 1e9 (float) / 1e75 (double) would overflow them.
  // Single-geometry families (ray, point distance, bounds) still answer, with finite outputs.
  using T = TypeParam;
  const T over = supportedMagnitude<T>() * T(2);
  const auto& c = Cooked<T>::get();  // unit cube hull and mesh (|coordinate| <= 1), 0.25-spaced heightfield
  const std::vector<Geometry<T>> tooLarge = {
      SphereGeometry<T>(over),
      CapsuleGeometry<T>(over, T(1)),
      CapsuleGeometry<T>(T(1), over),
      BoxGeometry<T>(T(1), over, T(1)),
      ConvexMeshGeometry<T>(c.hull, MeshScale<T>(Vec3<T>(T(1), T(1), over))),
      TriangleMeshGeometry<T>(c.mesh, MeshScale<T>(Vec3<T>(-over, T(1), T(1)))),
      HeightFieldGeometry<T>(c.heightField, T(1), over, T(0.25))};
  for (const Geometry<T>& g : tooLarge) {
    FamilyInputs<T> in;
    in.geom0 = in.geom1 = g;
    for (const FamilyOutcome& o : runEveryFamily(in)) {  // runEveryFamily flags any non-finite accepted output
      if (o.family == "raycast" || o.family == "pointDistance" || o.family == "bounds") {
        EXPECT_NE(o.status.code, StatusCode::InvalidArgument) << toString(g.type()) << " " << o.family;
        continue;
      }
      EXPECT_EQ(o.status.code, StatusCode::InvalidArgument) << toString(g.type()) << " " << o.family;
      EXPECT_NE(o.status.toString().find("supported magnitude"), std::string::npos) << o.status.toString();
    }
  }
}

TYPED_TEST(BadInputQueries, SizesAtTheSupportedMagnitudeAreAcceptedWithFiniteAnswers) {
  using T = TypeParam;
  const T limit = supportedMagnitude<T>();
  const auto& c = Cooked<T>::get();
  for (const Geometry<T>& g : std::vector<Geometry<T>>{SphereGeometry<T>(limit), CapsuleGeometry<T>(T(1), limit),
                                                     BoxGeometry<T>(limit, T(1), T(1)),
                                                     ConvexMeshGeometry<T>(c.hull, MeshScale<T>(Vec3<T>::Constant(limit)))}) {
    FamilyInputs<T> in;
    in.geom0 = in.geom1 = g;
    in.pose1.p.x() = limit;  // the largest supported offset too
    for (const FamilyOutcome& o : runEveryFamily(in))  // runEveryFamily flags any non-finite accepted output
      EXPECT_TRUE(o.status.ok()) << toString(g.type()) << " " << o.family << ": " << o.status.toString();
  }
}

TYPED_TEST(BadInputQueries, ZeroNonFiniteOrNegativeConvexScaleIsInvalidArgument) {
  using T = TypeParam;
  const auto& hull = Cooked<T>::get().hull;
  for (const Vec3<T>& s : {Vec3<T>(T(1), T(0), T(1)), Vec3<T>(T(1), kNaN<T>, T(1)), Vec3<T>(T(-1), T(1), T(1))}) {
    FamilyInputs<T> in;
    in.geom0 = in.geom1 = ConvexMeshGeometry<T>(hull, MeshScale<T>(s));
    expectEveryFamilyReturns(in, StatusCode::InvalidArgument);
  }
  FamilyInputs<T> in;
  in.geom0 = in.geom1 = ConvexMeshGeometry<T>(hull, MeshScale<T>(Vec3<T>::Ones(), Quat<T>(T(2), T(0), T(0), T(0))));
  expectEveryFamilyReturns(in, StatusCode::InvalidArgument);
}

TYPED_TEST(BadInputQueries, ZeroOrNonFiniteMeshAndHeightFieldScalesAreInvalidArgument) {
  using T = TypeParam;
  const auto& mesh = Cooked<T>::get().mesh;
  const auto& hf = Cooked<T>::get().heightField;
  const std::vector<Geometry<T>> bad = {
      TriangleMeshGeometry<T>(mesh, MeshScale<T>(Vec3<T>(T(0), T(1), T(1)))),
      TriangleMeshGeometry<T>(mesh, MeshScale<T>(Vec3<T>(kInf<T>, T(1), T(1)))),
      HeightFieldGeometry<T>(hf, T(0), T(1), T(1)), HeightFieldGeometry<T>(hf, T(1), T(-1), T(1)),
      HeightFieldGeometry<T>(hf, T(1), T(1), kNaN<T>)};
  for (const Geometry<T>& g : bad) {
    FamilyInputs<T> in;
    in.geom1 = g;
    // geom0 stays a sphere: meshes and heightfields cannot be swept.
    expectEveryFamilyReturns(in, StatusCode::InvalidArgument);
  }
}

TYPED_TEST(BadInputQueries, MissingCookedDataOrCallbacksIsInvalidArgument) {
  using T = TypeParam;
  const std::vector<Geometry<T>> bad = {ConvexMeshGeometry<T>(nullptr), TriangleMeshGeometry<T>(nullptr),
                                        HeightFieldGeometry<T>(nullptr, T(1), T(1), T(1)), CustomGeometry<T>(nullptr)};
  for (const Geometry<T>& g : bad) {
    FamilyInputs<T> in;
    in.geom1 = g;
    expectEveryFamilyReturns(in, StatusCode::InvalidArgument);
  }
}

TYPED_TEST(BadInputQueries, EmptyOrMalformedCookedDataIsDegenerateMesh) {
  using T = TypeParam;
  auto malformedHf = std::make_shared<HeightField<T>>();
  malformedHf->rows = malformedHf->columns = 5;  // no samples: what a hand-built struct may look like
  const std::vector<Geometry<T>> bad = {
      ConvexMeshGeometry<T>(std::make_shared<const ConvexMesh<T>>()),
      TriangleMeshGeometry<T>(std::make_shared<const TriangleMesh<T>>()),
      HeightFieldGeometry<T>(malformedHf, T(1), T(1), T(1))};
  for (const Geometry<T>& g : bad) {
    FamilyInputs<T> in;
    in.geom1 = g;
    expectEveryFamilyReturns(in, StatusCode::DegenerateMesh);
  }
}

TYPED_TEST(BadInputQueries, PairsTheSpecLeavesUndefinedReturnUnsupported) {
  using T = TypeParam;
  FamilyInputs<T> in;
  in.geom0 = in.geom1 = PlaneGeometry<T>();
  const std::vector<FamilyOutcome> out = runEveryFamily(in);
  for (const FamilyOutcome& o : out)
    if (o.family == "overlap" || o.family == "penetration" || o.family == "distance" || o.family == "distanceWithin" ||
        o.family == "sweep" || o.family == "pointDistance")
      EXPECT_EQ(o.status.code, StatusCode::Unsupported) << o.family << ": " << o.status.toString();
  in.geom0 = SphereGeometry<T>(T(1));
  in.geom1 = heightFieldGeometry<T>();
  EXPECT_EQ(runEveryFamily(in)[5].status.code, StatusCode::Unsupported);  // point distance to a heightfield
}

TYPED_TEST(BadInputQueries, NaNQueryPointIsInvalidArgument) {
  using T = TypeParam;
  for (const T bad : {kNaN<T>, -kInf<T>}) {
    FamilyInputs<T> in;
    in.point.z() = bad;
    EXPECT_EQ(runEveryFamily(in)[5].status.code, StatusCode::InvalidArgument);
  }
}

TYPED_TEST(BadInputQueries, NegativeOrNonFiniteBoundsOffsetAndNonPositiveInflationAreInvalidArgument) {
  using T = TypeParam;
  for (const auto& [offset, inflation] : std::vector<std::pair<T, T>>{
           {T(-1), T(1)}, {kNaN<T>, T(1)}, {kInf<T>, T(1)}, {T(0), T(0)}, {T(0), T(-1)}, {T(0), kNaN<T>}}) {
    FamilyInputs<T> in;
    in.boundsOffset = offset;
    in.boundsInflation = inflation;
    EXPECT_EQ(runEveryFamily(in)[6].status.code, StatusCode::InvalidArgument) << offset << " " << inflation;
  }
}

TYPED_TEST(BadInputQueries, NegativeOrNonFiniteSweepInflationIsInvalidArgument) {
  using T = TypeParam;
  for (const T inflation : {T(-0.1), kNaN<T>, kInf<T>}) {
    FamilyInputs<T> in;
    in.inflation = inflation;
    EXPECT_EQ(runEveryFamily(in)[1].status.code, StatusCode::InvalidArgument);
  }
}

TYPED_TEST(BadInputQueries, CustomShapeFactoriesRejectNonPositiveOrNonFiniteSizes) {
  using T = TypeParam;
  for (const auto& [r, h] : std::vector<std::pair<T, T>>{{T(0), T(1)}, {T(1), T(-1)}, {kNaN<T>, T(1)}, {T(1), kInf<T>}}) {
    CustomGeometry<T> out;
    EXPECT_EQ(makeCylinder(r, h, out).code, StatusCode::InvalidArgument);
    EXPECT_EQ(makeCone(r, h, out).code, StatusCode::InvalidArgument);
    EXPECT_EQ(out.callbacks, nullptr);
  }
}

}  // namespace
}  // namespace gq::hardening
