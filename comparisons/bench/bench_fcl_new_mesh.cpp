// New BVHModels through gq::fcl against FCL 0.7, side by side in one run: the cost of the first query on a model
// just built (FCL has built its BV tree at endModel; gq::fcl answers on that tree until cooking pays), and a
// MoveIt-like pattern: 100 new mesh objects, each queried 3 times (collide against a box, a sphere and a capsule).
// Building the models is not timed (manual time around the queries only); gq::fcl forgets each model before it is
// destroyed, so no query finds another model's cooked data at a reused address.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "gq/fcl/fcl.h"

namespace {

using Model = ::fcl::BVHModel<::fcl::OBBRSSd>;

// A closed sphere mesh of 2 rings segments triangles, its radius varied per vertex by `noise` (a scanned object).
std::shared_ptr<Model> sphereMesh(int triangles, std::mt19937& rng, double noise) {
  const int rings = triangles >= 10000 ? 50 : 20, segments = triangles / (2 * rings);
  std::uniform_real_distribution<double> u(1 - noise, 1 + noise);
  std::vector<::fcl::Vector3d> vertices;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double th = M_PI * i / rings, ph = 2 * M_PI * j / segments, r = 0.8 * u(rng);
      vertices.emplace_back(r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th));
    }
  std::vector<::fcl::Triangle> faces;
  const auto at = [&](int i, int j) { return std::size_t(i * segments + (j % segments)); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      faces.emplace_back(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      faces.emplace_back(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  auto model = std::make_shared<Model>();
  model->beginModel();
  model->addSubModel(vertices, faces);
  model->endModel();
  return model;
}

::fcl::Transform3d nearSurface(std::mt19937& rng) {
  std::normal_distribution<double> g(0, 1);
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  ::fcl::Transform3d tf = ::fcl::Transform3d::Identity();
  tf.linear() = q.normalized().toRotationMatrix();
  tf.translation() = ::fcl::Vector3d(g(rng), g(rng), g(rng)).normalized() * (0.8 + 0.3 * g(rng));
  return tf;
}

struct Probe {
  std::shared_ptr<::fcl::CollisionGeometryd> shape;
  ::fcl::Transform3d pose;
};
std::vector<Probe> probes(std::mt19937& rng) {
  return {{std::make_shared<::fcl::Boxd>(0.3, 0.2, 0.25), nearSurface(rng)},
          {std::make_shared<::fcl::Sphered>(0.15), nearSurface(rng)},
          {std::make_shared<::fcl::Capsuled>(0.1, 0.4), nearSurface(rng)}};
}

// Out of line: callgrind counts the queries by these two functions (--toggle-collect).
template <bool kGq> [[gnu::noinline]] double collideOnce(const Model& m, const Probe& p) {
  ::fcl::CollisionRequestd request;
  ::fcl::CollisionResultd result;
  const ::fcl::Transform3d identity = ::fcl::Transform3d::Identity();
  if constexpr (kGq) return double(gq::fcl::collide(&m, identity, p.shape.get(), p.pose, request, result));
  else return double(::fcl::collide(&m, identity, p.shape.get(), p.pose, request, result));
}

template <bool kGq> [[gnu::noinline]] double distanceOnce(const Model& m, const Probe& p) {
  ::fcl::DistanceRequestd request;
  ::fcl::DistanceResultd result;
  const ::fcl::Transform3d identity = ::fcl::Transform3d::Identity();
  if constexpr (kGq) return gq::fcl::distance(&m, identity, p.shape.get(), p.pose, request, result);
  else return ::fcl::distance(&m, identity, p.shape.get(), p.pose, request, result);
}

using Clock = std::chrono::steady_clock;

// The first query (args: triangles, probe 0 box / 1 sphere / 2 capsule, 0 collide / 1 distance) on a new model.
template <bool kGq> void firstQuery(benchmark::State& state) {
  std::mt19937 rng(7);
  const int triangles = int(state.range(0));
  const bool distance = state.range(2) != 0;
  for (auto _ : state) {
    const std::shared_ptr<Model> model = sphereMesh(triangles, rng, 0.02);
    const Probe probe = probes(rng)[std::size_t(state.range(1))];
    const auto start = Clock::now();
    benchmark::DoNotOptimize(distance ? distanceOnce<kGq>(*model, probe) : collideOnce<kGq>(*model, probe));
    state.SetIterationTime(std::chrono::duration<double>(Clock::now() - start).count());
    if constexpr (kGq) gq::fcl::forgetGeometry<double>(model.get());
  }
  state.SetLabel(std::to_string(triangles) + " triangles, " + (distance ? "distance " : "collide ") +
                 (state.range(1) == 0 ? "box" : state.range(1) == 1 ? "sphere" : "capsule"));
}

// MoveIt-like: 100 new models (arg: triangles), each queried 3 times (collide against a box, a sphere, a capsule).
template <bool kGq> void moveItPattern(benchmark::State& state) {
  std::mt19937 rng(11);
  const int triangles = int(state.range(0));
  for (auto _ : state) {
    double seconds = 0;
    for (int object = 0; object < 100; ++object) {
      const std::shared_ptr<Model> model = sphereMesh(triangles, rng, 0.02);
      const std::vector<Probe> ps = probes(rng);
      const auto start = Clock::now();
      for (const Probe& p : ps) benchmark::DoNotOptimize(collideOnce<kGq>(*model, p));
      seconds += std::chrono::duration<double>(Clock::now() - start).count();
      if constexpr (kGq) gq::fcl::forgetGeometry<double>(model.get());
    }
    state.SetIterationTime(seconds);
  }
  state.SetLabel("100 new models of " + std::to_string(triangles) + " triangles, 3 collides each");
}

void firstArgs(benchmark::internal::Benchmark* b) {
  for (int triangles : {1000, 10000})
    for (int probe : {0, 1, 2})
      for (int query : {0, 1}) b->Args({triangles, probe, query});
  b->UseManualTime()->Unit(benchmark::kMicrosecond)->Iterations(50);
}

}  // namespace

BENCHMARK(firstQuery<false>)->Name("first_query/fcl")->Apply(firstArgs);
BENCHMARK(firstQuery<true>)->Name("first_query/gq_fcl")->Apply(firstArgs);
BENCHMARK(moveItPattern<false>)->Name("moveit_100_objects/fcl")->Arg(1000)->Arg(10000)->UseManualTime()
    ->Unit(benchmark::kMicrosecond)->Iterations(1);
BENCHMARK(moveItPattern<true>)->Name("moveit_100_objects/gq_fcl")->Arg(1000)->Arg(10000)->UseManualTime()
    ->Unit(benchmark::kMicrosecond)->Iterations(1);

BENCHMARK_MAIN();
