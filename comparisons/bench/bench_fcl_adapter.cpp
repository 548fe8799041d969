// gq::fcl against FCL 0.7 on the same ::fcl objects, side by side in one run: collide (boolean, FCL's default
// request) and distance (nearest points) per pair family over 256 seeded random poses, and broadphase self
// collision of 1000 objects (DynamicAABBTreeCollisionManager, narrow phase in the callback).
#include <cstdlib>
#include <benchmark/benchmark.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

#include "gq/cooking.h"
#include "gq/fcl/fcl.h"

namespace {

constexpr int kPoses = 256;
using Geom = std::shared_ptr<::fcl::CollisionGeometryd>;

::fcl::Transform3d randomPose(std::mt19937& rng, double extent) {
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> u(-extent, extent);
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  ::fcl::Transform3d tf = ::fcl::Transform3d::Identity();
  tf.linear() = q.normalized().toRotationMatrix();
  tf.translation() = ::fcl::Vector3d(u(rng), u(rng), u(rng));
  return tf;
}

// An FCL Convex from the hull of `count` random points on a unit-ish ellipsoid (faces from gq's cooked polygons).
Geom convexHull(int count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0, 1);
  std::vector<gq::Vec3<double>> points;
  for (int i = 0; i < count; ++i) points.push_back(gq::Vec3<double>(0.6 * g(rng), 0.5 * g(rng), 0.4 * g(rng)).normalized() * 0.6);
  std::shared_ptr<const gq::ConvexMesh<double>> hull;
  if (!gq::cookConvexMesh(points, hull).ok()) std::abort();  // random points on an ellipsoid: a valid hull
  auto vertices = std::make_shared<std::vector<::fcl::Vector3d>>(hull->vertices.begin(), hull->vertices.end());
  auto faces = std::make_shared<std::vector<int>>();
  for (const auto& p : hull->polygons) {
    faces->push_back(int(p.indexCount));
    for (std::uint32_t k = 0; k < p.indexCount; ++k) faces->push_back(int(hull->polygonVertices[p.indexBase + k]));
  }
  return std::make_shared<::fcl::Convexd>(vertices, int(hull->polygons.size()), faces);
}

Geom sphereMesh(double r, int rings, int segments) {
  auto model = std::make_shared<::fcl::BVHModel<::fcl::OBBRSSd>>();
  const auto at = [&](int i, int j) {
    const double th = M_PI * i / rings, ph = 2 * M_PI * j / segments;
    return ::fcl::Vector3d(r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th));
  };
  model->beginModel();
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      model->addTriangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
      model->addTriangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
    }
  model->endModel();
  return model;
}

struct Family {
  Geom a, b;
};

Family family(int id) {
  switch (id) {
    case 0: return {std::make_shared<::fcl::Sphered>(0.5), std::make_shared<::fcl::Sphered>(0.4)};
    case 1: return {std::make_shared<::fcl::Boxd>(1.0, 0.6, 0.8), std::make_shared<::fcl::Boxd>(0.7, 0.9, 0.5)};
    case 2: return {std::make_shared<::fcl::Capsuled>(0.3, 1.0), std::make_shared<::fcl::Capsuled>(0.25, 0.8)};
    case 3: return {std::make_shared<::fcl::Sphered>(0.5), std::make_shared<::fcl::Boxd>(1.0, 0.6, 0.8)};
    case 4: return {std::make_shared<::fcl::Capsuled>(0.3, 1.0), std::make_shared<::fcl::Boxd>(1.0, 0.6, 0.8)};
    case 5: return {std::make_shared<::fcl::Cylinderd>(0.4, 1.0), std::make_shared<::fcl::Boxd>(1.0, 0.6, 0.8)};
    case 6: return {convexHull(30, 1), convexHull(30, 2)};
    case 7: return {convexHull(100, 3), convexHull(100, 4)};
    case 8: return {sphereMesh(0.8, 16, 24), std::make_shared<::fcl::Sphered>(0.3)};
    case 9: return {sphereMesh(0.8, 16, 24), convexHull(30, 5)};
    default: return {std::make_shared<::fcl::Sphered>(0.5), std::make_shared<::fcl::Cylinderd>(0.4, 1.0)};
  }
}
const char* familyName(int id) {
  static const char* names[] = {"sphere_sphere", "box_box",    "capsule_capsule", "sphere_box",   "capsule_box",
                                "cylinder_box",  "convex30",   "convex100",       "mesh_sphere",  "mesh_convex30",
                                "sphere_cylinder"};
  return names[id];
}
constexpr int kFamilies = 11;

std::vector<::fcl::Transform3d> poses(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<::fcl::Transform3d> out;
  for (int i = 0; i < kPoses; ++i) out.push_back(randomPose(rng, 0.9));
  return out;
}

// Each query once over the timed poses before timing: gq::fcl converts (cooks) a Convex or BVHModel on its first
// use and builds a hull's GJK start table on the first GJK query that reaches it, as FCL builds its own data in the
// constructors; both belong outside the per-call cost. Out of line so that callgrind's per-call counts of the loops
// exclude it.
[[gnu::noinline]] void warmUp(const Family& f, const std::vector<::fcl::Transform3d>& pa,
                              const std::vector<::fcl::Transform3d>& pb) {
  for (std::size_t k = 0; k < pa.size() && k < pb.size(); ++k) {
    ::fcl::CollisionResultd c;
    gq::fcl::collide(f.a.get(), pa[k], f.b.get(), pb[k], ::fcl::CollisionRequestd(), c);
    ::fcl::DistanceResultd d;
    gq::fcl::distance(f.a.get(), pa[k], f.b.get(), pb[k], ::fcl::DistanceRequestd(true), d);
  }
}

template <bool Gq> void BM_Collide(benchmark::State& state) {
  const Family f = family(int(state.range(0)));
  const auto pa = poses(1), pb = poses(2);
  const ::fcl::CollisionRequestd request;
  warmUp(f, pa, pb);
  std::size_t i = 0, hits = 0;
  for (auto _ : state) {
    ::fcl::CollisionResultd result;
    const std::size_t k = i++ % kPoses;
    hits += Gq ? gq::fcl::collide(f.a.get(), pa[k], f.b.get(), pb[k], request, result)
               : ::fcl::collide(f.a.get(), pa[k], f.b.get(), pb[k], request, result);
  }
  benchmark::DoNotOptimize(hits);
  state.SetLabel(familyName(int(state.range(0))));
}

template <bool Gq> void BM_Distance(benchmark::State& state) {
  const Family f = family(int(state.range(0)));
  const auto pa = poses(3), pb = poses(4);
  const ::fcl::DistanceRequestd request(true);
  warmUp(f, pa, pb);
  std::size_t i = 0;
  double sum = 0;
  for (auto _ : state) {
    ::fcl::DistanceResultd result;
    const std::size_t k = i++ % kPoses;
    sum += Gq ? gq::fcl::distance(f.a.get(), pa[k], f.b.get(), pb[k], request, result)
              : ::fcl::distance(f.a.get(), pa[k], f.b.get(), pb[k], request, result);
  }
  benchmark::DoNotOptimize(sum);
  state.SetLabel(familyName(int(state.range(0))));
}

// MoveIt's pattern: the result pre-seeded with the distance to beat (its current minimum, here 0.05), so a pair
// farther than that changes nothing and needs no exact answer (FCL prunes its BVH traversal with it).
constexpr double kSeededMinDistance = 0.05;
template <bool Gq> void BM_DistanceSeeded(benchmark::State& state) {
  const Family f = family(int(state.range(0)));
  const auto pa = poses(3), pb = poses(4);
  const ::fcl::DistanceRequestd request(true);
  warmUp(f, pa, pb);
  std::size_t i = 0;
  double sum = 0;
  for (auto _ : state) {
    ::fcl::DistanceResultd result;
    result.min_distance = kSeededMinDistance;
    const std::size_t k = i++ % kPoses;
    sum += Gq ? gq::fcl::distance(f.a.get(), pa[k], f.b.get(), pb[k], request, result)
              : ::fcl::distance(f.a.get(), pa[k], f.b.get(), pb[k], request, result);
  }
  benchmark::DoNotOptimize(sum);
  state.SetLabel(familyName(int(state.range(0))));
}

// 1000 mixed objects (sphere, box, capsule, cylinder in turn), anywhere in [-6, 6]^3 or, sparse, within 0.1 of the
// nodes of a 10 x 10 x 10 grid of spacing 1.6 (none touch), with random orientations.
struct Scene {
  std::vector<std::unique_ptr<::fcl::CollisionObjectd>> objects;
  std::vector<::fcl::CollisionObjectd*> pointers;
  explicit Scene(bool sparse = false) {
    std::mt19937 rng(sparse ? 43 : 42);
    std::uniform_real_distribution<double> u(0.15, 0.35);
    for (int i = 0; i < 1000; ++i) {
      Geom g;
      switch (i % 4) {
        case 0: g = std::make_shared<::fcl::Sphered>(u(rng)); break;
        case 1: g = std::make_shared<::fcl::Boxd>(2 * u(rng), 2 * u(rng), 2 * u(rng)); break;
        case 2: g = std::make_shared<::fcl::Capsuled>(u(rng), 2 * u(rng)); break;
        default: g = std::make_shared<::fcl::Cylinderd>(u(rng), 2 * u(rng));
      }
      ::fcl::Transform3d tf = randomPose(rng, sparse ? 0.1 : 6.0);
      if (sparse) tf.translation() += 1.6 * ::fcl::Vector3d(i % 10, (i / 10) % 10, i / 100);
      objects.push_back(std::make_unique<::fcl::CollisionObjectd>(g, tf));
      pointers.push_back(objects.back().get());
    }
  }
};

template <bool Gq> bool countCollision(::fcl::CollisionObjectd* a, ::fcl::CollisionObjectd* b, void* data) {
  ::fcl::CollisionRequestd request;
  ::fcl::CollisionResultd result;
  *static_cast<std::size_t*>(data) += Gq ? gq::fcl::collide(a, b, request, result) : ::fcl::collide(a, b, request, result);
  return false;
}

// gq's or FCL's dynamic AABB tree manager over the scene's objects, set up.
template <bool Gq> std::unique_ptr<::fcl::BroadPhaseCollisionManagerd> setUpManager(Scene& scene) {
  std::unique_ptr<::fcl::BroadPhaseCollisionManagerd> manager;
  if (Gq) manager = std::make_unique<gq::fcl::DynamicAABBTreeCollisionManagerd>();
  else manager = std::make_unique<::fcl::DynamicAABBTreeCollisionManagerd>();
  manager->registerObjects(scene.pointers);
  manager->setup();
  return manager;
}

template <bool Gq> void BM_BroadphaseSelfCollide(benchmark::State& state) {
  Scene scene;
  const auto manager = setUpManager<Gq>(scene);
  std::size_t pairs = 0;
  for (auto _ : state) {
    pairs = 0;
    manager->collide(&pairs, countCollision<Gq>);
  }
  state.SetLabel("colliding pairs " + std::to_string(pairs));
}

// Self distance on the sparse scene, each library's manager with its DefaultDistanceFunction (the running minimum
// prunes both the tree and, through the pre-seeded result, the narrow phase).
template <bool Gq> void BM_BroadphaseSelfDistance(benchmark::State& state) {
  Scene scene(true);
  const auto manager = setUpManager<Gq>(scene);
  double minimum = 0;
  for (auto _ : state) {
    ::fcl::DefaultDistanceData<double> data;
    data.request.enable_nearest_points = true;
    manager->distance(&data, Gq ? gq::fcl::DefaultDistanceFunction<double> : ::fcl::DefaultDistanceFunction<double>);
    minimum = data.result.min_distance;
  }
  state.SetLabel("min distance " + std::to_string(minimum));
}

// The broadphase alone: the callback only counts candidate pairs (tree quality and traversal, no narrow phase).
bool countCandidate(::fcl::CollisionObjectd*, ::fcl::CollisionObjectd*, void* data) {
  ++*static_cast<std::size_t*>(data);
  return false;
}

template <bool Gq> void BM_BroadphaseCandidates(benchmark::State& state) {
  Scene scene;
  const auto manager = setUpManager<Gq>(scene);
  std::size_t candidates = 0;
  for (auto _ : state) {
    candidates = 0;
    manager->collide(&candidates, countCandidate);
  }
  state.SetLabel("candidate pairs " + std::to_string(candidates));
}

void families(benchmark::internal::Benchmark* b) {
  for (int i = 0; i < kFamilies; ++i) b->Arg(i);
}

BENCHMARK(BM_Collide<false>)->Name("collide/fcl")->Apply(families);
BENCHMARK(BM_Collide<true>)->Name("collide/gq_fcl")->Apply(families);
BENCHMARK(BM_Distance<false>)->Name("distance/fcl")->Apply(families);
BENCHMARK(BM_Distance<true>)->Name("distance/gq_fcl")->Apply(families);
// The pairs whose answer comes from a search (GJK, BVH traversal): convex30, convex100, mesh_sphere, mesh_convex30.
void searchedFamilies(benchmark::internal::Benchmark* b) {
  for (int i = 6; i <= 9; ++i) b->Arg(i);
}
BENCHMARK(BM_DistanceSeeded<false>)->Name("distance_seeded/fcl")->Apply(searchedFamilies);
BENCHMARK(BM_DistanceSeeded<true>)->Name("distance_seeded/gq_fcl")->Apply(searchedFamilies);
BENCHMARK(BM_BroadphaseSelfCollide<false>)->Name("broadphase_self_1000/fcl")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BroadphaseSelfCollide<true>)->Name("broadphase_self_1000/gq_fcl")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BroadphaseSelfDistance<false>)->Name("broadphase_self_distance_1000/fcl")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BroadphaseSelfDistance<true>)->Name("broadphase_self_distance_1000/gq_fcl")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BroadphaseCandidates<false>)->Name("broadphase_candidates_1000/fcl")->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_BroadphaseCandidates<true>)->Name("broadphase_candidates_1000/gq_fcl")->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
