#pragma once
// Aggregates verdicts per query family x backend x precision; prints the table, writes the CSV per family and
// the disagreement report.
#include <iosfwd>
#include <string>
#include <vector>

#include "judge.h"
#include "loaded_case.h"

namespace gq::compare {

struct CaseRecord {
  const LoadedCase* c = nullptr;
  std::string backend;
  Verdict verdict;
  double ns = 0;
};

struct Row {
  std::string family, backend, precision;
  std::size_t cases = 0, answered = 0, unsupported = 0, failed = 0, wrongBooleans = 0, ambiguous = 0,
              beyondTolerance = 0;
  std::size_t withError = 0;  // answers that gave a comparable value
  double medianError = 0, maxError = 0, medianNs = 0;
};

std::vector<Row> summarize(const std::vector<CaseRecord>& records);
void printTable(std::ostream& out, const std::vector<Row>& rows);
// The readable report: per query family, gq and every backend that answers at least one of its cases (accuracy,
// median time, and time relative to gq on the cases both answered), then the backends that answer none.
void printSummary(std::ostream& out, const std::vector<Row>& rows, const std::vector<CaseRecord>& records);
// comparisons/results/compare_<family>.csv, one line per backend x precision, with date and machine.
bool writeCsv(const std::string& dir, const std::vector<Row>& rows, std::string& error);
// Every case where a backend disagrees with the exact answer (wrong boolean, ambiguous boolean, value beyond
// tolerance, failure), classified, with gq's answer beside it. Returns the number of cases listed.
std::size_t writeDisagreements(const std::string& path, const std::vector<CaseRecord>& records);
std::size_t countDisagreements(const std::vector<CaseRecord>& records);
bool isDisagreement(Outcome o);

std::string machineName();
std::string todayUtc();
// The source tree's commit (git rev-parse --short=8), or "unknown" outside a git checkout: result rows carry it.
std::string sourceCommit();

}  // namespace gq::compare
