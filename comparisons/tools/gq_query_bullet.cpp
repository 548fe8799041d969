// gq-query-bullet / gq-query-bullet64 [--backend bullet|gq-bullet] [--repeat N] CASES.jsonl: a Bullet backend in
// one precision (float libraries or float64 libraries). `gq-query --backend bullet` (and gq-bullet) runs both and
// merges their answers. gq-bullet (gq through the Bullet adapter) exists when the adapter was built.
#include <iostream>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>

#include "bullet_backend.h"
#include "runner.h"

int main(int argc, char** argv) {
  CLI::App app{"Runs a case file through Bullet in this program's precision (see gq-query --backend bullet)."};
  int repeat = 1;
  std::string casesPath;
  std::string backendName = "bullet";
#ifdef GQ_HAVE_BULLET_ADAPTER
  app.add_option("--backend", backendName, "bullet (Bullet's own queries) or gq-bullet (gq through the adapter)")
      ->check(CLI::IsMember({"bullet", "gq-bullet"}));
#else
  app.add_option("--backend", backendName, "bullet")->check(CLI::IsMember({"bullet"}));
#endif
  app.add_option("--repeat", repeat, "runs per query; ns is the median")->check(CLI::PositiveNumber);
  app.add_option("cases", casesPath, "case file (.jsonl)")->required();
  CLI11_PARSE(app, argc, argv);
  std::unique_ptr<gq::cases::Backend> backend;
#ifdef GQ_HAVE_BULLET_ADAPTER
  if (backendName == "gq-bullet") backend = std::make_unique<gq::cases::GqBulletBackend>();
#endif
  if (!backend) backend = std::make_unique<gq::cases::BulletBackend>();
  std::ios::sync_with_stdio(false);
  std::string error;
  if (!gq::cases::runCaseFile(casesPath, *backend, repeat, std::cout, error)) {
    std::cerr << argv[0] << ": " << error << '\n';
    return 1;
  }
  return 0;
}
