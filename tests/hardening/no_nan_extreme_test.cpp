// No NaN out: every query family over extreme but valid inputs (sizes 1e-6 ... 1e6, coordinates to
// 1e6, nearly parallel and nearly degenerate configurations) answers with finite numbers or an error status.
// runEveryFamily (query_families.h) fails the test on any accepted call with a non-finite output.
#include <gtest/gtest.h>

#include <cmath>

#include "query_families.h"

namespace gq::hardening {
namespace {

template <class T> class NoNaN : public ::testing::Test {};
TYPED_TEST_SUITE(NoNaN, Scalars);

const double kSizes[] = {1e-6, 1e-3, 1.0, 1e3, 1e6};

// The geometry of `type` with characteristic size `s` (a plane has none).
template <class T> Geometry<T> scaled(std::size_t type, double s) {
  const Cooked<T>& c = Cooked<T>::get();
  const T ts = T(s);
  switch (static_cast<GeometryType>(type)) {
    case GeometryType::Sphere: return SphereGeometry<T>(ts);
    case GeometryType::Plane: return PlaneGeometry<T>();
    case GeometryType::Capsule: return CapsuleGeometry<T>(T(0.3) * ts, T(0.6) * ts);
    case GeometryType::Box: return BoxGeometry<T>(ts, T(0.5) * ts, T(2) * ts);
    case GeometryType::ConvexMesh: return ConvexMeshGeometry<T>(c.hull, MeshScale<T>(ts));
    case GeometryType::TriangleMesh: return TriangleMeshGeometry<T>(c.mesh, MeshScale<T>(ts));
    case GeometryType::HeightField: return HeightFieldGeometry<T>(c.heightField, ts, T(0.25) * ts, T(0.25) * ts);
    case GeometryType::Custom: {
      CustomGeometry<T> cyl;
      EXPECT_TRUE(makeCylinder(T(0.5) * ts, T(0.75) * ts, cyl).ok());
      return cyl;
    }
  }
  return {};
}

// Relative placements of geom1 against geom0 at combined size `s`: coincident, touching within 1e-7, nearly
// parallel (rotated by 1e-7 rad, offset sideways), far (1e6 away), and a nearly grazing direction.
template <class T> std::vector<FamilyInputs<T>> configurations(const Geometry<T>& g0, const Geometry<T>& g1, double s,
                                                               const Vec3<T>& base) {
  std::vector<FamilyInputs<T>> out;
  const Quat<T> tiny(Eigen::AngleAxis<T>(T(1e-7), Vec3<T>(T(0), T(0), T(1)).normalized()));
  const Vec3<T> grazing = Vec3<T>(T(1), T(1e-7), T(-1e-7)).normalized();
  const std::vector<std::pair<Vec3<T>, Quat<T>>> offsets = {
      {Vec3<T>::Zero(), Quat<T>::Identity()},
      {Vec3<T>(T(2 * s * (1 + 1e-7)), T(0), T(0)), Quat<T>::Identity()},
      {Vec3<T>(T(0), T(2 * s), T(0)), tiny},
      {Vec3<T>(T(1e6), T(-1e6), T(1e6)), tiny},
      {Vec3<T>(T(s), T(s * 1e-7), T(0)), Quat<T>(T(std::sqrt(0.5)), T(0), T(std::sqrt(0.5)), T(0))}};
  for (const auto& [offset, rotation] : offsets) {
    FamilyInputs<T> in;
    in.geom0 = g0;
    in.geom1 = g1;
    in.pose0 = Transform<T>(base, tiny);
    in.pose1 = Transform<T>(base + offset, rotation);
    in.origin = in.pose1.p - T(10 * s) * grazing + Vec3<T>(T(0), T(0.1 * s), T(0));
    in.dir = grazing;
    in.maxDist = T(1e7);
    in.point = in.pose1.p + Vec3<T>(T(0.5 * s), T(1e-7 * s), T(0));
    in.inflation = T(0.01 * s);
    out.push_back(in);
  }
  return out;
}

TYPED_TEST(NoNaN, EveryFamilyOverExtremeSizesAndPlacementsAnswersFiniteOrAnError) {
  using T = TypeParam;
  std::size_t answered = 0, rejected = 0;
  for (const Vec3<T>& base : {Vec3<T>::Zero().eval(), Vec3<T>(T(1e6), T(-1e6), T(1e6))})
    for (std::size_t t0 = 0; t0 < kGeometryTypeCount; ++t0)
      for (std::size_t t1 = 0; t1 < kGeometryTypeCount; ++t1)
        for (const double s0 : kSizes)
          for (const double s1 : {s0, s0 * 1e-3, s0 * 1e3}) {
            if (s1 < 1e-6 || s1 > 1e6) continue;
            for (const FamilyInputs<T>& in : configurations(scaled<T>(t0, s0), scaled<T>(t1, s1), s0, base)) {
              for (const FamilyOutcome& o : runEveryFamily(in)) (o.status.ok() ? answered : rejected)++;
              if (::testing::Test::HasFailure()) {
                ADD_FAILURE() << "types " << t0 << "," << t1 << " sizes " << s0 << "," << s1 << " base "
                              << base.transpose();
                return;
              }
            }
          }
  EXPECT_GT(answered, rejected);  // extreme but valid: most calls answer
}

TYPED_TEST(NoNaN, MeshQueriesOverExtremeSizesAnswerFiniteOrAnError) {
  using T = TypeParam;
  const Vec3<T> grazing = Vec3<T>(T(1e-7), T(-1e-7), T(-1)).normalized();
  for (const double s : kSizes)
    for (const Vec3<T>& base : {Vec3<T>::Zero().eval(), Vec3<T>(T(1e6), T(1e6), T(-1e6))}) {
      const TriangleMeshGeometry<T> mesh(Cooked<T>::get().mesh, MeshScale<T>(T(s)));
      const HeightFieldGeometry<T> hf(Cooked<T>::get().heightField, T(s), T(s), T(s));
      const Transform<T> meshPose(base);
      for (const std::size_t type : {0u, 2u, 3u, 4u, 7u}) {
        const Geometry<T> g = scaled<T>(type, s);
        const Transform<T> pose(base + Vec3<T>(T(0.9 * s), T(0.3 * s), T(s * (1 - 1e-7))));
        PenetrationResult<T> r;
        Status st = computeTriangleMeshPenetration(r, g, pose, mesh, meshPose);
        if (st.ok()) EXPECT_TRUE(isFinite(r.direction) && std::isfinite(r.depth)) << type << " " << s;
        st = computeHeightFieldPenetration(r, g, pose, hf, meshPose);
        if (st.ok()) EXPECT_TRUE(isFinite(r.direction) && std::isfinite(r.depth)) << type << " " << s;

        Triangle<T> tris[12];
        for (std::uint32_t i = 0; i < 12; ++i) ASSERT_TRUE(getTriangle(mesh, meshPose, i, tris[i]).ok());
        SweepHit<T> hit;
        bool hasHit = false;
        st = sweepTriangles<T>(grazing, T(4 * s), g, Transform<T>(pose.p + Vec3<T>(T(0), T(0), T(2 * s))), tris, 12u,
                               hit, hasHit, TriangleSweepSettings<T>{kDefaultHitFlags, nullptr, T(0.001 * s)});
        if (st.ok() && hasHit)
          EXPECT_TRUE(isFinite(hit.position) && isFinite(hit.normal) && std::isfinite(hit.distance)) << type << " " << s;

        ContactBuffer<T> contacts;
        st = generateTriangleContacts(g, pose, tris[2], 2u, contacts,
                                      TriangleContactSettings<T>{T(0.1 * s), T(0.01 * s), T(s)});
        for (std::uint32_t i = 0; st.ok() && i < contacts.count; ++i)
          EXPECT_TRUE(isFinite(contacts.contacts[i].position) && isFinite(contacts.contacts[i].normal) &&
                      std::isfinite(contacts.contacts[i].separation)) << type << " " << s;

        std::uint32_t results[32];
        TriangleOverlapPageResult received;
        st = findOverlapTriangleMesh(g, pose, mesh, meshPose, TriangleOverlapPage{results, 32u, 0u}, received);
        for (std::uint32_t i = 0; st.ok() && i < received.count; ++i) EXPECT_LT(results[i], 12u);
      }
      bool found = false;
      const Status st = findOverlapTriangleMeshPairs<T>([](std::uint32_t, std::uint32_t) { return true; }, mesh,
                                                        meshPose, mesh, Transform<T>(base + Vec3<T>::Constant(T(s))),
                                                        found, T(1e-7 * s));
      EXPECT_TRUE(st.ok() || *st.message() != '\0');
    }
}

// Regression (found by fuzz_raycast): a double ray whose mesh-space origin lies beyond the float range made the float
// BVH slab test accept empty node lanes (inf - inf = NaN) and read nodes[0xffffffff].
TEST(NoNaNDouble, RaysFromBeyondTheFloatRangeAnswerFiniteForEveryGeometry) {
  using T = double;
  for (const Geometry<T>& g : everyGeometry<T>())
    for (const double far : {1e39, 1e100, 1e300}) {
      for (const Transform<T>& pose : {Transform<T>(), Transform<T>(Vec3<T>(T(4e100), T(-1e200), T(5e205)))}) {
        RaycastHit<T> hits[4];
        std::uint32_t count = 0;
        const Vec3<T> origin = pose.p + Vec3<T>(T(far), T(0.1), T(0.2));
        for (const HitFlags flags : {kDefaultHitFlags, kDefaultHitFlags | HitFlag::MeshMultiple}) {
          const Status s = raycast(origin, Vec3<T>(T(-1), T(0), T(0)), g, pose, T(2 * far), flags, 4u, hits, count);
          ASSERT_TRUE(s.ok()) << toString(g.type()) << " " << s.toString();
          for (std::uint32_t i = 0; i < count; ++i)
            EXPECT_TRUE(isFinite(hits[i].position) && isFinite(hits[i].normal) && std::isfinite(hits[i].distance))
                << toString(g.type()) << " from " << far;
        }
      }
    }
}

// Regression (found by fuzz_raycast): origin near -1.4e307 against a mirrored, rotated, double-sided mesh gave hits
// with NaN distance and position (the watertight test's products overflow; NaN passed t <= maxDist).
TEST(NoNaNDouble, RayOriginNearTheDoubleLimitGivesNoNaNHits) {
  using T = double;
  const MeshScale<T> scale(Vec3<T>::Constant(T(-1.3125)), Quat<T>(T(-0.5), T(-0.5), T(-0.5), T(-0.5)));
  const Geometry<T> mesh = TriangleMeshGeometry<T>(Cooked<T>::get().mesh, scale, MeshGeometryFlag::DoubleSided);
  const Transform<T> pose(Vec3<T>::Constant(T(-1.3125)),
                          Quat<T>(T(-0.21174347428431575), T(-0.21174347428431575), T(0.55456624217320794),
                                  T(0.77639273904249106)).normalized());
  const Vec3<T> origin(T(-4), T(-0.625), T(-1.3997060152723061e+307));
  const Vec3<T> dir = Vec3<T>(T(1.0219713197572166e-275), T(-1), T(-4.900392699363832e-284)).normalized();
  for (const T maxDist : {T(4.94066e-324), T(1), kInf<T>}) {
    RaycastHit<T> hits[4];
    std::uint32_t count = 0;
    ASSERT_TRUE(raycast(origin, dir, mesh, pose, maxDist, kDefaultHitFlags | HitFlag::MeshMultiple | HitFlag::UV, 4u,
                        hits, count).ok());
    for (std::uint32_t i = 0; i < count; ++i)
      EXPECT_TRUE(std::isfinite(hits[i].distance) && isFinite(hits[i].position) && std::isfinite(hits[i].u));
  }
}

// Regression (found by fuzz_mesh_queries): a capsule of radius 1.8e180 and half height 1.7e278 against a
// double-sided cube mesh made computeTriangleMeshPenetration return Ok with a non-finite direction/depth.
TEST(NoNaNDouble, HugeCapsuleMeshPenetrationIsFiniteOrAnError) {
  using T = double;
  const Geometry<T> capsule = CapsuleGeometry<T>(T(1.8079690119310907e+180), T(1.7201529712891337e+278));
  const TriangleMeshGeometry<T> mesh(Cooked<T>::get().mesh, MeshScale<T>(), MeshGeometryFlag::DoubleSided);
  const Transform<T> pose(Vec3<T>(T(4.5), T(-2.061175303536391e-245), T(-1.2432276683596013e-23)),
                          Quat<T>(T(-1.6952321677816607e-192), T(-0.57716242136646911), T(0.70341670104038434),
                                  T(0.41483549035714973)).normalized());
  const Transform<T> meshPose(Vec3<T>(T(2.3125), T(-4.125), T(5.0625)),
                              Quat<T>(T(0.87642183312277178), T(-0.46275072788882349), T(1.918865728887961e-81),
                                      T(-0.13321611863466132)).normalized());
  for (const std::uint32_t maxIter : {1u, 4u}) {
    PenetrationResult<T> r = sentinelPenetration<T>();
    const Status s = computeTriangleMeshPenetration(r, capsule, pose, mesh, meshPose, maxIter);
    if (s.ok()) EXPECT_TRUE(isFinite(r.direction) && std::isfinite(r.depth));
    else EXPECT_TRUE(sameBits(r, sentinelPenetration<T>())) << s.toString();
  }
}

// Regression (found by fuzz_pair_queries): in float, a heightfield with columnScale 8.3e27 and a shape 8.3e27 away
// made distance()'s growing search radius loop forever (its bound overflowed to +inf).
TEST(NoNaNFloat, DistanceToAHeightFieldBeyondTheFloatRangeTerminates) {
  using T = float;
  const HeightFieldGeometry<T> hf(Cooked<T>::get().heightField, T(1.4012984643248171e-45), T(5.375),
                                  T(8.290288497941718e+27), MeshGeometryFlag::DoubleSided);
  const Transform<T> hfPose(Vec3<T>(T(3.4392579466537215e+24), T(1.5625), T(1.229822955384114e+27)));
  const Transform<T> shapePose(Vec3<T>(T(-0.0009453499224036932), T(8.290288497941718e+27), T(-1.3840866813552566e-05)));
  CustomGeometry<T> cylinder, cone;
  ASSERT_TRUE(makeCylinder(T(1), T(1), cylinder).ok());
  ASSERT_TRUE(makeCone(T(1), T(1), cone).ok());
  for (const Geometry<T>& g : {Geometry<T>(cylinder), Geometry<T>(cone), Geometry<T>(SphereGeometry<T>(T(1)))}) {
    DistanceResult<T> r = sentinelDistance<T>();
    const Status s = distance(r, g, shapePose, Geometry<T>(hf), hfPose);
    if (s.ok()) EXPECT_TRUE(std::isfinite(r.distance) && isFinite(r.point0) && isFinite(r.point1));
    else EXPECT_TRUE(sameBits(r, sentinelDistance<T>())) << s.toString();
  }
}

// Regression (found by fuzz_raycast under UBSan): a heightfield ray whose cell range lies entirely beyond the grid
// (origin ~1e161 cells away) converted the floor of that position to int64 (undefined behaviour).
TEST(NoNaNDouble, HeightFieldRayFarBeyondTheGridMissesWithoutOverflow) {
  using T = double;
  const Geometry<T> hf = heightFieldGeometry<T>();
  for (const double far : {1e19, 1e161, 1e300})
    for (const Vec3<T>& dir : {Vec3<T>::UnitX().eval(), Vec3<T>(T(-1), T(0), T(0)), Vec3<T>(T(0), T(0), T(1))}) {
      RaycastHit<T> hits[2];
      std::uint32_t count = 7;
      ASSERT_TRUE(raycast(Vec3<T>(T(far), T(0.1), T(far)), dir, hf, Transform<T>(), T(1), kDefaultHitFlags, 2u, hits,
                          count).ok());
      EXPECT_EQ(count, 0u);
    }
}

// Regression (found by fuzz_raycast; exact input in tests/fuzz/known_crashes/fuzz_raycast_heightfield_float_nan.bin):
// a float ray from y = 1e6 going up past a heightfield returned Ok with a NaN distance.
TEST(NoNaNFloat, HeightFieldRayFromFarAboveGivesNoNaNHits) {
  using T = float;
  const Vec3<T> dir = Vec3<T>(T(1.0191115947815027e-16), T(1), T(-1.3123142572624147e-08)).normalized();
  for (const T heightScale : {T(1), T(1e-30), T(1e30)})
    for (const T maxDist : {T(5.28491e-10), T(1), T(1e7)}) {
      const Geometry<T> hf = HeightFieldGeometry<T>(Cooked<T>::get().heightField, heightScale, T(0.25), T(0.25),
                                                    MeshGeometryFlag::DoubleSided);
      RaycastHit<T> hits[6];
      std::uint32_t count = 0;
      ASSERT_TRUE(raycast(Vec3<T>(T(6.4375), T(1e6), T(-3.125)), dir, hf, Transform<T>(Vec3<T>(T(1), T(-3.6875), T(3.75))),
                          maxDist, HitFlag::Position | HitFlag::MeshBothSides, 6u, hits, count).ok());
      for (std::uint32_t i = 0; i < count; ++i) EXPECT_TRUE(std::isfinite(hits[i].distance) && isFinite(hits[i].position));
    }
}

}  // namespace
}  // namespace gq::hardening
