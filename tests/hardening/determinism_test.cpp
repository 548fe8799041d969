// Determinism: the same inputs give bitwise-identical outputs on repeated calls in any order, after
// re-cooking the same data, and in a fresh process (different addresses: no result may depend on pointer order or
// on state left behind by earlier queries).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "scenario_digest.h"

namespace gq::hardening {
namespace {

constexpr std::size_t kScenarios = 640;  // 10 per ordered type pair
constexpr std::uint64_t kSeed = 2026;

template <class T> class Determinism : public ::testing::Test {};
TYPED_TEST_SUITE(Determinism, Scalars);

TYPED_TEST(Determinism, RepeatedAndReversedRunsGiveIdenticalBits) {
  using T = TypeParam;
  const std::vector<Geometry<T>> geoms = everyGeometry<T>();
  std::vector<Scenario<T>> list = makeScenarios<T>(kScenarios, kSeed);
  // Per-scenario digests, so a reversed order can be compared entry by entry.
  std::vector<std::uint64_t> forward, again, reversed(list.size());
  for (const auto& s : list) forward.push_back(digestOf<T>(geoms, {s}));
  for (const auto& s : list) again.push_back(digestOf<T>(geoms, {s}));
  for (std::size_t i = list.size(); i-- > 0;) reversed[i] = digestOf<T>(geoms, {list[i]});
  EXPECT_EQ(forward, again);
  EXPECT_EQ(forward, reversed);
}

TYPED_TEST(Determinism, RecookedDataGivesIdenticalBits) {
  using T = TypeParam;
  std::shared_ptr<const ConvexMesh<T>> hull;
  std::shared_ptr<const TriangleMesh<T>> mesh;
  ASSERT_TRUE(cookConvexMesh(octahedronPoints<T>(), hull).ok());
  ASSERT_TRUE(cookTriangleMesh(cubePoints<T>(), cubeTriangles(), mesh).ok());
  std::vector<Geometry<T>> recooked = everyGeometry<T>();
  recooked[4] = ConvexMeshGeometry<T>(hull, recooked[4].template get<ConvexMeshGeometry<T>>().scale);
  recooked[5] = TriangleMeshGeometry<T>(mesh, recooked[5].template get<TriangleMeshGeometry<T>>().scale);
  const auto list = makeScenarios<T>(kScenarios, kSeed);
  EXPECT_EQ(digestOf(everyGeometry<T>(), list), digestOf(recooked, list));
}

// Prints "digest <float> <double>" for the fresh-process comparison below (and checks both are computed).
TEST(DeterminismDigest, PrintsTheWorkloadDigest) {
  const std::uint64_t f = digestOf(everyGeometry<float>(), makeScenarios<float>(kScenarios, kSeed));
  const std::uint64_t d = digestOf(everyGeometry<double>(), makeScenarios<double>(kScenarios, kSeed));
  std::printf("digest %016llx %016llx\n", static_cast<unsigned long long>(f), static_cast<unsigned long long>(d));
  EXPECT_NE(f, d);
}

TEST(DeterminismDigest, FreshProcessGivesIdenticalBits) {
  const std::uint64_t f = digestOf(everyGeometry<float>(), makeScenarios<float>(kScenarios, kSeed));
  const std::uint64_t d = digestOf(everyGeometry<double>(), makeScenarios<double>(kScenarios, kSeed));
  // This program again, running only the printing test.
  std::error_code ec;
  const std::string self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
  ASSERT_FALSE(ec) << ec.message();
  const std::string cmd = "'" + self + "' --gtest_filter=DeterminismDigest.PrintsTheWorkloadDigest 2>/dev/null";
  FILE* child = popen(cmd.c_str(), "r");
  ASSERT_NE(child, nullptr);
  unsigned long long cf = 0, cd = 0;
  bool found = false;
  char line[512];
  while (std::fgets(line, sizeof line, child))
    if (std::sscanf(line, "digest %llx %llx", &cf, &cd) == 2) found = true;
  EXPECT_EQ(pclose(child), 0);
  ASSERT_TRUE(found) << "the child printed no digest";
  EXPECT_EQ(cf, f);
  EXPECT_EQ(cd, d);
}

}  // namespace
}  // namespace gq::hardening
