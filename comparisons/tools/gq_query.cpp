// gq-query [--backend gq] [--repeat N] CASES.jsonl > RESULTS.jsonl  (format: /work/shared/CASES.md)
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "backend.h"
#include "runner.h"

int main(int argc, char** argv) {
  CLI::App app{"Runs a case file (one JSON query per line) and prints one JSON result per line."};
  std::string backendName = "gq";
  int repeat = 1;
  std::string casesPath;
  app.add_option("--backend", backendName, "backend answering the queries")
      ->check(CLI::IsMember(gq::cases::backendNames()));
  app.add_option("--repeat", repeat, "runs per query; ns is the median")->check(CLI::PositiveNumber);
  app.add_option("cases", casesPath, "case file (.jsonl)")->required();
  CLI11_PARSE(app, argc, argv);

  std::unique_ptr<gq::cases::Backend> backend = gq::cases::makeBackend(backendName);
  std::ios::sync_with_stdio(false);
  std::string error;
  if (!gq::cases::runCaseFile(casesPath, *backend, repeat, std::cout, error)) {
    std::cerr << "gq-query: " << error << '\n';
    return 1;
  }
  return 0;
}
