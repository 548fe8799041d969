// Self distance (the least distance over the checked shape pairs) on Panda's collision meshes, per representation,
// gq::urdf's selfDistance against the FCL checker's (MoveIt's narrow-phase pattern: fcl::distance with the result
// pre-seeded by the smallest distance so far), over 64 seeded random collision-free configurations (FCL stops at a
// first penetration, so colliding ones would not compare like for like). Needs ../shared (the robot files).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "gq/urdf/fcl_checker.h"
#include "gq/urdf/robot.h"
#include "gq/urdf/self_collision.h"
#include "panda_model.h"

namespace {

using namespace gq::urdf;

// 64 collision-free configurations of the model (gq's checker decides; the same seed for both libraries).
std::vector<std::vector<double>> freeConfigurations(const std::shared_ptr<const RobotModel<double>>& model) {
  SelfCollisionChecker<double> checker(model);
  std::uint64_t rng = 11;
  std::vector<std::vector<double>> qs;
  while (qs.size() < 64) {
    std::vector<double> q = randomConfiguration(*model, rng);
    CollisionResult r;
    if (checker.checkSelfCollision(q, r).ok() && !r.colliding) qs.push_back(std::move(q));
  }
  return qs;
}

template <bool Gq> void BM_SelfDistance(benchmark::State& state) {
  const auto rep = Representation(state.range(0));
  const auto model = gqbench::loadPanda(rep);
  if (!model) {
    state.SkipWithError("cannot load Panda from ../shared/robots");
    return;
  }
  const auto qs = freeConfigurations(model);
  SelfCollisionChecker<double> gq(model);
  std::unique_ptr<FclSelfCollisionChecker> fcl;
  if (!Gq && !FclSelfCollisionChecker::create(model, fcl).ok()) {
    state.SkipWithError("FCL checker");
    return;
  }
  std::size_t k = 0;
  double sum = 0;
  for (auto _ : state) {
    SelfDistanceResult<double> d;
    if (Gq) (void)gq.selfDistance(qs[k++ % qs.size()], d);  // valid input: timed
    else (void)fcl->selfDistance(qs[k++ % qs.size()], d);
    sum += d.distance;
  }
  benchmark::DoNotOptimize(sum);
  state.SetLabel(rep == Representation::Mesh ? "mesh" : "hull");
}

void representations(benchmark::internal::Benchmark* b) {
  b->Arg(int(Representation::Mesh))->Arg(int(Representation::Hull))->Unit(benchmark::kMicrosecond);
}
BENCHMARK(BM_SelfDistance<false>)->Name("self_distance/fcl")->Apply(representations);
BENCHMARK(BM_SelfDistance<true>)->Name("self_distance/gq")->Apply(representations);

}  // namespace

BENCHMARK_MAIN();
