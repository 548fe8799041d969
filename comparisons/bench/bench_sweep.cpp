// Sweeps against the Stanford bunny and against a convex hull: gq::sweep (double, float) vs Bullet 3.24 (float)
// btCollisionWorld::convexSweepTest with ClosestConvexResultCallback, on the same 64 seeded sweeps per scene. Swept
// shapes: box, capsule and a 32-point convex hull, each about 5 % of the target's size, starting on a sphere of 1.5x
// the target's size and aimed at a point near its centre (most sweeps hit). Bullet margins are 0 (the shapes are
// then the same solids as gq's; Bullet's default 0.04 margin would grow its hull). Counters: `hits` and
// `meanDistance` over the 64 sweeps, so the backends' answers can be compared in the output.
// Run: bench_sweep --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <cstdlib>
#include <BulletCollision/CollisionDispatch/btCollisionWorld.h>
#include <BulletCollision/CollisionShapes/btBvhTriangleMeshShape.h>
#include <BulletCollision/CollisionShapes/btTriangleIndexVertexArray.h>
#include <benchmark/benchmark.h>
#include <btBulletCollisionCommon.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "gq/cooking.h"
#include "gq/io.h"
#include "gq/query.h"

namespace {

constexpr int kSweeps = 64;
enum class Target { Bunny, Hull };
enum class Swept { Box, Capsule, Convex };

struct SweepCase {
  gq::Transform<double> start;
  gq::Vec3<double> dir;
};

struct Scene {
  std::vector<gq::Vec3<double>> vertices;  // bunny, centred
  std::vector<gq::TriangleIndices> triangles;
  std::vector<gq::Vec3<double>> targetHull, sweptHull;
  double size = 1;
  std::vector<SweepCase> sweeps;
  bool ok = false;
};

std::vector<gq::Vec3<double>> randomPoints(std::mt19937_64& gen, int count, double radius) {
  std::normal_distribution<double> n;
  std::uniform_real_distribution<double> u(0.6, 1.0);
  std::vector<gq::Vec3<double>> out;
  for (int i = 0; i < count; ++i) out.push_back(gq::Vec3<double>(n(gen), n(gen), n(gen)).normalized() * (radius * u(gen)));
  return out;
}

const Scene& scene() {
  static const Scene s = [] {
    Scene out;
    gq::MeshData<double> data;
    if (!gq::loadMeshFile(std::string(GQ_SHARED_DIR) + "/meshes/stanford-bunny.obj", data).ok()) return out;
    gq::Bounds3<double> b;
    for (const auto& v : data.vertices) b.include(v);
    for (const auto& v : data.vertices) out.vertices.push_back(v - b.center());
    out.triangles = data.triangles;
    out.size = (b.max - b.min).maxCoeff();
    std::mt19937_64 gen(9876);
    out.targetHull = randomPoints(gen, 64, 0.5 * out.size);
    out.sweptHull = randomPoints(gen, 32, 0.05 * out.size);
    std::normal_distribution<double> n;
    std::uniform_real_distribution<double> u(-0.2 * out.size, 0.2 * out.size);
    for (int i = 0; i < kSweeps; ++i) {
      const gq::Vec3<double> from = gq::Vec3<double>(n(gen), n(gen), n(gen)).normalized() * (1.5 * out.size);
      const gq::Vec3<double> aim(u(gen), u(gen), u(gen));
      out.sweeps.push_back({gq::Transform<double>(from, gq::Quat<double>(n(gen), n(gen), n(gen), n(gen)).normalized()),
                            (aim - from).normalized()});
    }
    out.ok = true;
    return out;
  }();
  return s;
}

double maxDist() { return 3 * scene().size; }
double boxHalf() { return 0.04 * scene().size; }
double capsuleRadius() { return 0.03 * scene().size; }
double capsuleHalfHeight() { return 0.04 * scene().size; }

// Mean signed distance (gq::distance in double, GJK to 1e-12) between the swept shape placed at each reported
// time of impact and the target: 0 for an exact time of impact, < 0 when a backend stops inside the target.
struct Report {
  std::vector<int> index;
  std::vector<double> distance;
};
double meanGapAtHits(Target target, Swept swept, const Report& r);

// ---- gq --------------------------------------------------------------------------------------------------------
template <class T> std::vector<gq::Vec3<T>> cast(const std::vector<gq::Vec3<double>>& v) {
  std::vector<gq::Vec3<T>> out;
  for (const auto& p : v) out.push_back(p.template cast<T>());
  return out;
}

template <class T> gq::Geometry<T> gqTarget(Target t) {
  const Scene& s = scene();
  if (t == Target::Bunny) {
    std::shared_ptr<const gq::TriangleMesh<T>> mesh;
    if (!gq::cookTriangleMesh(cast<T>(s.vertices), s.triangles, mesh).ok()) std::abort();  // the scene is valid
    return gq::TriangleMeshGeometry<T>(mesh, gq::MeshScale<T>(), gq::MeshGeometryFlag::DoubleSided);
  }
  std::shared_ptr<const gq::ConvexMesh<T>> hull;
  if (!gq::cookConvexMesh(cast<T>(s.targetHull), hull).ok()) std::abort();
  return gq::ConvexMeshGeometry<T>(hull);
}

template <class T> gq::Geometry<T> gqSwept(Swept w) {
  if (w == Swept::Box) return gq::BoxGeometry<T>(T(boxHalf()), T(boxHalf()), T(boxHalf()));
  if (w == Swept::Capsule) return gq::CapsuleGeometry<T>(T(capsuleRadius()), T(capsuleHalfHeight()));
  std::shared_ptr<const gq::ConvexMesh<T>> hull;
  if (!gq::cookConvexMesh(cast<T>(scene().sweptHull), hull).ok()) std::abort();
  return gq::ConvexMeshGeometry<T>(hull);
}

template <class T> void BM_Sweep_gq(benchmark::State& state, Target target, Swept swept) {
  if (!scene().ok) return state.SkipWithError("bunny not found");
  const gq::Geometry<T> g1 = gqTarget<T>(target), g0 = gqSwept<T>(swept);
  std::vector<gq::Transform<T>> starts;
  std::vector<gq::Vec3<T>> dirs;
  for (const SweepCase& c : scene().sweeps) {
    starts.push_back(c.start.template cast<T>());
    dirs.push_back(c.dir.template cast<T>().normalized());
  }
  int hits = 0;
  double total = 0;
  Report report;
  for (auto _ : state) {
    hits = 0;
    total = 0;
    report = Report();
    for (int i = 0; i < kSweeps; ++i) {
      gq::SweepHit<T> hit;
      bool hasHit = false;
      (void)gq::sweep(dirs[i], T(maxDist()), g0, starts[i], g1, gq::Transform<T>(), hit, hasHit);  // valid input: timed
      if (hasHit) {
        ++hits;
        total += double(hit.distance);
        report.index.push_back(i);
        report.distance.push_back(double(hit.distance));
      }
    }
    benchmark::DoNotOptimize(total);
  }
  state.counters["hits"] = hits;
  state.counters["meanDistance"] = hits ? total / hits : 0.0;
  state.counters["meanGapAtHit"] = meanGapAtHits(target, swept, report);
  state.SetItemsProcessed(state.iterations() * kSweeps);
}

// ---- Bullet ----------------------------------------------------------------------------------------------------
btVector3 bt(const gq::Vec3<double>& v) { return btVector3(btScalar(v.x()), btScalar(v.y()), btScalar(v.z())); }
btTransform bt(const gq::Transform<double>& t) {
  return btTransform(btQuaternion(btScalar(t.q.x()), btScalar(t.q.y()), btScalar(t.q.z()), btScalar(t.q.w())), bt(t.p));
}

struct BulletWorld {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  btDbvtBroadphase broadphase;
  btCollisionWorld world{&dispatcher, &broadphase, &config};
  std::vector<int> indices;
  std::vector<btScalar> vertices;
  std::unique_ptr<btTriangleIndexVertexArray> array;
  std::unique_ptr<btCollisionShape> shape;
  btCollisionObject object;

  explicit BulletWorld(Target target) {
    const Scene& s = scene();
    if (target == Target::Bunny) {
      for (const auto& v : s.vertices) vertices.insert(vertices.end(), {btScalar(v.x()), btScalar(v.y()), btScalar(v.z())});
      for (const auto& t : s.triangles) indices.insert(indices.end(), {int(t[0]), int(t[1]), int(t[2])});
      array = std::make_unique<btTriangleIndexVertexArray>(int(s.triangles.size()), indices.data(), 3 * int(sizeof(int)),
                                                           int(s.vertices.size()), vertices.data(), 3 * int(sizeof(btScalar)));
      shape = std::make_unique<btBvhTriangleMeshShape>(array.get(), true);
    } else {
      auto hull = std::make_unique<btConvexHullShape>();
      for (const auto& p : s.targetHull) hull->addPoint(bt(p), false);
      hull->recalcLocalAabb();
      hull->setMargin(0);
      shape = std::move(hull);
    }
    object.setCollisionShape(shape.get());
    world.addCollisionObject(&object);
    world.updateAabbs();
  }
};

std::unique_ptr<btConvexShape> bulletSwept(Swept w) {
  if (w == Swept::Box) {
    auto box = std::make_unique<btBoxShape>(btVector3(btScalar(boxHalf()), btScalar(boxHalf()), btScalar(boxHalf())));
    box->setMargin(0);
    return box;
  }
  // btCapsuleShapeX(radius, height): height is the length of the segment between the two hemisphere centres.
  if (w == Swept::Capsule) return std::make_unique<btCapsuleShapeX>(btScalar(capsuleRadius()), btScalar(2 * capsuleHalfHeight()));
  auto hull = std::make_unique<btConvexHullShape>();
  for (const auto& p : scene().sweptHull) hull->addPoint(bt(p), false);
  hull->recalcLocalAabb();
  hull->setMargin(0);
  return hull;
}

void BM_Sweep_bullet(benchmark::State& state, Target target, Swept swept) {
  if (!scene().ok) return state.SkipWithError("bunny not found");
  BulletWorld w(target);
  const std::unique_ptr<btConvexShape> cast = bulletSwept(swept);
  std::vector<btTransform> from, to;
  for (const SweepCase& c : scene().sweeps) {
    from.push_back(bt(c.start));
    gq::Transform<double> end = c.start;
    end.p += maxDist() * c.dir;
    to.push_back(bt(end));
  }
  int hits = 0;
  double total = 0;
  Report report;
  for (auto _ : state) {
    hits = 0;
    total = 0;
    report = Report();
    for (int i = 0; i < kSweeps; ++i) {
      btCollisionWorld::ClosestConvexResultCallback cb(from[i].getOrigin(), to[i].getOrigin());
      w.world.convexSweepTest(cast.get(), from[i], to[i], cb);
      if (cb.hasHit()) {
        ++hits;
        total += double(cb.m_closestHitFraction) * maxDist();
        report.index.push_back(i);
        report.distance.push_back(double(cb.m_closestHitFraction) * maxDist());
      }
    }
    benchmark::DoNotOptimize(total);
  }
  state.counters["hits"] = hits;
  state.counters["meanDistance"] = hits ? total / hits : 0.0;
  state.counters["meanGapAtHit"] = meanGapAtHits(target, swept, report);
  state.SetItemsProcessed(state.iterations() * kSweeps);
}

double meanGapAtHits(Target target, Swept swept, const Report& r) {
  if (r.index.empty()) return 0.0;
  const gq::Geometry<double> g1 = gqTarget<double>(target), g0 = gqSwept<double>(swept);
  double sum = 0;
  for (std::size_t k = 0; k < r.index.size(); ++k) {
    const SweepCase& c = scene().sweeps[std::size_t(r.index[k])];
    gq::Transform<double> at = c.start;
    at.p += r.distance[k] * c.dir;
    gq::DistanceResult<double> d;
    (void)gq::distance(d, g0, at, g1, gq::Transform<double>());  // valid input: timed
    sum += d.distance;
  }
  return sum / double(r.index.size());
}

void registerAll() {
  const std::pair<Target, const char*> targets[] = {{Target::Bunny, "bunny"}, {Target::Hull, "hull64"}};
  const std::pair<Swept, const char*> swept[] = {{Swept::Box, "box"}, {Swept::Capsule, "capsule"}, {Swept::Convex, "convex32"}};
  for (const auto& [t, tn] : targets)
    for (const auto& [w, wn] : swept) {
      const std::string name = std::string(wn) + "_vs_" + tn;
      benchmark::RegisterBenchmark(("Sweep/" + name + "/gq_double").c_str(), BM_Sweep_gq<double>, t, w);
      benchmark::RegisterBenchmark(("Sweep/" + name + "/gq_float").c_str(), BM_Sweep_gq<float>, t, w);
      benchmark::RegisterBenchmark(("Sweep/" + name + "/bullet").c_str(), BM_Sweep_bullet, t, w);
    }
}

}  // namespace

int main(int argc, char** argv) {
  registerAll();
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
