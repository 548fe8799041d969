// fuzz_pair_queries' findings, replayed byte for byte through the fuzzer's own decoder from tests/fuzz/known_crashes/
// (also replayed by scripts/sanitize's smoke).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../fuzz/fuzz_decode.h"

namespace {

std::vector<std::uint8_t> knownCrash(const std::string& name) {
  std::ifstream in(std::string(GQ_SOURCE_DIR) + "/tests/fuzz/known_crashes/" + name, std::ios::binary);
  EXPECT_TRUE(in.good()) << name;
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Float convex hull against a triangle mesh with a tiny triangle: its normal's squared norm underflowed, the push
// direction came out with length 0.97.
TEST(FuzzPairFindings, PenetrationAgainstATinyTriangleGivesAUnitDirection) {
  const std::vector<std::uint8_t> bytes = knownCrash("fuzz_pair_queries_float_tiny_triangle_push_direction.bin");
  gq::fuzz::Bytes in(bytes.data(), bytes.size());
  ASSERT_TRUE(in.flag());  // float
  const gq::Geometry<float> g0 = gq::fuzz::geometry<float>(in);
  const gq::Transform<float> p0 = in.pose<float>();
  const gq::Geometry<float> g1 = gq::fuzz::geometry<float>(in);
  const gq::Transform<float> p1 = in.pose<float>();
  ASSERT_EQ(g1.type(), gq::GeometryType::TriangleMesh);
  gq::PenetrationResult<float> r;
  const gq::Status s = gq::computePenetration(r, g0, p0, g1, p1);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(r.direction.norm(), 1.0f, 1e-5f);
}

// Float spheres whose centres differ by ~1e-20: |c1 - c0|^2 is subnormal and keeps a few bits, so d / |d| had length
// 1.02 (penetration direction and distance normal).
TEST(FuzzPairFindings, SpheresWithASubnormalSquaredOffsetGetUnitNormals) {
  const std::vector<std::uint8_t> bytes = knownCrash("fuzz_pair_queries_float_sphere_subnormal_offset_normal.bin");
  gq::fuzz::Bytes in(bytes.data(), bytes.size());
  ASSERT_TRUE(in.flag());  // float
  const gq::Geometry<float> g0 = gq::fuzz::geometry<float>(in);
  const gq::Transform<float> p0 = in.pose<float>();
  const gq::Geometry<float> g1 = gq::fuzz::geometry<float>(in);
  const gq::Transform<float> p1 = in.pose<float>();
  ASSERT_EQ(g0.type(), gq::GeometryType::Sphere);
  ASSERT_EQ(g1.type(), gq::GeometryType::Sphere);
  gq::PenetrationResult<float> pen;
  ASSERT_TRUE(gq::computePenetration(pen, g0, p0, g1, p1).ok());
  ASSERT_TRUE(pen.penetrating);
  EXPECT_NEAR(pen.direction.norm(), 1.0f, 1e-5f);
  gq::DistanceResult<float> d;
  ASSERT_TRUE(gq::distance(d, g0, p0, g1, p1).ok());
  EXPECT_NEAR(d.normal.norm(), 1.0f, 1e-5f);
}

}  // namespace
