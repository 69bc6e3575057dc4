#pragma once
/// Errors against a closed form that the docs print, one per mesh of a series that halves the
/// element size: each held to half the last digit printed, and falling at second order.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <vector>

namespace plisse::test {

/// errors[k] within half_digit[k] of printed[k], and each halving of the mesh cutting the error
/// more than 3.5-fold (second order cuts it fourfold, first order twofold).
template <std::size_t N>
void expect_printed_second_order(const std::vector<double>& errors,
                                 const std::array<double, N>& printed,
                                 const std::array<double, N>& half_digit) {
  ASSERT_EQ(errors.size(), N);
  for (std::size_t k = 0; k < N; ++k) EXPECT_NEAR(errors[k], printed[k], half_digit[k]) << k;
  for (std::size_t k = 0; k + 1 < N; ++k)
    EXPECT_GT(errors[k] / errors[k + 1], 3.5) << "second order, halving " << k;
}

}  // namespace plisse::test
