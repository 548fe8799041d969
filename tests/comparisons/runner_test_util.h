#pragma once
// Helpers: run case lines through the gq backend and parse the result lines back.
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gq_backend.h"
#include "runner.h"

namespace gq::cases::test {

inline std::vector<nlohmann::json> runLines(const std::string& text, int repeat = 1,
                                            const std::string& baseDir = GQ_SOURCE_DIR "/comparisons/cases/examples") {
  std::istringstream in(text);
  std::ostringstream out;
  GqBackend backend;
  runCases(in, baseDir, backend, repeat, out);
  std::vector<nlohmann::json> results;
  std::istringstream lines(out.str());
  for (std::string line; std::getline(lines, line);) results.push_back(nlohmann::json::parse(line));
  return results;
}

inline nlohmann::json runOne(const std::string& line) {
  const std::vector<nlohmann::json> r = runLines(line + "\n");
  return r.size() == 1 ? r[0] : nlohmann::json();
}

template <class T> struct PrecisionName;
template <> struct PrecisionName<float> { static constexpr const char* value = "float"; };
template <> struct PrecisionName<double> { static constexpr const char* value = "double"; };

// Distance tolerance for answers of unit-sized shapes computed in T.
template <class T> double distanceTolerance() { return std::is_same_v<T, float> ? 2e-5 : 1e-12; }

}  // namespace gq::cases::test
