// gq::fcl's full results equal FCL 0.7's in float on seeded random poses for every pair family, except the listed
// deliberate differences (full_results.h; tests/fcl/deliberate_differences.txt).
#include "full_results.h"

namespace gq::fcltest {
namespace {

constexpr int kPoses = 200;

std::uint32_t seedOf(const Pair& p) { return 7000u + 100u * std::uint32_t(p.first) + std::uint32_t(p.second); }

class FclFullResultsFloat : public ::testing::TestWithParam<Pair> {};

TEST_P(FclFullResultsFloat, CollideBooleansEqualFclsOutsideTheTouchBand) {
  FullResultCase<float> c = makeFullResultCase<float>(GetParam(), seedOf(GetParam()));
  checkCollideBooleans(c, kPoses, seedOf(GetParam()) + 1);
  printSummary(c, "booleans");
  EXPECT_EQ(c.listed.count("unlisted"), 0u);
}

TEST_P(FclFullResultsFloat, ContactsEqualFcls) {
  FullResultCase<float> c = makeFullResultCase<float>(GetParam(), seedOf(GetParam()));
  checkContacts(c, kPoses, seedOf(GetParam()) + 2);
  printSummary(c, "contacts");
  EXPECT_EQ(c.listed.count("unlisted"), 0u);
}

TEST_P(FclFullResultsFloat, DistancesAndNearestPointsEqualFcls) {
  FullResultCase<float> c = makeFullResultCase<float>(GetParam(), seedOf(GetParam()));
  checkDistances(c, kPoses, seedOf(GetParam()) + 3, false);
  printSummary(c, "distances");
  EXPECT_EQ(c.listed.count("unlisted"), 0u);
}

TEST_P(FclFullResultsFloat, SignedDistancesEqualFcls) {
  FullResultCase<float> c = makeFullResultCase<float>(GetParam(), seedOf(GetParam()));
  checkDistances(c, kPoses, seedOf(GetParam()) + 4, true);
  printSummary(c, "signed distances");
  EXPECT_EQ(c.listed.count("unlisted"), 0u);
}

INSTANTIATE_TEST_SUITE_P(AllFamilies, FclFullResultsFloat, ::testing::ValuesIn(fullResultPairs()), PairName());

}  // namespace
}  // namespace gq::fcltest
