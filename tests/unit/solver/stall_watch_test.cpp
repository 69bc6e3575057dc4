// The stalled-solve test of Newton (solver/stall_watch.hpp) on sequences of residual norms whose
// verdict is counted by hand.
#include "solver/stall_watch.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace plisse {
namespace {

NewtonSettings settings(int iterations, double ratio) {
  NewtonSettings s;
  s.stall_iterations = iterations;
  s.stall_ratio = ratio;
  return s;
}

/// The index (0: the start) of the norm at which the watch says "stalled", or -1.
int stalled_at(StallWatch& watch, const std::vector<double>& norms) {
  watch.restart();
  for (std::size_t k = 0; k < norms.size(); ++k)
    if (watch.stalled(norms[k])) return static_cast<int>(k);
  return -1;
}

TEST(StallWatch, GivesUpAfterTheGivenRunOfSmallCuts) {
  StallWatch watch(settings(3, 0.9));
  // Cuts: 0.5 (not stalled), then 0.99, 0.95, 0.92 (three stalls in a row): at index 4.
  EXPECT_EQ(stalled_at(watch, {1.0, 0.5, 0.495, 0.47, 0.4324}), 4);
}

TEST(StallWatch, AGoodIterationStartsTheCountAgain) {
  StallWatch watch(settings(3, 0.9));
  // Two stalls, a cut to 0.5 of the norm before, two stalls: never three in a row.
  EXPECT_EQ(stalled_at(watch, {1.0, 0.99, 0.98, 0.49, 0.485, 0.48}), -1);
  // A third stall after them: index 6.
  EXPECT_EQ(stalled_at(watch, {1.0, 0.99, 0.98, 0.49, 0.485, 0.48, 0.475}), 6);
}

TEST(StallWatch, ACutOfExactlyTheRatioIsNotAStall) {
  // 0.5 * 0.5 = 0.25 and 0.25 * 0.5 = 0.125 are exact in binary: a norm equal to ratio times the
  // one before is progress enough; one just above it is not.
  StallWatch watch(settings(2, 0.5));
  EXPECT_EQ(stalled_at(watch, {1.0, 0.5, 0.25, 0.125}), -1);
  EXPECT_EQ(stalled_at(watch, {1.0, 0.5000001, 0.2500001}), 2);
}

TEST(StallWatch, ARisingResidualStallsToo) {
  StallWatch watch(settings(2, 0.9));
  EXPECT_EQ(stalled_at(watch, {1.0, 2.0, 3.0}), 2);
}

TEST(StallWatch, ZeroIterationsNeverGivesUp) {
  StallWatch watch(settings(0, 0.9));
  EXPECT_EQ(stalled_at(watch, std::vector<double>(50, 1.0)), -1);
}

TEST(StallWatch, RestartForgetsTheLastSolve) {
  StallWatch watch(settings(2, 0.9));
  watch.restart();
  EXPECT_FALSE(watch.stalled(1.0));
  EXPECT_FALSE(watch.stalled(1.0));  // one stall
  watch.restart();
  // The first norm of a new solve is a start, not a stall after the 1.0 before.
  EXPECT_FALSE(watch.stalled(1.0));
  EXPECT_FALSE(watch.stalled(1.0));  // one stall of this solve
  EXPECT_TRUE(watch.stalled(1.0));   // two
}

TEST(StallWatch, DescribesTheRunItGaveUpOn) {
  StallWatch watch(settings(2, 0.9));
  ASSERT_EQ(stalled_at(watch, {8.0, 4.0, 3.9, 3.8}), 3);
  const std::string text = watch.describe();
  EXPECT_NE(text.find("stalled: 2 iterations in a row each left the residual above 0.9 times "
                      "the one before (from 4 to 3.8; solver.newton.stall_iterations, "
                      "stall_ratio)"),
            std::string::npos)
      << text;
}

}  // namespace
}  // namespace plisse
