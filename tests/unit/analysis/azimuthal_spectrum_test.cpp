// Azimuthal harmonic analysis: exact coefficients of trigonometric polynomials on full and sector
// grids, harmonic removal, periodic/clamped resampling, and sector detection from azimuths.
#include "analysis/azimuthal_spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "analysis/wrinkle_rings.hpp"

namespace plisse {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

std::vector<double> on_grid(const AzimuthGrid& grid, double (*f)(double)) {
  std::vector<double> g;
  for (int k = 0; k < grid.n_points(); ++k) g.push_back(f(grid.theta(k) - grid.start));
  return g;
}

TEST(AzimuthalSpectrum, FullCircleFourierCoefficientsAreExact) {
  const AzimuthGrid grid = make_azimuth_grid(360.0, 0.7);
  EXPECT_TRUE(grid.full());
  EXPECT_EQ(grid.n_intervals, 2048);
  EXPECT_EQ(grid.count_step, 1);
  const auto g = on_grid(grid, [](double t) {
    return 0.3 + 2.0 * std::cos(3 * t) - 0.5 * std::sin(7 * t) + 0.1 * std::cos(150 * t + 1.0);
  });
  const AzimuthalSpectrum sp = compute_spectrum(grid, g, 200);
  // Discrete orthogonality of the N-point DFT: exact to round-off for degree < N/2.
  for (int j = 0; j <= 200; ++j) {
    const double expected = j == 0 ? 0.3 : j == 3 ? 2.0 : j == 7 ? 0.5 : j == 150 ? 0.1 : 0.0;
    EXPECT_NEAR(sp.amplitude(j), expected, 1e-12) << "j = " << j;
  }
  EXPECT_NEAR(sp.b[7], -0.5, 1e-12);
}

TEST(AzimuthalSpectrum, SectorCosineCoefficientsAreExactAndCountsScale) {
  for (double sector : {45.0, 90.0, 180.0}) {
    const AzimuthGrid grid = make_azimuth_grid(sector, -0.2);
    EXPECT_FALSE(grid.full());
    EXPECT_EQ(grid.count_step, static_cast<int>(180.0 / sector));
    const double S = sector * kDeg;
    std::vector<double> g;
    for (int k = 0; k < grid.n_points(); ++k) {
      const double t = grid.theta(k) - grid.start;
      g.push_back(-0.4 + 1.5 * std::cos(3 * kPi * t / S) + 0.25 * std::cos(11 * kPi * t / S));
    }
    const AzimuthalSpectrum sp = compute_spectrum(grid, g, 40);
    EXPECT_EQ(sp.count_step, grid.count_step);
    // Trapezoid-weighted cosine sums (DCT-I) are exact for cos(j pi t / S), j < N.
    for (int j = 0; j <= 40; ++j) {
      const double expected = j == 0 ? 0.4 : j == 3 ? 1.5 : j == 11 ? 0.25 : 0.0;
      EXPECT_NEAR(sp.amplitude(j), expected, 1e-12) << "sector " << sector << ", j = " << j;
    }
  }
}

TEST(AzimuthalSpectrum, RemoveHarmonicsLeavesOnlyTheHigherOnes) {
  const AzimuthGrid grid = make_azimuth_grid(360.0, 0.0);
  auto g = on_grid(grid, [](double t) {
    return 5.0 + 3.0 * std::cos(t) + 2.0 * std::sin(2 * t) + 0.5 * std::cos(9 * t);
  });
  const AzimuthalSpectrum sp = compute_spectrum(grid, g, 10);
  remove_harmonics(grid, sp, 3, g);
  for (int k = 0; k < grid.n_points(); ++k)
    EXPECT_NEAR(g[static_cast<std::size_t>(k)], 0.5 * std::cos(9 * grid.theta(k)), 1e-12);
}

TEST(AzimuthalSpectrum, ResamplingIsPeriodicOnACircleAndClampedOnASector) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 2 * kPi);
  std::uniform_int_distribution<int> branch(-3, 3);
  std::vector<double> theta, value;
  for (int i = 0; i < 2000; ++i) {
    const double t = angle(rng);
    theta.push_back(t + 2 * kPi * branch(rng));  // any branch of the angle
    value.push_back(std::cos(t));
  }
  const AzimuthGrid grid = make_azimuth_grid(360.0, 0.0);
  const auto g = resample_on_grid(theta, value, grid);
  // Linear interpolation of cos: error <= max gap^2 / 8; 2000 random points on a circle leave
  // gaps below 0.04 rad with overwhelming probability (fixed seed), so error < 2e-4.
  for (int k = 0; k < grid.n_points(); ++k)
    EXPECT_NEAR(g[static_cast<std::size_t>(k)], std::cos(grid.theta(k)), 2e-4);

  // Sector [0, 90 deg] sampled only on [10, 80] deg: the ends take the end values.
  const std::vector<double> t2 = {10 * kDeg, 45 * kDeg, 80 * kDeg}, v2 = {1.0, 2.0, 4.0};
  const AzimuthGrid sector = make_azimuth_grid(90.0, 0.0);
  const auto s = resample_on_grid(t2, v2, sector);
  EXPECT_DOUBLE_EQ(s.front(), 1.0);
  EXPECT_DOUBLE_EQ(s.back(), 4.0);
  EXPECT_NEAR(s[static_cast<std::size_t>(sector.n_intervals / 2)], 2.0, 1e-12);  // 45 deg
}

TEST(DetectSector, SpansAreRoundedAndStartsFollowTheLargestGap) {
  const auto angles = [](double from_deg, double to_deg, int n) {
    std::vector<double> t;
    for (int i = 0; i <= n; ++i) t.push_back((from_deg + (to_deg - from_deg) * i / n) * kDeg);
    return t;
  };
  auto full = angles(-180.0, 180.0, 100);
  full.pop_back();
  EXPECT_EQ(detect_sector(full).sector_deg, 360.0);
  const DetectedSector quarter = detect_sector(angles(0.0, 90.0, 30));
  EXPECT_EQ(quarter.sector_deg, 90.0);
  EXPECT_NEAR(quarter.start, 0.0, 1e-15);
  const DetectedSector half = detect_sector(angles(-90.0, 90.0, 50));
  EXPECT_EQ(half.sector_deg, 180.0);
  EXPECT_NEAR(half.start, -kPi / 2, 1e-15);
  // A quarter across the +-180 deg cut: 135..180 and -180..-135 deg.
  std::vector<double> wrapped;
  for (double t : angles(135.0, 225.0, 30)) wrapped.push_back(t > kPi ? t - 2 * kPi : t);
  const DetectedSector across = detect_sector(wrapped);
  EXPECT_EQ(across.sector_deg, 90.0);
  EXPECT_NEAR(across.start, 135.0 * kDeg, 1e-12);
  EXPECT_EQ(detect_sector(angles(0.0, 45.0, 10)).sector_deg, 45.0);
  // Coarse full ring (12 points, gaps of 30 deg) is still a full circle.
  auto coarse = angles(0.0, 360.0, 12);
  coarse.pop_back();
  EXPECT_EQ(detect_sector(coarse).sector_deg, 360.0);
}

}  // namespace
}  // namespace plisse
