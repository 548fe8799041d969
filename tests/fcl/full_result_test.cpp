// gq::fcl's full results equal FCL 0.7's in double on seeded random poses for every pair family, except the listed
// deliberate differences (full_results.h; tests/fcl/deliberate_differences.txt).
#include "full_results.h"

namespace gq::fcltest {
namespace {

GQ_FCL_FULL_RESULT_TESTS(FclFullResults, double, 5000u);

}  // namespace
}  // namespace gq::fcltest
