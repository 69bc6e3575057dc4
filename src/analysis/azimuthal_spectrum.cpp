#include "analysis/azimuthal_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "core/error.hpp"

namespace plisse {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// cos and sin of the phases of harmonic j at grid point k: j t_k on a full circle, j pi t_k /
/// sector on a sector. Both are (j k mod P) times the step 2 pi / P with the period P = N (full)
/// or 2N (sector), so one table of P values serves every (j, k), exactly for large j k.
class PhaseTable {
 public:
  explicit PhaseTable(const AzimuthGrid& grid)
      : period_(grid.full() ? grid.n_intervals : 2 * grid.n_intervals),
        cos_(static_cast<std::size_t>(period_)),
        sin_(static_cast<std::size_t>(period_)) {
    for (int i = 0; i < period_; ++i) {
      const double p = kTwoPi * i / period_;
      cos_[static_cast<std::size_t>(i)] = std::cos(p);
      sin_[static_cast<std::size_t>(i)] = std::sin(p);
    }
  }
  std::size_t index(int j, int k) const {
    return static_cast<std::size_t>((static_cast<long long>(j) * k) % period_);
  }
  double cos(std::size_t i) const { return cos_[i]; }
  double sin(std::size_t i) const { return sin_[i]; }

 private:
  int period_;
  std::vector<double> cos_, sin_;
};

}  // namespace

bool AzimuthGrid::full() const { return sector > kTwoPi - 1e-9; }

double AzimuthGrid::theta(int k) const { return start + sector * k / n_intervals; }

double AzimuthGrid::weight(int k) const {
  if (full() || (k > 0 && k < n_intervals)) return 1.0 / n_intervals;
  return 0.5 / n_intervals;
}

AzimuthGrid make_azimuth_grid(double sector_deg, double start) {
  AzimuthGrid grid;
  grid.start = start;
  grid.sector = sector_deg * std::numbers::pi / 180.0;
  grid.n_intervals = std::max(256, static_cast<int>(std::lround(2048.0 * sector_deg / 360.0)));
  grid.count_step = grid.full() ? 1 : static_cast<int>(std::lround(180.0 / sector_deg));
  return grid;
}

std::vector<double> resample_on_grid(const std::vector<double>& theta,
                                     const std::vector<double>& value, const AzimuthGrid& grid) {
  PLISSE_CHECK(!theta.empty() && theta.size() == value.size(),
               "resample_on_grid: need as many values as angles, at least one");
  // Samples in [start - margin, start + 2 pi - margin), sorted: the margin keeps points of a
  // sector's start plane that round-off puts just below `start` at the beginning.
  const double margin = grid.full() ? 0.0 : 0.5 * (kTwoPi - grid.sector);
  std::vector<std::pair<double, double>> s(theta.size());
  for (std::size_t i = 0; i < theta.size(); ++i) {
    double t = std::fmod(theta[i] - grid.start + margin, kTwoPi);
    if (t < 0.0) t += kTwoPi;
    s[i] = {t - margin, value[i]};
  }
  std::sort(s.begin(), s.end());
  const std::size_t n = s.size();
  std::vector<double> g(static_cast<std::size_t>(grid.n_points()));
  const auto lerp = [](double t0, double v0, double t1, double v1, double t) {
    return t1 > t0 ? v0 + (v1 - v0) * (t - t0) / (t1 - t0) : 0.5 * (v0 + v1);
  };
  std::size_t i = 0;  // first sample with angle > t (grid points increase with k)
  for (int k = 0; k < grid.n_points(); ++k) {
    const double t = grid.theta(k) - grid.start;
    while (i < n && s[i].first <= t) ++i;
    double v;
    if (i == 0) {
      v = grid.full() ? lerp(s[n - 1].first - kTwoPi, s[n - 1].second, s[0].first, s[0].second, t)
                      : s[0].second;
    } else if (i == n) {
      v = grid.full() ? lerp(s[n - 1].first, s[n - 1].second, s[0].first + kTwoPi, s[0].second, t)
                      : s[n - 1].second;
    } else {
      v = lerp(s[i - 1].first, s[i - 1].second, s[i].first, s[i].second, t);
    }
    g[static_cast<std::size_t>(k)] = v;
  }
  return g;
}

double AzimuthalSpectrum::amplitude(int j) const {
  const auto i = static_cast<std::size_t>(j);
  return j == 0 ? std::abs(a[0]) : std::hypot(a[i], b[i]);
}

AzimuthalSpectrum compute_spectrum(const AzimuthGrid& grid, const std::vector<double>& g,
                                   int j_max) {
  PLISSE_CHECK(static_cast<int>(g.size()) == grid.n_points(), "compute_spectrum: signal size");
  PLISSE_CHECK(
      j_max >= 0 && (grid.full() ? 2 * j_max < grid.n_intervals : j_max < grid.n_intervals),
      "compute_spectrum: harmonic " << j_max << " beyond the grid's resolution");
  AzimuthalSpectrum sp;
  sp.count_step = grid.count_step;
  sp.a.assign(static_cast<std::size_t>(j_max) + 1, 0.0);
  sp.b.assign(static_cast<std::size_t>(j_max) + 1, 0.0);
  const PhaseTable table(grid);
  for (int j = 0; j <= j_max; ++j) {
    double a = 0.0, b = 0.0;
    for (int k = 0; k < grid.n_points(); ++k) {
      const double wg = grid.weight(k) * g[static_cast<std::size_t>(k)];
      const std::size_t p = table.index(j, k);
      a += wg * table.cos(p);
      b += wg * table.sin(p);
    }
    if (!grid.full()) b = 0.0;  // the even (cosine) series of a sector has no sine terms
    const double factor = j == 0 ? 1.0 : 2.0;
    sp.a[static_cast<std::size_t>(j)] = factor * a;
    sp.b[static_cast<std::size_t>(j)] = factor * b;
  }
  return sp;
}

void remove_harmonics(const AzimuthGrid& grid, const AzimuthalSpectrum& spectrum, int j_end,
                      std::vector<double>& g) {
  const int j_last = std::min(j_end - 1, spectrum.j_max());
  const PhaseTable table(grid);
  for (int k = 0; k < grid.n_points(); ++k) {
    double v = 0.0;
    for (int j = 0; j <= j_last; ++j) {
      const std::size_t p = table.index(j, k);
      const auto i = static_cast<std::size_t>(j);
      v += spectrum.a[i] * table.cos(p) + spectrum.b[i] * table.sin(p);
    }
    g[static_cast<std::size_t>(k)] -= v;
  }
}

std::vector<double> harmonics_sum(const AzimuthGrid& grid, const AzimuthalSpectrum& spectrum,
                                  const std::vector<int>& j_list) {
  for (int j : j_list)
    PLISSE_CHECK(j >= 0 && j <= spectrum.j_max(),
                 "harmonics_sum: harmonic " << j << " not computed");
  const PhaseTable table(grid);
  std::vector<double> g(static_cast<std::size_t>(grid.n_points()), 0.0);
  for (int k = 0; k < grid.n_points(); ++k) {
    double v = 0.0;
    for (int j : j_list) {
      const std::size_t p = table.index(j, k);
      const auto i = static_cast<std::size_t>(j);
      v += spectrum.a[i] * table.cos(p) + spectrum.b[i] * table.sin(p);
    }
    g[static_cast<std::size_t>(k)] = v;
  }
  return g;
}

}  // namespace plisse
