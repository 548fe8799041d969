// The peers of bench_scene on the same objects and rays (bench_scene_fixture.h), in the same run:
//  - EmbreeSceneRaycast: the 100k scene rays through Embree 3's BVH over the 1000 objects as one user geometry whose
//    intersect callback is gq's raycast on that object's prepared shape (the same exact answer per object as
//    Scene::raycastClosest: the two differ only in the structure over the objects); float rays, rtcIntersect1.
//  - EmbreeBunnyIntersect1 / EmbreeBunnyIntersect1M: the 1M bunny rays (float) against Embree's triangle BVH
//    (RTC_BUILD_QUALITY_HIGH, as bench_raycast_mesh), one rtcIntersect1 per ray or the whole array through
//    rtcIntersect1M; GqFloatBunnyRaycastBatch/threads: the same float rays as one gq raycastBatch on the float bunny
//    (default settings: coherent order on 1 thread, input order on 2).
//  - FclSelfPairs: FCL 0.7's DynamicAABBTreeCollisionManager over the same 1000 objects as FCL shapes (the capsule
//    along Z turned onto gq's X, the box by full sides, the hulls as Convex with gq's cooked faces, the bunnies as
//    BVHModel<OBBRSS>), the narrow phase fcl::collide in the callback; `pairs` counts the colliding pairs.
#include <benchmark/benchmark.h>
#include <embree3/rtcore.h>
#include <fcl/fcl.h>

#include <cmath>
#include <memory>
#include <vector>

#include "bench_scene_fixture.h"
#include "gq/batch.h"
#include "gq/query.h"
#include "gq/shape.h"

namespace {
using namespace bench_scene;

// ---- Embree: the scene's objects as one user geometry -----------------------------------------------------------

struct UserObjects {
  const Fixture* fixture = nullptr;
  std::vector<gq::Shape<T>> shapes;
};

void objectBounds(const RTCBoundsFunctionArguments* args) {
  const auto& objects = *static_cast<const UserObjects*>(args->geometryUserPtr);
  gq::Bounds3<T> b;
  (void)gq::computeGeomBounds(b, objects.fixture->geometries[args->primID], objects.fixture->poses[args->primID]);
  RTCBounds* o = args->bounds_o;
  // Outward to float: Embree's box must hold the double one.
  o->lower_x = std::nextafter(float(b.min.x()), -INFINITY);
  o->lower_y = std::nextafter(float(b.min.y()), -INFINITY);
  o->lower_z = std::nextafter(float(b.min.z()), -INFINITY);
  o->upper_x = std::nextafter(float(b.max.x()), INFINITY);
  o->upper_y = std::nextafter(float(b.max.y()), INFINITY);
  o->upper_z = std::nextafter(float(b.max.z()), INFINITY);
}

void objectIntersect(const RTCIntersectFunctionNArguments* args) {
  if (!args->valid[0]) return;
  const auto& objects = *static_cast<const UserObjects*>(args->geometryUserPtr);
  RTCRayHit& rh = *reinterpret_cast<RTCRayHit*>(args->rayhit);  // N == 1: rtcIntersect1
  const V origin(rh.ray.org_x, rh.ray.org_y, rh.ray.org_z);
  const V dir = V(rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z).normalized();
  gq::RaycastHit<T> hit;
  std::uint32_t n = 0;
  (void)gq::raycast(origin, dir, objects.shapes[args->primID], objects.fixture->poses[args->primID], T(rh.ray.tfar),
                    gq::kDefaultHitFlags, 1u, &hit, n);
  if (n == 0 || hit.distance < rh.ray.tnear || hit.distance >= rh.ray.tfar) return;
  rh.ray.tfar = float(hit.distance);
  rh.hit.Ng_x = float(hit.normal.x());
  rh.hit.Ng_y = float(hit.normal.y());
  rh.hit.Ng_z = float(hit.normal.z());
  rh.hit.u = rh.hit.v = 0;
  rh.hit.primID = args->primID;
  rh.hit.geomID = args->geomID;
  rh.hit.instID[0] = args->context->instID[0];
}

struct EmbreeScenes {
  RTCDevice device = nullptr;
  RTCScene objects = nullptr, bunny = nullptr;
  UserObjects user;
  bool ok = false;
  ~EmbreeScenes() {
    if (objects) rtcReleaseScene(objects);
    if (bunny) rtcReleaseScene(bunny);
    if (device) rtcReleaseDevice(device);
  }
};

const EmbreeScenes& embree() {
  static const EmbreeScenes* e = [] {
    auto* out = new EmbreeScenes();
    const Fixture& f = fixture();
    if (!f.ok) return out;
    // Embree's default device: "threads=1" limits oneTBB to one thread in the whole process (a global control),
    // which would also hold gq's threaded batches in this program to one thread. The rays below are cast one at a
    // time from the benchmark's thread either way.
    out->device = rtcNewDevice(nullptr);
    out->user.fixture = &f;
    for (const auto& g : f.geometries) {
      gq::Shape<T> s;
      if (!gq::Shape<T>::make(g, s).ok()) return out;
      out->user.shapes.push_back(std::move(s));
    }
    out->objects = rtcNewScene(out->device);
    RTCGeometry user = rtcNewGeometry(out->device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(user, unsigned(f.geometries.size()));
    rtcSetGeometryUserData(user, &out->user);
    rtcSetGeometryBoundsFunction(user, objectBounds, nullptr);
    rtcSetGeometryIntersectFunction(user, objectIntersect);
    rtcCommitGeometry(user);
    rtcAttachGeometry(out->objects, user);
    rtcReleaseGeometry(user);
    rtcCommitScene(out->objects);

    out->bunny = rtcNewScene(out->device);
    rtcSetSceneBuildQuality(out->bunny, RTC_BUILD_QUALITY_HIGH);
    RTCGeometry mesh = rtcNewGeometry(out->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(mesh, RTC_BUILD_QUALITY_HIGH);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                          3 * sizeof(float), f.bunnyVertices.size()));
    for (std::size_t i = 0; i < f.bunnyVertices.size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + k] = float(f.bunnyVertices[i][k] * f.bunnyScale);
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(mesh, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), f.bunnyTriangles.size()));
    for (std::size_t i = 0; i < f.bunnyTriangles.size(); ++i)
      for (int k = 0; k < 3; ++k) idx[3 * i + k] = f.bunnyTriangles[i][k];
    rtcCommitGeometry(mesh);
    rtcAttachGeometry(out->bunny, mesh);
    rtcReleaseGeometry(mesh);
    rtcCommitScene(out->bunny);
    out->ok = true;
    return out;
  }();
  return *e;
}

void setRay(RTCRayHit& rh, const V& o, const V& d, float tfar) {
  rh.ray.org_x = float(o.x());
  rh.ray.org_y = float(o.y());
  rh.ray.org_z = float(o.z());
  rh.ray.dir_x = float(d.x());
  rh.ray.dir_y = float(d.y());
  rh.ray.dir_z = float(d.z());
  rh.ray.tnear = 0;
  rh.ray.tfar = tfar;
  rh.ray.mask = 0xffffffffu;
  rh.ray.flags = 0;
  rh.ray.time = 0;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

// One rtcIntersect1 per ray of (origins, dirs) into `scene`, up to maxDist; `hits` counts the rays that hit.
void intersectEach(benchmark::State& state, RTCScene scene, const std::vector<V>& origins, const std::vector<V>& dirs,
                   int count, float maxDist) {
  std::int64_t hits = 0;
  for (auto _ : state) {
    hits = 0;
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    for (int i = 0; i < count; ++i) {
      RTCRayHit rh;
      setRay(rh, origins[i], dirs[i], maxDist);
      rtcIntersect1(scene, &ctx, &rh);
      hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
    }
    benchmark::DoNotOptimize(hits);
  }
  state.SetItemsProcessed(state.iterations() * count);
  state.counters["hits"] = double(hits);
}

void BM_EmbreeSceneRaycast(benchmark::State& state) {
  const EmbreeScenes& e = embree();
  if (!e.ok) return state.SkipWithError("bunny not found or setup failed");
  const Fixture& f = fixture();
  intersectEach(state, e.objects, f.origins, f.dirs, kRays, 80.0f);
}

void BM_EmbreeBunnyIntersect1(benchmark::State& state) {
  const EmbreeScenes& e = embree();
  if (!e.ok) return state.SkipWithError("bunny not found or setup failed");
  const Fixture& f = fixture();
  intersectEach(state, e.bunny, f.bunnyOrigins, f.bunnyDirs, kBunnyRays, 10.0f);
}

void BM_EmbreeBunnyIntersect1M(benchmark::State& state) {
  const EmbreeScenes& e = embree();
  if (!e.ok) return state.SkipWithError("bunny not found or setup failed");
  const Fixture& f = fixture();
  std::vector<RTCRayHit> rays(kBunnyRays);
  std::int64_t hits = 0;
  for (auto _ : state) {
    for (int i = 0; i < kBunnyRays; ++i) setRay(rays[i], f.bunnyOrigins[i], f.bunnyDirs[i], 10.0f);
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    rtcIntersect1M(e.bunny, &ctx, rays.data(), unsigned(kBunnyRays), sizeof(RTCRayHit));
    benchmark::DoNotOptimize(rays.data());
  }
  for (const auto& r : rays) hits += r.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  state.SetItemsProcessed(state.iterations() * kBunnyRays);
  state.counters["hits"] = double(hits);
}

void BM_GqFloatBunnyRaycastBatch(benchmark::State& state) {
  const Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("bunny not found or setup failed");
  using F = gq::Vec3<float>;
  std::vector<F> vertices, origins, dirs;
  for (const auto& v : f.bunnyVertices) vertices.push_back((v * f.bunnyScale).cast<float>());
  for (int i = 0; i < kBunnyRays; ++i) {
    origins.push_back(f.bunnyOrigins[i].cast<float>());
    dirs.push_back(f.bunnyDirs[i].cast<float>().normalized());
  }
  std::shared_ptr<const gq::TriangleMesh<float>> mesh;
  gq::Shape<float> bunny;
  if (!gq::cookTriangleMesh(vertices, f.bunnyTriangles, mesh).ok() ||
      !gq::Shape<float>::make(gq::TriangleMeshGeometry<float>(mesh), bunny).ok())
    return state.SkipWithError("float bunny");
  std::vector<gq::RaycastHit<float>> hits(kBunnyRays);
  std::vector<std::uint8_t> has(kBunnyRays);
  gq::BatchSettings settings;
  settings.threads = std::uint32_t(state.range(0));
  gq::RayBatch<float> rays;
  rays.origins = gq::StridedArray<F>(origins.data(), kBunnyRays);
  rays.unitDirs = gq::StridedArray<F>(dirs.data(), kBunnyRays);
  rays.maxDist = 10.0f;
  rays.hitFlags = kBothFaces;
  for (auto _ : state) {
    (void)gq::raycastBatch(rays, bunny, gq::Transform<float>(), hits.data(), has.data(), nullptr, settings);
    benchmark::DoNotOptimize(has.data());
  }
  state.SetItemsProcessed(state.iterations() * kBunnyRays);
  std::int64_t n = 0;
  for (auto h : has) n += h;
  state.counters["hits"] = double(n);
}

// ---- FCL: the same objects in its dynamic AABB tree manager -------------------------------------------------------

using FclGeom = std::shared_ptr<::fcl::CollisionGeometryd>;

FclGeom fclHull(const gq::ConvexMeshGeometry<T>& g) {
  const gq::ConvexMesh<T>& hull = *g.mesh;
  const gq::Mat3<T> scale = g.scale.toMatrix();
  auto vertices = std::make_shared<std::vector<::fcl::Vector3d>>();
  for (const auto& v : hull.vertices) vertices->push_back(scale * v);
  auto faces = std::make_shared<std::vector<int>>();
  for (const auto& p : hull.polygons) {
    faces->push_back(int(p.indexCount));
    for (std::uint32_t k = 0; k < p.indexCount; ++k) faces->push_back(int(hull.polygonVertices[p.indexBase + k]));
  }
  return std::make_shared<::fcl::Convexd>(vertices, int(hull.polygons.size()), faces);
}

FclGeom fclMesh(const Fixture& f, const gq::TriangleMeshGeometry<T>& g) {
  auto model = std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>();
  const gq::Mat3<T> scale = g.scale.toMatrix();
  std::vector<::fcl::Vector3d> points;
  for (const auto& v : f.bunnyVertices) points.push_back(scale * v);
  std::vector<::fcl::Triangle> triangles;
  for (const auto& t : f.bunnyTriangles) triangles.emplace_back(t[0], t[1], t[2]);
  model->beginModel();
  model->addSubModel(points, triangles);
  model->endModel();
  return model;
}

struct FclObjects {
  std::vector<std::unique_ptr<::fcl::CollisionObjectd>> objects;
  std::vector<::fcl::CollisionObjectd*> pointers;
  bool ok = false;
};

FclObjects fclObjects(const Fixture& f) {
  FclObjects out;
  for (std::size_t i = 0; i < f.geometries.size(); ++i) {
    const gq::Geometry<T>& g = f.geometries[i];
    ::fcl::Transform3d tf = ::fcl::Transform3d::Identity();
    tf.linear() = f.poses[i].q.toRotationMatrix();
    tf.translation() = f.poses[i].p;
    FclGeom geom;
    switch (g.type()) {
      case gq::GeometryType::Sphere: geom = std::make_shared<::fcl::Sphered>(g.get<gq::SphereGeometry<T>>().radius); break;
      case gq::GeometryType::Capsule: {
        const auto& c = g.get<gq::CapsuleGeometry<T>>();
        geom = std::make_shared<::fcl::Capsuled>(c.radius, 2 * c.halfHeight);
        tf.linear() = tf.linear() * Eigen::AngleAxisd(M_PI / 2, ::fcl::Vector3d::UnitY()).toRotationMatrix();  // Z -> X
        break;
      }
      case gq::GeometryType::Box: geom = std::make_shared<::fcl::Boxd>(2 * g.get<gq::BoxGeometry<T>>().halfExtents); break;
      case gq::GeometryType::ConvexMesh: geom = fclHull(g.get<gq::ConvexMeshGeometry<T>>()); break;
      case gq::GeometryType::TriangleMesh: geom = fclMesh(f, g.get<gq::TriangleMeshGeometry<T>>()); break;
      default: return out;
    }
    out.objects.push_back(std::make_unique<::fcl::CollisionObjectd>(geom, tf));
    out.pointers.push_back(out.objects.back().get());
  }
  out.ok = true;
  return out;
}

bool countColliding(::fcl::CollisionObjectd* a, ::fcl::CollisionObjectd* b, void* data) {
  ::fcl::CollisionRequestd request;
  ::fcl::CollisionResultd result;
  *static_cast<std::int64_t*>(data) += ::fcl::collide(a, b, request, result) > 0;
  return false;
}

void BM_FclSelfPairs(benchmark::State& state) {
  const Fixture& f = fixture();
  if (!f.ok) return state.SkipWithError("bunny not found or setup failed");
  FclObjects objects = fclObjects(f);
  if (!objects.ok) return state.SkipWithError("an object FCL has no shape for");
  ::fcl::DynamicAABBTreeCollisionManagerd manager;
  manager.registerObjects(objects.pointers);
  manager.setup();
  std::int64_t pairs = 0;
  for (auto _ : state) {
    pairs = 0;
    manager.collide(&pairs, countColliding);
    benchmark::DoNotOptimize(pairs);
  }
  state.counters["pairs"] = double(pairs);
}

}  // namespace

BENCHMARK(BM_EmbreeSceneRaycast)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EmbreeBunnyIntersect1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EmbreeBunnyIntersect1M)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GqFloatBunnyRaycastBatch)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FclSelfPairs)->Unit(benchmark::kMillisecond);
