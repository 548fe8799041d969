#pragma once
// Judges one backend answer against the exact answer stored under "expect" in the case line (suites/suite.h).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "case.h"
#include "result.h"

namespace gq::compare {

// Relative tolerances gq is held to: double 1e-9 for closed forms and SAT, 1e-7 for GJK/EPA and meshes; float
// 1e-4 for everything.
double toleranceFor(cases::Precision precision, const std::string& toleranceClass);

enum class Outcome {
  Correct,        // boolean right (or not judged) and value within tolerance
  Ambiguous,      // boolean differs, but the exact configuration is within tolerance of flipping it
  WrongBoolean,   // boolean differs and the exact margin exceeds the tolerance
  BeyondTolerance,
  Unsupported,    // "unsupported: ..."
  Failed,         // any other status
};
const char* toString(Outcome o);

struct Verdict {
  Outcome outcome = Outcome::Correct;
  std::optional<double> error;  // |answer - exact| / scale, when both give a value
  std::string answer;           // the backend's answer in words, for the disagreement report
  std::string exact;            // the exact answer in words
};

// `family` is the query name ("overlap", "penetration", "distance", "raycast", "pointDistance").
Verdict judge(const std::string& family, cases::Precision precision, const nlohmann::json& expect,
              const cases::Result& result);

}  // namespace gq::compare
