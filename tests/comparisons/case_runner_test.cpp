// The runner's mapping from case lines to gq queries and back to result lines, in float and double. Expected
// values are closed forms computed here in long double.
#include <cmath>
#include <fstream>

#include <gtest/gtest.h>

#include "result_writer.h"
#include "runner_test_util.h"
#include "timing.h"

namespace gq::cases::test {
namespace {

template <class T> class CaseRunner : public ::testing::Test {
 protected:
  // Prefixes a case body with its id and this suite's precision.
  static std::string line(const char* id, const std::string& body) {
    return std::string("{\"id\":\"") + id + "\",\"precision\":\"" + PrecisionName<T>::value + "\"," + body + "}";
  }
  static double tol() { return distanceTolerance<T>(); }
};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(CaseRunner, Scalars);

TYPED_TEST(CaseRunner, IdsArePreservedInOrder) {
  std::string text;
  for (int i = 0; i < 5; ++i)
    text += this->line(std::to_string(10 - i).c_str(), R"("query":"bounds","geom":{"type":"sphere","radius":1})") + "\n";
  const std::vector<nlohmann::json> r = runLines(text);
  ASSERT_EQ(r.size(), 5u);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(r[i]["id"], std::to_string(10 - i));
}

// Sphere of radius 2 at (1,2,3) (rotated: must not matter); ray along +Z offset 1 from the centre line.
TYPED_TEST(CaseRunner, SphereRaycastDistanceMatchesClosedForm) {
  const nlohmann::json r = runOne(this->line("s", R"("query":"raycast","geom":{"type":"sphere","radius":2},)"
                                        R"("pose":{"p":[1,2,3],"q":[0.3,0.1,-0.2,0.9]},"origin":[2,2,-7],"dir":[0,0,1],)"
                                        R"("maxDist":100,"flags":["position","normal"])"));
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  ASSERT_EQ(r["hits"].size(), 1u) << r.dump();
  const long double expected = 10.0L - std::sqrt(3.0L);
  const nlohmann::json& hit = r["hits"][0];
  EXPECT_NEAR(hit["distance"].get<double>(), double(expected), 10 * this->tol());
  ASSERT_TRUE(hit.contains("position") && hit.contains("normal")) << hit.dump();
  EXPECT_NEAR(hit["position"][2].get<double>(), double(-7.0L + expected), 10 * this->tol());
  EXPECT_NEAR(hit["normal"][0].get<double>(), 0.5, 10 * this->tol());  // (1, 0, -sqrt 3) / 2
  EXPECT_EQ(hit["faceIndex"].get<std::uint32_t>(), 4294967295u);
  EXPECT_FALSE(hit.contains("u"));
}

TYPED_TEST(CaseRunner, RaycastPrintsOnlyRequestedFields) {
  const nlohmann::json r = runOne(this->line("n", R"("query":"raycast","geom":{"type":"box","halfExtents":[1,2,3]},)"
                                        R"("origin":[-10,0,0],"dir":[1,0,0],"maxDist":100,"flags":["normal"])"));
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  ASSERT_EQ(r["hits"].size(), 1u) << r.dump();
  const nlohmann::json& hit = r["hits"][0];
  EXPECT_NEAR(hit["distance"].get<double>(), 9.0, this->tol());
  EXPECT_FALSE(hit.contains("position"));
  EXPECT_FALSE(hit.contains("u"));
  ASSERT_TRUE(hit.contains("normal"));
  EXPECT_NEAR(hit["normal"][0].get<double>(), -1.0, this->tol());
}

TYPED_TEST(CaseRunner, RayMissPrintsEmptyHitList) {
  const nlohmann::json r = runOne(this->line("m", R"("query":"raycast","geom":{"type":"sphere","radius":1},)"
                                        R"("origin":[0,5,0],"dir":[1,0,0],"maxDist":100)"));
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  EXPECT_TRUE(r["hits"].is_array());
  EXPECT_EQ(r["hits"].size(), 0u);
}

TYPED_TEST(CaseRunner, MeshRaycastReportsFaceIndexAndBarycentrics) {
  const nlohmann::json r = runOne(this->line("uv", R"("query":"raycast","geom":{"type":"mesh","vertices":[[0,0,0],[2,0,0],[0,2,0]],)"
                                         R"("triangles":[[0,1,2]],"doubleSided":true},"origin":[0.5,0.25,1],)"
                                         R"("dir":[0,0,-1],"maxDist":10,"flags":["uv","faceIndex"])"));
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  ASSERT_EQ(r["hits"].size(), 1u) << r.dump();
  const nlohmann::json& hit = r["hits"][0];
  EXPECT_NEAR(hit["distance"].get<double>(), 1.0, this->tol());
  EXPECT_EQ(hit["faceIndex"].get<std::uint32_t>(), 0u);
  // position = (1-u-v) v0 + u v1 + v v2 with v1 = (2,0,0), v2 = (0,2,0): u = x/2, v = y/2.
  EXPECT_NEAR(hit["u"].get<double>(), 0.25, this->tol());
  EXPECT_NEAR(hit["v"].get<double>(), 0.125, this->tol());
}

TYPED_TEST(CaseRunner, BoundsOfCapsuleMatchClosedForm) {
  const nlohmann::json r = runOne(this->line("b", R"("query":"bounds","geom":{"type":"capsule","radius":0.5,"halfHeight":1},)"
                                        R"("pose":{"p":[1,2,3]},"offset":0.25,"inflation":2)"));
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  // Extents (1.5, 0.5, 0.5) grow by the offset, then scale by the inflation about the centre.
  const double ex = (1.5 + 0.25) * 2, eyz = (0.5 + 0.25) * 2;
  EXPECT_NEAR(r["min"][0].get<double>(), 1 - ex, this->tol());
  EXPECT_NEAR(r["max"][0].get<double>(), 1 + ex, this->tol());
  EXPECT_NEAR(r["min"][1].get<double>(), 2 - eyz, this->tol());
  EXPECT_NEAR(r["max"][2].get<double>(), 3 + eyz, this->tol());
}

TYPED_TEST(CaseRunner, PointDistanceToBoxMatchesClosedForm) {
  const nlohmann::json r = runOne(this->line("p", R"("query":"pointDistance","point":[3,4,0],"geom":{"type":"box","halfExtents":[1,1,1]})"));
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  EXPECT_NEAR(r["distance"].get<double>(), std::sqrt(4.0 + 9.0), 4 * this->tol());
  EXPECT_NEAR(r["closestPoint"][0].get<double>(), 1.0, this->tol());
  EXPECT_NEAR(r["closestPoint"][1].get<double>(), 1.0, this->tol());
  EXPECT_EQ(r["closestIndex"].get<std::uint32_t>(), 4294967295u);
}

// Cylinders are answered (gq's custom cylinder, axis X like the capsule): the bounds enclose the half height along X
// and the radius across, within the custom shapes' bounds margin (a few percent).
TYPED_TEST(CaseRunner, CylinderIsAnsweredWithBoundsThatEncloseIt) {
  const nlohmann::json r = runOne(this->line("c", R"("query":"bounds","geom":{"type":"cylinder","radius":1,"halfHeight":2})"));
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  const double half[3] = {2, 1, 1};
  for (int k = 0; k < 3; ++k) {
    EXPECT_LE(r["min"][k].get<double>(), -half[k]) << r.dump();
    EXPECT_GE(r["min"][k].get<double>(), -1.05 * half[k]) << r.dump();
    EXPECT_GE(r["max"][k].get<double>(), half[k]) << r.dump();
    EXPECT_LE(r["max"][k].get<double>(), 1.05 * half[k]) << r.dump();
  }
}

// Pair queries either answer with their fields or say "unsupported: ..." (the gq API decides, not the runner).
TYPED_TEST(CaseRunner, PairQueriesAnswerOrReportUnsupported) {
  const std::string pair = R"("geom0":{"type":"sphere","radius":1},"pose0":{"p":[0,0,0]},)"
                           R"("geom1":{"type":"sphere","radius":1},"pose1":{"p":[1.5,0,0]})";
  const std::vector<std::pair<std::string, const char*>> queries = {
      {R"("query":"overlap",)" + pair, "overlap"},
      {R"("query":"penetration",)" + pair, "penetrating"},
      {R"("query":"distance",)" + pair, "point0"},
      {R"("query":"sweep","dir":[1,0,0],"maxDist":5,)" + pair, "hit"}};
  for (const auto& [body, field] : queries) {
    const nlohmann::json r = runOne(this->line("pair", body));
    ASSERT_TRUE(r.contains("ok")) << body;
    if (r["ok"].get<bool>()) EXPECT_TRUE(r.contains(field)) << r.dump();
    else EXPECT_EQ(r["error"].get<std::string>().rfind("unsupported: ", 0), 0u) << r.dump();
  }
}

TYPED_TEST(CaseRunner, InvalidQueryInputReportsGqStatusMessage) {
  // A non-unit direction is rejected by gq's validation; the runner passes the message through.
  const nlohmann::json r = runOne(this->line("d", R"("query":"raycast","geom":{"type":"sphere","radius":1},)"
                                        R"("origin":[0,0,5],"dir":[0,0,-2],"maxDist":10)"));
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_NE(r["error"].get<std::string>().find("not a unit vector"), std::string::npos) << r.dump();
}

TEST(CaseRunnerTiming, RepeatRunsTheQueryThatManyTimesAndReportsMedian) {
  int calls = 0;
  const double ns = medianNanoseconds(7, [&] { ++calls; });
  EXPECT_EQ(calls, 7);
  EXPECT_GE(ns, 0.0);
  const std::vector<nlohmann::json> r = runLines(R"({"id":1,"query":"bounds","geom":{"type":"sphere","radius":1}})" "\n", 25);
  ASSERT_EQ(r.size(), 1u);
  ASSERT_TRUE(r[0]["ns"].is_number()) << r[0].dump();
  EXPECT_GE(r[0]["ns"].get<double>(), 0.0);
}

TEST(ResultWriter, PrintsDoublesThatReadBackExactly) {
  Result result;
  result.ok = true;
  PointDistanceOut out;
  out.distance = 0.1 + 0.2;  // 0.30000000000000004: needs 17 significant digits
  out.closestPoint = Vec3d(1.0 / 3.0, std::nextafter(1.0, 2.0), -1e-300);
  result.fields = out;
  const nlohmann::json j = nlohmann::json::parse(resultLine("x", result));
  EXPECT_EQ(j["distance"].get<double>(), 0.1 + 0.2);
  EXPECT_EQ(j["closestPoint"][0].get<double>(), 1.0 / 3.0);
  EXPECT_EQ(j["closestPoint"][1].get<double>(), std::nextafter(1.0, 2.0));
  EXPECT_EQ(j["closestPoint"][2].get<double>(), -1e-300);
}

TEST(ResultWriter, MapsEveryPairQueryToItsFields) {
  Result r;
  r.ok = true;
  r.fields = PenetrationOut{true, Vec3d(0, 1, 0), 0.5};
  auto j = nlohmann::json::parse(resultLine(1, r));
  EXPECT_TRUE(j["penetrating"].get<bool>());
  EXPECT_EQ(j["direction"][1].get<double>(), 1.0);
  EXPECT_EQ(j["depth"].get<double>(), 0.5);
  r.fields = DistanceOut{-0.25, Vec3d(1, 0, 0), Vec3d(0.75, 0, 0), Vec3d(-1, 0, 0)};
  j = nlohmann::json::parse(resultLine(1, r));
  EXPECT_EQ(j["distance"].get<double>(), -0.25);
  EXPECT_EQ(j["point1"][0].get<double>(), 0.75);
  EXPECT_EQ(j["normal"][0].get<double>(), -1.0);
  SweepOut sweep;
  sweep.hit = true;
  sweep.distance = 2;
  sweep.normal = Vec3d(0, 0, 1);
  sweep.initialOverlap = false;
  r.fields = sweep;
  j = nlohmann::json::parse(resultLine(1, r));
  EXPECT_TRUE(j["hit"].get<bool>());
  EXPECT_EQ(j["distance"].get<double>(), 2.0);
  EXPECT_FALSE(j.contains("position"));  // not computed, not printed
  EXPECT_EQ(j["normal"][2].get<double>(), 1.0);
  EXPECT_EQ(j["faceIndex"].get<std::uint32_t>(), 4294967295u);
  EXPECT_FALSE(j["initialOverlap"].get<bool>());
  r.fields = OverlapOut{true};
  EXPECT_TRUE(nlohmann::json::parse(resultLine(1, r))["overlap"].get<bool>());
}

TEST(ResultWriter, FailurePrintsIdOkErrorAndNs) {
  const std::string line = resultLine("id-1", Result::failure("unsupported: overlap is not implemented yet"));
  EXPECT_EQ(line.rfind(R"({"id":"id-1","ok":false,"error":"unsupported: overlap is not implemented yet")", 0), 0u)
      << line;
  EXPECT_TRUE(nlohmann::json::parse(line).contains("ns"));
}

// Every example case file parses and runs: one result per case, ids in order, each ok or with an error.
TEST(ExampleCaseFiles, EveryQueryAndPrecisionRunsWithIdsInOrder) {
  for (const char* name : {"raycast", "pair_queries", "point_and_bounds", "malformed"}) {
    const std::string path = std::string(GQ_SOURCE_DIR) + "/comparisons/cases/examples/" + name + ".jsonl";
    std::ifstream in(path);
    ASSERT_TRUE(in) << path;
    std::vector<nlohmann::json> ids;
    for (std::string line; std::getline(in, line);) {
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const auto j = nlohmann::json::parse(line, nullptr, false);
      ids.push_back(j.is_discarded() ? nlohmann::json() : j.value("id", nlohmann::json()));
    }
    GqBackend backend;
    std::ostringstream out;
    std::string error;
    ASSERT_TRUE(runCaseFile(path, backend, 1, out, error)) << error;
    std::istringstream lines(out.str());
    std::size_t i = 0;
    for (std::string line; std::getline(lines, line); ++i) {
      const auto r = nlohmann::json::parse(line);
      ASSERT_LT(i, ids.size()) << name;
      EXPECT_EQ(r["id"], ids[i]) << name << " result " << i;
      EXPECT_TRUE(r["ok"].get<bool>() || r["error"].is_string()) << line;
    }
    EXPECT_EQ(i, ids.size()) << name;
  }
}

TEST(ExampleCaseFiles, MalformedExampleFailsExactlyTheBadLines) {
  GqBackend backend;
  std::ostringstream out;
  std::string error;
  RunSummary summary;
  ASSERT_TRUE(runCaseFile(GQ_SOURCE_DIR "/comparisons/cases/examples/malformed.jsonl", backend, 1, out, error, &summary));
  EXPECT_EQ(summary.cases, 7u);
  // bad JSON, missing radius, wrong type, unknown geometry, unknown query; the two well-formed cases answer.
  EXPECT_EQ(summary.failed, 5u);
}

}  // namespace
}  // namespace gq::cases::test
