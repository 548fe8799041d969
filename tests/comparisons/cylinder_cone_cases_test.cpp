// Cylinders and cones in case files are built as core's ready-made custom shapes (axis = local X; the cone's base
// disk at x = -halfHeight, apex at +halfHeight) and answered by the gq backend. Expected values are closed forms.
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>

#include "runner_test_util.h"

namespace gq::cases::test {
namespace {

constexpr double kExact = 1e-12;  // closed-form kernels (bounds, raycasts, sphere-cylinder overlap) in double
constexpr double kIterative = 1e-6;  // GJK/EPA and conservative advancement in double

void expectVec(const nlohmann::json& v, double x, double y, double z, double tol) {
  ASSERT_TRUE(v.is_array() && v.size() == 3) << v.dump();
  EXPECT_NEAR(v[0].get<double>(), x, tol) << v.dump();
  EXPECT_NEAR(v[1].get<double>(), y, tol) << v.dump();
  EXPECT_NEAR(v[2].get<double>(), z, tol) << v.dump();
}

// The example file's results, by id.
std::map<std::string, nlohmann::json> runExampleFile() {
  const std::string path = GQ_SOURCE_DIR "/comparisons/cases/examples/cylinder_cone.jsonl";
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::map<std::string, nlohmann::json> byId;
  for (const nlohmann::json& r : runLines(text.str())) byId[r["id"].get<std::string>()] = r;
  return byId;
}

class CylinderConeCases : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { results_ = new std::map<std::string, nlohmann::json>(runExampleFile()); }
  static void TearDownTestSuite() {
    delete results_;
    results_ = nullptr;
  }
  // The answered result of one case (fails the test when gq did not answer it).
  static const nlohmann::json& answer(const std::string& id) {
    static const nlohmann::json missing;
    const auto it = results_->find(id);
    if (it == results_->end()) {
      ADD_FAILURE() << "no result for " << id;
      return missing;
    }
    EXPECT_TRUE(it->second.value("ok", false)) << it->second.dump();
    return it->second;
  }
  static std::map<std::string, nlohmann::json>* results_;
};
std::map<std::string, nlohmann::json>* CylinderConeCases::results_ = nullptr;

TEST_F(CylinderConeCases, EveryCaseOfTheExampleFileIsAnswered) {
  ASSERT_EQ(results_->size(), 11u);
  for (const auto& [id, r] : *results_) EXPECT_TRUE(r.value("ok", false)) << r.dump();
}

TEST_F(CylinderConeCases, BoundsAreTheAxisAlignedBoxOfTheSolid) {
  const nlohmann::json& cylinder = answer("bounds-cylinder");  // radius 1, halfHeight 2 (along X), at (1,2,3)
  expectVec(cylinder["min"], -1, 1, 2, kExact);
  expectVec(cylinder["max"], 3, 3, 4, kExact);
  const nlohmann::json& cone = answer("bounds-cone");  // float
  expectVec(cone["min"], -2, -1, -1, 1e-6);
  expectVec(cone["max"], 2, 1, 1, 1e-6);
}

TEST_F(CylinderConeCases, RaysHitTheCylinderSideAndCap) {
  const nlohmann::json& side = answer("raycast-cylinder-side");
  ASSERT_EQ(side["hits"].size(), 1u) << side.dump();
  EXPECT_NEAR(side["hits"][0]["distance"].get<double>(), 4.0, kExact);
  expectVec(side["hits"][0]["position"], 0.5, -1, 0, kExact);
  expectVec(side["hits"][0]["normal"], 0, -1, 0, kExact);
  const nlohmann::json& cap = answer("raycast-cylinder-cap");
  ASSERT_EQ(cap["hits"].size(), 1u) << cap.dump();
  EXPECT_NEAR(cap["hits"][0]["distance"].get<double>(), 8.0, kExact);
  expectVec(cap["hits"][0]["normal"], -1, 0, 0, kExact);
}

// Cone radius 1, halfHeight 1: at x = 0 its radius is 1/2; the side's outward normal is (1, -2, 0) / sqrt 5 there.
TEST_F(CylinderConeCases, RaysHitTheConeSideAndBase) {
  const nlohmann::json& side = answer("raycast-cone-side");
  ASSERT_EQ(side["hits"].size(), 1u) << side.dump();
  EXPECT_NEAR(side["hits"][0]["distance"].get<double>(), 4.5, kExact);
  expectVec(side["hits"][0]["position"], 0, -0.5, 0, kExact);
  expectVec(side["hits"][0]["normal"], 1 / std::sqrt(5.0), -2 / std::sqrt(5.0), 0, kExact);
  const nlohmann::json& base = answer("raycast-cone-base");  // the base disk is at x = -halfHeight
  ASSERT_EQ(base["hits"].size(), 1u) << base.dump();
  EXPECT_NEAR(base["hits"][0]["distance"].get<double>(), 4.0, kExact);
  expectVec(base["hits"][0]["normal"], -1, 0, 0, kExact);
}

TEST_F(CylinderConeCases, SphereAgainstCylinderOverlapsOnlyWithinItsRadius) {
  EXPECT_TRUE(answer("overlap-sphere-cylinder")["overlap"].get<bool>());         // gap -0.1
  EXPECT_FALSE(answer("overlap-sphere-cylinder-apart")["overlap"].get<bool>());  // gap 0.1
}

// The sphere's centre (-3,0,0) faces the cone's base disk at x = -1: distance 3 - 1 - 0.5.
TEST_F(CylinderConeCases, SphereToConeDistanceReachesTheBaseDisk) {
  const nlohmann::json& r = answer("distance-sphere-cone");
  EXPECT_NEAR(r["distance"].get<double>(), 1.5, kIterative);
  expectVec(r["point0"], -2.5, 0, 0, kIterative);
  expectVec(r["point1"], -1, 0, 0, kIterative);
  expectVec(r["normal"], 1, 0, 0, kIterative);
}

// libccd's cylinder pair along z: axial overlap 0.25 - (0.3 - 0.5) = 0.45 is smaller than the radial 0.85, so the
// depth is 0.45 and geom0 leaves downwards.
TEST_F(CylinderConeCases, LibccdCylinderPairPenetratesByTheAxialOverlap) {
  const nlohmann::json& r = answer("penetration-libccd-cylinders");
  EXPECT_TRUE(r["penetrating"].get<bool>());
  EXPECT_NEAR(r["depth"].get<double>(), 0.45, kIterative);
  expectVec(r["direction"], 0, 0, -1, kIterative);
}

// A sphere of radius 0.5 swept along +X from x = -10 touches the cap x = -2 when its centre reaches -2.5.
TEST_F(CylinderConeCases, SweptSphereStopsAtTheCylinderCap) {
  const nlohmann::json& r = answer("sweep-sphere-cylinder");
  ASSERT_TRUE(r["hit"].get<bool>()) << r.dump();
  EXPECT_NEAR(r["distance"].get<double>(), 7.5, kIterative);
  expectVec(r["normal"], -1, 0, 0, kIterative);
}

// Both precisions, built by the same factory path: a cylinder and a cone with invalid sizes report core's
// validation message, not an unsupported shape.
template <class T> class CylinderConeSizes : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(CylinderConeSizes, Scalars);

TYPED_TEST(CylinderConeSizes, NonPositiveSizesAreInvalidAndValidOnesAnswer) {
  for (const char* type : {"cylinder", "cone"}) {
    const auto line = [&](double radius) {
      std::ostringstream s;
      s << R"({"id":"s","precision":")" << PrecisionName<TypeParam>::value << R"(","query":"raycast","geom":{"type":")"
        << type << R"(","radius":)" << radius << R"(,"halfHeight":1},"origin":[0,-5,0],"dir":[0,1,0],"maxDist":10})";
      return s.str();
    };
    const nlohmann::json bad = runOne(line(-1));
    EXPECT_FALSE(bad.value("ok", true)) << bad.dump();
    EXPECT_NE(bad.value("error", std::string()).rfind("unsupported", 0), 0u) << bad.dump();
    const nlohmann::json good = runOne(line(1));
    ASSERT_TRUE(good.value("ok", false)) << good.dump();
    ASSERT_EQ(good["hits"].size(), 1u) << good.dump();
    // The cylinder's side is at |y| = 1; the cone (radius 1 at x = -1, 0 at x = 1) is 1/2 wide at x = 0.
    EXPECT_NEAR(good["hits"][0]["distance"].get<double>(), std::string(type) == "cylinder" ? 4.0 : 4.5,
                distanceTolerance<TypeParam>());
  }
}

}  // namespace
}  // namespace gq::cases::test
