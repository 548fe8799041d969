#include "runner.h"

#include <filesystem>
#include <fstream>
#include <istream>
#include <ostream>

#include "case_parser.h"
#include "result_writer.h"

namespace gq::cases {
namespace {

bool isBlank(const std::string& s) { return s.find_first_not_of(" \t\r\n") == std::string::npos; }

}  // namespace

RunSummary runCases(std::istream& in, const std::string& baseDir, Backend& backend, int repeat, std::ostream& out) {
  CaseParser parser(baseDir);
  RunSummary summary;
  std::string text;
  for (std::size_t line = 1; std::getline(in, text); ++line) {
    if (isBlank(text)) continue;
    Case c;
    nlohmann::json id;
    std::string error;
    const Result result = parser.parse(text, line, c, id, error) ? backend.run(c, repeat) : Result::failure(error);
    out << resultLine(id, result) << '\n';
    ++summary.cases;
    if (!result.ok) ++summary.failed;
  }
  out.flush();
  return summary;
}

bool runCaseFile(const std::string& path, Backend& backend, int repeat, std::ostream& out, std::string& error,
                 RunSummary* summary) {
  std::error_code ec;
  std::ifstream in(path);
  if (!in || std::filesystem::is_directory(path, ec)) {
    error = "cannot read case file '" + path + "'";
    return false;
  }
  const std::string baseDir = std::filesystem::absolute(path).parent_path().string();
  const RunSummary s = runCases(in, baseDir, backend, repeat, out);
  if (summary != nullptr) *summary = s;
  return true;
}

}  // namespace gq::cases
