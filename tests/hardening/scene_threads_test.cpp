// Thread safety of one shared Scene: 8 threads run every const scene query (closest, any and all-hits rays, sweeps,
// overlaps, nearest, overlapping pairs) and single-threaded batches over the same scene at once; each thread's answers
// must equal the single-threaded ones bit for bit. scripts/sanitize runs this under ThreadSanitizer, which reports
// any data race on the scene, its instances' cooked data or the batch code. (Batches on oneTBB's workers are checked
// for determinism in the core suite: Debian's oneTBB is not built with TSan, whose reports from inside it would say
// nothing about gq.)
#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "gq/batch.h"
#include "gq/scene.h"
#include "hardening_fixtures.h"

namespace gq::hardening {
namespace {

constexpr unsigned kThreads = 8;
constexpr int kInstances = 96;
constexpr int kQueries = 64;

template <class T> Transform<T> instancePose(int i) {
  const double a = 0.37 * i;
  return Transform<T>(Vec3<T>(T(2.5 * (i % 6)), T(2.5 * ((i / 6) % 4)), T(2.5 * (i / 24))),
                      Quat<T>(Eigen::AngleAxis<T>(T(a), Vec3<T>(T(std::sin(a)), T(std::cos(a)), T(0.5)).normalized())));
}

// Every geometry type except the plane (an unbounded plane would touch every query), 96 instances on a grid.
template <class T> Scene<T> sharedScene() {
  std::vector<Geometry<T>> geoms = everyGeometry<T>();
  geoms.erase(geoms.begin() + 1);
  Scene<T> scene;
  for (int i = 0; i < kInstances; ++i)
    EXPECT_TRUE(scene.add(InstanceId(1000 + i), geoms[i % geoms.size()], instancePose<T>(i)).ok());
  scene.rebuild();
  return scene;
}

template <class T> struct Query {
  Vec3<T> origin, dir, point;
};

template <class T> std::vector<Query<T>> queries() {
  std::vector<Query<T>> q;
  for (int i = 0; i < kQueries; ++i) {
    const double a = 0.91 * i, b = 0.53 * i;
    const Vec3<T> dir = Vec3<T>(T(std::cos(a) * std::cos(b)), T(std::sin(a) * std::cos(b)), T(std::sin(b))).normalized();
    q.push_back({Vec3<T>(T(6), T(4), T(3)) - dir * T(20), dir, Vec3<T>(T(0.4 * (i % 16)), T(0.3 * (i % 11)), T(0.2 * (i % 9)))});
  }
  return q;
}

// Everything the scene answers for one query, flattened for a bitwise comparison.
template <class T> struct Answers {
  SceneRaycastHit<T> closest{}, any{};
  bool hasClosest = false, hasAny = false, hasSweep = false, hasNearest = false;
  std::vector<SceneRaycastHit<T>> all;
  SceneSweepHit<T> sweep{};
  std::vector<InstanceId> overlapping;
  SceneDistanceResult<T> nearest{};

  bool operator==(const Answers& o) const {
    auto sameRay = [](const SceneRaycastHit<T>& a, const SceneRaycastHit<T>& b) { return a.id == b.id && sameBits(a.hit, b.hit); };
    if (hasClosest != o.hasClosest || hasAny != o.hasAny || hasSweep != o.hasSweep || hasNearest != o.hasNearest)
      return false;
    if (hasClosest && !sameRay(closest, o.closest)) return false;
    if (hasAny && !sameRay(any, o.any)) return false;
    if (hasSweep && !(sweep.id == o.sweep.id && sameBits(sweep.hit, o.sweep.hit))) return false;
    if (hasNearest && !(nearest.id == o.nearest.id && sameBits(nearest.result, o.nearest.result))) return false;
    if (all.size() != o.all.size() || overlapping != o.overlapping) return false;
    for (std::size_t k = 0; k < all.size(); ++k)
      if (!sameRay(all[k], o.all[k])) return false;
    return true;
  }
};

template <class T>
Answers<T> ask(const Scene<T>& scene, const Shape<T>& sphere, const Shape<T>& box, const Query<T>& q) {
  Answers<T> a;
  const T far = T(100);
  EXPECT_TRUE(scene.raycastClosest(q.origin, q.dir, far, a.closest, a.hasClosest).ok());
  EXPECT_TRUE(scene.raycastAny(q.origin, q.dir, far, a.any, a.hasAny).ok());
  SceneRaycastHit<T> hits[8];
  std::uint32_t n = 0;
  EXPECT_TRUE(scene.raycastAll(q.origin, q.dir, far, kDefaultHitFlags | HitFlag::MeshMultiple, 8, hits, n).ok());
  a.all.assign(hits, hits + n);
  EXPECT_TRUE(scene.sweepClosest(q.dir, far, sphere, Transform<T>(q.origin), a.sweep, a.hasSweep).ok());
  EXPECT_TRUE(scene.overlapAll(box, Transform<T>(q.point), a.overlapping).ok());
  EXPECT_TRUE(scene.nearest(sphere, Transform<T>(q.point), std::numeric_limits<T>::infinity(), a.nearest, a.hasNearest).ok());
  return a;
}

template <class T> class SceneThreads : public ::testing::Test {};
TYPED_TEST_SUITE(SceneThreads, Scalars);

TYPED_TEST(SceneThreads, EightThreadsQueryingOneSceneGetTheSingleThreadedBits) {
  using T = TypeParam;
  const Scene<T> scene = sharedScene<T>();
  Shape<T> sphere, box;
  ASSERT_TRUE(Shape<T>::make(SphereGeometry<T>(T(0.3)), sphere).ok());
  ASSERT_TRUE(Shape<T>::make(BoxGeometry<T>(T(0.8), T(0.6), T(0.5)), box).ok());
  const std::vector<Query<T>> list = queries<T>();
  std::vector<Answers<T>> single;
  for (const auto& q : list) single.push_back(ask(scene, sphere, box, q));
  std::vector<ScenePair> pairs;
  ASSERT_TRUE(scene.overlappingPairs(pairs).ok());
  ASSERT_FALSE(pairs.empty());
  std::size_t hitRays = 0;
  for (const auto& a : single) hitRays += a.hasClosest ? 1 : 0;
  ASSERT_GT(hitRays, list.size() / 4) << "the rays must reach the instances for the test to mean something";

  std::vector<std::vector<Answers<T>>> perThread(kThreads, std::vector<Answers<T>>(list.size()));
  std::vector<std::vector<ScenePair>> pairsPerThread(kThreads);
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      const std::size_t shift = t * list.size() / kThreads;  // different queries at the same moment
      for (std::size_t k = 0; k < list.size(); ++k) {
        const std::size_t i = (k + shift) % list.size();
        perThread[t][i] = ask(scene, sphere, box, list[i]);
      }
      EXPECT_TRUE(scene.overlappingPairs(pairsPerThread[t]).ok());
    });
  for (auto& th : threads) th.join();
  for (unsigned t = 0; t < kThreads; ++t) {
    for (std::size_t i = 0; i < list.size(); ++i) EXPECT_TRUE(perThread[t][i] == single[i]) << "thread " << t << " query " << i;
    EXPECT_EQ(pairsPerThread[t], pairs) << "thread " << t;
  }
}

TYPED_TEST(SceneThreads, EightThreadsRunningBatchesOnOneSceneGetTheSingleThreadedBits) {
  using T = TypeParam;
  const Scene<T> scene = sharedScene<T>();
  const std::vector<Query<T>> list = queries<T>();
  std::vector<Vec3<T>> origins, dirs;
  for (const auto& q : list) {
    origins.push_back(q.origin);
    dirs.push_back(q.dir);
  }
  RayBatch<T> rays;
  rays.origins = StridedArray<Vec3<T>>(origins.data(), origins.size());
  rays.unitDirs = StridedArray<Vec3<T>>(dirs.data(), dirs.size());
  rays.maxDist = T(100);
  BatchSettings callingThread;
  callingThread.threads = 1;
  std::vector<SceneRaycastHit<T>> single(list.size());
  std::vector<std::uint8_t> singleHas(list.size(), 0);
  ASSERT_TRUE(raycastBatch(rays, scene, single.data(), singleHas.data(), nullptr, callingThread).ok());

  std::vector<std::vector<SceneRaycastHit<T>>> hits(kThreads, std::vector<SceneRaycastHit<T>>(list.size()));
  std::vector<std::vector<std::uint8_t>> has(kThreads, std::vector<std::uint8_t>(list.size(), 0));
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      EXPECT_TRUE(raycastBatch(rays, scene, hits[t].data(), has[t].data(), nullptr, callingThread).ok());
    });
  for (auto& th : threads) th.join();
  for (unsigned t = 0; t < kThreads; ++t) {
    EXPECT_EQ(has[t], singleHas) << "thread " << t;
    for (std::size_t i = 0; i < list.size(); ++i)
      if (singleHas[i]) EXPECT_TRUE(hits[t][i].id == single[i].id && sameBits(hits[t][i].hit, single[i].hit)) << i;
  }
}

}  // namespace
}  // namespace gq::hardening
