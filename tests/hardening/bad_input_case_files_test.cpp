// The bad-input contract of case files (gq-query's runner, /work/shared/CASES.md): docs/hardening.md, table "case
// files", one test per row. A bad line gives one "ok":false result naming the line; the run goes on; nothing non-finite
// is ever printed (nlohmann writes NaN/Inf as null, so a null number would show it).
#ifdef GQ_HARDENING_HAVE_CASES
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gq_backend.h"
#include "runner.h"

namespace gq::hardening {
namespace {

const std::string kExamples = GQ_SOURCE_DIR "/comparisons/cases/examples";

std::vector<nlohmann::json> runText(const std::string& text) {
  std::istringstream in(text);
  std::ostringstream out;
  cases::GqBackend backend;
  cases::runCases(in, kExamples, backend, 1, out);
  std::vector<nlohmann::json> results;
  std::istringstream lines(out.str());
  for (std::string line; std::getline(lines, line);) {
    results.push_back(nlohmann::json::parse(line, nullptr, /*allow_exceptions*/ false));
    EXPECT_FALSE(results.back().is_discarded()) << "not JSON: " << line;
  }
  return results;
}

std::size_t nonBlankLines(const std::string& text) {
  std::size_t n = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (line.find_first_not_of(" \t\r") != std::string::npos) ++n;
  return n;
}

// No number in a result is null or non-finite (ids and error strings aside).
void expectFiniteNumbers(const nlohmann::json& j, const std::string& where) {
  if (j.is_number_float()) EXPECT_TRUE(std::isfinite(j.get<double>())) << where;
  if (j.is_object())
    for (auto it = j.begin(); it != j.end(); ++it) {
      if (it.key() == "id") continue;
      EXPECT_FALSE(it.value().is_null()) << where << " field " << it.key() << " is null (NaN?)";
      expectFiniteNumbers(it.value(), where + "." + it.key());
    }
  if (j.is_array())
    for (const auto& e : j) expectFiniteNumbers(e, where + "[]");
}

TEST(BadInputCaseFiles, EveryTruncationOfTheExampleFilesGivesOneResultPerLine) {
  for (const char* name : {"pair_queries.jsonl", "point_and_bounds.jsonl", "raycast.jsonl", "malformed.jsonl"}) {
    std::ifstream in(kExamples + "/" + name);
    std::stringstream text;
    text << in.rdbuf();
    const std::string full = text.str();
    ASSERT_FALSE(full.empty()) << name;
    for (int k = 1; k <= 12; ++k) {
      const std::string cut = full.substr(0, full.size() * std::size_t(k) / 12);
      const std::vector<nlohmann::json> results = runText(cut);
      EXPECT_EQ(results.size(), nonBlankLines(cut)) << name << " cut " << k;
      for (const auto& r : results) {
        ASSERT_TRUE(r.contains("ok")) << r.dump();
        if (r["ok"].get<bool>()) expectFiniteNumbers(r, name);
        else EXPECT_FALSE(r.value("error", std::string()).empty()) << r.dump();
      }
    }
  }
}

TEST(BadInputCaseFiles, OutOfRangeNumbersAndDegenerateInputsGiveOkFalseWithAMessage) {
  const std::vector<std::string> lines = {
      R"({"id":1,"query":"bounds","geom":{"type":"sphere","radius":1e999}})",
      R"({"id":2,"query":"bounds","geom":{"type":"sphere","radius":-1}})",
      R"({"id":3,"query":"raycast","geom":{"type":"box","halfExtents":[1,1,1]},"origin":[0,0,-5],"dir":[0,0,0],"maxDist":10})",
      R"({"id":4,"query":"overlap","geom0":{"type":"sphere","radius":1},"pose0":{"p":[0,0,0],"q":[0,0,0,0]},"geom1":{"type":"sphere","radius":1}})",
      R"({"id":5,"query":"overlap","geom0":{"type":"convex","points":[[0,0,0],[1,0,0],[0,1,0],[1,1,0]]},"geom1":{"type":"sphere","radius":1}})",
      R"({"id":6,"query":"raycast","geom":{"type":"mesh","vertices":[[0,0,0],[1,0,0],[0,1,0]],"triangles":[[0,1,7]]},"origin":[0,0,-5],"dir":[0,0,1],"maxDist":10})",
      R"({"id":7,"query":"bounds","geom":{"type":"heightfield","rows":4294967295,"columns":4294967295,"heights":[]}})",
      R"({"id":8,"query":"sweep","geom0":{"type":"sphere","radius":1},"geom1":{"type":"box","halfExtents":[1,1,1]},"dir":[1,0,0],"maxDist":-3})",
      R"({"id":9,"query":"pointDistance","geom":{"type":"box","halfExtents":[1,1,1]},"point":[1e400,0,0]})",
      R"({"id":10,"query":"raycast","geom":{"type":"mesh","file":"does_not_exist.obj"},"origin":[0,0,-5],"dir":[0,0,1],"maxDist":10})",
      R"([1,2,3])", R"("just a string")", R"({"id":13})", "\x01\x02\xff\xfe"};
  std::string text;
  for (const auto& l : lines) text += l + "\n";
  const std::vector<nlohmann::json> results = runText(text);
  ASSERT_EQ(results.size(), lines.size());
  for (std::size_t i = 0; i < results.size(); ++i) {
    EXPECT_FALSE(results[i]["ok"].get<bool>()) << lines[i] << " -> " << results[i].dump();
    EXPECT_FALSE(results[i].value("error", std::string()).empty()) << results[i].dump();
  }
}

TEST(BadInputCaseFiles, MissingCaseFileIsTheOnlyFatalError) {
  cases::GqBackend backend;
  std::ostringstream out;
  std::string error;
  EXPECT_FALSE(cases::runCaseFile("/nonexistent/cases.jsonl", backend, 1, out, error));
  EXPECT_FALSE(error.empty());
  EXPECT_TRUE(out.str().empty());
}

}  // namespace
}  // namespace gq::hardening
#endif  // GQ_HARDENING_HAVE_CASES
