// gq-query-bullet / gq-query-bullet64 [--repeat N] CASES.jsonl: the Bullet backend in one precision (float libraries
// or float64 libraries). `gq-query --backend bullet` runs both and merges their answers.
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "bullet_backend.h"
#include "runner.h"

int main(int argc, char** argv) {
  CLI::App app{"Runs a case file through Bullet in this program's precision (see gq-query --backend bullet)."};
  int repeat = 1;
  std::string casesPath;
  app.add_option("--repeat", repeat, "runs per query; ns is the median")->check(CLI::PositiveNumber);
  app.add_option("cases", casesPath, "case file (.jsonl)")->required();
  CLI11_PARSE(app, argc, argv);
  gq::cases::BulletBackend backend;
  std::ios::sync_with_stdio(false);
  std::string error;
  if (!gq::cases::runCaseFile(casesPath, backend, repeat, std::cout, error)) {
    std::cerr << argv[0] << ": " << error << '\n';
    return 1;
  }
  return 0;
}
