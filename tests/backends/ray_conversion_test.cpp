// Convention conversions of the ray and sweep backends (embree, bullet) on cases with closed-form answers: a ray
// through a posed triangle (distance, position, normal, barycentrics, face index, back-face culling), the capsule
// axis, the heightfield sample layout and centring, a sphere swept against a box.
#include <cmath>

#include <gtest/gtest.h>

#include "backend_test_util.h"

namespace gq::cases::test {
namespace {

// Embree and Bullet's float build intersect in float; Bullet's double build iterates for convex shapes.
template <class T> double rayTolerance() { return std::is_same_v<T, float> ? 1e-4 : 1e-6; }

template <class T> class RayConversion : public ::testing::Test {
 protected:
  static const char* precision() { return PrecisionOf<T>::name; }
  static double tol() { return rayTolerance<T>(); }
  static json ray(const json& geom, const json& p, const json& origin, const json& dir, double maxDist,
                  const json& flags) {
    return {{"id", "ray"}, {"precision", precision()}, {"query", "raycast"}, {"geom", geom}, {"pose", p},
            {"origin", origin}, {"dir", dir}, {"maxDist", maxDist}, {"flags", flags}};
  }
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(RayConversion, Scalars);

// Triangle (0,0,0),(2,0,0),(0,2,0) (normal +Z) posed by Rx(90 deg) then (1,2,3): world (1,2,3),(3,2,3),(1,2,5), normal
// -Y. The barycentric point u = 0.25 (weight of v1), v = 0.5 (weight of v2) is local (0.5,1,0), world (1.5,2,4).
json triangle(bool doubleSided) {
  return {{"type", "mesh"}, {"vertices", json::array({vec(0, 0, 0), vec(2, 0, 0), vec(0, 2, 0)})},
          {"triangles", json::array({json::array({0, 1, 2})})}, {"doubleSided", doubleSided}};
}
json trianglePose() { return pose(vec(1, 2, 3), axisAngle(1, 0, 0, M_PI / 2)); }

TYPED_TEST(RayConversion, RayThroughPosedTriangleReportsDistancePointNormalAndBarycentrics) {
  const json c = this->ray(triangle(false), trianglePose(), vec(1.5, -3, 4), vec(0, 1, 0), 100,
                           json::array({"position", "normal", "uv", "faceIndex"}));
  for (const std::string backend : {"embree", "bullet"}) {
    SCOPED_TRACE(backend);
    const json r = runOne(backend, c);
    ASSERT_TRUE(r.value("ok", false)) << r.dump();
    ASSERT_EQ(r["hits"].size(), 1u) << r.dump();
    const json& h = r["hits"][0];
    EXPECT_NEAR(num(h["distance"]), 5.0, 10 * this->tol());
    EXPECT_LT(dist3(h["position"], 1.5, 2, 4), 10 * this->tol()) << h.dump();
    EXPECT_LT(dist3(h["normal"], 0, -1, 0), 10 * this->tol()) << h.dump();
    EXPECT_EQ(h["faceIndex"].get<std::uint32_t>(), 0u);
    if (backend == std::string("embree")) {  // Bullet's ray callback carries no barycentrics
      EXPECT_NEAR(num(h["u"]), 0.25, 10 * this->tol());
      EXPECT_NEAR(num(h["v"]), 0.5, 10 * this->tol());
    }
  }
}

// From the back (+Y side) a single-sided triangle is missed; double-sided, or with meshBothSides, it is hit at the
// same distance with the normal turned towards the ray.
TYPED_TEST(RayConversion, BackFacesAreCulledUnlessDoubleSided) {
  for (const std::string backend : {"embree", "bullet"}) {
    SCOPED_TRACE(backend);
    const json single = runOne(backend, this->ray(triangle(false), trianglePose(), vec(1.5, 7, 4), vec(0, -1, 0), 100,
                                                  json::array({"normal"})));
    ASSERT_TRUE(single.value("ok", false)) << single.dump();
    EXPECT_EQ(single["hits"].size(), 0u) << single.dump();
    const json both = runOne(backend, this->ray(triangle(false), trianglePose(), vec(1.5, 7, 4), vec(0, -1, 0), 100,
                                                json::array({"normal", "meshBothSides"})));
    const json dbl = runOne(backend, this->ray(triangle(true), trianglePose(), vec(1.5, 7, 4), vec(0, -1, 0), 100,
                                               json::array({"normal"})));
    for (const json& r : {both, dbl}) {
      ASSERT_TRUE(r.value("ok", false)) << r.dump();
      ASSERT_EQ(r["hits"].size(), 1u) << r.dump();
      EXPECT_NEAR(num(r["hits"][0]["distance"]), 5.0, 10 * this->tol());
      EXPECT_LT(dist3(r["hits"][0]["normal"], 0, 1, 0), 10 * this->tol()) << r.dump();
    }
  }
}

// anyHit through rtcOccluded1 still reports the hit's distance (recorded by the filter function).
TYPED_TEST(RayConversion, EmbreeAnyHitReportsTheAcceptedHit) {
  const json r = runOne("embree", this->ray(triangle(false), trianglePose(), vec(1.5, -3, 4), vec(0, 1, 0), 100,
                                            json::array({"anyHit"})));
  ASSERT_TRUE(r.value("ok", false)) << r.dump();
  ASSERT_EQ(r["hits"].size(), 1u) << r.dump();
  EXPECT_NEAR(num(r["hits"][0]["distance"]), 5.0, 10 * this->tol());
  const json miss = runOne("embree", this->ray(triangle(false), trianglePose(), vec(1.5, -3, 4), vec(0, 1, 0), 4.9,
                                               json::array({"anyHit"})));
  EXPECT_EQ(miss["hits"].size(), 0u) << miss.dump();
}

// Bullet's btCapsuleShapeX with height 2 * halfHeight: a ray along the axis hits the cap at 10 - 2 - 0.5 = 7.5; a
// ray along Y through the axis at x = 1.5 hits at 10 - 0.5.
TYPED_TEST(RayConversion, BulletCapsuleAlongX) {
  const std::vector<json> r = runBackend(
      "bullet", {this->ray(capsule(0.5, 2), pose(vec(0, 0, 0)), vec(-10, 0, 0), vec(1, 0, 0), 100, json::array()),
                 this->ray(capsule(0.5, 2), pose(vec(0, 0, 0)), vec(1.5, -10, 0), vec(0, 1, 0), 100, json::array())});
  ASSERT_EQ(r.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_TRUE(r[i].value("ok", false)) << r[i].dump();
    ASSERT_EQ(r[i]["hits"].size(), 1u) << r[i].dump();
  }
  // Bullet casts rays at convex shapes by conservative advancement: ~1e-4 relative.
  EXPECT_NEAR(num(r[0]["hits"][0]["distance"]), 7.5, 1e-3);
  EXPECT_NEAR(num(r[1]["hits"][0]["distance"]), 9.5, 1e-3);
}

// Heightfield 3 x 4 samples with height = row index, heightScale 2, rowScale 0.5, columnScale 3, posed at (10,0,0):
// the surface is y = 2 * (x - 10) / 0.5 over x in [10, 11], z in [0, 9]. A vertical ray at (10.3, 50, 7) hits y = 1.2.
// (A transposed layout would give y = 2 z / 3; a missing centring offset shifts everything.)
TYPED_TEST(RayConversion, BulletHeightFieldSampleLayoutAndOrigin) {
  json heights = json::array();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) heights.push_back(r);
  const json hf = {{"type", "heightfield"}, {"rows", 3}, {"columns", 4}, {"heights", heights}, {"rowScale", 0.5},
                   {"columnScale", 3}, {"heightScale", 2}};
  const json r = runOne("bullet", this->ray(hf, pose(vec(10, 0, 0)), vec(10.3, 50, 7), vec(0, -1, 0), 100,
                                            json::array({"position", "normal"})));
  ASSERT_TRUE(r.value("ok", false)) << r.dump();
  ASSERT_EQ(r["hits"].size(), 1u) << r.dump();
  EXPECT_NEAR(num(r["hits"][0]["distance"]), 50 - 1.2, 1e3 * this->tol());
  // Surface normal of y = 4 (x - 10): (-4, 1, 0) / sqrt(17).
  const double s = 1 / std::sqrt(17.0);
  EXPECT_LT(dist3(r["hits"][0]["normal"], -4 * s, s, 0), 1e3 * this->tol()) << r.dump();
}

// A unit sphere swept along +X from x = -5 against a unit box at the origin touches after 3.
TYPED_TEST(RayConversion, BulletSphereSweptAgainstBox) {
  const json c = {{"id", "sweep"}, {"precision", this->precision()}, {"query", "sweep"}, {"geom0", sphere(1)},
                  {"pose0", pose(vec(-5, 0.5, 0))}, {"dir", vec(1, 0, 0)}, {"maxDist", 10}, {"geom1", box(1, 1, 1)},
                  {"pose1", pose(vec(0, 0, 0))}, {"flags", json::array({"position", "normal"})}};
  const json r = runOne("bullet", c);
  ASSERT_TRUE(r.value("ok", false)) << r.dump();
  ASSERT_TRUE(r["hit"].get<bool>()) << r.dump();
  EXPECT_NEAR(num(r["distance"]), 3.0, 1e-3);
  EXPECT_LT(dist3(r["normal"], -1, 0, 0), 1e-3) << r.dump();
}

// A double case goes to gq-query-bullet64 and a float case to gq-query-bullet: both are answered in one run.
TYPED_TEST(RayConversion, BulletForwardingAnswersBothPrecisionsInOrder) {
  json f = this->ray(sphere(1), pose(vec(0, 0, 0)), vec(-5, 0, 0), vec(1, 0, 0), 100, json::array());
  json d = f;
  f["precision"] = "float";
  f["id"] = "f";
  d["precision"] = "double";
  d["id"] = "d";
  const std::vector<json> r = runBackend("bullet", {f, d, f});
  ASSERT_EQ(r.size(), 3u);
  EXPECT_EQ(r[0]["id"], "f");
  EXPECT_EQ(r[1]["id"], "d");
  for (const json& x : r) {
    ASSERT_TRUE(x.value("ok", false)) << x.dump();
    ASSERT_EQ(x["hits"].size(), 1u);
    EXPECT_NEAR(num(x["hits"][0]["distance"]), 4.0, 1e-3);
  }
}

}  // namespace
}  // namespace gq::cases::test
