#pragma once
// Runs one backend over the cases in child processes, so a native library that crashes or hangs on a hard case
// (FCL segfaults on some) costs that case only: it is recorded as failed ("crashed: signal N") and a fresh child
// goes on with the next case. The child judges each answer and streams the verdicts back through a pipe.
#include <functional>
#include <string>
#include <vector>

#include "loaded_case.h"
#include "report.h"

namespace gq::compare {

// A case that runs longer than this (all repeats together) is killed and recorded as failed.
inline constexpr unsigned kCaseTimeLimitSeconds = 20;

std::vector<CaseRecord> runBackendIsolated(const std::string& backendName, const std::vector<LoadedCase>& cases,
                                           int repeat, const std::function<void()>& onCaseDone);

}  // namespace gq::compare
