// The indented block of indentation_test.cpp one refinement further (4, 8, 16 cells per edge;
// about 2e4 unknowns on the finest level, several load steps): labelled slow.
#include "verification/indentation_cases.hpp"

namespace plisse::test {
namespace {

TEST(IndentationFine, PressureHasNoCheckerboard) {
  ASSERT_NO_FATAL_FAILURE(expect_smooth_pressure({4, 8, 16}));
}

}  // namespace
}  // namespace plisse::test
