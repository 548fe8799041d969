// gq-make-suites [--out DIR]: writes DIR/<family>.jsonl, one case per line with its exact answer under "expect".
#include <filesystem>
#include <fstream>
#include <iostream>

#include <CLI/CLI.hpp>

#include "suite.h"

int main(int argc, char** argv) {
  CLI::App app{"Writes the exact-answer case suites (gq-query format plus \"expect\")."};
  std::string out = "comparisons/cases/suites";
  bool embedded = false;
  app.add_option("--out", out, "output folder");
  app.add_flag("--embedded", embedded, "write the small embedded default suites instead");
  CLI11_PARSE(app, argc, argv);
  std::filesystem::create_directories(out);
  const auto options = embedded ? gq::suites::embeddedOptions() : gq::suites::fileOptions();
  for (const auto& suite : gq::suites::makeSuites(options)) {
    const std::string path = out + "/" + suite.family + ".jsonl";
    std::ofstream f(path);
    for (const auto& c : suite.cases) f << c.dump() << '\n';
    if (!f) {
      std::cerr << "gq-make-suites: cannot write " << path << '\n';
      return 1;
    }
    std::cout << path << ": " << suite.cases.size() << " cases\n";
  }
  return 0;
}
