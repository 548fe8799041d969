// Bunny vs bunny boolean overlap: gq::overlap (dual BVH traversal + exact triangle-triangle SAT, double and float)
// vs FCL 0.7 collide on BVHModel<OBBRSS> (num_max_contacts = 1, the boolean query), on the same 64 seeded poses
// (the second bunny moved by up to its own size, about half of the poses overlapping). Counter `overlapping` = pairs
// reported as intersecting, so the two backends' answers can be compared in the output.
#include <benchmark/benchmark.h>
#include <fcl/fcl.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "gq/cooking.h"
#include "gq/io.h"
#include "gq/query.h"

namespace {

constexpr int kPoses = 64;

struct Scene {
  gq::MeshData<double> data;
  std::vector<gq::Transform<double>> poses;
  bool ok = false;
};

const Scene& scene() {
  static const Scene s = [] {
    Scene out;
    if (!gq::loadMeshFile(std::string(GQ_SHARED_DIR) + "/meshes/stanford-bunny.obj", out.data).ok()) return out;
    gq::Bounds3<double> b;
    for (const auto& v : out.data.vertices) b.include(v);
    for (auto& v : out.data.vertices) v -= b.center();  // centred: rotations keep the bunnies near each other
    const double size = (b.max - b.min).maxCoeff();
    std::mt19937_64 gen(4321);
    std::uniform_real_distribution<double> u(-0.6 * size, 0.6 * size);
    std::normal_distribution<double> n;
    for (int i = 0; i < kPoses; ++i)
      out.poses.emplace_back(gq::Vec3<double>(u(gen), u(gen), u(gen)),
                             gq::Quat<double>(n(gen), n(gen), n(gen), n(gen)).normalized());
    out.ok = true;
    return out;
  }();
  return s;
}

template <class T> void BM_Overlap_gq(benchmark::State& state) {
  const Scene& s = scene();
  if (!s.ok) return state.SkipWithError("bunny not found");
  std::vector<gq::Vec3<T>> vertices;
  for (const auto& v : s.data.vertices) vertices.push_back(v.template cast<T>());
  std::shared_ptr<const gq::TriangleMesh<T>> mesh;
  if (!gq::cookTriangleMesh(vertices, s.data.triangles, mesh).ok()) return state.SkipWithError("cooking failed");
  const gq::Geometry<T> g = gq::TriangleMeshGeometry<T>(mesh);
  std::vector<gq::Transform<T>> poses;
  for (const auto& p : s.poses) poses.push_back(p.template cast<T>());
  int overlapping = 0;
  for (auto _ : state) {
    overlapping = 0;
    for (const auto& pose : poses) {
      bool hit = false;
      (void)gq::overlap(g, gq::Transform<T>(), g, pose, hit);  // valid input: timed
      overlapping += hit;
    }
    benchmark::DoNotOptimize(overlapping);
  }
  state.counters["overlapping"] = overlapping;
  state.SetItemsProcessed(state.iterations() * kPoses);
}

void BM_Overlap_fcl(benchmark::State& state) {
  const Scene& s = scene();
  if (!s.ok) return state.SkipWithError("bunny not found");
  auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
  std::vector<fcl::Vector3d> vertices(s.data.vertices.begin(), s.data.vertices.end());
  std::vector<fcl::Triangle> triangles;
  for (const auto& t : s.data.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  model->beginModel();
  model->addSubModel(vertices, triangles);
  model->endModel();
  fcl::CollisionObjectd a(model, fcl::Transform3d::Identity());
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> others;
  for (const auto& p : s.poses) others.push_back(std::make_unique<fcl::CollisionObjectd>(model, p.toIsometry()));
  fcl::CollisionRequestd request;  // num_max_contacts = 1: stop at the first intersecting triangle pair
  int overlapping = 0;
  for (auto _ : state) {
    overlapping = 0;
    for (const auto& b : others) {
      fcl::CollisionResultd result;
      fcl::collide(&a, b.get(), request, result);
      overlapping += result.isCollision();
    }
    benchmark::DoNotOptimize(overlapping);
  }
  state.counters["overlapping"] = overlapping;
  state.SetItemsProcessed(state.iterations() * kPoses);
}

BENCHMARK_TEMPLATE(BM_Overlap_gq, double)->Name("BM_Overlap_gq_double")->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(BM_Overlap_gq, float)->Name("BM_Overlap_gq_float")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Overlap_fcl)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
