// gq::fcl's full results equal FCL 0.7's in double on seeded random poses for every pair family, except the listed
// deliberate differences (full_results.h; tests/fcl/deliberate_differences.txt).
#include "full_results.h"

namespace gq::fcltest {
namespace {

constexpr int kPoses = 200;

std::uint32_t seedOf(const Pair& p) { return 5000u + 100u * std::uint32_t(p.first) + std::uint32_t(p.second); }

class FclFullResults : public ::testing::TestWithParam<Pair> {};

TEST_P(FclFullResults, CollideBooleansEqualFclsOutsideTheTouchBand) {
  FullResultCase<double> c = makeFullResultCase<double>(GetParam(), seedOf(GetParam()));
  checkCollideBooleans(c, kPoses, seedOf(GetParam()) + 1);
  printSummary(c, "booleans");
  EXPECT_EQ(c.listed.count("unlisted"), 0u);
}

TEST_P(FclFullResults, ContactsEqualFcls) {
  FullResultCase<double> c = makeFullResultCase<double>(GetParam(), seedOf(GetParam()));
  checkContacts(c, kPoses, seedOf(GetParam()) + 2);
  printSummary(c, "contacts");
  EXPECT_EQ(c.listed.count("unlisted"), 0u);
}

TEST_P(FclFullResults, DistancesAndNearestPointsEqualFcls) {
  FullResultCase<double> c = makeFullResultCase<double>(GetParam(), seedOf(GetParam()));
  checkDistances(c, kPoses, seedOf(GetParam()) + 3, false);
  printSummary(c, "distances");
  EXPECT_EQ(c.listed.count("unlisted"), 0u);
}

TEST_P(FclFullResults, SignedDistancesEqualFcls) {
  FullResultCase<double> c = makeFullResultCase<double>(GetParam(), seedOf(GetParam()));
  checkDistances(c, kPoses, seedOf(GetParam()) + 4, true);
  printSummary(c, "signed distances");
  EXPECT_EQ(c.listed.count("unlisted"), 0u);
}

INSTANTIATE_TEST_SUITE_P(AllFamilies, FclFullResults, ::testing::ValuesIn(fullResultPairs()), PairName());

}  // namespace
}  // namespace gq::fcltest
