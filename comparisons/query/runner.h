#pragma once
// Runs a case file through a backend: one output line per non-blank input line, same order, same id.
#include <iosfwd>
#include <string>

#include "backend.h"

namespace gq::cases {

struct RunSummary {
  std::size_t cases = 0;   // output lines written
  std::size_t failed = 0;  // of which "ok":false
};

// Relative mesh paths in the cases resolve against `baseDir`. Malformed lines give "ok":false and the run goes on.
RunSummary runCases(std::istream& in, const std::string& baseDir, Backend& backend, int repeat, std::ostream& out);

// Runs the file at `path`; false (with `error`) only if it cannot be opened.
bool runCaseFile(const std::string& path, Backend& backend, int repeat, std::ostream& out, std::string& error,
                 RunSummary* summary = nullptr);

}  // namespace gq::cases
