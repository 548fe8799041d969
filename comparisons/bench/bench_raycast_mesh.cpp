// Raycasts against the shared meshes (bunny 69,451 triangles, fandisk 12,946, teapot 6,320, spot 5,856): gq in double
// and float through prepared shapes (gq::Shape<T>) vs Embree 3 (float, single thread, RTC_BUILD_QUALITY_HIGH), closest
// hit (rtcIntersect1), any hit as an occlusion test (rtcOccluded1) and all hits (gq MeshMultiple vs an Embree intersect
// filter that records every hit and rejects it so the traversal goes on), on fixed sets of seeded rays whose origins
// lie 1, 4 and 16 units outside the mesh's bounding sphere: half aimed at random points of the surface, half through
// random points of the bounds. Also BVH build time and bytes per triangle.
// Embree never culls back faces, so the gq rows use MeshBothSides.
// Bullet (float build, bunny at 4 units only): btBvhTriangleMeshShape (quantized BVH) performRaycast with a
// btTriangleRaycastCallback, both faces; its "any hit" row answers 0 to stop shortening, but Bullet's BVH walk has
// no early exit.
// Benchmark names: <query>_<backend>/<mesh>/d<distance> (build rows: build_<backend>/<mesh>).
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <BulletCollision/NarrowPhaseCollision/btRaycastCallback.h>
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <memory>
#include <random>
#include <string>

#include "gq/cooking.h"
#include "gq/io.h"
#include "gq/query.h"
#include "gq/shape.h"

namespace {

constexpr std::size_t kRays = 100000;
constexpr std::uint32_t kMaxAllHits = 64;
const char* const kMeshes[] = {"bunny", "fandisk", "teapot", "spot"};
const double kDistances[] = {1.0, 4.0, 16.0};

struct Rays {
  std::vector<gq::Vec3<double>> origin, dir;
  double maxDist = 0;
};

std::string meshFile(const std::string& name) {
  return std::string(GQ_SHARED_DIR) + "/meshes/" + (name == "bunny" ? "stanford-bunny" : name) + ".obj";
}

const gq::MeshData<double>& meshData(const std::string& name) {
  static std::map<std::string, gq::MeshData<double>> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  gq::MeshData<double> d;
  const gq::Status s = gq::loadMeshFile(meshFile(name), d);
  if (!s.ok()) {
    std::fprintf(stderr, "%s\n", s.toString().c_str());
    std::exit(1);
  }
  return cache.emplace(name, std::move(d)).first->second;
}

template <class T> gq::MeshData<T> meshAs(const std::string& name) {
  gq::MeshData<T> m;
  for (const auto& v : meshData(name).vertices) m.vertices.push_back(v.template cast<T>());
  m.triangles = meshData(name).triangles;
  return m;
}

const Rays& rays(const std::string& name, double distance) {
  static std::map<std::pair<std::string, double>, Rays> cache;
  auto it = cache.find({name, distance});
  if (it != cache.end()) return it->second;
  const auto& m = meshData(name);
  gq::Bounds3<double> b;
  for (const auto& v : m.vertices) b.include(v);
  const gq::Vec3<double> c = b.center();
  const double radius = 0.5 * (b.max - b.min).norm();
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> n;
  auto unit = [&] { return gq::Vec3<double>(n(rng), n(rng), n(rng)).normalized(); };
  Rays out;
  out.maxDist = 4 * (radius + distance);
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
    const gq::Vec3<double> o = c + unit() * (radius + distance);
    out.origin.push_back(o);
    out.dir.push_back((target - o).normalized());
  }
  return cache.emplace(std::make_pair(name, distance), std::move(out)).first->second;
}

// ---- gq -------------------------------------------------------------------------------------------------------
template <class T>
std::shared_ptr<const gq::TriangleMesh<T>> cookMesh(const std::string& name, gq::MeshCookReport* report = nullptr) {
  const gq::MeshData<T> m = meshAs<T>(name);
  std::shared_ptr<const gq::TriangleMesh<T>> mesh;
  if (!gq::cookTriangleMesh(m.vertices, m.triangles, mesh, report).ok()) std::exit(1);
  return mesh;
}

template <class T> const gq::Shape<T>& shapeOf(const std::string& name) {
  static std::map<std::string, gq::Shape<T>> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  gq::Shape<T> shape;
  if (!gq::Shape<T>::make(gq::TriangleMeshGeometry<T>(cookMesh<T>(name)), shape).ok()) std::exit(1);
  return cache.emplace(name, shape).first->second;
}

template <class T> void gqRaycast(benchmark::State& state, std::string name, double distance, gq::HitFlags flags,
                                  std::uint32_t maxHits) {
  const gq::Shape<T>& shape = shapeOf<T>(name);
  const Rays& r = rays(name, distance);
  std::vector<gq::Vec3<T>> o, d;
  for (std::size_t i = 0; i < kRays; ++i) {
    o.push_back(r.origin[i].template cast<T>());
    d.push_back(r.dir[i].template cast<T>());
  }
  const gq::Transform<T> pose;
  std::vector<gq::RaycastHit<T>> hit(maxHits);
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < kRays; ++i) {
      std::uint32_t n = 0;
      (void)gq::raycast(o[i], d[i], shape, pose, T(r.maxDist), flags, maxHits, hit.data(), n);  // valid input: timed
      hits += n;
      benchmark::DoNotOptimize(hit.data());
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * kRays));
  state.counters["hits_per_ray"] = double(hits) / double(kRays);
}

const gq::HitFlags kClosest = gq::kDefaultHitFlags | gq::HitFlag::MeshBothSides;
// Any hit as an occlusion test (what rtcOccluded1 answers): no optional field asked for (the face index is always
// reported).
const gq::HitFlags kAny = gq::HitFlag::MeshBothSides | gq::HitFlag::AnyHit;
const gq::HitFlags kAll = gq::kDefaultHitFlags | gq::HitFlag::MeshBothSides | gq::HitFlag::MeshMultiple;

template <class T> void gqBuild(benchmark::State& state, std::string name) {
  const gq::MeshData<T> m = meshAs<T>(name);
  gq::MeshCookReport report;
  for (auto _ : state) {
    std::shared_ptr<const gq::TriangleMesh<T>> mesh;
    (void)gq::cookTriangleMesh(m.vertices, m.triangles, mesh, &report);  // timed; the mesh cooks when loaded
    benchmark::DoNotOptimize(mesh);
  }
  state.counters["bytes_per_triangle"] = double(report.bvhBytes) / double(report.cookedTriangles);
}

// ---- Embree ---------------------------------------------------------------------------------------------------
std::int64_t gEmbreeBytes = 0;
bool trackMemory(void*, ssize_t bytes, bool) {
  gEmbreeBytes += bytes;
  return true;
}

// All hits: the filter records each hit in the context's collector and rejects it, so the traversal goes on. A
// RTC_BUILD_QUALITY_HIGH BVH splits large triangles into several leaves (spatial splits), and the filter then sees
// the same triangle once per leaf the ray enters: on spot at 4 units 0.9 % of the rays report one triangle twice (a
// long double brute force over all triangles agrees with gq's count, not the raw filter count). The collector keeps
// the triangle too, and duplicates are removed after the sort, as a user collecting all hits must.
struct AllHits {
  struct Hit {
    float t;
    unsigned prim;
    bool operator<(const Hit& o) const { return t < o.t || (t == o.t && prim < o.prim); }
    bool operator==(const Hit& o) const { return t == o.t && prim == o.prim; }
  };
  std::uint32_t count = 0;
  Hit hit[1024];
};
struct AllHitsContext {
  RTCIntersectContext ctx;
  AllHits* hits;
};
void collectHit(const RTCFilterFunctionNArguments* args) {
  auto* hits = reinterpret_cast<AllHitsContext*>(args->context)->hits;
  if (hits->count < 1024)
    hits->hit[hits->count++] = {RTCRayN_tfar(args->ray, args->N, 0), RTCHitN_primID(args->hit, args->N, 0)};
  args->valid[0] = 0;
}

struct EmbreeScene {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::int64_t bvhBytes = 0;
  EmbreeScene(const std::string& name, bool collectAll) {
    device = rtcNewDevice("threads=1");
    rtcSetDeviceMemoryMonitorFunction(device, trackMemory, nullptr);
    const gq::MeshData<float> m = meshAs<float>(name);
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
    if (collectAll) rtcSetGeometryIntersectFilterFunction(geom, collectHit);
    rtcCommitGeometry(geom);
    rtcAttachGeometry(scene, geom);
    rtcReleaseGeometry(geom);
    const std::int64_t before = gEmbreeBytes;
    rtcCommitScene(scene);
    bvhBytes = gEmbreeBytes - before;  // acceleration structure incl. its triangle copies, not the buffers
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  ~EmbreeScene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
};

const EmbreeScene& embreeScene(const std::string& name, bool collectAll) {
  static std::map<std::pair<std::string, bool>, std::unique_ptr<EmbreeScene>> cache;
  auto& s = cache[{name, collectAll}];
  if (!s) s = std::make_unique<EmbreeScene>(name, collectAll);
  return *s;
}

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

void embreeClosest(benchmark::State& state, std::string name, double distance) {
  const EmbreeScene& es = embreeScene(name, false);
  const Rays& r = rays(name, distance);
  std::vector<RTCRay> in(kRays);
  for (std::size_t i = 0; i < kRays; ++i) in[i] = embreeRay(r, i);
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < kRays; ++i) {
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      RTCRayHit rh;
      rh.ray = in[i];
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(es.scene, &ctx, &rh);
      hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
      benchmark::DoNotOptimize(rh);
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * kRays));
  state.counters["hits_per_ray"] = double(hits) / double(kRays);
}

void embreeAny(benchmark::State& state, std::string name, double distance) {
  const EmbreeScene& es = embreeScene(name, false);
  const Rays& r = rays(name, distance);
  std::vector<RTCRay> in(kRays);
  for (std::size_t i = 0; i < kRays; ++i) in[i] = embreeRay(r, i);
  std::size_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < kRays; ++i) {
      RTCIntersectContext ctx;
      rtcInitIntersectContext(&ctx);
      RTCRay ray = in[i];
      rtcOccluded1(es.scene, &ctx, &ray);
      hits += ray.tfar < 0.0f;  // Embree marks occlusion with tfar = -inf
      benchmark::DoNotOptimize(ray);
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * kRays));
  state.counters["hits_per_ray"] = double(hits) / double(kRays);
}

// Every hit along the ray, sorted by distance (gq's MeshMultiple returns its hits sorted), each triangle once.
void embreeAll(benchmark::State& state, std::string name, double distance) {
  const EmbreeScene& es = embreeScene(name, true);
  const Rays& r = rays(name, distance);
  std::vector<RTCRay> in(kRays);
  for (std::size_t i = 0; i < kRays; ++i) in[i] = embreeRay(r, i);
  std::size_t hits = 0;
  AllHits all;
  for (auto _ : state) {
    hits = 0;
    for (std::size_t i = 0; i < kRays; ++i) {
      AllHitsContext ctx;
      rtcInitIntersectContext(&ctx.ctx);
      ctx.hits = &all;
      all.count = 0;
      RTCRayHit rh;
      rh.ray = in[i];
      rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(es.scene, &ctx.ctx, &rh);
      std::sort(all.hit, all.hit + all.count);
      hits += std::size_t(std::unique(all.hit, all.hit + all.count) - all.hit);
      benchmark::DoNotOptimize(all);
    }
  }
  state.SetItemsProcessed(std::int64_t(state.iterations() * kRays));
  state.counters["hits_per_ray"] = double(hits) / double(kRays);
}

void embreeBuild(benchmark::State& state, std::string name) {
  std::int64_t bytes = 0;
  for (auto _ : state) {
    EmbreeScene es(name, false);
    bytes = es.bvhBytes;
    benchmark::DoNotOptimize(es.scene);
  }
  state.counters["bytes_per_triangle"] = double(bytes) / double(meshData(name).triangles.size());
}

// ---- Bullet ---------------------------------------------------------------------------------------------------
struct BulletMesh {
  std::vector<btScalar> vertices;
  std::vector<int> indices;
  std::unique_ptr<btTriangleIndexVertexArray> array;
  std::unique_ptr<btBvhTriangleMeshShape> shape;
  explicit BulletMesh(const gq::MeshData<double>& m) {
    for (const auto& v : m.vertices)
      for (int k = 0; k < 3; ++k) vertices.push_back(btScalar(v[k]));
    for (const auto& t : m.triangles)
      for (int k = 0; k < 3; ++k) indices.push_back(int(t[k]));
    array = std::make_unique<btTriangleIndexVertexArray>(int(m.triangles.size()), indices.data(),
                                                         3 * int(sizeof(int)), int(m.vertices.size()),
                                                         vertices.data(), 3 * int(sizeof(btScalar)));
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

void bulletRays(benchmark::State& state, std::string name, double distance, bool anyHit) {
  BulletMesh bm(meshData(name));
  const Rays& r = rays(name, distance);
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
  state.counters["hits_per_ray"] = double(hits) / double(kRays);
}

void bulletBuild(benchmark::State& state, std::string name) {
  for (auto _ : state) {
    BulletMesh bm(meshData(name));
    benchmark::DoNotOptimize(bm.shape.get());
  }
}

// gq and its peers alternate within each mesh and distance, so they see the same machine load.
void registerAll() {
  auto reg = [](const std::string& n, auto fn) { benchmark::RegisterBenchmark(n.c_str(), fn)->Unit(benchmark::kNanosecond); };
  for (const char* mesh : kMeshes) {
    const std::string m = mesh;
    for (double dist : kDistances) {
      const std::string suffix = "/" + m + "/d" + std::to_string(int(dist));
      reg("closest_gq_double" + suffix, [=](benchmark::State& s) { gqRaycast<double>(s, m, dist, kClosest, 1); });
      reg("closest_gq_float" + suffix, [=](benchmark::State& s) { gqRaycast<float>(s, m, dist, kClosest, 1); });
      reg("closest_embree" + suffix, [=](benchmark::State& s) { embreeClosest(s, m, dist); });
      reg("any_gq_double" + suffix, [=](benchmark::State& s) { gqRaycast<double>(s, m, dist, kAny, 1); });
      reg("any_gq_float" + suffix, [=](benchmark::State& s) { gqRaycast<float>(s, m, dist, kAny, 1); });
      reg("any_embree" + suffix, [=](benchmark::State& s) { embreeAny(s, m, dist); });
      if (dist == 4.0) {
        reg("all_gq_double" + suffix,
            [=](benchmark::State& s) { gqRaycast<double>(s, m, dist, kAll, kMaxAllHits); });
        reg("all_gq_float" + suffix, [=](benchmark::State& s) { gqRaycast<float>(s, m, dist, kAll, kMaxAllHits); });
        reg("all_embree" + suffix, [=](benchmark::State& s) { embreeAll(s, m, dist); });
      }
      if (m == "bunny" && dist == 4.0) {
        reg("closest_bullet" + suffix, [=](benchmark::State& s) { bulletRays(s, m, dist, false); });
        reg("any_bullet" + suffix, [=](benchmark::State& s) { bulletRays(s, m, dist, true); });
      }
    }
    reg("build_gq_double/" + m, [=](benchmark::State& s) { gqBuild<double>(s, m); });
    reg("build_gq_float/" + m, [=](benchmark::State& s) { gqBuild<float>(s, m); });
    reg("build_embree/" + m, [=](benchmark::State& s) { embreeBuild(s, m); });
    if (m == "bunny") reg("build_bullet/" + m, [=](benchmark::State& s) { bulletBuild(s, m); });
  }
}

}  // namespace

int main(int argc, char** argv) {
  registerAll();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
