// The allowed-collision matrix: adjacent links across fixed joints (MoveIt), same link, SRDF pairs.
#include <gtest/gtest.h>

#include "robot_paths.h"

namespace gq::urdf::test {
namespace {

// On the real robots of the shared data folder (skipped when it does not hold them).
template <class T> class AllowedCollisionsData : public RobotDataTest {};
TYPED_TEST_SUITE(AllowedCollisionsData, Scalars);

template <class T> std::shared_ptr<RobotModel<T>> pandaWithoutSrdf() {
  auto m = std::make_shared<RobotModel<T>>();
  const Status s = loadRobot(robotFile(kPandaPrimitives.urdf), "", testOptions(Representation::Hull), *m);
  if (!s.ok()) {
    ADD_FAILURE() << s.toString();
    return nullptr;
  }
  return m;
}

template <class T> bool allowed(const RobotModel<T>& m, const char* a, const char* b) {
  return m.isAllowed(std::uint32_t(m.findLink(a)), std::uint32_t(m.findLink(b)));
}

TYPED_TEST(AllowedCollisionsData, LinksJoinedByAMovingJointAreAdjacent) {
  const auto m = pandaWithoutSrdf<TypeParam>();
  ASSERT_TRUE(m);
  EXPECT_TRUE(allowed(*m, "panda_link3", "panda_link4"));
  EXPECT_EQ(m->allowedReason[std::size_t(m->findLink("panda_link3")) * m->links.size() + std::size_t(m->findLink("panda_link4"))],
            "adjacent");
  EXPECT_FALSE(allowed(*m, "panda_link3", "panda_link5"));  // two joints apart: checked
}

TYPED_TEST(AllowedCollisionsData, AdjacencyCrossesFixedJointsToTheNextMovingLink) {
  // panda_link7 -fixed- panda_link8 (no shapes) -fixed- panda_hand form one rigid body, whose moving neighbours
  // are panda_link6 (joint7) and the fingers (prismatic): all of them are adjacent to every link of the body.
  const auto m = pandaWithoutSrdf<TypeParam>();
  ASSERT_TRUE(m);
  EXPECT_TRUE(allowed(*m, "panda_link7", "panda_hand"));
  EXPECT_TRUE(allowed(*m, "panda_hand", "panda_leftfinger"));
  EXPECT_TRUE(allowed(*m, "panda_link6", "panda_hand"));
  EXPECT_TRUE(allowed(*m, "panda_link7", "panda_leftfinger"));
  EXPECT_FALSE(allowed(*m, "panda_link5", "panda_hand"));
  EXPECT_FALSE(allowed(*m, "panda_link6", "panda_leftfinger"));
  EXPECT_FALSE(allowed(*m, "panda_leftfinger", "panda_rightfinger"));  // siblings, not parent-child
}

TYPED_TEST(AllowedCollisionsData, ShapesOfTheSameLinkAreNeverChecked) {
  const auto m = pandaWithoutSrdf<TypeParam>();
  ASSERT_TRUE(m);
  for (std::uint32_t i = 0; i < m->links.size(); ++i) EXPECT_TRUE(m->isAllowed(i, i));
}

TYPED_TEST(AllowedCollisionsData, SrdfDisabledPairsAreAllowed) {
  const auto m = loadCached<TypeParam>(kPandaPrimitives, Representation::Hull);
  ASSERT_TRUE(m);
  EXPECT_TRUE(allowed(*m, "panda_link0", "panda_link4"));  // reason="Never" in panda.srdf
  EXPECT_TRUE(allowed(*m, "panda_leftfinger", "panda_rightfinger"));
  const auto ur5 = loadCached<TypeParam>(kUr5, Representation::Hull);
  ASSERT_TRUE(ur5);
  EXPECT_TRUE(allowed(*ur5, "forearm_link", "wrist_3_link"));
  EXPECT_FALSE(allowed(*ur5, "base_link", "forearm_link"));
}

TYPED_TEST(AllowedCollisionsData, HomeIsTheSrdfGroupStateOrZeroClampedIntoLimits) {
  using T = TypeParam;
  const auto panda = loadCached<T>(kPanda, Representation::Hull);
  ASSERT_TRUE(panda);
  EXPECT_EQ(panda->homeSource, "SRDF group_state 'default'");
  EXPECT_NEAR(panda->home[3], T(-2.35619), T(1e-6));  // panda_joint4
  const auto ur5 = loadCached<T>(kUr5, Representation::Hull);
  ASSERT_TRUE(ur5);
  for (T v : ur5->home) EXPECT_EQ(v, T(0));
}

}  // namespace
}  // namespace gq::urdf::test
