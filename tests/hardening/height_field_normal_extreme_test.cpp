// Heightfield raycast normals when the edge cross product overflows the scalar: the normal was the normalized plain
// cross product of two triangle edges, inf for large height/row/column scales, and inf / inf = NaN. Found by
// fuzz_raycast (float field); the input is replayed here through the fuzzer's own decoder, byte for byte
// (tests/fuzz/known_crashes/fuzz_raycast_heightfield_float_nan_normal.bin, also replayed by scripts/sanitize).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "../fuzz/fuzz_decode.h"

namespace {

TEST(HeightFieldNormalExtreme, FuzzInputWithOverflowingEdgeCrossProductGivesAFiniteUnitNormal) {
  const std::uint8_t input[] = {
      0xdd, 0x06, 0x14, 0x92, 0x75, 0xfa, 0xeb, 0x54, 0xd3, 0x51, 0xe0, 0x31, 0xc1, 0x51, 0xa7, 0xe6,
      0x9a, 0xa5, 0xef, 0xf2, 0x0a, 0xb4, 0xaf, 0x3b, 0x9a, 0x5a, 0x7e, 0x8e, 0x25, 0xff, 0xff, 0xff,
      0x09, 0x00, 0x00, 0x00, 0x97, 0x7e, 0xa0, 0x35, 0x3f, 0xd7, 0xc2, 0xc2, 0xc0, 0x91, 0xb4, 0xaf,
      0x3b, 0x9a, 0x5a, 0x7e, 0x8e, 0x25, 0x00, 0x00, 0x3f, 0x26, 0x0a, 0x6a, 0x18, 0x98, 0xa5};
  // The decoding steps of fuzz_raycast.cpp, in its order.
  gq::fuzz::Bytes in(input, sizeof input);
  ASSERT_TRUE(in.flag());  // float
  const gq::Geometry<float> geom = gq::fuzz::geometry<float>(in);
  ASSERT_EQ(geom.type(), gq::GeometryType::HeightField);
  const gq::Transform<float> pose = in.pose<float>();
  const gq::Vec3<float> origin = in.vec<float>();
  const gq::Vec3<float> dir = in.direction<float>();
  const float maxDist = in.scalar<float>();
  const gq::HitFlags flags = gq::fuzz::hitFlags(in);
  const std::uint32_t maxHits = std::uint32_t(in.small(9));
  ASSERT_TRUE(flags.has(gq::HitFlag::Normal));
  gq::RaycastHit<float> hits[8];
  std::uint32_t count = 0;
  ASSERT_TRUE(gq::raycast(origin, dir, geom, pose, maxDist, flags, maxHits, hits, count).ok());
  ASSERT_GE(count, 1u);  // the hit whose normal was NaN
  for (std::uint32_t i = 0; i < count; ++i) {
    EXPECT_TRUE(gq::isFinite(hits[i].normal)) << "hit " << i;
    EXPECT_NEAR(hits[i].normal.norm(), 1.0f, 1e-5f) << "hit " << i;
    EXPECT_TRUE(std::isfinite(hits[i].distance));
  }
}

}  // namespace
