// gq-compare: runs every backend of gq-query over the exact-answer suites and reports, per query family x
// backend x precision, cases answered, wrong booleans, median and max relative error, median ns per query.
// Prints, per family, gq and the backends that answer it (--table: every row, answered or not).
//   gq-compare [--suites DIR] [--backends gq,fcl] [--repeat N] [--results DIR] [--no-plot] [--table] [--check]
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "backend.h"
#include "external_run.h"
#include "isolated_run.h"
#include "judge.h"
#include "loaded_case.h"
#include "report.h"

namespace {

// A one-line progress bar on stderr, redrawn at each whole percent.
class Progress {
 public:
  explicit Progress(std::size_t total) : total_(total) {}
  void step(const std::string& label) {
    const int percent = total_ ? int(100 * ++done_ / total_) : 100;
    if (percent == last_) return;
    last_ = percent;
    const int filled = percent * 40 / 100;
    std::cerr << "\r[" << std::string(filled, '#') << std::string(40 - filled, '.') << "] " << percent << "% "
              << label << "        " << std::flush;
    if (done_ == total_) std::cerr << '\n';
  }

 private:
  std::size_t total_, done_ = 0;
  int last_ = -1;
};

// Cases where gq misses its own tolerances: the --check failures.
std::vector<const gq::compare::CaseRecord*> gqFailures(const std::vector<gq::compare::CaseRecord>& records) {
  std::vector<const gq::compare::CaseRecord*> out;
  for (const auto& r : records)
    if (r.backend == "gq" && (r.verdict.outcome == gq::compare::Outcome::WrongBoolean ||
                              r.verdict.outcome == gq::compare::Outcome::BeyondTolerance))
      out.push_back(&r);
  return out;
}

// gq-query sits beside gq-compare in the build tree.
std::string gqQueryPath() {
  std::error_code ec;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  return (ec ? std::filesystem::path(".") : self.parent_path()).string() + "/gq-query";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Speed versus error of every backend on the exact-answer suites."};
  std::string suitesDir, resultsDir = GQ_COMPARE_RESULTS_DIR, plotScript = GQ_COMPARE_PLOT_SCRIPT;
  std::vector<std::string> backendNames = gq::cases::backendNames();
  int repeat = 3;
  bool noPlot = false, check = false, table = false;
  app.add_option("--suites", suitesDir, "folder of <family>.jsonl suites (default: the embedded default suites)");
  app.add_option("--backends", backendNames, "backends to run (default: all)")
      ->delimiter(',')
      ->check(CLI::IsMember(gq::cases::backendNames()));
  app.add_option("--repeat", repeat, "runs per query; ns is the median")->check(CLI::PositiveNumber);
  app.add_option("--results", resultsDir, "folder for the CSVs, plots and disagreements.md");
  app.add_flag("--no-plot", noPlot, "skip the matplotlib plots");
  app.add_flag("--table", table, "print the full table (every family x backend x precision, answered or not)");
  app.add_flag("--check", check, "exit 1 unless gq has no wrong boolean and meets every tolerance");
  CLI11_PARSE(app, argc, argv);

  const gq::compare::LoadedSuites suites =
      suitesDir.empty() ? gq::compare::loadEmbeddedSuites() : gq::compare::loadSuiteFolder(suitesDir);
  for (const std::string& e : suites.errors) std::cerr << "gq-compare: suite error: " << e << '\n';
  if (suites.cases.empty()) {
    std::cerr << "gq-compare: no cases\n";
    return 1;
  }

  std::vector<gq::compare::CaseRecord> records;
  records.reserve(suites.cases.size() * backendNames.size());
  Progress progress(suites.cases.size() * backendNames.size());
  for (const std::string& name : backendNames) {
    std::string label = name;
    auto part = gq::compare::isExternalBackend(name)
                    ? gq::compare::runBackendExternal(gqQueryPath(), name, suites.cases, repeat)
                    : gq::compare::runBackendIsolated(name, suites.cases, repeat, [&] { progress.step(label); });
    if (gq::compare::isExternalBackend(name))
      for (std::size_t i = 0; i < part.size(); ++i) progress.step(label);
    records.insert(records.end(), std::make_move_iterator(part.begin()), std::make_move_iterator(part.end()));
  }

  const auto rows = gq::compare::summarize(records);
  if (table) gq::compare::printTable(std::cout, rows);
  else gq::compare::printSummary(std::cout, rows, records);
  std::cout << '\n';
  std::string error;
  if (!gq::compare::writeCsv(resultsDir, rows, error)) {
    std::cerr << "gq-compare: " << error << '\n';
    return 1;
  }
  const std::string reportPath = resultsDir + "/disagreements.md";
  const std::size_t listed = gq::compare::writeDisagreements(reportPath, records);
  const std::size_t disagreements = gq::compare::countDisagreements(records);
  std::cout << "results: " << resultsDir << "/compare_<family>.csv; " << disagreements
            << " disagreements classified in " << reportPath << '\n';
  if (!noPlot) {
    const std::string command = "/usr/bin/python3 '" + plotScript + "' '" + resultsDir + "'";
    const bool plotted = std::system(command.c_str()) == 0;
    if (!plotted) std::cerr << "gq-compare: plots skipped (python3-matplotlib missing?)\n";
    std::vector<std::string> plots;
    for (const auto& row : rows)
      for (const char* ext : {".png", ".svg"}) {
        const std::string path = resultsDir + "/compare_" + row.family + ext;
        if (std::filesystem::exists(path) && std::find(plots.begin(), plots.end(), path) == plots.end())
          plots.push_back(path);
      }
    if (plotted && !plots.empty()) {
      std::cout << "plots (speed against error per family):\n";
      for (const std::string& path : plots) std::cout << "  " << path << '\n';
    }
  }

  if (!check) return 0;
  bool pass = suites.errors.empty() && listed == disagreements;
  if (listed != disagreements)
    std::cerr << "gq-compare: the report lists " << listed << " of " << disagreements << " disagreements\n";
  const auto failures = gqFailures(records);
  for (std::size_t i = 0; i < failures.size() && i < 30; ++i)
    std::cerr << "gq-compare: gq " << toString(failures[i]->verdict.outcome) << ": " << failures[i]->c->id << " ("
              << failures[i]->c->family << "): exact " << failures[i]->verdict.exact << ", gq "
              << failures[i]->verdict.answer << '\n';
  if (!failures.empty()) pass = false;
  std::cout << (pass ? "check passed: gq has no wrong boolean and meets every tolerance\n"
                     : "check FAILED\n");
  return pass ? 0 : 1;
}
