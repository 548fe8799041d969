// CASES.md: "A malformed line gives ok:false with a message naming the line and the field, and the run goes on."
#include <gtest/gtest.h>

#include "runner_test_util.h"

namespace gq::cases::test {
namespace {

bool contains(const nlohmann::json& j, const char* key, const std::string& text) {
  return j.contains(key) && j[key].is_string() && j[key].get<std::string>().find(text) != std::string::npos;
}

const char* kGood = R"({"id":"good","query":"bounds","geom":{"type":"sphere","radius":1}})";

TEST(CaseFile, BadJsonLineReportsLineAndRunContinues) {
  const auto r = runLines(std::string("{\"id\":1,\"query\":\n") + kGood + "\n");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_FALSE(r[0]["ok"].get<bool>());
  EXPECT_TRUE(r[0]["id"].is_null());
  EXPECT_TRUE(contains(r[0], "error", "line 1: invalid JSON")) << r[0].dump();
  EXPECT_EQ(r[1]["id"], "good");
  EXPECT_TRUE(r[1]["ok"].get<bool>()) << r[1].dump();
}

TEST(CaseFile, MissingFieldNamesLineAndField) {
  const auto r = runLines(std::string(kGood) + "\n" + R"({"id":7,"query":"bounds","geom":{"type":"sphere"}})" + "\n");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[1]["id"], 7);
  EXPECT_FALSE(r[1]["ok"].get<bool>());
  EXPECT_TRUE(contains(r[1], "error", "line 2: field 'geom.radius': missing")) << r[1].dump();
}

TEST(CaseFile, WrongTypeNamesField) {
  const auto r = runOne(R"({"id":"w","query":"raycast","geom":{"type":"box","halfExtents":[1,"2",3]},"origin":[0,0,5],"dir":[0,0,-1]})");
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_TRUE(contains(r, "error", "line 1: field 'geom.halfExtents[1]': expected a number")) << r.dump();
}

TEST(CaseFile, UnknownGeometryNamesTypeField) {
  const auto r = runOne(R"({"id":"u","query":"bounds","geom":{"type":"torus","radius":1}})");
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_TRUE(contains(r, "error", "field 'geom.type': unknown geometry type 'torus'")) << r.dump();
}

TEST(CaseFile, UnknownQueryNamesQueryField) {
  const auto r = runOne(R"({"id":"q","query":"teleport","geom":{"type":"sphere","radius":1}})");
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_TRUE(contains(r, "error", "field 'query': unknown query 'teleport'")) << r.dump();
}

TEST(CaseFile, UnknownPrecisionAndFlagAreRejected) {
  const auto r = runLines(
      R"({"id":1,"precision":"half","query":"bounds","geom":{"type":"sphere","radius":1}})"
      "\n"
      R"({"id":2,"query":"raycast","geom":{"type":"sphere","radius":1},"origin":[0,0,5],"dir":[0,0,-1],"flags":["sparkle"]})"
      "\n");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_TRUE(contains(r[0], "error", "field 'precision'")) << r[0].dump();
  EXPECT_TRUE(contains(r[1], "error", "field 'flags[0]': unknown hit flag 'sparkle'")) << r[1].dump();
}

TEST(CaseFile, HeightfieldSampleCountMustMatchRowsTimesColumns) {
  const auto r = runOne(
      R"({"id":"h","query":"bounds","geom":{"type":"heightfield","rows":2,"columns":3,"heights":[0,0,0,0,0]}})");
  EXPECT_TRUE(contains(r, "error", "field 'geom.heights': expected rows * columns = 6 numbers, got 5")) << r.dump();
}

TEST(CaseFile, MissingIdIsReportedWithNullId) {
  const auto r = runOne(R"({"query":"bounds","geom":{"type":"sphere","radius":1}})");
  EXPECT_TRUE(r["id"].is_null());
  EXPECT_TRUE(contains(r, "error", "field 'id': missing")) << r.dump();
}

TEST(CaseFile, BlankLinesAreSkippedAndLineNumbersStayTrue) {
  const auto r = runLines(std::string("\n   \n") + R"({"id":"x","query":"bounds","geom":{"type":"plane","bogus":1},"pose":{"q":[0,0,0,0]}})" + "\n");
  ASSERT_EQ(r.size(), 1u);
  EXPECT_TRUE(contains(r[0], "error", "line 3: field 'pose.q': quaternion has zero length")) << r[0].dump();
}

TEST(CaseFile, MissingMeshFileReportsFileField) {
  const auto r = runOne(R"({"id":"m","query":"bounds","geom":{"type":"mesh","file":"no-such-mesh.obj"}})");
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_TRUE(contains(r, "error", "line 1: field 'geom.file'")) << r.dump();
}

TEST(CaseFile, UnreadableFileIsTheOnlyFatalError) {
  GqBackend backend;
  std::ostringstream out;
  std::string error;
  EXPECT_FALSE(runCaseFile("/nonexistent/cases.jsonl", backend, 1, out, error));
  EXPECT_NE(error.find("cannot read"), std::string::npos);
  EXPECT_TRUE(out.str().empty());
}

}  // namespace
}  // namespace gq::cases::test
