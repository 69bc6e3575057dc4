#include "analysis/wrinkle_lines.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "analysis/point_location.hpp"
#include "core/error.hpp"

namespace plisse {
namespace {

/// An extremum is a crest when it is at least this fraction of the largest |w| (W24).
constexpr double kCrestFraction = 0.1;

/// One extremum of w: its position and value, refined on the parabola through it and its two
/// neighbours.
struct Extremum {
  double s = 0.0;
  double w = 0.0;
};

/// The vertex of the parabola through (s[k-1], w[k-1]), (s[k], w[k]), (s[k+1], w[k+1]); the
/// sample itself when the parabola is flat or its vertex lies beyond the neighbours.
Extremum refine(const std::vector<double>& s, const std::vector<double>& w, std::size_t k) {
  const double h1 = s[k] - s[k - 1], h2 = s[k + 1] - s[k];
  const double dm = w[k - 1] - w[k], dp = w[k + 1] - w[k];
  const double c = (h2 * dm + h1 * dp) / (h1 * h2 * (h1 + h2));
  const double b = (dp - c * h2 * h2) / h2;
  if (c == 0.0) return {s[k], w[k]};
  const double offset = -b / (2.0 * c);
  if (!(offset >= -h1 && offset <= h2)) return {s[k], w[k]};
  return {s[k] + offset, w[k] - b * b / (4.0 * c)};
}

/// Linear interpolation of the increasing table (s, f) at t (clamped to its ends).
double interpolate_at(const std::vector<double>& s, const std::vector<double>& f, double t) {
  if (t <= s.front()) return f.front();
  if (t >= s.back()) return f.back();
  const std::size_t j = static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), t) -
                                                 s.begin());  // s[j-1] <= t < s[j]
  const double r = (t - s[j - 1]) / (s[j] - s[j - 1]);
  return f[j - 1] + r * (f[j] - f[j - 1]);
}

/// Cubics in s, written in tau = (s - middle) / half in [-1, 1] for their conditioning: the smooth
/// shape taken off the line (wrinkles.md, W22), which holds a beam's bending, a sheet's lateral bow
/// and the stretch along the line.
struct CubicBasis {
  double middle = 0.0, half = 1.0;
  Eigen::RowVector4d at(double s) const {
    const double t = (s - middle) / half;
    return {1.0, t, t * t, t * t * t};
  }
  /// The second derivative in s of the cubic with `coefficients` (rows: c0..c3), at s.
  Eigen::RowVector3d second_derivative(const Eigen::Matrix<double, 4, 3>& coefficients,
                                       double s) const {
    const double t = (s - middle) / half;
    return (2.0 * coefficients.row(2) + 6.0 * t * coefficients.row(3)) / (half * half);
  }
};

/// The least-squares cubic of each coordinate of `values` (rows) at the distances `at`.
Eigen::Matrix<double, 4, 3> fit_cubic(const CubicBasis& basis, const std::vector<double>& at,
                                      const Eigen::MatrixX3d& values) {
  Eigen::MatrixX4d V(static_cast<Eigen::Index>(at.size()), 4);
  for (std::size_t i = 0; i < at.size(); ++i) V.row(static_cast<Eigen::Index>(i)) = basis.at(at[i]);
  return V.colPivHouseholderQr().solve(values);
}

/// The deviation of one pass (W23-W24): w along the residual's principal direction, its crests.
struct Deviation {
  std::vector<double> w;
  double largest = 0.0, low = 0.0, high = 0.0;
  std::vector<Extremum> crests;
};

Deviation deviation_from(const std::vector<double>& s, const Eigen::MatrixX3d& residual) {
  const std::size_t n = s.size();
  const Eigen::JacobiSVD<Eigen::MatrixX3d> svd(residual, Eigen::ComputeFullV);
  const Eigen::Vector3d direction = svd.matrixV().col(0);
  Deviation d;
  d.w.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    d.w[i] = residual.row(static_cast<Eigen::Index>(i)).dot(direction);
    d.largest = std::max(d.largest, std::abs(d.w[i]));
    d.low = std::min(d.low, d.w[i]);
    d.high = std::max(d.high, d.w[i]);
  }
  // W24: alternating extrema of at least kCrestFraction of the largest |w|; of two of one sign in
  // a row, the larger.
  const std::vector<double>& w = d.w;
  for (std::size_t k = 1; k + 1 < n; ++k) {
    const bool crest = w[k] > 0.0 && w[k] >= w[k - 1] && w[k] >= w[k + 1];
    const bool trough = w[k] < 0.0 && w[k] <= w[k - 1] && w[k] <= w[k + 1];
    if (!(crest || trough) || std::abs(w[k]) < kCrestFraction * d.largest) continue;
    const Extremum e = refine(s, w, k);
    if (!d.crests.empty() && (d.crests.back().w > 0.0) == (e.w > 0.0)) {
      if (std::abs(e.w) > std::abs(d.crests.back().w)) d.crests.back() = e;
      continue;
    }
    d.crests.push_back(e);
  }
  return d;
}

/// The wavelength of the crests (W26) along `along` (a distance at each s): twice the mean distance
/// between the zeros of w that separate consecutive crests, each where w changes sign between
/// two samples, interpolated linearly; with two crests, twice their distance. The zeros of a wave
/// whose height grows or decays along the line stay where they are, where its crests move towards
/// the higher ones.
double crest_wavelength(const std::vector<double>& s, const std::vector<double>& w,
                        const std::vector<Extremum>& crests, const std::vector<double>& along) {
  if (crests.size() < 2) return 0.0;
  std::vector<double> zeros;
  std::size_t i = 0;
  for (std::size_t k = 0; k + 1 < crests.size(); ++k) {
    while (i + 1 < s.size() && s[i + 1] <= crests[k].s) ++i;
    for (; i + 1 < s.size() && s[i] < crests[k + 1].s; ++i)
      if ((w[i] > 0.0) != (w[i + 1] > 0.0)) {
        zeros.push_back(s[i] + w[i] * (s[i + 1] - s[i]) / (w[i] - w[i + 1]));
        ++i;
        break;
      }
  }
  if (zeros.size() < 2)
    return 2.0 *
           (interpolate_at(s, along, crests.back().s) - interpolate_at(s, along, crests.front().s));
  return 2.0 * (interpolate_at(s, along, zeros.back()) - interpolate_at(s, along, zeros.front())) /
         static_cast<double>(zeros.size() - 1);
}

/// The smooth shape under wrinkles of wavelength `lambda` (W22b): the means of x over one
/// wavelength, centred at the samples whose window lies on the line, fitted by a cubic q; the
/// mean of a cubic p over lambda is p + lambda^2 p'' / 24, so p = q - lambda^2 q'' / 24. Empty
/// when fewer than 8 windows fit on the line.
std::optional<Eigen::MatrixX3d> smooth_under_waves(const CubicBasis& basis,
                                                   const std::vector<double>& s,
                                                   const Eigen::MatrixX3d& X, double lambda) {
  const std::size_t n = s.size();
  // The integral of the piecewise-linear x from s[0] to each sample, and to any t.
  Eigen::MatrixX3d integral(static_cast<Eigen::Index>(n), 3);
  integral.row(0).setZero();
  for (std::size_t i = 1; i < n; ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    integral.row(r) = integral.row(r - 1) + 0.5 * (s[i] - s[i - 1]) * (X.row(r) + X.row(r - 1));
  }
  const auto integral_to = [&](double t) -> Eigen::RowVector3d {
    const std::size_t j = static_cast<std::size_t>(
        std::clamp<std::ptrdiff_t>(std::upper_bound(s.begin(), s.end(), t) - s.begin(), 1,
                                   static_cast<std::ptrdiff_t>(n - 1)));
    const auto r = static_cast<Eigen::Index>(j - 1);
    const double h = t - s[j - 1], r_t = h / (s[j] - s[j - 1]);
    const Eigen::RowVector3d x_t = X.row(r) + r_t * (X.row(r + 1) - X.row(r));
    return integral.row(r) + 0.5 * h * (X.row(r) + x_t);
  };
  std::vector<double> centres;
  std::vector<Eigen::RowVector3d> means;
  for (std::size_t i = 0; i < n; ++i)
    if (s[i] - 0.5 * lambda >= s.front() && s[i] + 0.5 * lambda <= s.back()) {
      centres.push_back(s[i]);
      means.push_back((integral_to(s[i] + 0.5 * lambda) - integral_to(s[i] - 0.5 * lambda)) /
                      lambda);
    }
  if (centres.size() < 8) return std::nullopt;
  Eigen::MatrixX3d M(static_cast<Eigen::Index>(centres.size()), 3);
  for (std::size_t i = 0; i < centres.size(); ++i) M.row(static_cast<Eigen::Index>(i)) = means[i];
  const Eigen::Matrix<double, 4, 3> q = fit_cubic(basis, centres, M);
  Eigen::MatrixX3d smooth(static_cast<Eigen::Index>(n), 3);
  for (std::size_t i = 0; i < n; ++i)
    smooth.row(static_cast<Eigen::Index>(i)) =
        basis.at(s[i]) * q - lambda * lambda / 24.0 * basis.second_derivative(q, s[i]);
  return smooth;
}

}  // namespace

LineMetrics measure_line(const std::vector<double>& s, const std::vector<Vec3d>& x,
                         int min_crests) {
  const std::size_t n = s.size();
  PLISSE_CHECK(x.size() == n, "measure_line: " + std::to_string(x.size()) + " points for " +
                                  std::to_string(n) + " distances");
  PLISSE_CHECK(n >= 8, "measure_line: a line needs at least 8 points, got " + std::to_string(n));
  PLISSE_CHECK(min_crests >= 1, "measure_line: min_crests must be at least 1");
  for (std::size_t i = 1; i < n; ++i)
    PLISSE_CHECK(s[i] > s[i - 1], "measure_line: the distances must increase");

  const CubicBasis basis{0.5 * (s.front() + s.back()), 0.5 * (s.back() - s.front())};
  Eigen::MatrixX3d X(static_cast<Eigen::Index>(n), 3);
  for (std::size_t i = 0; i < n; ++i) X.row(static_cast<Eigen::Index>(i)) = x[i].transpose();
  // W22: the least-squares cubic of each coordinate.
  const Eigen::Matrix<double, 4, 3> first_fit = fit_cubic(basis, s, X);
  Eigen::MatrixX3d smooth(static_cast<Eigen::Index>(n), 3);
  for (std::size_t i = 0; i < n; ++i)
    smooth.row(static_cast<Eigen::Index>(i)) = basis.at(s[i]) * first_fit;
  Deviation d = deviation_from(s, X - smooth);
  LineMetrics m;
  m.deviation = d.high - d.low;
  // A straight line to round-off of its coordinates has no crests.
  const double scale = X.cwiseAbs().maxCoeff() + 2.0 * basis.half;
  if (!(d.largest > 1e-12 * scale) || static_cast<int>(d.crests.size()) < min_crests) return m;

  // W22b: the cubic also takes the waves' own projection on the cubics, a smooth term of relative
  // size about 1 / (pi crests) that tilts and shifts them; twice, the smooth shape is fitted
  // again to the means over the wavelength found, which hold no waves.
  for (int pass = 0; pass < 2 && d.crests.size() >= 2; ++pass) {
    const auto better = smooth_under_waves(basis, s, X, crest_wavelength(s, d.w, d.crests, s));
    if (!better) break;
    Deviation next = deviation_from(s, X - *better);
    if (static_cast<int>(next.crests.size()) < min_crests) break;
    smooth = *better;
    d = std::move(next);
  }
  m.deviation = d.high - d.low;
  m.crests = static_cast<int>(d.crests.size());
  const std::vector<Extremum>& crests = d.crests;
  // W25: the largest height of a crest over the mean of the troughs beside it (of an end crest,
  // over its one neighbour): a smooth slope left under the wrinkles cancels.
  if (crests.size() < 2) {
    m.amplitude = m.deviation;
    return m;
  }
  for (std::size_t k = 0; k < crests.size(); ++k) {
    const double beside = k == 0                   ? crests[1].w
                          : k + 1 == crests.size() ? crests[k - 1].w
                                                   : 0.5 * (crests[k - 1].w + crests[k + 1].w);
    m.amplitude = std::max(m.amplitude, std::abs(crests[k].w - beside));
  }
  // W26: along the undeformed line and along the smooth shape.
  std::vector<double> arc(n, 0.0);
  for (std::size_t i = 1; i < n; ++i)
    arc[i] = arc[i - 1] + (smooth.row(static_cast<Eigen::Index>(i)) -
                           smooth.row(static_cast<Eigen::Index>(i - 1)))
                              .norm();
  m.reference_wavelength = crest_wavelength(s, d.w, crests, s);
  m.wavelength = crest_wavelength(s, d.w, crests, arc);
  return m;
}

LineGauge::LineGauge(const Mesh& mesh, const Vec3d& from, const Vec3d& to, int points,
                     LineMirror mirror)
    : mirror_(mirror) {
  PLISSE_CHECK(points >= 2, "LineGauge: a line needs at least 2 points");
  const double length = (to - from).norm();
  PLISSE_CHECK(length > 0.0, "LineGauge: the line's two ends are the same point");
  direction_ = (to - from) / length;
  s_.reserve(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i) {
    const double r = static_cast<double>(i) / (points - 1);
    const Vec3d X = from + r * (to - from);
    const MeshPoint at = locate_point(mesh, X);
    s_.push_back(r * length);
    reference_.push_back(at.position);
    weights_.push_back(interpolation_weights(mesh, at));
    if (at.distance > outside_.distance) outside_ = {i, X, at.distance};
  }
}

std::vector<Vec3d> LineGauge::deformed(const std::vector<Vec3d>& displacement) const {
  std::vector<Vec3d> x(reference_.size());
  for (std::size_t i = 0; i < x.size(); ++i)
    x[i] = reference_[i] + interpolate(weights_[i], displacement);
  return x;
}

LineSamples LineGauge::samples(const std::vector<Vec3d>& displacement) const {
  std::vector<Vec3d> x = deformed(displacement);
  if (mirror_ == LineMirror::none) return {s_, std::move(x)};
  // W21: the samples reflected in the plane through the mirrored end's current point, normal to
  // the undeformed line (a mirror plane crossed at a right angle keeps both), continue the line
  // beyond that end. Its distances run from -length (mirror `from`) or up to 2 length (`to`).
  const std::size_t n = s_.size();
  const bool at_from = mirror_ == LineMirror::from;
  const Vec3d origin = at_from ? x.front() : x.back();
  const double s_origin = at_from ? s_.front() : s_.back();
  LineSamples whole;
  whole.s.reserve(2 * n - 1);
  whole.x.reserve(2 * n - 1);
  const auto reflected = [&](std::size_t i) {
    whole.s.push_back(2.0 * s_origin - s_[i]);
    whole.x.push_back(x[i] - 2.0 * (x[i] - origin).dot(direction_) * direction_);
  };
  if (at_from)
    for (std::size_t i = n - 1; i >= 1; --i) reflected(i);
  for (std::size_t i = 0; i < n; ++i) {
    whole.s.push_back(s_[i]);
    whole.x.push_back(x[i]);
  }
  if (!at_from)
    for (std::size_t i = n - 1; i-- > 0;) reflected(i);
  return whole;
}

}  // namespace plisse
