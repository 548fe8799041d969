// fuzz_pair_queries' findings, replayed byte for byte through the fuzzer's own decoder from tests/fuzz/known_crashes/
// (also replayed by scripts/sanitize's smoke).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
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

// Overlap and penetration say apart, and distance is `apart` within `tolerance`.
template <class T> void expectApartInEveryFamily(const Pair<T>& f, T apart, T tolerance) {
  bool overlapping = true;
  ASSERT_TRUE(gq::overlap(f.g0, f.p0, f.g1, f.p1, overlapping).ok());
  EXPECT_FALSE(overlapping);
  gq::PenetrationResult<T> pen;
  ASSERT_TRUE(gq::computePenetration(pen, f.g0, f.p0, f.g1, f.p1).ok());
  EXPECT_FALSE(pen.penetrating);
  gq::DistanceResult<T> d;
  ASSERT_TRUE(gq::distance(d, f.g0, f.p0, f.g1, f.p1).ok());
  EXPECT_NEAR(d.distance, apart, tolerance);
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

// A float sphere of radius 7.94 1.62 from a cube hull scaled by (8.9e-19, 7.1e8, 3.5) about a rotated frame: a sheet
// whose vertices reach 7e8. Its face normals came from a general 3x3 inverse of the scale matrix, rounding noise in
// float: SAT met no usable axis, so overlap said yes and penetration answered depth FLT_MAX (found by the
// fuzzer's cross-family check). S^-1 now comes from the scale factors. Apart, in both orders; pushed 3.62 towards
// the sheet (along double's exact normal), 2 deep (float rounds the sheet's vertices by ~0.06).
TEST(FuzzPairFindings, HullScaledToASheetKeepsItsFaceNormals) {
  const Pair<float> f = knownPair<float>("fuzz_pair_queries_float_sheet_hull_penetration_depth_flt_max.bin");
  ASSERT_EQ(f.g1.type(), gq::GeometryType::ConvexMesh);
  for (const bool swap : {false, true}) {
    bool overlapping = true;
    gq::PenetrationResult<float> pen;
    if (swap) {
      ASSERT_TRUE(gq::overlap(f.g1, f.p1, f.g0, f.p0, overlapping).ok());
      ASSERT_TRUE(gq::computePenetration(pen, f.g1, f.p1, f.g0, f.p0).ok());
    } else {
      ASSERT_TRUE(gq::overlap(f.g0, f.p0, f.g1, f.p1, overlapping).ok());
      ASSERT_TRUE(gq::computePenetration(pen, f.g0, f.p0, f.g1, f.p1).ok());
    }
    EXPECT_FALSE(overlapping) << "swapped " << swap;
    EXPECT_FALSE(pen.penetrating) << "swapped " << swap;
  }
  const auto& sheet = f.g1.get<gq::ConvexMeshGeometry<float>>();
  const gq::Geometry<double> sheetD = gq::ConvexMeshGeometry<double>(
      gq::fuzz::FallbackData<double>::get().hull,
      gq::MeshScale<double>(sheet.scale.scale.cast<double>(), sheet.scale.rotation.cast<double>()));
  ASSERT_EQ(f.g0.type(), gq::GeometryType::Capsule);
  const double radius = f.g0.get<gq::CapsuleGeometry<float>>().radius;
  const gq::Transform<double> p0(f.p0.p.cast<double>()), p1(f.p1.p.cast<double>());
  gq::DistanceResult<double> exact;
  ASSERT_TRUE(gq::distance(exact, gq::Geometry<double>(gq::SphereGeometry<double>(radius)), p0, sheetD, p1).ok());
  ASSERT_NEAR(exact.distance, 1.6204, 1e-3);  // the gap, also by enumerating the parallelepiped's features
  const gq::Transform<float> pushed((f.p0.p.cast<double>() + exact.normal * (exact.distance + 2)).cast<float>());
  gq::PenetrationResult<float> pen;
  ASSERT_TRUE(gq::computePenetration(pen, f.g0, pushed, f.g1, f.p1).ok());
  ASSERT_TRUE(pen.penetrating);
  EXPECT_NEAR(pen.depth, 2.0f, 0.25f);
  EXPECT_NEAR(std::abs(pen.direction.cast<double>().dot(exact.normal)), 1.0, 1e-3);
}

// A float hull scaled by (7.9, 1.3e6, 4.4e-41) against a sphere of radius 7.9: the smallest factor is subnormal, so
// 1/s overflowed, every face normal came out NaN and penetration answered depth FLT_MAX. Normals now map by
// min|s| / s. The depth is double's for the same numbers, within the rounding of the sheet's float vertices.
TEST(FuzzPairFindings, HullWithASubnormalScaleFactorGetsAFiniteDepth) {
  const Pair<float> f = knownPair<float>("fuzz_pair_queries_float_subnormal_hull_scale_depth_flt_max.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::ConvexMesh);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::Sphere);
  const auto& hull = f.g0.get<gq::ConvexMeshGeometry<float>>();
  ASSERT_LT(std::abs(hull.scale.scale.minCoeff()), std::numeric_limits<float>::min());  // subnormal
  gq::PenetrationResult<float> pen;
  ASSERT_TRUE(gq::computePenetration(pen, f.g0, f.p0, f.g1, f.p1).ok());
  ASSERT_TRUE(pen.penetrating);
  const gq::Geometry<double> hullD = gq::ConvexMeshGeometry<double>(
      gq::fuzz::FallbackData<double>::get().hull,
      gq::MeshScale<double>(hull.scale.scale.cast<double>(), hull.scale.rotation.cast<double>()));
  const gq::Geometry<double> ballD = gq::SphereGeometry<double>(f.g1.get<gq::SphereGeometry<float>>().radius);
  const gq::Transform<double> p0(f.p0.p.cast<double>(), f.p0.q.cast<double>());
  const gq::Transform<double> p1(f.p1.p.cast<double>(), f.p1.q.cast<double>());
  gq::PenetrationResult<double> reference;
  ASSERT_TRUE(gq::computePenetration(reference, hullD, p0, ballD, p1).ok());
  ASSERT_TRUE(reference.penetrating);
  EXPECT_NEAR(pen.depth, reference.depth, 0.25);  // two ulps of the vertices (~1.3e6 in float)
  EXPECT_NEAR(pen.direction.cast<double>().dot(reference.direction), 1.0, 1e-3);
}

}  // namespace

// Two findings whose inputs give one shape a pose quaternion of norm 1.00083 (validation accepts 1e-3): overlap and
// penetration took the pair frame from the raw quaternions, a rotation scaled by |q|^2 = 1.0017; every family now
// normalises it (HardCases.QuaternionsWithinTheUnitToleranceAreNormalisedByEveryFamily). The exact answers below use
// the normalised rotation.
namespace {
gq::Vec3<long double> unitAxisX(const gq::Transform<double>& pose) {
  return (pose.q.cast<long double>().normalized() * gq::Vec3<long double>::UnitX());
}
}  // namespace

// A capsule (radius 2.5625) lying 1.0 above a custom cone of radius 6.375 and half-height 2.2e-308 (a disk), across
// it: the minimum push lifts it off the disk by radius - 1.0 along the disk's axis. Was 1.5714 along a direction of
// length 1.0017.
TEST(FuzzPairFindings, CapsuleLyingOnAFlatCustomDiskIsPushedOffAlongTheDiskAxis) {
  const Pair<double> f = knownPair<double>("fuzz_pair_queries_double_capsule_on_flat_custom_disk.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::Capsule);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::Custom);
  const auto& capsule = f.g0.get<gq::CapsuleGeometry<double>>();
  // The capsule's segment ends, their heights above the disk's plane along its axis: equal (the capsule is level).
  const gq::Vec3<long double> axis = unitAxisX(f.p1), along = unitAxisX(f.p0) * (long double)capsule.halfHeight;
  const gq::Vec3<long double> centre = (f.p0.p - f.p1.p).cast<long double>();
  const long double h0 = (centre + along).dot(axis), h1 = (centre - along).dot(axis);
  ASSERT_NEAR(double(h0), double(h1), 1e-12);
  ASSERT_GT(h0, 0.0L);
  const double exact = double(capsule.radius - std::min(h0, h1));
  ASSERT_NEAR(exact, 1.5625, 1e-9);
  gq::PenetrationResult<double> pen;
  ASSERT_TRUE(gq::computePenetration(pen, f.g0, f.p0, f.g1, f.p1).ok());
  ASSERT_TRUE(pen.penetrating);
  EXPECT_NEAR(pen.depth, exact, 1e-9);
  EXPECT_NEAR(pen.direction.norm(), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(double(pen.direction.cast<long double>().dot(axis))), 1.0, 1e-9);
  gq::DistanceResult<double> d;
  ASSERT_TRUE(gq::distance(d, f.g0, f.p0, f.g1, f.p1).ok());
  EXPECT_NEAR(d.distance, -exact, 1e-9);
}

// A unit cube hull 0.7 from the centre of the end cap of a capsule of radius and half-height 1e30: every way out is
// 1e30 plus a few units, 1e30 in double. Penetration answered 9.983e29 (the capsule 0.17 % too small, off by 1.7e27).
TEST(FuzzPairFindings, UnitCubeInsideTheCapOfAHugeCapsuleIsItsRadiusDeep) {
  const Pair<double> f = knownPair<double>("fuzz_pair_queries_double_unit_cube_in_huge_capsule_cap.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::ConvexMesh);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::Capsule);
  const auto& capsule = f.g1.get<gq::CapsuleGeometry<double>>();
  ASSERT_EQ(capsule.radius, 1e30);
  // The cube's centre near the cap's centre (the segment's end nearer to it).
  const gq::Vec3<long double> end = unitAxisX(f.p1) * (long double)capsule.halfHeight;
  const gq::Vec3<long double> c = (f.p0.p - f.p1.p).cast<long double>();
  ASSERT_LT(double(std::min((c - end).norm(), (c + end).norm())), 1.0);
  const double tol = 8 * std::numeric_limits<double>::epsilon() * 1e30;
  gq::PenetrationResult<double> pen;
  ASSERT_TRUE(gq::computePenetration(pen, f.g0, f.p0, f.g1, f.p1).ok());
  ASSERT_TRUE(pen.penetrating);
  EXPECT_NEAR(pen.depth, 1e30, tol);
  EXPECT_NEAR(pen.direction.norm(), 1.0, 1e-12);
  gq::DistanceResult<double> d;
  ASSERT_TRUE(gq::distance(d, f.g0, f.p0, f.g1, f.p1).ok());
  EXPECT_NEAR(d.distance, -1e30, tol);
}

// Hulls scaled past T's precision (penetration/degenerate_hull.h; DegenerateHullPenetration.* covers the family).
// A double sphere of radius 2.0625 centred on a cube hull scaled (0.125, 1e-266, 7.9) by a rotation 1e-65 off the
// identity: pushed out through the sheet's face, 2.0625 (the radius; the sheet is 1e-266 thick), as distance says.
// Penetration answered 1.9375 along the sheet, out through its rim 0.125 away, which leaves them overlapping.
TEST(FuzzPairFindings, SphereCentredOnAHullScaledToASheetIsPushedOutThroughTheSheet) {
  const Pair<double> f = knownPair<double>("fuzz_pair_queries_double_sphere_centred_on_flat_hull.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::Sphere);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::ConvexMesh);
  const double radius = f.g0.get<gq::SphereGeometry<double>>().radius;
  const auto& sheet = f.g1.get<gq::ConvexMeshGeometry<double>>();
  const Eigen::Vector3d normal = f.p1.q.normalized() * (sheet.scale.rotation.normalized() * Eigen::Vector3d::UnitY());
  gq::PenetrationResult<double> pen;
  ASSERT_TRUE(gq::computePenetration(pen, f.g0, f.p0, f.g1, f.p1).ok());
  ASSERT_TRUE(pen.penetrating);
  EXPECT_NEAR(pen.depth, radius, 1e-12);
  EXPECT_NEAR(std::abs(pen.direction.dot(normal)), 1.0, 1e-12);
  gq::DistanceResult<double> d;
  ASSERT_TRUE(gq::distance(d, f.g0, f.p0, f.g1, f.p1).ok());
  EXPECT_NEAR(d.distance, -radius, 1e-12);
}

// The same sheet (a cube hull scaled (0.125, 1e-266, 7.9)) 2e39 below a sphere of radius 2.06 (found by the harness's
// cross-family check on sheets and needles): penetration answered "1 deep" along the sheet's
// normal while overlap and distance said apart. GJK's resolution for a pair 2e39 across is far coarser than the
// radius, so the kernel went to SAT, whose face normals the scale rotation's rounding decides; GJK's separating axis
// is a proof at any resolution and now answers first.
TEST(FuzzPairFindings, SphereFarFromAHullScaledToASheetIsApartInEveryFamily) {
  const Pair<double> f = knownPair<double>("fuzz_pair_queries_double_sphere_far_from_flat_hull.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::Sphere);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::ConvexMesh);
  const double apart = (f.p1.p - f.p0.p).norm();  // 2e39: the sizes (2.06, 7.9) are below its rounding
  expectApartInEveryFamily(f, apart, 1e-12 * apart);
}

// A float sphere of radius 4.19 beside a 10-vertex hull scaled (9.0e-36, 3.2e-12, 7.56), a needle about 43 long:
// apart, 4.488 (overlap and distance agreed; the same distance in double). Penetration answered 2.013 deep.
TEST(FuzzPairFindings, SphereBesideAHullScaledToANeedleIsApartInEveryFamily) {
  expectApartInEveryFamily(knownPair<float>("fuzz_pair_queries_float_sphere_beside_needle_hull_penetration.bin"),
                           4.488f, 1e-3f);
}

// A float sphere (radius 5.3) 7.7e8 from the centre of a custom cylinder of radius and half-height 1e30 (found by the
// harness's cross-family check on float pairs of scale 1e9+): overlap said yes, penetration "not
// penetrating" and distance non-finite. The cylinder's GJK size overflowed (|(h, r, r)|^2 > FLT_MAX) and its support
// squared direction components; in float the depth is the radius, 1e30 (the offset is below its resolution).
TEST(FuzzPairFindings, SphereInsideAFloatCylinder1e30WideIsItsRadiusDeep) {
  const FloatPair f = knownPair<float>("fuzz_pair_queries_float_sphere_inside_1e30_cylinder_size_overflow.bin");
  ASSERT_EQ(f.g1.type(), gq::GeometryType::Custom);
  gq::PenetrationResult<float> pen;
  ASSERT_TRUE(gq::computePenetration(pen, f.g0, f.p0, f.g1, f.p1).ok());
  ASSERT_TRUE(pen.penetrating);
  EXPECT_NEAR(double(pen.depth), 1e30, 1e-3 * 1e30);
  gq::DistanceResult<float> d;
  ASSERT_TRUE(gq::distance(d, f.g0, f.p0, f.g1, f.p1).ok());
  EXPECT_NEAR(double(d.distance), -1e30, 1e-3 * 1e30);
}

// A double sphere of radius 4.9e-299 swept against a triangle mesh scaled by -4.7e-224 at the same place (a libFuzzer
// timeout after 3,078,385 executions): the sweep's bisection for the contact
// looped forever once its interval was two adjacent doubles (its resolution, GJK's tolerance for a pair 1e-224
// across, lies far below their spacing near 0.5). It now stops there. The sweep answers, a hit within the mesh's
// size of the start.
TEST(FuzzPairFindings, SweepOfATinySphereAgainstATinyMeshTerminates) {
  const std::string name = "fuzz_pair_queries_double_tiny_sphere_sweep_tiny_mesh_bisection_hang.bin";
  std::ifstream file(std::string(GQ_SOURCE_DIR) + "/tests/fuzz/known_crashes/" + name, std::ios::binary);
  ASSERT_TRUE(file.good());
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
  gq::fuzz::Bytes in(bytes.data(), bytes.size());
  ASSERT_FALSE(in.flag());  // double
  const gq::Geometry<double> g0 = gq::fuzz::geometry<double>(in);
  const gq::Transform<double> p0 = in.pose<double>();
  const gq::Geometry<double> g1 = gq::fuzz::geometry<double>(in);
  const gq::Transform<double> p1 = in.pose<double>();
  in.flag();  // the distance query's cache flag
  const gq::Vec3<double> dir = in.direction<double>();
  const double maxDist = in.scalar<double>();
  const gq::HitFlags flags = gq::fuzz::hitFlags(in);
  const double inflation = in.flag() ? in.scalar<double>() : 0.0;
  ASSERT_EQ(g1.type(), gq::GeometryType::TriangleMesh);
  gq::SweepHit<double> hit;
  bool hasHit = false;
  ASSERT_TRUE(gq::sweep(dir, maxDist, g0, p0, g1, p1, hit, hasHit, flags, inflation).ok());
  ASSERT_TRUE(hasHit);
  EXPECT_LE(hit.distance, 1e-222);
}

// A float capsule (radius 1.4e-23) 3.5e-23 off the edge of a cube mesh 6.4 wide: in the mesh's frame its offsets round
// away and it touches, 5e-23 deep. The push's squared norm (~3e-45) is subnormal, and total / |total| came out 3 %
// long (direction length 1.031). The iteration's sum is now normalised range-safely (tryUnit, rangeSafeNorm).
TEST(FuzzPairFindings, CapsuleTouchingAMeshAtASubnormalSquaredDepthGetsAUnitDirection) {
  const FloatPair f = knownPair<float>("fuzz_pair_queries_float_capsule_mesh_tiny_depth_non_unit_direction.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::Capsule);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::TriangleMesh);
  gq::PenetrationResult<float> r;
  const gq::Status s = gq::computePenetration(r, f.g0, f.p0, f.g1, f.p1);
  ASSERT_TRUE(s.ok()) << s.toString();
  ASSERT_TRUE(r.penetrating);
  EXPECT_LT(r.depth, 1e-22f);
  EXPECT_NEAR(r.direction.norm(), 1.0f, 1e-5f);
}

// Two float hulls (8 vertices each, 5.5 apart in x) overlapping 1.71 deep. EPA's closest face could not be expanded
// in float (the new faces came out as rounding slivers) and was kept as final, while a face 2.125 deep converged:
// `distance` answered -2.125 where `computePenetration` (SAT) answered 1.71. EPA now reports a converged face only
// when it is the closest of all, and two hulls whose EPA does not converge take the SAT's exact depth. Exact: the
// closest face of the Minkowski difference's hull, in double.
TEST(FuzzPairFindings, HullPairDistanceIsMinusTheExactDepthWhenEpaCannotExpandItsClosestFace) {
  const FloatPair f = knownPair<float>("fuzz_pair_queries_float_hull_pair_penetration_vs_distance.bin");
  ASSERT_EQ(f.g0.type(), gq::GeometryType::ConvexMesh);
  ASSERT_EQ(f.g1.type(), gq::GeometryType::ConvexMesh);
  const auto worldVertices = [](const gq::Geometry<float>& g, const gq::Transform<float>& p) {
    const auto& h = g.get<gq::ConvexMeshGeometry<float>>();
    std::vector<gq::Vec3<double>> out;
    for (const auto& v : h.mesh->vertices) out.push_back(p.transform(gq::Vec3<float>(h.scale.toMatrix() * v)).cast<double>());
    return out;
  };
  std::vector<gq::Vec3<double>> difference;  // B - A: holds the origin when they overlap
  for (const auto& a : worldVertices(f.g0, f.p0))
    for (const auto& b : worldVertices(f.g1, f.p1)) difference.push_back(b - a);
  std::shared_ptr<const gq::ConvexMesh<double>> hull;
  ASSERT_TRUE(gq::cookConvexMesh(difference, hull).ok());
  double exact = std::numeric_limits<double>::infinity();
  for (const auto& face : hull->polygons) exact = std::min(exact, -face.d);
  gq::DistanceResult<float> d;
  const gq::Status s = gq::distance(d, f.g0, f.p0, f.g1, f.p1);
  ASSERT_TRUE(s.ok()) << s.toString();
  EXPECT_NEAR(d.distance, -exact, 1e-5 * exact);
  EXPECT_NEAR(d.normal.norm(), 1.0f, 1e-5f);
  EXPECT_NEAR((d.point1 - d.point0 - d.distance * d.normal).norm(), 0.0f, 1e-5f);
  gq::PenetrationResult<float> pen;
  ASSERT_TRUE(gq::computePenetration(pen, f.g0, f.p0, f.g1, f.p1).ok());
  EXPECT_NEAR(pen.depth, exact, 1e-5 * exact);
}
