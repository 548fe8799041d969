// Thread safety and single- vs multi-thread determinism: 8 threads share the same cooked
// hull, mesh and heightfield (and the same Geometry objects) and run raycasts, sweeps, overlaps, penetration and
// distances at once; each thread's output digest must equal the single-threaded one. scripts/sanitize runs this
// under ThreadSanitizer, which reports any data race on the shared data.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>
#include <thread>

#include "scenario_digest.h"

namespace gq::hardening {
namespace {

constexpr unsigned kThreads = 8;

template <class T> class SharedDataThreads : public ::testing::Test {};
TYPED_TEST_SUITE(SharedDataThreads, Scalars);

TYPED_TEST(SharedDataThreads, EightThreadsOnSharedCookedDataMatchTheSingleThreadedBits) {
  using T = TypeParam;
  const std::vector<Geometry<T>> geoms = everyGeometry<T>();  // one set of instances, shared by every thread
  const std::vector<Scenario<T>> list = makeScenarios<T>(320, 77);
  std::vector<std::uint64_t> single;
  for (const auto& s : list) single.push_back(digestOf<T>(geoms, {s}));
  std::vector<std::vector<std::uint64_t>> perThread(kThreads, std::vector<std::uint64_t>(list.size(), 0));
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      // Each thread starts at a different scenario, so different pairs run at the same moment.
      const std::size_t shift = t * list.size() / kThreads;
      for (std::size_t k = 0; k < list.size(); ++k) {
        const std::size_t i = (k + shift) % list.size();
        perThread[t][i] = digestOf<T>(geoms, {list[i]});
      }
    });
  for (auto& th : threads) th.join();
  for (unsigned t = 0; t < kThreads; ++t) EXPECT_EQ(perThread[t], single) << "thread " << t;
}

// The hull above has 6 vertices and gets no GJK support start table (built lazily, per mesh, above 8 vertices), and
// the single-threaded pass runs first. Here a fresh 64-vertex hull's first GJK queries come from 8 threads at once,
// so the lazy table build itself is raced (under TSan in scripts/sanitize); every thread must match the
// single-threaded answers computed afterwards.
TYPED_TEST(SharedDataThreads, EightThreadsRacingToBuildAHullsSupportTableGetTheSingleThreadedBits) {
  using T = TypeParam;
  std::vector<Vec3<T>> points;  // Fibonacci sphere: every point a hull vertex
  for (int i = 0; i < 64; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / 64.0, r = std::sqrt(1.0 - z * z), phi = 2.399963229728653 * i;
    points.emplace_back(T(r * std::cos(phi)), T(r * std::sin(phi)), T(z));
  }
  std::shared_ptr<const ConvexMesh<T>> hull;
  ASSERT_TRUE(cookConvexMesh(points, hull).ok());
  ASSERT_GT(hull->vertices.size(), 8u);
  const Geometry<T> convex = ConvexMeshGeometry<T>(hull);
  const Geometry<T> box = BoxGeometry<T>(T(0.4), T(0.3), T(0.2));
  constexpr int kPoses = 200;
  const auto poseOf = [](int i) {
    const T a = T(0.031) * T(i);
    return Transform<T>(Vec3<T>(T(1.2) * std::cos(a), T(0.9) * std::sin(T(1.7) * a), T(0.6) * std::sin(a)),
                        Quat<T>(Eigen::AngleAxis<T>(a, Vec3<T>(T(0.3), T(0.5), T(0.81)).normalized())));
  };
  const auto run = [&](int i, DistanceResult<T>& d, bool& hit) {
    EXPECT_TRUE(distance(d, convex, Transform<T>(), box, poseOf(i)).ok());
    EXPECT_TRUE(overlap(convex, Transform<T>(), box, poseOf(i), hit).ok());
  };
  std::vector<std::vector<DistanceResult<T>>> distances(kThreads, std::vector<DistanceResult<T>>(kPoses));
  std::vector<std::vector<char>> hits(kThreads, std::vector<char>(kPoses, 0));
  std::atomic<unsigned> ready{0};
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      ++ready;
      while (ready.load() < kThreads) std::this_thread::yield();  // first queries as close together as possible
      for (int i = 0; i < kPoses; ++i) {
        bool hit = false;
        run(i, distances[t][std::size_t(i)], hit);
        hits[t][std::size_t(i)] = hit;
      }
    });
  for (auto& th : threads) th.join();
  int overlapping = 0;
  for (int i = 0; i < kPoses; ++i) {
    DistanceResult<T> d;
    bool hit = false;
    run(i, d, hit);
    overlapping += hit;
    for (unsigned t = 0; t < kThreads; ++t) {
      EXPECT_TRUE(sameBits(distances[t][std::size_t(i)], d)) << "thread " << t << " pose " << i;
      EXPECT_EQ(bool(hits[t][std::size_t(i)]), hit) << "thread " << t << " pose " << i;
    }
  }
  EXPECT_GT(overlapping, 0);
  EXPECT_LT(overlapping, kPoses);
}

}  // namespace
}  // namespace gq::hardening
