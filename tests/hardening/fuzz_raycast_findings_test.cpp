// fuzz_raycast's findings of 2026-11-22, replayed byte for byte through the fuzzer's own decoder (the inputs are also
// in tests/fuzz/known_crashes/ and replayed by scripts/sanitize's smoke). All were float raycasts that answered Ok
// with a non-finite field after millions of executions.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "../fuzz/fuzz_decode.h"

namespace {

struct Replay {
  gq::GeometryType type = gq::GeometryType::Sphere;
  gq::HitFlags flags;
  gq::Status status;
  std::vector<gq::RaycastHit<float>> hits;
};

// The decoding steps of fuzz_raycast.cpp, in its order, for a float input.
Replay replayRaycast(const std::vector<std::uint8_t>& input) {
  gq::fuzz::Bytes in(input.data(), input.size());
  Replay r;
  EXPECT_TRUE(in.flag());  // float
  const gq::Geometry<float> geom = gq::fuzz::geometry<float>(in);
  r.type = geom.type();
  const gq::Transform<float> pose = in.pose<float>();
  const gq::Vec3<float> origin = in.vec<float>();
  const gq::Vec3<float> dir = in.direction<float>();
  const float maxDist = in.scalar<float>();
  r.flags = gq::fuzz::hitFlags(in);
  const std::uint32_t maxHits = std::uint32_t(in.small(9));
  gq::RaycastHit<float> hits[8];
  std::uint32_t count = 0;
  r.status = gq::raycast(origin, dir, geom, pose, maxDist, r.flags, maxHits, hits, count);
  if (r.status.ok()) r.hits.assign(hits, hits + count);
  return r;
}

// Heights and row/column scales whose edge cross product overflows float: the normal was normalize(inf) = NaN.
TEST(FuzzRaycastFindings, HeightFieldNormalWithOverflowingEdgeCrossProductIsAFiniteUnitVector) {
  const Replay r = replayRaycast({0xdd, 0x06, 0x14, 0x92, 0x75, 0xfa, 0xeb, 0x54, 0xd3, 0x51, 0xe0, 0x31, 0xc1,
                                  0x51, 0xa7, 0xe6, 0x9a, 0xa5, 0xef, 0xf2, 0x0a, 0xb4, 0xaf, 0x3b, 0x9a, 0x5a,
                                  0x7e, 0x8e, 0x25, 0xff, 0xff, 0xff, 0x09, 0x00, 0x00, 0x00, 0x97, 0x7e, 0xa0,
                                  0x35, 0x3f, 0xd7, 0xc2, 0xc2, 0xc0, 0x91, 0xb4, 0xaf, 0x3b, 0x9a, 0x5a, 0x7e,
                                  0x8e, 0x25, 0x00, 0x00, 0x3f, 0x26, 0x0a, 0x6a, 0x18, 0x98, 0xa5});
  ASSERT_EQ(r.type, gq::GeometryType::HeightField);
  ASSERT_TRUE(r.status.ok()) << r.status.toString();
  ASSERT_TRUE(r.flags.has(gq::HitFlag::Normal));
  ASSERT_GE(r.hits.size(), 1u);  // the hit whose normal was NaN
  for (const auto& h : r.hits) {
    EXPECT_TRUE(gq::isFinite(h.normal));
    EXPECT_NEAR(h.normal.norm(), 1.0f, 1e-5f);
    EXPECT_TRUE(std::isfinite(h.distance));
  }
}

// maxDist = inf and a ray all but parallel to a hull face far away in the hull's frame: the entry parameter
// overflowed to inf, passed every test and came out as a hit at distance inf. Such a ray never enters: no hit.
TEST(FuzzRaycastFindings, ConvexEntryParameterThatOverflowsIsNoHit) {
  const Replay r = replayRaycast({0xff, 0xfc, 0x02, 0x8f, 0xeb, 0x06, 0x76, 0x32, 0x41, 0x66, 0xde, 0x9d, 0x41,
                                  0xc1, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41, 0x41,
                                  0x41, 0x41, 0x41, 0x41, 0xde, 0xc7, 0x2a, 0x7c, 0x79, 0xf8, 0x35, 0x46, 0x6a,
                                  0xf7, 0x9f, 0x11, 0x79, 0x61, 0x82, 0x10, 0x57, 0x32, 0x37, 0x1d, 0x6b, 0x8d,
                                  0x95, 0x22, 0x01, 0x61, 0x37, 0x80, 0x01, 0x00, 0x00, 0x11, 0x63, 0x48, 0xea,
                                  0xec, 0xa2, 0xe5, 0xfd, 0x72, 0x64, 0x34, 0x46, 0xc7, 0x00, 0x00, 0x7f, 0xed,
                                  0x2a, 0xa4, 0xad, 0x87});
  ASSERT_EQ(r.type, gq::GeometryType::ConvexMesh);
  ASSERT_TRUE(r.status.ok()) << r.status.toString();
  EXPECT_TRUE(r.hits.empty());
  for (const auto& h : r.hits) EXPECT_TRUE(std::isfinite(h.distance));
}

// A float box seen from x = -2.98e38 along +X with maxDist = inf (found by fuzz_raycast after 2.8M executions): in
// the box's frame one direction component is tiny and the origin's carries a rounding error of the order of its ulp
// (~1e31), so that slab's entry parameter overflowed to inf and came out as a hit at distance inf. At that range
// float cannot tell whether the ray meets a box of size 1; the façade's rule (a hit has a finite distance) makes it a
// miss.
TEST(FuzzRaycastFindings, BoxEntryParameterThatOverflowsIsNoHit) {
  const Replay r = replayRaycast({0x43, 0x63, 0x48, 0xea, 0x6c, 0xa2, 0xe5, 0x00, 0x59, 0x8a, 0xe2, 0x1f, 0xf1,
                                  0x95, 0x04, 0x3c, 0x02, 0x66, 0x05, 0xff, 0x79, 0x4d, 0x08, 0x5c, 0x24, 0xca,
                                  0x41, 0xd6, 0x8f, 0xf5, 0xff, 0xff, 0x60, 0x10, 0x00, 0x73, 0x31, 0x26, 0x90,
                                  0x3c, 0x00, 0x75, 0xf5, 0x54, 0xb4, 0x01, 0x00, 0x00, 0x01, 0x8d, 0x03});
  ASSERT_EQ(r.type, gq::GeometryType::Box);
  ASSERT_TRUE(r.status.ok()) << r.status.toString();
  for (const auto& h : r.hits) EXPECT_TRUE(std::isfinite(h.distance));
}

// The same rule for a kernel the fuzzer has not reached: a plane approached at a grazing angle from far away, whose
// hit parameter s / |n.d| exceeds the largest T. maxDist = inf: no hit; a ray that gets there within range still hits.
template <class T> void expectGrazingFarPlaneIsNoHit(T far, T approach) {
  const gq::Geometry<T> plane = gq::PlaneGeometry<T>();
  const gq::Vec3<T> dir = gq::Vec3<T>(-approach, 1, 0).normalized();
  gq::RaycastHit<T> hit;
  std::uint32_t count = 9;
  gq::Status s = gq::raycast(gq::Vec3<T>(far, 0, 0), dir, plane, gq::Transform<T>::identity(), std::numeric_limits<T>::infinity(),
                             gq::kDefaultHitFlags, 1, &hit, count);
  ASSERT_TRUE(s.ok()) << s.toString();
  EXPECT_EQ(count, 0u) << "hit at " << hit.distance;
  s = gq::raycast(gq::Vec3<T>(T(1), 0, 0), dir, plane, gq::Transform<T>::identity(), std::numeric_limits<T>::infinity(),
                  gq::kDefaultHitFlags, 1, &hit, count);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_EQ(count, 1u);
  EXPECT_TRUE(std::isfinite(hit.distance));
  EXPECT_NEAR(double(hit.distance), 1.0 / double(-dir.x()), 1e-5 / double(-dir.x()));
}

TEST(FuzzRaycastFindings, EntryParameterBeyondTheLargestFloatIsNoHit) { expectGrazingFarPlaneIsNoHit<float>(3e38f, 1e-6f); }
TEST(FuzzRaycastFindings, EntryParameterBeyondTheLargestDoubleIsNoHit) { expectGrazingFarPlaneIsNoHit<double>(1e308, 1e-10); }

// A sphere at x = FLT_MAX and a ray from x = -FLT_MAX (found after 26.5M executions): origin - centre overflowed to
// -inf and the hit distance came out NaN. Such an origin has no position in the shape's frame: InvalidArgument.
TEST(FuzzRaycastFindings, OriginWhoseOffsetFromThePoseOverflowsIsInvalidArgument) {
  const Replay r = replayRaycast({0x09, 0x00, 0x63, 0xec, 0x0c, 0x43, 0xe5, 0xa2, 0x0b, 0x8f, 0x1f, 0x00, 0xfc, 0x00, 0xff, 0x64, 0x3b, 0x00,
                                  0x00, 0x00, 0x05, 0x0d, 0x3c, 0x15, 0x07, 0x66, 0x05, 0x0d, 0x79, 0x4d, 0x08, 0x58, 0x24, 0xff, 0xff, 0x66});
  ASSERT_EQ(r.type, gq::GeometryType::Sphere);
  EXPECT_EQ(r.status.code, gq::StatusCode::InvalidArgument) << r.status.toString();
  EXPECT_TRUE(r.hits.empty());
}

TEST(FuzzRaycastFindings, OriginOffsetCheckKeepsFarButRepresentableRays) {
  // The check rejects only overflow: a ray 2e18 away (its quadratic, ~4e36, still fits float) hits at 2e18 - 1.
  const gq::Geometry<float> sphere = gq::SphereGeometry<float>(1.0f);
  const gq::Transform<float> pose(gq::Vec3<float>(1e18f, 0, 0));
  gq::RaycastHit<float> hit;
  std::uint32_t count = 0;
  const gq::Status s = gq::raycast(gq::Vec3<float>(-1e18f, 0, 0), gq::Vec3<float>(1, 0, 0), sphere, pose, 3e18f,
                                   gq::kDefaultHitFlags, 1, &hit, count);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_EQ(count, 1u);
  EXPECT_TRUE(std::isfinite(hit.distance));
  EXPECT_NEAR(hit.distance, 2e18f, 1e12f);
}

}  // namespace
