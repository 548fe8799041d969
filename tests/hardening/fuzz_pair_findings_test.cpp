// fuzz_pair_queries' findings, replayed byte for byte through the fuzzer's own decoder from tests/fuzz/known_crashes/
// (also replayed by scripts/sanitize's smoke).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

#include "../fuzz/fuzz_decode.h"

namespace {

// The two geometries and poses fuzz_pair_queries decodes first from an input in known_crashes/.
template <class T> struct Pair {
  gq::Geometry<T> g0, g1;
  gq::Transform<T> p0, p1;
};
using FloatPair = Pair<float>;

template <class T> Pair<T> knownPair(const std::string& name) {
  std::ifstream file(std::string(GQ_SOURCE_DIR) + "/tests/fuzz/known_crashes/" + name, std::ios::binary);
  EXPECT_TRUE(file.good()) << name;
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  gq::fuzz::Bytes in(bytes.data(), bytes.size());
  EXPECT_EQ(in.flag(), (std::is_same_v<T, float>));  // the precision byte
  Pair<T> pair;
  pair.g0 = gq::fuzz::geometry<T>(in);
  pair.p0 = in.pose<T>();
  pair.g1 = gq::fuzz::geometry<T>(in);
  pair.p1 = in.pose<T>();
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
  const FloatPair f = knownPair<float>("fuzz_pair_queries_float_tiny_triangle_push_direction.bin");
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
  const FloatPair f = knownPair<float>("fuzz_pair_queries_float_sphere_subnormal_offset_normal.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::Sphere);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::Sphere);
  expectUnitPushAndDistanceNormal(f);
}

// Float sphere centre ~1e-22 off a capsule's axis: the offset's square is subnormal, and the push direction came out
// with length 0.90 (penetration direction; the distance normal shares the ball kernel).
TEST(FuzzPairFindings, SphereNextToACapsuleAxisGetsAUnitPushDirection) {
  const FloatPair f = knownPair<float>("fuzz_pair_queries_float_capsule_sphere_on_axis_direction.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::Capsule);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::Sphere);
  expectUnitPushAndDistanceNormal(f);
}

// A double capsule of radius and half-height 1e30 and a unit cube 1e30 away, (sqrt 2 - 1) 1e30 apart. In the
// capsule's frame the cube's vertices rounded to one point and its edges to rounding noise: penetration answered
// "penetrating, depth 1e30" along a direction of length 0.86 while overlap and distance said apart. The kernels now
// run in the smaller shape's frame (core/src/common/pair_frame.h); in either argument order.
TEST(FuzzPairFindings, UnitCubeFarFromAHugeCapsuleKeepsItsShape) {
  const Pair<double> f = knownPair<double>("fuzz_pair_queries_double_unit_cube_far_from_huge_capsule.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::Capsule);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::ConvexMesh);
  const double apart = (std::sqrt(2.0) - 1) * 1e30;
  for (const bool swap : {false, true}) {
    const gq::Geometry<double>& a = swap ? f.g1 : f.g0;
    const gq::Geometry<double>& b = swap ? f.g0 : f.g1;
    const gq::Transform<double>& pa = swap ? f.p1 : f.p0;
    const gq::Transform<double>& pb = swap ? f.p0 : f.p1;
    bool overlapping = true;
    ASSERT_TRUE(gq::overlap(a, pa, b, pb, overlapping).ok());
    EXPECT_FALSE(overlapping) << "swapped " << swap;
    gq::PenetrationResult<double> pen;
    ASSERT_TRUE(gq::computePenetration(pen, a, pa, b, pb).ok());
    EXPECT_FALSE(pen.penetrating) << "swapped " << swap;
    gq::DistanceResult<double> d;
    ASSERT_TRUE(gq::distance(d, a, pa, b, pb).ok());
    EXPECT_NEAR(d.distance / apart, 1.0, 1e-9) << "swapped " << swap;
  }
}

}  // namespace
