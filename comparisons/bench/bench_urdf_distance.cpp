// gq::urdf self distance (the minimum signed distance over the checked shape pairs) on Panda's collision meshes,
// per representation, over 64 seeded random configurations: the cost of SelfCollisionChecker::selfDistance.
// Needs ../shared (the robot files).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "gq/urdf/robot.h"
#include "gq/urdf/self_collision.h"

namespace {

using namespace gq::urdf;

std::shared_ptr<const RobotModel<double>> panda(Representation rep) {
  const std::string robots = std::string(GQ_SHARED_DIR) + "/robots";
  LoadOptions o;
  o.representation = rep;
  o.packagePaths = {robots};
  o.useRosPackagePath = false;
  o.errorSamplesPerShape = 0;
  auto model = std::make_shared<RobotModel<double>>();
  const std::string base = robots + "/example-robot-data/robots/panda_description/";
  if (!loadRobot(base + "urdf/panda.urdf", base + "srdf/panda.srdf", o, *model).ok()) return nullptr;
  return model;
}

void BM_SelfDistance(benchmark::State& state) {
  const auto rep = Representation(state.range(0));
  const auto model = panda(rep);
  if (!model) {
    state.SkipWithError("cannot load Panda from ../shared/robots");
    return;
  }
  SelfCollisionChecker<double> checker(model);
  std::uint64_t rng = 11;
  std::vector<std::vector<double>> qs;
  for (int i = 0; i < 64; ++i) qs.push_back(randomConfiguration(*model, rng));
  std::size_t k = 0, narrow = 0, calls = 0;
  double sum = 0;
  for (auto _ : state) {
    SelfDistanceResult<double> d;
    checker.selfDistance(qs[k++ % qs.size()], d);
    sum += d.distance;
    narrow += checker.lastNarrowPhasePairs();
    ++calls;
  }
  benchmark::DoNotOptimize(sum);
  state.counters["narrow_pairs"] = double(narrow) / double(calls ? calls : 1);
  state.SetLabel(rep == Representation::Mesh ? "mesh" : "hull");
}

BENCHMARK(BM_SelfDistance)->Name("self_distance/panda")->Arg(int(Representation::Mesh))->Arg(int(Representation::Hull))
    ->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
