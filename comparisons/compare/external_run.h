#pragma once
// Backends that live in a separate program (Bullet: its float and float64 builds cannot share one process, so
// `gq-query --backend bullet` forwards to two helper programs). gq-compare writes the cases to a file, runs
// gq-query on it and reads the result lines back.
#include <string>
#include <vector>

#include "loaded_case.h"
#include "report.h"

namespace gq::compare {

bool isExternalBackend(const std::string& name);

// Runs `gqQuery --backend name --repeat repeat` over the cases; a missing or failing program gives every case a
// failed verdict with the reason.
std::vector<CaseRecord> runBackendExternal(const std::string& gqQuery, const std::string& name,
                                           const std::vector<LoadedCase>& cases, int repeat);

}  // namespace gq::compare
