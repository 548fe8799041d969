// neverColliding: the sampled "never in collision" pairs, and the SRDF written from them.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "robot_paths.h"

namespace gq::urdf::test {
namespace {

// On the real robots of the shared data folder (skipped when it does not hold them).
template <class T> class NeverCollidingData : public RobotDataTest {};
TYPED_TEST_SUITE(NeverCollidingData, Scalars);

TYPED_TEST(NeverCollidingData, ListsExactlyThePairsWithoutContactInTheSamples) {
  using T = TypeParam;
  const auto m = loadCached<T>(kUr5, Representation::Hull);
  ASSERT_TRUE(m);
  NeverCollidingResult r;
  ASSERT_TRUE(neverColliding<T>(m, 2000, 3, r).ok());
  const std::size_t n = m->links.size();
  for (const auto& p : r.never) EXPECT_EQ(r.contactCount[p.a * n + p.b], 0u);
  // Every checked pair with contacts is absent from the list; some pairs do collide on a UR5.
  std::size_t touched = 0;
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      if (r.contactCount[a * n + b] > 0) {
        ++touched;
        EXPECT_EQ(std::find(r.never.begin(), r.never.end(), LinkPair{a, b}), r.never.end());
      }
  EXPECT_GT(touched, 0u);
  // Same seed, same answer.
  NeverCollidingResult again;
  ASSERT_TRUE(neverColliding<T>(m, 2000, 3, again).ok());
  EXPECT_EQ(again.never, r.never);
}

TYPED_TEST(NeverCollidingData, WrittenSrdfReloadsAndDisablesThePairs) {
  using T = TypeParam;
  const auto m = loadCached<T>(kUr5, Representation::Hull);
  ASSERT_TRUE(m);
  NeverCollidingResult r;
  ASSERT_TRUE(neverColliding<T>(m, 1000, 11, r).ok());
  const std::string srdf = writeSrdfDisableCollisions(*m, r.never);
  EXPECT_NE(srdf.find("reason=\"Adjacent\""), std::string::npos);
  std::ifstream in(robotFile(kUr5.urdf));
  std::stringstream urdf;
  urdf << in.rdbuf();
  RobotModel<T> reloaded;
  const Status s = loadRobotFromStrings(urdf.str(), srdf, "/", testOptions(Representation::Hull), reloaded);
  ASSERT_TRUE(s.ok()) << s.toString();
  for (const auto& p : r.never) EXPECT_TRUE(reloaded.isAllowed(p.a, p.b)) << m->links[p.a].name << " " << m->links[p.b].name;
}

TYPED_TEST(NeverCollidingData, ZeroSamplesIsInvalid) {
  NeverCollidingResult r;
  const auto m = loadCached<TypeParam>(kUr5, Representation::Hull);
  ASSERT_TRUE(m);
  EXPECT_EQ(neverColliding<TypeParam>(m, 0, 1, r).code, StatusCode::InvalidArgument);
}

}  // namespace
}  // namespace gq::urdf::test
