// gq-demo: the README's default demo. Builds an embedded scene (no files) and prints the speed-vs-error report,
// one section per query family.
#include <iostream>

#include <CLI/CLI.hpp>

#include "report.h"

int main(int argc, char** argv) {
  gq::demo::DemoOptions options;
  CLI::App app{"GeomQuery demo: speed against error on an embedded scene"};
  app.add_option("--rays", options.rays, "rays per geometry")->check(CLI::PositiveNumber);
  app.add_option("--repetitions", options.repetitions, "timed passes (median)")->check(CLI::PositiveNumber);
  app.add_option("--seed", options.seed, "seed of the ray set");
  CLI11_PARSE(app, argc, argv);

  std::cout << "GeomQuery demo (embedded scene: sphere, plane, capsule, box, convex hull, torus mesh, sine "
               "heightfield)\n\n";
  gq::demo::printRaycastSection(options, std::cout);
  return 0;
}
