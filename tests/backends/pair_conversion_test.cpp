// Convention conversions of the pair-query backends (fcl, fcl-indep, libccd, libccd-mpr, bullet) on cases with
// closed-form answers: capsule axis and full length, penetration direction (moves geom0), distance normal (geom0
// to geom1) and witness points, box corners, sphere pairs, the plane's half-space, scaled hulls.
#include <cmath>

#include <gtest/gtest.h>

#include "backend_test_util.h"

namespace gq::cases::test {
namespace {

// Closed-form tolerance: iterative solvers (GJK/EPA) stop at ~1e-6 relative in double; float builds at ~1e-4.
// Anything through libccd (fcl's GST_LIBCCD, libccd itself) is looser: its EPA stops at epa_tolerance 1e-4 on the
// polytope, which on spheres leaves depth errors of ~2.5e-3 and witness-point errors of ~1e-4 (measured). A wrong
// convention (axis, half vs full length, sign) errs by O(1), so these still decide every conversion.
// Penetration directions within 0.15 (~8.6 degrees): libccd's EPA on a unit sphere pair is 5.6 degrees off
// (measured); a wrong sign or axis errs by sqrt(2) or more.
constexpr double kDirectionTolerance = 0.15;

template <class T> double closedFormTolerance(const std::string& backend) {
  if (backend == "fcl" || backend.rfind("libccd", 0) == 0) return 5e-4;
  return std::is_same_v<T, float> ? 2e-3 : 1e-5;
}

const std::vector<std::string> kDistanceBackends = {"fcl", "fcl-indep", "bullet"};
const std::vector<std::string> kPenetrationBackends = {"fcl", "fcl-indep", "libccd", "libccd-mpr", "bullet"};

template <class T> class PairConversion : public ::testing::Test {
 protected:
  static const char* precision() { return PrecisionOf<T>::name; }
  static double tol(const std::string& backend) { return closedFormTolerance<T>(backend); }
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(PairConversion, Scalars);

// Capsule r = 0.5, halfHeight 2 along local X (rotated to world Y about Z), sphere r = 0.5 on its axis 3.5 from the
// centre: gap 3.5 - 2 - 0.5 - 0.5 = 0.5. A backend using Z or the full length as half length would get 2.5 or -1.5.
TYPED_TEST(PairConversion, CapsuleAxisIsLocalXWithHalfHeight) {
  const json q = axisAngle(0, 0, 1, M_PI / 2);
  const json c = pairCase("distance", this->precision(), capsule(0.5, 2), pose(vec(1, 2, 3), q), sphere(0.5),
                          pose(vec(1, 5.5, 3)));
  for (const std::string& backend : kDistanceBackends) {
    SCOPED_TRACE(backend);
    const json r = runOne(backend, c);
    ASSERT_TRUE(r.value("ok", false)) << r.dump();
    EXPECT_NEAR(num(r["distance"]), 0.5, this->tol(backend));
    EXPECT_LT(dist3(r["point0"], 1, 4.5, 3), 10 * this->tol(backend)) << r.dump();  // capsule end cap tip
    EXPECT_LT(dist3(r["point1"], 1, 5.0, 3), 10 * this->tol(backend)) << r.dump();
    EXPECT_LT(dist3(r["normal"], 0, 1, 0), 10 * this->tol(backend)) << r.dump();
  }
}

// The same capsule, unrotated, overlapped along its axis by 0.1: the direction moving the capsule out is -X.
TYPED_TEST(PairConversion, CapsulePenetrationAlongAxisMovesGeom0Out) {
  const json c = pairCase("penetration", this->precision(), capsule(0.5, 2), pose(vec(0, 0, 0)), sphere(0.5),
                          pose(vec(2.9, 0, 0)));
  for (const std::string& backend : kPenetrationBackends) {
    SCOPED_TRACE(backend);
    const json r = runOne(backend, c);
    ASSERT_TRUE(r.value("ok", false)) << r.dump();
    EXPECT_TRUE(r["penetrating"].get<bool>());
    EXPECT_NEAR(num(r["depth"]), 0.1, 10 * this->tol(backend));
    EXPECT_LT(dist3(r["direction"], -1, 0, 0), kDirectionTolerance) << r.dump();
  }
}

// Box half extents (1,2,3), sphere r = 1 centred at the corner + (1,1,1): distance sqrt(3) - 1 along (1,1,1)/sqrt(3).
TYPED_TEST(PairConversion, BoxCornerDistanceAndWitnessPoints) {
  const json c = pairCase("distance", this->precision(), box(1, 2, 3), pose(vec(0, 0, 0)), sphere(1),
                          pose(vec(2, 3, 4)));
  const double s = 1 / std::sqrt(3.0);
  for (const std::string& backend : kDistanceBackends) {
    SCOPED_TRACE(backend);
    const json r = runOne(backend, c);
    ASSERT_TRUE(r.value("ok", false)) << r.dump();
    EXPECT_NEAR(num(r["distance"]), std::sqrt(3.0) - 1, this->tol(backend));
    EXPECT_LT(dist3(r["point0"], 1, 2, 3), 10 * this->tol(backend)) << r.dump();
    EXPECT_LT(dist3(r["point1"], 2 - s, 3 - s, 4 - s), 10 * this->tol(backend)) << r.dump();
    EXPECT_LT(dist3(r["normal"], s, s, s), 10 * this->tol(backend)) << r.dump();
  }
}

// Unit spheres 1.5 apart along X: depth 0.5, geom0 moves along -X; signed distance -0.5.
TYPED_TEST(PairConversion, SpherePairDepthDirectionAndSignedDistance) {
  const json pen = pairCase("penetration", this->precision(), sphere(1), pose(vec(0, 0, 0)), sphere(1),
                            pose(vec(1.5, 0, 0)));
  for (const std::string& backend : kPenetrationBackends) {
    SCOPED_TRACE(backend);
    const json r = runOne(backend, pen);
    ASSERT_TRUE(r.value("ok", false)) << r.dump();
    EXPECT_TRUE(r["penetrating"].get<bool>());
    EXPECT_NEAR(num(r["depth"]), 0.5, 10 * this->tol(backend));
    EXPECT_LT(dist3(r["direction"], -1, 0, 0), kDirectionTolerance) << r.dump();
  }
  json dist = pen;
  dist["query"] = "distance";
  for (const std::string& backend : kDistanceBackends) {
    SCOPED_TRACE(backend);
    const json r = runOne(backend, dist);
    ASSERT_TRUE(r.value("ok", false)) << r.dump();
    EXPECT_NEAR(num(r["distance"]), -0.5, 10 * this->tol(backend));
  }
}

// Overlap booleans of a sphere pair 2.1 apart (no) and 1.9 apart (yes), for every backend answering overlap.
TYPED_TEST(PairConversion, SpherePairOverlapBooleans) {
  for (const std::string& backend : kPenetrationBackends) {
    SCOPED_TRACE(backend);
    for (const double gap : {2.1, 1.9}) {
      const json r = runOne(backend, pairCase("overlap", this->precision(), sphere(1), pose(vec(0, 0, 0)), sphere(1),
                                              pose(vec(0, gap, 0))));
      ASSERT_TRUE(r.value("ok", false)) << r.dump();
      EXPECT_EQ(r["overlap"].get<bool>(), gap < 2) << gap;
    }
  }
}

// gq's plane is x = 0 with solid x <= 0 (FCL Halfspace n = +X, d = 0). A unit sphere centred at x = 0.5 sinks 0.5:
// it leaves along +X; a plane rotated to face +Y and moved to y = 3 sinks a sphere at y = 3.25 by 0.75.
TYPED_TEST(PairConversion, PlaneIsHalfSpaceBelowXZero) {
  const std::string backend = "fcl";
  const json c = pairCase("penetration", this->precision(), sphere(1), pose(vec(0.5, 7, -2)), plane(), pose(vec(0, 0, 0)));
  const json r = runOne("fcl", c);
  ASSERT_TRUE(r.value("ok", false)) << r.dump();
  EXPECT_TRUE(r["penetrating"].get<bool>());
  EXPECT_NEAR(num(r["depth"]), 0.5, 10 * this->tol(backend));
  EXPECT_LT(dist3(r["direction"], 1, 0, 0), kDirectionTolerance) << r.dump();
  const json rotated = pairCase("penetration", this->precision(), sphere(1), pose(vec(4, 3.25, 1)), plane(),
                                pose(vec(0, 3, 0), axisAngle(0, 0, 1, M_PI / 2)));
  const json r2 = runOne("fcl", rotated);
  ASSERT_TRUE(r2.value("ok", false)) << r2.dump();
  EXPECT_NEAR(num(r2["depth"]), 0.75, 10 * this->tol(backend));
  EXPECT_LT(dist3(r2["direction"], 0, 1, 0), kDirectionTolerance) << r2.dump();
}

// A hull of the cube [-1,1]^3 with mesh scale (2,1,1) along axes rotated 90 degrees about Z: the scaled box has
// half extents (1,2,1). A unit sphere at (0, 4, 0) is 1 away, one at (3.5,0,0) is 1.5 away.
TYPED_TEST(PairConversion, ScaledHullUsesRotatedScaleAxes) {
  json cube = json::array();
  for (int i = 0; i < 8; ++i) cube.push_back(vec(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
  json hull = convex(cube);
  hull["scale"] = {{"s", vec(2, 1, 1)}, {"q", axisAngle(0, 0, 1, M_PI / 2)}};
  for (const std::string& backend : kDistanceBackends) {
    SCOPED_TRACE(backend);
    const json r = runOne(backend, pairCase("distance", this->precision(), hull, pose(vec(0, 0, 0)), sphere(1),
                                            pose(vec(0, 4, 0))));
    ASSERT_TRUE(r.value("ok", false)) << r.dump();
    EXPECT_NEAR(num(r["distance"]), 1.0, this->tol(backend));
    const json r2 = runOne(backend, pairCase("distance", this->precision(), hull, pose(vec(0, 0, 0)), sphere(1),
                                             pose(vec(3.5, 0, 0))));
    ASSERT_TRUE(r2.value("ok", false)) << r2.dump();
    EXPECT_NEAR(num(r2["distance"]), 1.5, this->tol(backend));
  }
  for (const std::string backend : {"libccd", "libccd-mpr"}) {
    SCOPED_TRACE(backend);
    const json r = runOne(backend, pairCase("penetration", this->precision(), hull, pose(vec(0, 0, 0)), sphere(1),
                                            pose(vec(0, 2.5, 0))));
    ASSERT_TRUE(r.value("ok", false)) << r.dump();
    EXPECT_NEAR(num(r["depth"]), 0.5, 10 * this->tol(backend));
    EXPECT_LT(dist3(r["direction"], 0, -1, 0), kDirectionTolerance) << r.dump();
  }
}

// Queries a backend cannot answer say "unsupported" and the run goes on.
TYPED_TEST(PairConversion, UnansweredQueriesSayUnsupported) {
  const json ray = {{"id", 1}, {"precision", this->precision()}, {"query", "raycast"}, {"geom", sphere(1)},
                    {"origin", vec(-5, 0, 0)}, {"dir", vec(1, 0, 0)}, {"maxDist", 10}};
  for (const std::string backend : {"fcl", "libccd"}) {
    const std::vector<json> r = runBackend(backend, {ray, ray});
    ASSERT_EQ(r.size(), 2u);
    EXPECT_FALSE(r[0]["ok"].get<bool>());
    EXPECT_EQ(r[1]["error"].get<std::string>().rfind("unsupported: ", 0), 0u) << r[1].dump();
  }
  const json libccdDistance = runOne("libccd", pairCase("distance", this->precision(), sphere(1), pose(vec(0, 0, 0)),
                                                        sphere(1), pose(vec(3, 0, 0))));
  EXPECT_EQ(libccdDistance["error"].get<std::string>().rfind("unsupported: ", 0), 0u) << libccdDistance.dump();
}

}  // namespace
}  // namespace gq::cases::test
