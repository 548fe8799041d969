// Raycasts against the Stanford bunny (69,451 triangles): gq in double and float vs Embree 3 (float, single
// thread, RTC_BUILD_QUALITY_HIGH), closest hit (rtcIntersect1) and any hit (rtcOccluded1), on one fixed set of
// 1M seeded rays: half aimed at random points of the surface from outside, half through random points of the
// bounds in random directions. Also BVH build time and BVH bytes per triangle.
// Embree never culls back faces, so the headline gq rows use MeshBothSides; "gq_*_culled" rows use the default.
// Bullet (float build): btBvhTriangleMeshShape (quantized BVH) performRaycast with a btTriangleRaycastCallback,
// both faces; its "any hit" row answers 0 to stop shortening, but Bullet's BVH walk has no early exit.
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <cstdio>
#include <memory>
#include <cstdlib>
#include <limits>
#include <random>

#include "gq/cooking.h"
#include "gq/io.h"
#include "gq/query.h"

namespace {

constexpr std::size_t kRays = 1000000;

struct Rays {
  std::vector<gq::Vec3<double>> origin, dir;
  double maxDist = 0;
};

const gq::MeshData<double>& bunny() {
  static const gq::MeshData<double> data = [] {
    gq::MeshData<double> d;
    const gq::Status s = gq::loadMeshFile(std::string(GQ_SHARED_DIR) + "/meshes/stanford-bunny.obj", d);
    if (!s.ok()) {
      std::fprintf(stderr, "%s\n", s.toString().c_str());
      std::exit(1);
    }
    return d;
  }();
  return data;
}

template <class T> gq::MeshData<T> bunnyAs() {
  gq::MeshData<T> m;
  for (const auto& v : bunny().vertices) m.vertices.push_back(v.cast<T>());
  m.triangles = bunny().triangles;
  return m;
}

const Rays& rays() {
  static const Rays r = [] {
    const auto& m = bunny();
    gq::Bounds3<double> b;
    for (const auto& v : m.vertices) b.include(v);
    const gq::Vec3<double> c = b.center();
    const double radius = b.extents().norm();
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> n;
    auto unit = [&] { return gq::Vec3<double>(n(rng), n(rng), n(rng)).normalized(); };
    Rays out;
    out.maxDist = 10 * radius;
    for (std::size_t i = 0; i < kRays; ++i) {
      gq::Vec3<double> target;
      if (i % 2 == 0) {  // a random point of a random triangle
        const auto& t = m.triangles[std::size_t(u(rng) * double(m.triangles.size())) % m.triangles.size()];
        double a = u(rng), bb = u(rng);
        if (a + bb > 1) { a = 1 - a; bb = 1 - bb; }
        target = (1 - a - bb) * m.vertices[t[0]] + a * m.vertices[t[1]] + bb * m.vertices[t[2]];
      } else {  // a random point of the bounds
        target = b.min + (b.max - b.min).cwiseProduct(gq::Vec3<double>(u(rng), u(rng), u(rng)));
      }
      const gq::Vec3<double> o = c + unit() * (2 * radius);
      out.origin.push_back(o);
      out.dir.push_back((target - o).normalized());
    }
    return out;
  }();
  return r;
}

// ---- gq -------------------------------------------------------------------------------------------------------
template <class T> std::shared_ptr<const gq::TriangleMesh<T>> cookBunny(gq::MeshCookReport* report = nullptr) {
  const gq::MeshData<T> m = bunnyAs<T>();
  std::shared_ptr<const gq::TriangleMesh<T>> mesh;
  if (!gq::cookTriangleMesh(m.vertices, m.triangles, mesh, report).ok()) std::exit(1);
  return mesh;
}

template <class T> void gqRaycast(benchmark::State& state, gq::HitFlags flags) {
  const gq::Geometry<T> g = gq::TriangleMeshGeometry<T>(cookBunny<T>());
  const Rays& r = rays();
  std::vector<gq::Vec3<T>> o, d;
  for (std::size_t i = 0; i < kRays; ++i) {
    o.push_back(r.origin[i].cast<T>());
    d.push_back(r.dir[i].cast<T>());
  }
  const gq::Transform<T> pose;
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < kRays; ++i) {
      gq::RaycastHit<T> hit;
      std::uint32_t n = 0;
      (void)gq::raycast(o[i], d[i], g, pose, T(r.maxDist), flags, 1, &hit, n);  // valid input: timed
      hits += n;
      benchmark::DoNotOptimize(hit);
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * kRays));
  state.counters["hit_fraction"] = double(hits) / double(kRays);
}

const gq::HitFlags kClosest = gq::kDefaultHitFlags | gq::HitFlag::MeshBothSides;
const gq::HitFlags kAny = gq::kDefaultHitFlags | gq::HitFlag::MeshBothSides | gq::HitFlag::AnyHit;

void BM_closest_gq_double(benchmark::State& s) { gqRaycast<double>(s, kClosest); }
void BM_closest_gq_float(benchmark::State& s) { gqRaycast<float>(s, kClosest); }
void BM_closest_gq_double_culled(benchmark::State& s) { gqRaycast<double>(s, gq::kDefaultHitFlags); }
void BM_any_gq_double(benchmark::State& s) { gqRaycast<double>(s, kAny); }
void BM_any_gq_float(benchmark::State& s) { gqRaycast<float>(s, kAny); }

template <class T> void gqBuild(benchmark::State& state) {
  const gq::MeshData<T> m = bunnyAs<T>();
  gq::MeshCookReport report;
  for (auto _ : state) {
    std::shared_ptr<const gq::TriangleMesh<T>> mesh;
    (void)gq::cookTriangleMesh(m.vertices, m.triangles, mesh, &report);  // timed; the mesh cooks when loaded
    benchmark::DoNotOptimize(mesh);
  }
  state.counters["bytes_per_triangle"] = double(report.bvhBytes) / double(report.cookedTriangles);
}
void BM_build_gq_double(benchmark::State& s) { gqBuild<double>(s); }
void BM_build_gq_float(benchmark::State& s) { gqBuild<float>(s); }

// ---- Embree ---------------------------------------------------------------------------------------------------
std::int64_t gEmbreeBytes = 0;
bool trackMemory(void*, ssize_t bytes, bool) {
  gEmbreeBytes += bytes;
  return true;
}

struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::int64_t bvhBytes = 0;
  EmbreeScene() {
    device = rtcNewDevice("threads=1");
    rtcSetDeviceMemoryMonitorFunction(device, trackMemory, nullptr);
    const gq::MeshData<float> m = bunnyAs<float>();
    scene = rtcNewScene(device);
    rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), m.vertices.size()));
    for (std::size_t i = 0; i < m.vertices.size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + k] = m.vertices[i][k];
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), m.triangles.size()));
    for (std::size_t i = 0; i < m.triangles.size(); ++i)
      for (int k = 0; k < 3; ++k) idx[3 * i + k] = m.triangles[i][k];
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    const std::int64_t before = gEmbreeBytes;
    rtcCommitScene(scene);
    bvhBytes = gEmbreeBytes - before;  // acceleration structure incl. its triangle copies, not the buffers
  }
  ~EmbreeScene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
};

RTCRay embreeRay(const Rays& r, std::size_t i) {
  RTCRay ray;
  ray.org_x = float(r.origin[i].x()); ray.org_y = float(r.origin[i].y()); ray.org_z = float(r.origin[i].z());
  ray.dir_x = float(r.dir[i].x()); ray.dir_y = float(r.dir[i].y()); ray.dir_z = float(r.dir[i].z());
  ray.tnear = 0.0f;
  ray.tfar = float(r.maxDist);
  ray.time = 0.0f;
  ray.mask = 0xffffffffu;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}

void BM_closest_embree(benchmark::State& state) {
  EmbreeScene es;
  const Rays& r = rays();
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < kRays; ++i) {
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      RTCRayHit rh;
      rh.ray = embreeRay(r, i);
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(es.scene, &ctx, &rh);
      hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
      benchmark::DoNotOptimize(rh);
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * kRays));
  state.counters["hit_fraction"] = double(hits) / double(kRays);
}

void BM_any_embree(benchmark::State& state) {
  EmbreeScene es;
  const Rays& r = rays();
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < kRays; ++i) {
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      RTCRay ray = embreeRay(r, i);
      rtcOccluded1(es.scene, &ctx, &ray);
      hits += ray.tfar < 0.0f;  // Embree marks occlusion with tfar = -inf
      benchmark::DoNotOptimize(ray);
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * kRays));
  state.counters["hit_fraction"] = double(hits) / double(kRays);
}

void BM_build_embree(benchmark::State& state) {
  std::int64_t bytes = 0;
  for (auto _ : state) {
    EmbreeScene es;
    bytes = es.bvhBytes;
    benchmark::DoNotOptimize(es.scene);
  }
  state.counters["bytes_per_triangle"] = double(bytes) / double(bunny().triangles.size());
}


// ---- Bullet ---------------------------------------------------------------------------------------------------
struct BulletMesh {
  std::vector<btScalar> vertices;
  std::vector<int> indices;
  std::unique_ptr<btTriangleIndexVertexArray> array;
  std::unique_ptr<btBvhTriangleMeshShape> shape;
  BulletMesh() {
    for (const auto& v : bunny().vertices)
      for (int k = 0; k < 3; ++k) vertices.push_back(btScalar(v[k]));
    for (const auto& t : bunny().triangles)
      for (int k = 0; k < 3; ++k) indices.push_back(int(t[k]));
    array = std::make_unique<btTriangleIndexVertexArray>(int(bunny().triangles.size()), indices.data(), 3 * int(sizeof(int)),
                                                         int(bunny().vertices.size()), vertices.data(), 3 * int(sizeof(btScalar)));
    shape = std::make_unique<btBvhTriangleMeshShape>(array.get(), true);  // quantized AABB compression
  }
};

class ClosestTriangle : public btTriangleRaycastCallback {
 public:
  ClosestTriangle(const btVector3& from, const btVector3& to, bool stopAtFirst)
      : btTriangleRaycastCallback(from, to), stopAtFirst_(stopAtFirst) {}
  btScalar reportHit(const btVector3&, btScalar fraction, int, int) override {
    hit = true;
    return stopAtFirst_ ? btScalar(0) : fraction;  // the returned fraction bounds later triangles
  }
  bool hit = false;

 private:
  bool stopAtFirst_;
};

void bulletRays(benchmark::State& state, bool anyHit) {
  BulletMesh bm;
  const Rays& r = rays();
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < kRays; ++i) {
      const gq::Vec3<double> to = r.origin[i] + r.dir[i] * r.maxDist;
      const btVector3 a(btScalar(r.origin[i].x()), btScalar(r.origin[i].y()), btScalar(r.origin[i].z()));
      const btVector3 b(btScalar(to.x()), btScalar(to.y()), btScalar(to.z()));
      ClosestTriangle cb(a, b, anyHit);
      bm.shape->performRaycast(&cb, a, b);
      hits += cb.hit;
      benchmark::DoNotOptimize(cb.m_hitFraction);
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * kRays));
  state.counters["hit_fraction"] = double(hits) / double(kRays);
}

void BM_closest_bullet(benchmark::State& state) { bulletRays(state, false); }
void BM_any_bullet(benchmark::State& state) { bulletRays(state, true); }

void BM_build_bullet(benchmark::State& state) {
  for (auto _ : state) {
    BulletMesh bm;
    benchmark::DoNotOptimize(bm.shape.get());
  }
}

}  // namespace

BENCHMARK(BM_closest_gq_double)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_closest_gq_float)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_closest_gq_double_culled)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_closest_embree)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_closest_bullet)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_any_gq_double)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_any_gq_float)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_any_embree)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_any_bullet)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_build_gq_double)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_build_gq_float)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_build_embree)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_build_bullet)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
