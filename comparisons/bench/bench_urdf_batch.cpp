// Panda self-collision over 100k seeded random configurations (an (N, dof) array): a loop of single checks on one
// checker, and gq::urdf::checkSelfCollisionBatch on 1 and 2 threads. Checks per second as items_per_second; wall
// time (the batch's work runs on other threads). Needs ../shared (the robot files).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>
#include <vector>

#include "gq/urdf/robot.h"
#include "gq/urdf/self_collision.h"
#include "panda_model.h"

namespace {

using namespace gq::urdf;

constexpr std::size_t kConfigurations = 100000;

struct PandaBatch {
  std::shared_ptr<const RobotModel<double>> model;
  std::vector<double> rows;  // kConfigurations x dof
  std::size_t dof = 0;
};

const PandaBatch* pandaBatch(Representation rep) {
  static std::unique_ptr<PandaBatch> cached[8];
  auto& slot = cached[int(rep) % 8];
  if (slot) return slot->model ? slot.get() : nullptr;
  slot = std::make_unique<PandaBatch>();
  const auto model = gqbench::loadPanda(rep);
  if (!model) return nullptr;
  slot->model = model;
  slot->dof = model->variables.size();
  std::uint64_t rng = 2026;
  for (std::size_t i = 0; i < kConfigurations; ++i) {
    const std::vector<double> q = randomConfiguration(*model, rng);
    slot->rows.insert(slot->rows.end(), q.begin(), q.end());
  }
  return slot.get();
}

void BM_PandaLoop(benchmark::State& state) {
  const PandaBatch* b = pandaBatch(Representation(state.range(0)));
  if (!b) return state.SkipWithError("cannot load Panda from ../shared/robots");
  SelfCollisionChecker<double> checker(b->model);
  CollisionRequest first;
  first.allPairs = false;
  std::vector<double> q(b->dof);
  std::size_t colliding = 0;
  for (auto _ : state) {
    colliding = 0;
    CollisionResult r;
    for (std::size_t i = 0; i < kConfigurations; ++i) {
      q.assign(b->rows.begin() + std::ptrdiff_t(i * b->dof), b->rows.begin() + std::ptrdiff_t((i + 1) * b->dof));
      if (!checker.checkSelfCollision(q, r, first).ok()) return state.SkipWithError("check failed");
      colliding += r.colliding ? 1 : 0;
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * kConfigurations));
  state.counters["colliding"] = double(colliding);
}

void BM_PandaBatch(benchmark::State& state) {
  const PandaBatch* b = pandaBatch(Representation(state.range(0)));
  if (!b) return state.SkipWithError("cannot load Panda from ../shared/robots");
  gq::BatchSettings settings;
  settings.threads = std::uint32_t(state.range(1));
  const auto configs = gq::StridedArray<double>(b->rows.data(), kConfigurations, b->dof * sizeof(double));
  std::vector<std::uint8_t> colliding(kConfigurations);
  for (auto _ : state) {
    if (!checkSelfCollisionBatch<double>(b->model, configs, b->dof, colliding.data(), nullptr, settings).ok())
      return state.SkipWithError("batch failed");
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * kConfigurations));
  std::size_t count = 0;
  for (std::uint8_t c : colliding) count += c;
  state.counters["colliding"] = double(count);
}

}  // namespace

BENCHMARK(BM_PandaLoop)->Arg(int(Representation::Hull))->Arg(int(Representation::Mesh))->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PandaBatch)
    ->Args({int(Representation::Hull), 1})
    ->Args({int(Representation::Hull), 2})
    ->Args({int(Representation::Mesh), 1})
    ->Args({int(Representation::Mesh), 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_MAIN();
