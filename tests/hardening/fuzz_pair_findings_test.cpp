// fuzz_pair_queries' findings, replayed byte for byte through the fuzzer's own decoder from tests/fuzz/known_crashes/
// (also replayed by scripts/sanitize's smoke).
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "../fuzz/fuzz_decode.h"

namespace {

// The two geometries and poses fuzz_pair_queries decodes first from a float input in known_crashes/.
struct FloatPair {
  gq::Geometry<float> g0, g1;
  gq::Transform<float> p0, p1;
};

FloatPair knownFloatPair(const std::string& name) {
  std::ifstream file(std::string(GQ_SOURCE_DIR) + "/tests/fuzz/known_crashes/" + name, std::ios::binary);
  EXPECT_TRUE(file.good()) << name;
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  gq::fuzz::Bytes in(bytes.data(), bytes.size());
  EXPECT_TRUE(in.flag());  // float
  FloatPair pair;
  pair.g0 = gq::fuzz::geometry<float>(in);
  pair.p0 = in.pose<float>();
  pair.g1 = gq::fuzz::geometry<float>(in);
  pair.p1 = in.pose<float>();
  return pair;
}

// The pair penetrates with a unit push direction, and its distance normal is unit too.
void expectUnitPushAndDistanceNormal(const FloatPair& f) {
  gq::PenetrationResult<float> pen;
  ASSERT_TRUE(gq::computePenetration(pen, f.g0, f.p0, f.g1, f.p1).ok());
  ASSERT_TRUE(pen.penetrating);
  EXPECT_NEAR(pen.direction.norm(), 1.0f, 1e-5f);
  gq::DistanceResult<float> d;
  ASSERT_TRUE(gq::distance(d, f.g0, f.p0, f.g1, f.p1).ok());
  EXPECT_NEAR(d.normal.norm(), 1.0f, 1e-5f);
}

// Float convex hull against a triangle mesh with a tiny triangle: its normal's squared norm underflowed, the push
// direction came out with length 0.97.
TEST(FuzzPairFindings, PenetrationAgainstATinyTriangleGivesAUnitDirection) {
  const FloatPair f = knownFloatPair("fuzz_pair_queries_float_tiny_triangle_push_direction.bin");
  ASSERT_EQ(f.g1.type(), gq::GeometryType::TriangleMesh);
  gq::PenetrationResult<float> r;
  const gq::Status s = gq::computePenetration(r, f.g0, f.p0, f.g1, f.p1);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_TRUE(r.penetrating);
  EXPECT_NEAR(r.direction.norm(), 1.0f, 1e-5f);
}

// Float spheres whose centres differ by ~1e-20: |c1 - c0|^2 is subnormal and keeps a few bits, so d / |d| had length
// 1.02 (penetration direction and distance normal).
TEST(FuzzPairFindings, SpheresWithASubnormalSquaredOffsetGetUnitNormals) {
  const FloatPair f = knownFloatPair("fuzz_pair_queries_float_sphere_subnormal_offset_normal.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::Sphere);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::Sphere);
  expectUnitPushAndDistanceNormal(f);
}

// Float sphere centre ~1e-22 off a capsule's axis: the offset's square is subnormal, and the push direction came out
// with length 0.90 (penetration direction; the distance normal shares the ball kernel).
TEST(FuzzPairFindings, SphereNextToACapsuleAxisGetsAUnitPushDirection) {
  const FloatPair f = knownFloatPair("fuzz_pair_queries_float_capsule_sphere_on_axis_direction.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::Capsule);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::Sphere);
  expectUnitPushAndDistanceNormal(f);
}

}  // namespace
