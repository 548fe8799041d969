#include "bullet_forward.h"

#include <cstdio>
#include <ostream>
#include <vector>

#include <nlohmann/json.hpp>

#include "bullet_backend.h"

namespace gq::cases {
namespace {

std::string shellQuote(const std::string& s) {
  std::string q = "'";
  for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}

// All output lines of `command`, or false when it cannot be started or exits non-zero.
bool readLines(const std::string& command, std::vector<std::string>& lines, std::string& error) {
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    error = "cannot run " + command;
    return false;
  }
  std::string current;
  char buffer[1 << 16];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    for (std::size_t i = 0; i < n; ++i) {
      if (buffer[i] != '\n') {
        current += buffer[i];
        continue;
      }
      lines.push_back(std::move(current));
      current.clear();
    }
  if (!current.empty()) lines.push_back(std::move(current));
  if (pclose(pipe) != 0) {
    error = command + " failed";
    return false;
  }
  return true;
}

// True when the result line is the other build's "wrong precision" answer.
bool isOtherPrecision(const std::string& line) {
  const nlohmann::json r = nlohmann::json::parse(line, nullptr, false);
  if (r.is_discarded() || !r.contains("error") || !r["error"].is_string()) return false;
  return r["error"].get<std::string>().rfind(kBulletPrecisionUnsupported, 0) == 0;
}

}  // namespace

bool runBulletForwarded(const std::string& toolDir, const std::string& backend, const std::string& casesPath,
                        int repeat, std::ostream& out, std::string& error) {
  std::vector<std::string> floatLines, doubleLines;
  const std::string args =
      " --backend " + shellQuote(backend) + " --repeat " + std::to_string(repeat) + " " + shellQuote(casesPath);
  if (!readLines(shellQuote(toolDir + "/gq-query-bullet") + args, floatLines, error)) return false;
  if (!readLines(shellQuote(toolDir + "/gq-query-bullet64") + args, doubleLines, error)) return false;
  if (floatLines.size() != doubleLines.size()) {
    error = "gq-query-bullet and gq-query-bullet64 wrote different numbers of lines";
    return false;
  }
  for (std::size_t i = 0; i < floatLines.size(); ++i)
    out << (isOtherPrecision(doubleLines[i]) ? floatLines[i] : doubleLines[i]) << '\n';
  out.flush();
  return true;
}

}  // namespace gq::cases
