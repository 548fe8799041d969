// gq::fcl from many threads on shared FCL objects: the cooked-geometry cache and the support shapes it keeps for
// each Convex are shared between threads, and every call must answer as it does alone (GJK writes its climbing hints
// into the shapes it runs on, so each call runs on its own copies).
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>
#include <random>
#include <thread>
#include <vector>

#include "fcl_scenes.h"
#include "gq/fcl/fcl.h"

namespace {

using ::fcl::Vector3d;
constexpr unsigned kThreads = 8;

// One call's answers: collide's count and distance's value, compared bit for bit.
struct Answers {
  std::size_t contacts = 0;
  double distance = 0;
  bool operator==(const Answers& o) const {
    return contacts == o.contacts && std::memcmp(&distance, &o.distance, sizeof(double)) == 0;
  }
};

Answers answersAt(const ::fcl::Convexd& a, const ::fcl::Convexd& b, const ::fcl::Transform3d& pose) {
  Answers out;
  ::fcl::CollisionResultd c;
  out.contacts = gq::fcl::collide<double>(&a, ::fcl::Transform3d::Identity(), &b, pose, ::fcl::CollisionRequestd(), c);
  ::fcl::DistanceResultd d;
  out.distance =
      gq::fcl::distance<double>(&a, ::fcl::Transform3d::Identity(), &b, pose, ::fcl::DistanceRequestd(true), d);
  return out;
}

// A 6-point hull (scanned: its climbing hint is read) against a 30-point one (climbed from its start table), at
// poses around their balls' contact distances, where the balls decide nothing and GJK runs. The threads start
// together, at different poses, on geometry none of them has cooked yet.
TEST(FclThreads, EightThreadsOnSharedConvexGetTheSingleThreadedAnswers) {
  std::mt19937 rng(31);
  std::vector<Vector3d> smallVertices, largeVertices;
  std::vector<std::vector<int>> smallFaces, largeFaces;
  gq::fcltest::randomHull(rng, 6, smallVertices, smallFaces);
  gq::fcltest::randomHull(rng, 30, largeVertices, largeFaces);
  const auto small = gq::fcltest::convexGeometry(smallVertices, smallFaces);
  const auto large = gq::fcltest::convexGeometry(largeVertices, largeFaces);
  std::vector<::fcl::Transform3d> poses;
  for (int i = 0; i < 300; ++i) {
    ::fcl::Transform3d pose = ::fcl::Transform3d::Identity();
    const double a = 0.037 * i;
    pose.linear() = Eigen::AngleAxisd(a, Vector3d(0.3, 0.5, 0.81).normalized()).toRotationMatrix();
    pose.translation() = (0.9 + 0.6 * std::sin(1.3 * a)) * Vector3d(std::cos(a), std::sin(1.7 * a), 0.5).normalized();
    poses.push_back(pose);
  }
  std::vector<std::vector<Answers>> perThread(kThreads, std::vector<Answers>(poses.size()));
  std::atomic<unsigned> ready{0};
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      ++ready;
      while (ready.load() < kThreads) std::this_thread::yield();
      const std::size_t shift = t * poses.size() / kThreads;
      for (std::size_t k = 0; k < poses.size(); ++k) {
        const std::size_t i = (k + shift) % poses.size();
        perThread[t][i] = answersAt(*small, *large, poses[i]);
      }
    });
  for (auto& th : threads) th.join();
  int hits = 0;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Answers alone = answersAt(*small, *large, poses[i]);
    hits += alone.contacts > 0;
    for (unsigned t = 0; t < kThreads; ++t) ASSERT_TRUE(perThread[t][i] == alone) << "thread " << t << " pose " << i;
  }
  // Both answers occur: the poses straddle contact.
  EXPECT_GT(hits, 30);
  EXPECT_LT(hits, 270);
}

}  // namespace
