// libFuzzer target: case-file parsing and running (gq-query's runner with the gq backend) on arbitrary text.
// Contract: one JSON result line per non-blank input line, nothing thrown. Inputs that name files are skipped:
// they could point the loader at /dev/zero (file loading has its own target, fuzz_mesh_file).
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "gq_backend.h"
#include "runner.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (text.find("file") != std::string::npos) return 0;
  std::istringstream in(text);
  std::ostringstream out;
  gq::cases::GqBackend backend;
  const gq::cases::RunSummary summary = gq::cases::runCases(in, "/nonexistent", backend, 1, out);
  std::istringstream lines(out.str());
  std::size_t results = 0;
  for (std::string line; std::getline(lines, line); ++results)
    if (nlohmann::json::parse(line, nullptr, false).is_discarded()) std::abort();  // output must stay JSON
  if (results != summary.cases) std::abort();
  return 0;
}
