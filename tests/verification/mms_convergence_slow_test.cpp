// The manufactured-solution rates one refinement further than mms_convergence_test.cpp
// (cube divisions 8, 16, 32; about 1.2e5 unknowns on the finest level): labelled slow.
#include "verification/mms_cases.hpp"

namespace plisse::test {
namespace {

TEST(ManufacturedSolutionFine, ExactIncompressibilityNeoHookeanConvergesOptimally) {
  ASSERT_NO_FATAL_FAILURE(expect_optimal_rates("MMS, neo-Hookean, exact incompressibility (fine)",
                                               exact_incompressible_neo_hookean(), {8, 16, 32}));
}

TEST(ManufacturedSolutionFine, NearIncompressibilityMooneyRivlinConvergesOptimally) {
  ASSERT_NO_FATAL_FAILURE(expect_optimal_rates("MMS, Mooney-Rivlin, kappa = 100 mu (fine)",
                                               near_incompressible_mooney_rivlin(), {8, 16, 32}));
}

}  // namespace
}  // namespace plisse::test
