// gq::distance (GJK/EPA, hill-climbing support) vs libccd's ccdGJKIntersect / ccdGJKPenetration on the same convex
// hulls (30, 100, 300 random points on an ellipsoid, all hull vertices) and the same 64 seeded pose pairs (about
// half of them overlapping). libccd gets an exhaustive support function over the hull vertices, as its users
// usually write it. Counters: `overlapping` = pairs the backend reported as intersecting.
#include <benchmark/benchmark.h>
#include <ccd/ccd.h>

#include <memory>
#include <random>
#include <vector>

#include "gq/cooking.h"
#include "gq/query.h"

namespace {

constexpr int kPairs = 64;

struct Scene {
  std::shared_ptr<const gq::ConvexMesh<double>> hull;
  std::vector<gq::Transform<double>> pose0, pose1;
};

std::shared_ptr<const gq::ConvexMesh<double>> randomHull(int n, std::mt19937_64& gen) {
  std::normal_distribution<double> normal;
  std::vector<gq::Vec3<double>> pts;
  for (int i = 0; i < n; ++i)
    pts.push_back(gq::Vec3<double>(normal(gen), normal(gen), normal(gen)).normalized().cwiseProduct(gq::Vec3<double>(1, 0.8, 0.6)));
  std::shared_ptr<const gq::ConvexMesh<double>> out;
  if (!gq::cookConvexMesh(pts, out).ok()) return nullptr;
  return out;
}

const Scene& scene(int n) {
  static std::vector<std::unique_ptr<Scene>> cache(512);
  if (!cache[n]) {
    auto s = std::make_unique<Scene>();
    std::mt19937_64 gen(1234 + n);
    s->hull = randomHull(n, gen);
    std::uniform_real_distribution<double> u(-1.1, 1.1);
    std::normal_distribution<double> normal;
    for (int i = 0; i < kPairs; ++i) {
      const auto rot = [&] { return gq::Quat<double>(normal(gen), normal(gen), normal(gen), normal(gen)).normalized(); };
      s->pose0.emplace_back(gq::Vec3<double>(u(gen), u(gen), u(gen)), rot());
      s->pose1.emplace_back(gq::Vec3<double>(u(gen), u(gen), u(gen)), rot());
    }
    cache[n] = std::move(s);
  }
  return *cache[n];
}

// ---- gq -----------------------------------------------------------------------------------------------------
void BM_GqDistance(benchmark::State& state) {
  const Scene& s = scene(int(state.range(0)));
  if (!s.hull) return state.SkipWithError("convex cooking failed");
  const gq::Geometry<double> g = gq::ConvexMeshGeometry<double>(s.hull);
  int overlapping = 0;
  for (auto _ : state) {
    overlapping = 0;
    for (int i = 0; i < kPairs; ++i) {
      gq::DistanceResult<double> r;
      gq::distance(r, g, s.pose0[i], g, s.pose1[i]);
      overlapping += r.distance <= 0;
      benchmark::DoNotOptimize(r);
    }
  }
  state.counters["overlapping"] = overlapping;
  state.SetItemsProcessed(state.iterations() * kPairs);
}

// Same poses, second call per pair with the GJK cache of the first (frame-to-frame coherence at zero motion).
void BM_GqDistanceWarm(benchmark::State& state) {
  const Scene& s = scene(int(state.range(0)));
  if (!s.hull) return state.SkipWithError("convex cooking failed");
  const gq::Geometry<double> g = gq::ConvexMeshGeometry<double>(s.hull);
  std::vector<gq::GjkCache<double>> caches(kPairs);
  for (int i = 0; i < kPairs; ++i) {
    gq::DistanceResult<double> r;
    gq::distance(r, g, s.pose0[i], g, s.pose1[i], &caches[i]);
  }
  for (auto _ : state) {
    for (int i = 0; i < kPairs; ++i) {
      gq::DistanceResult<double> r;
      gq::distance(r, g, s.pose0[i], g, s.pose1[i], &caches[i]);
      benchmark::DoNotOptimize(r);
    }
  }
  state.SetItemsProcessed(state.iterations() * kPairs);
}

// ---- libccd -------------------------------------------------------------------------------------------------
struct CcdHull {
  const gq::ConvexMesh<double>* hull;
  gq::Transform<double> pose;
};

void ccdSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const auto* h = static_cast<const CcdHull*>(obj);
  const gq::Vec3<double> d = h->pose.rotateInv(gq::Vec3<double>(dir->v[0], dir->v[1], dir->v[2]));
  const gq::Vec3<double>* best = &h->hull->vertices[0];
  double bestDot = best->dot(d);
  for (const auto& v : h->hull->vertices)
    if (v.dot(d) > bestDot) { bestDot = v.dot(d); best = &v; }
  const gq::Vec3<double> p = h->pose.transform(*best);
  ccdVec3Set(out, p.x(), p.y(), p.z());
}

void ccdCenter(const void* obj, ccd_vec3_t* out) {
  const auto* h = static_cast<const CcdHull*>(obj);
  const gq::Vec3<double> c = h->pose.transform(h->hull->center);
  ccdVec3Set(out, c.x(), c.y(), c.z());
}

ccd_t makeCcd() {
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = ccdSupport;
  ccd.support2 = ccdSupport;
  ccd.center1 = ccdCenter;
  ccd.center2 = ccdCenter;
  ccd.max_iterations = 128;
  ccd.epa_tolerance = 1e-12;
  ccd.dist_tolerance = 1e-12;
  return ccd;
}

void BM_CcdGJKIntersect(benchmark::State& state) {
  const Scene& s = scene(int(state.range(0)));
  if (!s.hull) return state.SkipWithError("convex cooking failed");
  const ccd_t ccd = makeCcd();
  int overlapping = 0;
  for (auto _ : state) {
    overlapping = 0;
    for (int i = 0; i < kPairs; ++i) {
      const CcdHull a{s.hull.get(), s.pose0[i]}, b{s.hull.get(), s.pose1[i]};
      overlapping += ccdGJKIntersect(&a, &b, &ccd);
    }
  }
  state.counters["overlapping"] = overlapping;
  state.SetItemsProcessed(state.iterations() * kPairs);
}

void BM_CcdGJKPenetration(benchmark::State& state) {
  const Scene& s = scene(int(state.range(0)));
  if (!s.hull) return state.SkipWithError("convex cooking failed");
  const ccd_t ccd = makeCcd();
  int overlapping = 0;
  for (auto _ : state) {
    overlapping = 0;
    for (int i = 0; i < kPairs; ++i) {
      const CcdHull a{s.hull.get(), s.pose0[i]}, b{s.hull.get(), s.pose1[i]};
      ccd_real_t depth;
      ccd_vec3_t dir, pos;
      overlapping += ccdGJKPenetration(&a, &b, &ccd, &depth, &dir, &pos) == 0;
      benchmark::DoNotOptimize(depth);
    }
  }
  state.counters["overlapping"] = overlapping;
  state.SetItemsProcessed(state.iterations() * kPairs);
}

}  // namespace

BENCHMARK(BM_GqDistance)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_GqDistanceWarm)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_CcdGJKIntersect)->Arg(30)->Arg(100)->Arg(300);
BENCHMARK(BM_CcdGJKPenetration)->Arg(30)->Arg(100)->Arg(300);

BENCHMARK_MAIN();
