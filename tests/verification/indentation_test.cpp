// No spurious pressure modes in a real solve: an indented block to 15 % indentation on cubes with
// 4 and 8 cells per edge (indentation_cases.hpp; 16 cells in indentation_slow_test.cpp).
#include "verification/indentation_cases.hpp"

namespace plisse::test {
namespace {

TEST(Indentation, PressureHasNoCheckerboard) {
  ASSERT_NO_FATAL_FAILURE(expect_smooth_pressure({4, 8}));
}

}  // namespace
}  // namespace plisse::test
