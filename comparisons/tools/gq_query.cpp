// gq-query [--backend gq|fcl|fcl-indep|libccd|libccd-mpr|embree|bullet|gq-fcl|gq-bullet] [--repeat N] CASES.jsonl > RESULTS.jsonl  (format: /work/shared/CASES.md)
#include <filesystem>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "backend.h"
#include "bullet_forward.h"
#include "runner.h"

int main(int argc, char** argv) {
  CLI::App app{"Runs a case file (one JSON query per line) and prints one JSON result per line."};
  std::string backendName = "gq";
  int repeat = 1;
  std::string casesPath;
  std::string fclSolver = "libccd";
  app.add_option("--backend", backendName, "backend answering the queries")
      ->check(CLI::IsMember(gq::cases::backendNames()));
  app.add_option("--repeat", repeat, "runs per query; ns is the median")->check(CLI::PositiveNumber);
  app.add_option("--fcl-solver", fclSolver, "FCL's GJK solver for --backend fcl: libccd (GST_LIBCCD) or indep (GST_INDEP)")
      ->check(CLI::IsMember({"libccd", "indep"}));
  app.add_option("cases", casesPath, "case file (.jsonl)")->required();
  CLI11_PARSE(app, argc, argv);

  if (backendName == "fcl" && fclSolver == "indep") backendName = "fcl-indep";
  std::ios::sync_with_stdio(false);
  std::string error;
  // Bullet's float and float64 builds (and the adapter over each) run as two helper programs.
  if (backendName == "bullet" || backendName == "gq-bullet") {
    const std::string toolDir = std::filesystem::canonical("/proc/self/exe").parent_path().string();
    if (!gq::cases::runBulletForwarded(toolDir, backendName, casesPath, repeat, std::cout, error)) {
      std::cerr << "gq-query: " << error << '\n';
      return 1;
    }
    return 0;
  }
  std::unique_ptr<gq::cases::Backend> backend = gq::cases::makeBackend(backendName);
  if (!gq::cases::runCaseFile(casesPath, *backend, repeat, std::cout, error)) {
    std::cerr << "gq-query: " << error << '\n';
    return 1;
  }
  return 0;
}
