// Scenes and batches (double). A seeded scene of 1000 mixed objects in a 40-unit cube: spheres, capsules, boxes, hulls
// (24 points on an ellipsoid) and 8 bunnies scaled to about 2 units, every object 0.2 to 2 units.
//  - SceneRaycast: 1M rays (origins in the cube, random directions, maxDist 80), Scene::raycastClosest per ray.
//  - BruteRaycast: the same rays against every object through the single raycast (the first 2000 rays: the loop is
//    slow); items_per_second of both are rays per second.
//  - SceneRaycastBatch/threads: the 1M rays as one raycastBatch, 1 and 2 threads (the speedup is the ratio).
//  - BunnyRaycastLoop, BunnyRaycastBatch/threads: 1M rays at the bunny, a loop of single raycasts vs a batch with the
//    default settings (coherent ray order, the threads sharing each block). The loop stores each ray's hit and hit flag
//    into arrays of 1M entries, as the batch does (and as a caller's loop keeping the answers does);
//    BunnyRaycastBatchInputOrder/threads: the batch in input order (coherentRayOrder false);
//    BunnyRaycastBatchKeptScratch/threads: the batch with one BatchScratch kept across calls.
//  - SelfPairs: Scene::overlappingPairs over the 1000 objects; BruteSelfPairs: every pair through overlap().
// Counters `hits` / `pairs` let the answers of the two forms be compared in the output.
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "gq/batch.h"
#include "gq/cooking.h"
#include "gq/io.h"
#include "gq/query.h"
#include "gq/scene.h"
#include "bench_scene_fixture.h"

namespace bench_scene {

const Fixture& fixture() {
  static const Fixture* f = [] {
    auto* out = new Fixture();
    gq::MeshData<T> data;
    if (!gq::loadMeshFile(std::string(GQ_SHARED_DIR) + "/meshes/stanford-bunny.obj", data).ok()) return out;
    gq::Bounds3<T> b;
    for (const auto& v : data.vertices) b.include(v);
    for (auto& v : data.vertices) v -= b.center();
    out->bunnyScale = T(2) / (b.max - b.min).maxCoeff();
    if (!gq::cookTriangleMesh(data.vertices, data.triangles, out->bunny).ok()) return out;
    out->bunnyVertices = data.vertices;
    out->bunnyTriangles = data.triangles;

    std::mt19937_64 gen(2024);
    std::uniform_real_distribution<T> u(-kHalf, kHalf), size(0.2, 2.0), pick(0, 1);
    std::normal_distribution<T> n;
    std::vector<V> hullPoints;
    for (int i = 0; i < 24; ++i) {
      const T x = n(gen), y = n(gen), z = n(gen);
      hullPoints.push_back(V(x, y, z).normalized().cwiseProduct(V(1, 0.8, 0.6)));
    }
    std::shared_ptr<const gq::ConvexMesh<T>> hull;
    if (!gq::cookConvexMesh(hullPoints, hull).ok()) return out;
    for (int i = 0; i < kObjects; ++i) {
      const T s = size(gen);
      const T p = pick(gen);
      gq::Geometry<T> g;
      if (i % 125 == 0) {
        g = gq::TriangleMeshGeometry<T>(out->bunny, gq::MeshScale<T>(out->bunnyScale));
      } else if (p < 0.25) {
        g = gq::SphereGeometry<T>(s * 0.5);
      } else if (p < 0.5) {
        g = gq::CapsuleGeometry<T>(s * 0.25, s * 0.5);
      } else if (p < 0.75) {
        g = gq::BoxGeometry<T>(s * 0.5, s * 0.3, s * 0.4);
      } else {
        g = gq::ConvexMeshGeometry<T>(hull, gq::MeshScale<T>(s * 0.5));
      }
      const T x = u(gen), y = u(gen), z = u(gen);
      const T qw = n(gen), qx = n(gen), qy = n(gen), qz = n(gen);
      const gq::Transform<T> pose(V(x, y, z), gq::Quat<T>(qw, qx, qy, qz).normalized());
      if (!out->scene.add(gq::InstanceId(i), g, pose).ok()) return out;
      out->geometries.push_back(g);
      out->poses.push_back(pose);
    }
    out->scene.rebuild();  // top down, as a user does after adding many instances
    for (int i = 0; i < kBunnyRays; ++i) {
      if (i < kRays) {
        const T x = u(gen), y = u(gen), z = u(gen);
        const T dx = n(gen), dy = n(gen), dz = n(gen);
        out->origins.emplace_back(x, y, z);
        out->dirs.push_back(V(dx, dy, dz).normalized());
      }
      // Bunny rays: origins 4 units out, aimed at points within its box.
      const T ox = n(gen), oy = n(gen), oz = n(gen);
      const V o = V(ox, oy, oz).normalized() * T(4);
      const T tx = u(gen), ty = u(gen), tz = u(gen);
      const V target = V(tx, ty, tz) * (T(0.6) / kHalf);
      out->bunnyOrigins.push_back(o);
      out->bunnyDirs.push_back((target - o).normalized());
    }
    out->ok = true;
    return out;
  }();
  return *f;
}

}  // namespace bench_scene

namespace {
using namespace bench_scene;

void BM_SceneRaycast(benchmark::State& state) {
  const Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("bunny not found or setup failed");
  std::int64_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (int i = 0; i < kRays; ++i) {
      gq::SceneRaycastHit<T> h;
      bool has = false;
      (void)f.scene.raycastClosest(f.origins[i], f.dirs[i], T(80), h, has);
      hits += has;
    }
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(state.iterations() * kRays);
  state.counters["hits"] = double(hits);
}

void BM_BruteRaycast(benchmark::State& state) {
  const Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("bunny not found or setup failed");
  std::int64_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (int i = 0; i < kBruteRays; ++i) {
      bool any = false;
      T best = T(80);
      for (std::size_t k = 0; k < f.geometries.size(); ++k) {
        gq::RaycastHit<T> h;
        std::uint32_t n = 0;
        (void)gq::raycast(f.origins[i], f.dirs[i], f.geometries[k], f.poses[k], T(80), gq::kDefaultHitFlags, 1u, &h, n);
        if (n && h.distance <= best) {
          best = h.distance;
          any = true;
        }
      }
      hits += any;
    }
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(state.iterations() * kBruteRays);
  state.counters["hits"] = double(hits);
}

void BM_SceneRaycastBatch(benchmark::State& state) {
  const Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("bunny not found or setup failed");
  std::vector<gq::SceneRaycastHit<T>> hits(kRays);
  std::vector<std::uint8_t> has(kRays);
  gq::BatchSettings settings;
  settings.threads = std::uint32_t(state.range(0));
  gq::RayBatch<T> rays;
  rays.origins = gq::StridedArray<V>(f.origins.data(), kRays);
  rays.unitDirs = gq::StridedArray<V>(f.dirs.data(), kRays);
  rays.maxDist = T(80);
  for (auto _ : state) {
    (void)gq::raycastBatch(rays, f.scene, hits.data(), has.data(), nullptr, settings);
    benchmark::DoNotOptimize(has.data());
  }
  state.SetItemsProcessed(state.iterations() * kRays);
  std::int64_t n = 0;
  for (auto h : has) n += h;
  state.counters["hits"] = double(n);
}

void BM_BunnyRaycastLoop(benchmark::State& state) {
  const Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("bunny not found or setup failed");
  gq::Shape<T> bunny;
  const gq::Geometry<T> bunnyGeometry = gq::TriangleMeshGeometry<T>(f.bunny, gq::MeshScale<T>(f.bunnyScale));
  if (!gq::Shape<T>::make(bunnyGeometry, bunny).ok()) return state.SkipWithError("shape");
  const gq::Transform<T> pose;
  std::vector<gq::RaycastHit<T>> hits(kBunnyRays);
  std::vector<std::uint8_t> has(kBunnyRays);
  for (auto _ : state) {
    for (int i = 0; i < kBunnyRays; ++i) {
      std::uint32_t n = 0;
      (void)gq::raycast(f.bunnyOrigins[i], f.bunnyDirs[i], bunny, pose, T(10), kBothFaces, 1u, &hits[i], n);
      has[i] = n > 0 ? 1 : 0;
    }
    benchmark::DoNotOptimize(has.data());
    benchmark::DoNotOptimize(hits.data());
  }
  state.SetItemsProcessed(state.iterations() * kBunnyRays);
  std::int64_t n = 0;
  for (auto h : has) n += h;
  state.counters["hits"] = double(n);
}

// The bunny's rays as one raycastBatch; coherent: the batch's coherent ray order (the default), else input order;
// keepScratch: one BatchScratch kept across the iterations (a caller casting batch after batch).
void bunnyRaycastBatch(benchmark::State& state, bool coherent, bool keepScratch = false) {
  const Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("bunny not found or setup failed");
  gq::Shape<T> bunny;
  const gq::Geometry<T> bunnyGeometry = gq::TriangleMeshGeometry<T>(f.bunny, gq::MeshScale<T>(f.bunnyScale));
  if (!gq::Shape<T>::make(bunnyGeometry, bunny).ok()) return state.SkipWithError("shape");
  std::vector<gq::RaycastHit<T>> hits(kBunnyRays);
  std::vector<std::uint8_t> has(kBunnyRays);
  gq::BatchSettings settings;
  settings.threads = std::uint32_t(state.range(0));
  settings.coherentRayOrder = coherent;
  gq::BatchScratch scratch;
  if (keepScratch) settings.scratch = &scratch;
  gq::RayBatch<T> rays;
  rays.origins = gq::StridedArray<V>(f.bunnyOrigins.data(), kBunnyRays);
  rays.unitDirs = gq::StridedArray<V>(f.bunnyDirs.data(), kBunnyRays);
  rays.maxDist = T(10);
  rays.hitFlags = kBothFaces;
  for (auto _ : state) {
    (void)gq::raycastBatch(rays, bunny, gq::Transform<T>(), hits.data(), has.data(), nullptr, settings);
    benchmark::DoNotOptimize(has.data());
  }
  state.SetItemsProcessed(state.iterations() * kBunnyRays);
  std::int64_t n = 0;
  for (auto h : has) n += h;
  state.counters["hits"] = double(n);
}

void BM_BunnyRaycastBatch(benchmark::State& state) { bunnyRaycastBatch(state, true); }
void BM_BunnyRaycastBatchInputOrder(benchmark::State& state) { bunnyRaycastBatch(state, false); }
void BM_BunnyRaycastBatchKeptScratch(benchmark::State& state) { bunnyRaycastBatch(state, true, true); }

void BM_SelfPairs(benchmark::State& state) {
  const Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("bunny not found or setup failed");
  std::vector<gq::ScenePair> pairs;
  for (auto _ : state) {
    (void)f.scene.overlappingPairs(pairs);
    benchmark::DoNotOptimize(pairs.data());
  }
  state.counters["pairs"] = double(pairs.size());
}

void BM_BruteSelfPairs(benchmark::State& state) {
  const Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("bunny not found or setup failed");
  std::int64_t pairs = 0;
  for (auto _ : state) {
    pairs = 0;
    for (std::size_t a = 0; a < f.geometries.size(); ++a) {
      for (std::size_t b = a + 1; b < f.geometries.size(); ++b) {
        bool hit = false;
        (void)gq::overlap(f.geometries[a], f.poses[a], f.geometries[b], f.poses[b], hit);
        pairs += hit;
      }
    }
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = double(pairs);
}

}  // namespace

BENCHMARK(BM_SceneRaycast)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BruteRaycast)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SceneRaycastBatch)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BunnyRaycastLoop)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BunnyRaycastBatch)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BunnyRaycastBatchInputOrder)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BunnyRaycastBatchKeptScratch)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SelfPairs)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BruteSelfPairs)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
