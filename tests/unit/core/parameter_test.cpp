#include "core/parameter.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "core/error.hpp"

namespace plisse {
namespace {

TEST(Range, PositiveRejectsZeroNegativeAndNonFinite) {
  const Range r = Range::positive();
  EXPECT_FALSE(r.violation(1e-12).has_value());
  EXPECT_EQ(*r.violation(0.0), "must be > 0 (got 0)");
  EXPECT_EQ(*r.violation(-2.5), "must be > 0 (got -2.5)");
  EXPECT_TRUE(r.violation(std::numeric_limits<double>::quiet_NaN()).has_value());
  EXPECT_TRUE(r.violation(std::numeric_limits<double>::infinity()).has_value());
}

TEST(Range, ClosedIntervalIncludesBounds) {
  const Range r = Range::closed(1, 100);
  EXPECT_FALSE(r.violation(1).has_value());
  EXPECT_FALSE(r.violation(100).has_value());
  EXPECT_EQ(*r.violation(101), "must be in [1, 100] (got 101)");
}

TEST(InputError, MessageNamesFileLineColumnAndKey) {
  const InputError e({"case.yaml", 12, 5, "material.c1"}, "must be > 0 (got -1)");
  EXPECT_STREQ(e.what(), "case.yaml:12:5: key 'material.c1': must be > 0 (got -1)");
  const InputError no_line({"--set", 0, 0, "mesh.layers"}, "expected an integer");
  EXPECT_STREQ(no_line.what(), "--set: key 'mesh.layers': expected an integer");
}

}  // namespace
}  // namespace plisse
