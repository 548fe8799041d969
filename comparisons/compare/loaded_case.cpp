#include "loaded_case.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "case_parser.h"
#include "suite.h"

namespace gq::compare {
namespace {

void addLine(const std::string& family, const std::string& text, std::size_t line, cases::CaseParser& parser,
             LoadedSuites& out) {
  LoadedCase lc;
  lc.family = family;
  nlohmann::json id;
  std::string error;
  if (!parser.parse(text, line, lc.input, id, error)) {
    out.errors.push_back(family + ": " + error);
    return;
  }
  const nlohmann::json j = nlohmann::json::parse(text);
  if (!j.contains("expect") || !j["expect"].is_object()) {
    out.errors.push_back(family + ": line " + std::to_string(line) + ": no \"expect\" object");
    return;
  }
  lc.expect = j["expect"];
  lc.id = id.is_string() ? id.get<std::string>() : id.dump();
  lc.group = lc.expect.value("group", "");
  lc.text = text;
  out.cases.push_back(std::move(lc));
}

}  // namespace

LoadedSuites loadEmbeddedSuites() {
  LoadedSuites out;
  for (const auto& suite : suites::makeSuites(suites::embeddedOptions())) {
    cases::CaseParser parser(".");
    std::size_t line = 0;
    for (const auto& c : suite.cases) addLine(suite.family, c.dump(), ++line, parser, out);
  }
  return out;
}

LoadedSuites loadSuiteFolder(const std::string& dir) {
  LoadedSuites out;
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.path().extension() == ".jsonl") files.push_back(entry.path());
  if (ec) out.errors.push_back("cannot read folder '" + dir + "'");
  std::sort(files.begin(), files.end());
  for (const auto& path : files) {
    std::ifstream in(path);
    cases::CaseParser parser(std::filesystem::absolute(path).parent_path().string());
    std::string text;
    for (std::size_t line = 1; std::getline(in, text); ++line)
      if (text.find_first_not_of(" \t\r") != std::string::npos) addLine(path.stem().string(), text, line, parser, out);
  }
  return out;
}

}  // namespace gq::compare
