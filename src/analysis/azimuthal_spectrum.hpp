#pragma once
/// Harmonic analysis of a ring signal over the azimuth: ordinary Fourier series on a full circle,
/// even (cosine) series on a sector bounded by two mirror planes (docs/theory/wrinkles.md, sec. 4).
#include <vector>

namespace plisse {

/// Uniform azimuth grid over the sector [start, start + sector]. A full circle (sector = 2 pi) has
/// n_intervals points theta_k = start + 2 pi k / N, k = 0..N-1 (periodic, weights 1/N); a sector
/// has N + 1 points theta_k = start + k sector / N, k = 0..N, with trapezoid weights (1/2N at the
/// two ends, 1/N inside). Weights sum to 1: sum_k w_k g_k is the mean of g over the sector.
struct AzimuthGrid {
  double start = 0.0;   ///< [rad]
  double sector = 0.0;  ///< [rad], 2 pi for a full circle
  int n_intervals = 0;  ///< N
  int count_step = 1;   ///< full-circle count of harmonic j: m = j count_step (= pi / sector
                        ///< for a sector, 1 for a full circle)
  bool full() const;
  int n_points() const { return full() ? n_intervals : n_intervals + 1; }
  double theta(int k) const;
  double weight(int k) const;
};

/// The grid for a sector of `sector_deg` degrees (45, 90, 180 or 360) starting at `start` [rad],
/// with N = max(256, 2048 sector_deg / 360) intervals.
AzimuthGrid make_azimuth_grid(double sector_deg, double start);

/// Linear interpolation of the samples (theta[i], value[i]) onto `grid` (wrinkles.md, W7).
/// `theta` in radians, any order and any branch (sorted internally after shifting into
/// [start, start + 2 pi)). A full circle is interpolated periodically; on a sector, grid points
/// beyond the first or last sample take that sample's value. Precondition: at least one sample.
std::vector<double> resample_on_grid(const std::vector<double>& theta,
                                     const std::vector<double>& value, const AzimuthGrid& grid);

/// Coefficients of a grid signal g_k (wrinkles.md, W9-W10):
///   full circle:  g(theta) = a_0 + sum_j a_j cos(j t) + b_j sin(j t),     t = theta - start
///   sector:       g(theta) = a_0 + sum_j a_j cos(j pi t / sector)         (b_j = 0)
/// with a_0 = sum_k w_k g_k, a_j = 2 sum_k w_k g_k cos(.), b_j = 2 sum_k w_k g_k sin(.), exact
/// for trigonometric polynomials of degree < N/2 (full) or < N (sector).
struct AzimuthalSpectrum {
  int count_step = 1;     ///< m = j count_step
  std::vector<double> a;  ///< a_j, j = 0..j_max
  std::vector<double> b;  ///< b_j (zero on a sector)
  int j_max() const { return static_cast<int>(a.size()) - 1; }
  /// A_j: |a_0| for j = 0, sqrt(a_j^2 + b_j^2) otherwise (the amplitude of the harmonic).
  double amplitude(int j) const;
};

/// The spectrum of `g` (one value per grid point) for j = 0..j_max. Precondition: j_max < N/2
/// on a full circle, j_max < N on a sector.
AzimuthalSpectrum compute_spectrum(const AzimuthGrid& grid, const std::vector<double>& g,
                                   int j_max);

/// Subtracts the harmonics j = 0..j_end-1 of `spectrum` from the grid signal `g` (in place).
void remove_harmonics(const AzimuthGrid& grid, const AzimuthalSpectrum& spectrum, int j_end,
                      std::vector<double>& g);

/// The grid signal of the harmonics `j_list` of `spectrum` alone: sum over j in j_list of
/// a_j cos(.) + b_j sin(.) at every grid point. Precondition: every j in 0..j_max.
std::vector<double> harmonics_sum(const AzimuthGrid& grid, const AzimuthalSpectrum& spectrum,
                                  const std::vector<int>& j_list);

}  // namespace plisse
