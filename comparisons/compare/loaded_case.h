#pragma once
// A suite case ready to run: parsed by the gq-query parser, with its exact answer.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case.h"

namespace gq::compare {

struct LoadedCase {
  std::string family;  // query family (the suite's name)
  std::string id;
  std::string group;   // hard-case family, from expect.group
  cases::Case input;
  nlohmann::json expect;
  std::string text;  // the case line, for backends that run in a separate program
};

struct LoadedSuites {
  std::vector<LoadedCase> cases;
  std::vector<std::string> errors;  // lines that did not parse (a broken suite is reported, not skipped silently)
};

// The embedded default suites (generated in memory) or every <family>.jsonl in `dir`.
LoadedSuites loadEmbeddedSuites();
LoadedSuites loadSuiteFolder(const std::string& dir);

}  // namespace gq::compare
