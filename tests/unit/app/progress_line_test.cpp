// The progress line of `plisse run`: every part it promises, from a step's numbers.
#include "app/progress_line.hpp"

#include <gtest/gtest.h>

#include <string>

namespace plisse::app {
namespace {

bool has(const std::string& line, const std::string& part) {
  return line.find(part) != std::string::npos;
}

StepInfo step_at(double time) {
  StepInfo info;
  info.step = 12;
  info.time = time;
  info.load_factor = time;
  info.dt = 0.02;
  info.newton_iterations = 6;
  info.reused_solves = 4;
  info.residual_norm = 1.017e-12;
  return info;
}

TEST(ProgressLine, StepTimeIterationsAndTheTimeLeftAtTheRateSoFar) {
  // 0.25 of the model time in 30 s of stepping: 0.75 to go takes 90 s more.
  const std::string line = progress_line(step_at(0.25), nullptr, {31.5, 30.0, 0.0, 1.0});
  EXPECT_TRUE(has(line, "step   12  t 0.25  load 0.2500  dt 0.02  newton  6  reuse  4")) << line;
  EXPECT_TRUE(has(line, "|R| 1.017e-12")) << line;
  EXPECT_TRUE(has(line, "elapsed 31.5s  left ~1m30s")) << line;
  EXPECT_FALSE(has(line, "cut-backs")) << line;
  EXPECT_FALSE(has(line, "stable")) << line;  // not checked
  // A resume counts only the model time stepped in this process: from 0.5, 0.25 in 10 s.
  EXPECT_TRUE(has(progress_line(step_at(0.75), nullptr, {12.0, 10.0, 0.5, 1.0}), "left ~10s"));
  // At the end there is nothing left to estimate.
  EXPECT_FALSE(has(progress_line(step_at(1.0), nullptr, {40.0, 40.0, 0.0, 1.0}), "left"));
}

// After cut-backs the rate so far would promise the end too soon: a step near a limit load is
// cut back over and over. The estimate comes back with a step taken at its first try.
TEST(ProgressLine, TheTimeLeftIsUnknownAfterCutBacks) {
  StepInfo info = step_at(0.25);
  info.cutbacks = 3;
  const std::string line = progress_line(info, nullptr, {31.5, 30.0, 0.0, 1.0});
  EXPECT_TRUE(has(line, "cut-backs 3")) << line;
  EXPECT_TRUE(has(line, "left unknown (steps cut back)")) << line;
  EXPECT_FALSE(has(line, "left ~")) << line;
  info.cutbacks = 0;
  EXPECT_TRUE(has(progress_line(info, nullptr, {31.5, 30.0, 0.0, 1.0}), "left ~1m30s"));
  // The last step ends the run whatever it took.
  info = step_at(1.0);
  info.cutbacks = 1;
  EXPECT_FALSE(has(progress_line(info, nullptr, {40.0, 40.0, 0.0, 1.0}), "left")) << "at the end";
}

// Under arc-length control the load factor may fall past a limit load: its rate gives no time
// left from the second step on (the first is taken under load control).
TEST(ProgressLine, TheTimeLeftIsUnknownUnderArcLengthControl) {
  StepInfo info = step_at(0.25);
  info.step = 2;
  const std::string line = progress_line(info, nullptr, {31.5, 30.0, 0.0, 1.0, true});
  EXPECT_TRUE(has(line, "left unknown (arc length)")) << line;
  EXPECT_FALSE(has(line, "left ~")) << line;
  info.step = 1;
  EXPECT_TRUE(has(progress_line(info, nullptr, {31.5, 30.0, 0.0, 1.0, true}), "left ~1m30s"));
}

TEST(ProgressLine, CutBacksStabilityAndTheLargestWrinkledRing) {
  StepInfo info = step_at(0.5);
  info.cutbacks = 2;
  info.negative_pivots = 3;
  info.expected_negative_pivots = 2;
  info.stable = false;
  WrinkleReport report;
  report.wrinkled = true;
  RingMetrics small, large, flat;
  small.latitude_deg = 10;
  small.count = 8;
  small.amplitude = 0.002;
  small.decision = RingDecision::wrinkled;
  large.latitude_deg = 30;
  large.count = 12;
  large.amplitude = 0.0123;
  large.decision = RingDecision::wrinkled;
  flat.latitude_deg = 50;
  flat.amplitude = 0.5;  // larger, but not called wrinkled
  flat.decision = RingDecision::global_shape;
  report.rings = {small, large, flat};
  const std::string line = progress_line(info, &report, {5.0, 5.0, 0.0, 1.0});
  EXPECT_TRUE(has(line, "cut-backs 2  UNSTABLE (3/2 neg. pivots)")) << line;
  EXPECT_TRUE(has(line, "wrinkled (ring 30 deg: 12 waves, 0.0123 mm)")) << line;
  info.negative_pivots = 2;
  info.zero_pivots = 1;
  EXPECT_TRUE(has(progress_line(info, nullptr, {5.0, 5.0, 0.0, 1.0}), "SINGULAR (1 zero pivot)"));
  info.zero_pivots = 0;
  info.stable = true;
  report.wrinkled = false;
  const std::string calm = progress_line(info, &report, {5.0, 5.0, 0.0, 1.0});
  EXPECT_TRUE(has(calm, "  stable  elapsed")) << calm;
  EXPECT_FALSE(has(calm, "wrinkled")) << calm;
}

// A wrinkled line (docs/theory/wrinkles.md, W27) higher than every wrinkled ring is the one named;
// a line below the threshold is not, however high.
TEST(ProgressLine, TheLargestWrinkledLineOrRing) {
  const StepInfo info = step_at(0.5);
  WrinkleReport report;
  report.wrinkled = true;
  RingMetrics ring;
  ring.latitude_deg = 30;
  ring.count = 12;
  ring.amplitude = 0.0123;
  ring.decision = RingDecision::wrinkled;
  report.rings = {ring};
  LineReading across{"across", {}, true}, noise{"noise", {}, false};
  across.metrics.crests = 7;
  across.metrics.amplitude = 0.114;
  noise.metrics.crests = 31;
  noise.metrics.amplitude = 0.5;
  const std::vector<LineReading> lines = {across, noise};
  const std::string line = progress_line(info, &report, {5.0, 5.0, 0.0, 1.0}, &lines);
  EXPECT_TRUE(has(line, "  wrinkled (line across: 7 crests, 0.114 mm)  elapsed")) << line;
  const std::vector<LineReading> low = {noise};
  const std::string ringed = progress_line(info, &report, {5.0, 5.0, 0.0, 1.0}, &low);
  EXPECT_TRUE(has(ringed, "wrinkled (ring 30 deg: 12 waves, 0.0123 mm)")) << ringed;
  report.wrinkled = false;
  EXPECT_FALSE(has(progress_line(info, &report, {5.0, 5.0, 0.0, 1.0}, &low), "wrinkled"));
}

TEST(ProgressLine, DurationsReadAsSecondsMinutesOrHours) {
  EXPECT_EQ(format_duration(0.4), "0s");
  EXPECT_EQ(format_duration(42.4), "42s");
  EXPECT_EQ(format_duration(185), "3m05s");
  EXPECT_EQ(format_duration(7620), "2h07m");
  EXPECT_EQ(format_duration(-3), "0s");
}

}  // namespace
}  // namespace plisse::app
