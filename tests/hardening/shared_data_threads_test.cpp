// Thread safety (issue 9, item 2) and single- vs multi-thread determinism (item 5): 8 threads share the same cooked
// hull, mesh and heightfield (and the same Geometry objects) and run raycasts, sweeps, overlaps, penetration and
// distances at once; each thread's output digest must equal the single-threaded one. scripts/sanitize runs this
// under ThreadSanitizer, which reports any data race on the shared data.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace gq::hardening
