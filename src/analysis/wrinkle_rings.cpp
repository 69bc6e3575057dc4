#include "analysis/wrinkle_rings.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "analysis/azimuthal_spectrum.hpp"
#include "analysis/cylindrical_frame.hpp"
#include "core/error.hpp"

namespace plisse {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// Sectors a ring can span: a full circle or a part bounded by mirror planes.
constexpr std::array<double, 4> kSectorsDeg = {45.0, 90.0, 180.0, 360.0};
/// A ring whose largest harmonic amplitude (m >= min_count) is at most this times its mean
/// radius is flat (round-off level): count 0 (wrinkles.md, W11); no harmonic at or below this
/// level belongs to the wrinkle band (W16).
constexpr double kFlatRelative = 1e-10;
/// The lowest count that changes the shape of a ring: m = 0 is its mean, m = 1 a shift of the
/// whole ring (wrinkles.md, W15).
constexpr int kFirstShapeCount = 2;

/// Sum_k w_k g_k: the mean of a grid signal over the sector.
double grid_mean(const AzimuthGrid& grid, const std::vector<double>& g) {
  double s = 0.0;
  for (int k = 0; k < grid.n_points(); ++k) s += grid.weight(k) * g[static_cast<std::size_t>(k)];
  return s;
}

/// Normal deviation of a ring from its mean shape (wrinkles.md, W6-W7):
///   d_k = (rho_k - rho-bar) n_rho-bar + (h_k - h-bar) n_h-bar,
/// with n-bar the normalised mean of the normal's (rho, h) components. Returns rho-bar too.
std::vector<double> normal_deviation(const AzimuthGrid& grid, const std::vector<double>& rho,
                                     const std::vector<double>& h, const std::vector<double>& n_rho,
                                     const std::vector<double>& n_h, double& mean_rho) {
  mean_rho = grid_mean(grid, rho);
  const double mean_h = grid_mean(grid, h);
  double nr = grid_mean(grid, n_rho), nh = grid_mean(grid, n_h);
  const double norm = std::hypot(nr, nh);
  if (norm > 0.0) {
    nr /= norm;
    nh /= norm;
  }
  std::vector<double> d(rho.size());
  for (std::size_t k = 0; k < d.size(); ++k) d[k] = (rho[k] - mean_rho) * nr + (h[k] - mean_h) * nh;
  return d;
}

}  // namespace

const char* ring_decision_name(RingDecision decision) {
  switch (decision) {
    case RingDecision::empty:
      return "empty";
    case RingDecision::flat:
      return "flat";
    case RingDecision::global_shape:
      return "global_shape";
    case RingDecision::local_shape:
      return "local_shape";
    case RingDecision::below_threshold:
      return "below_threshold";
    case RingDecision::wrinkled:
      return "wrinkled";
  }
  return "unknown";
}

std::vector<double> shape_envelope(const std::vector<int>& counts,
                                   const std::vector<double>& amplitudes) {
  PLISSE_CHECK(counts.size() == amplitudes.size(), "shape_envelope: one amplitude per count");
  std::vector<double> envelope(counts.size(), 0.0);
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const int m = counts[i];
    // (W15) E_m = max over 2 <= m' <= max(2, m/2), m' < m, of A_m' (m'/m)^2: the slowest decay
    // (kinks) of the harmonics of a global shape, continued from counts at most half of m (so
    // that the flank of a broad wrinkle peak does not raise the envelope of its own top), and
    // always from the ovalisation m' = 2.
    for (std::size_t k = 0; k < i; ++k) {
      const int mk = counts[k];
      if (mk < kFirstShapeCount || mk >= m || (mk > kFirstShapeCount && 2 * mk > m)) continue;
      const double r = static_cast<double>(mk) / m;
      envelope[i] = std::max(envelope[i], amplitudes[k] * r * r);
    }
  }
  return envelope;
}

int wrinkle_valley(const std::vector<int>& counts, const std::vector<double>& amplitudes,
                   std::size_t peak, double ratio) {
  PLISSE_CHECK(counts.size() == amplitudes.size() && peak < counts.size(),
               "wrinkle_valley: one amplitude per count, and the peak among them");
  // (W18) A wrinkle pattern of several waves is a band-limited peak: its spectrum rises to m*
  // from a valley. A local change of shape (a flat patch, a dent) has a broad, flat spectrum up
  // to m ~ circumference / its width, with no valley. The valley must be two consecutive
  // full-circle counts low: a ring symmetric about a plane (a patch on top and one below) has
  // its odd harmonics zero, and such a zero is no valley. On a grid of even counts only (a
  // quarter model) the symmetry is the model's and the odd counts are not there.
  const int top = counts[peak];
  // m* <= 2 is a peak only with min_count <= 2, where the user counts the global modes
  // themselves: there is no lower band to be separated from.
  if (top <= kFirstShapeCount) return 0;
  const double level = amplitudes[peak] / ratio;
  for (std::size_t k = 0; k < peak; ++k) {
    const int m = counts[k];
    if (m < std::max(1, top / 2)) continue;
    double v = amplitudes[k];
    if (k + 1 < counts.size() && counts[k + 1] == m + 1) {
      if (k + 1 == peak) continue;  // the pair would hold the peak itself
      v = std::max(v, amplitudes[k + 1]);
    }
    if (v < level) return m;
  }
  return -1;
}

void validate_ring_settings(const RingSettings& options) {
  PLISSE_CHECK(options.axis >= 0 && options.axis <= 2,
               "wrinkle rings: axis must be 0 (x), 1 (y) or 2 (z), got " << options.axis);
  PLISSE_CHECK(options.center.allFinite(), "wrinkle rings: the axis centre must be finite");
  for (double lat : options.latitudes_deg)
    PLISSE_CHECK(std::isfinite(lat) && lat > -90.0 && lat < 90.0,
                 "wrinkle rings: latitude " << lat << " deg is not in (-90, 90)");
  PLISSE_CHECK(options.min_count >= 1,
               "wrinkle rings: min_count must be >= 1, got " << options.min_count);
  PLISSE_CHECK(options.max_count >= options.min_count,
               "wrinkle rings: max_count (" << options.max_count << ") must be >= min_count ("
                                            << options.min_count << ")");
  PLISSE_CHECK(std::isfinite(options.peak_ratio) && options.peak_ratio >= 1.0,
               "wrinkle rings: peak_ratio must be >= 1, got " << options.peak_ratio);
  if (options.sector_deg) {
    const double s = *options.sector_deg;
    PLISSE_CHECK(std::find(kSectorsDeg.begin(), kSectorsDeg.end(), s) != kSectorsDeg.end(),
                 "wrinkle rings: sector_deg must be 45, 90, 180 or 360, got " << s);
  }
}

DetectedSector detect_sector(std::vector<double> theta) {
  PLISSE_CHECK(theta.size() >= 2, "detect_sector: need at least two azimuths");
  std::sort(theta.begin(), theta.end());
  // Largest cyclic gap; the wrap-around gap goes from the last angle to the first + 2 pi.
  double gap = theta.front() + kTwoPi - theta.back();
  double start = theta.front();
  for (std::size_t i = 1; i < theta.size(); ++i)
    if (theta[i] - theta[i - 1] > gap) {
      gap = theta[i] - theta[i - 1];
      start = theta[i];
    }
  const double span_deg = (kTwoPi - gap) / kDegree;
  DetectedSector out;
  double best = 1e300;
  for (double s : kSectorsDeg) {
    const double miss = std::abs(std::log(std::max(span_deg, 1e-9) / s));
    if (miss < best) {
      best = miss;
      out.sector_deg = s;
    }
  }
  out.start = out.sector_deg == 360.0 ? 0.0 : start;
  return out;
}

RingMetrics evaluate_ring(const RingSurface& surface, const RingSettings& options,
                          double latitude_deg) {
  validate_ring_settings(options);
  PLISSE_CHECK(std::isfinite(latitude_deg) && latitude_deg > -90.0 && latitude_deg < 90.0,
               "wrinkle rings: latitude " << latitude_deg << " deg is not in (-90, 90)");
  const CylindricalFrame frame(options.axis, options.center);
  const std::vector<RingPoint> points = surface.sample(frame, latitude_deg * kDegree);
  RingMetrics out;
  out.latitude_deg = latitude_deg;
  out.n_points = static_cast<int>(points.size());
  if (out.n_points < 4) return out;

  // Cylindrical components of each point, deformed (azimuth theta of x) and reference (W5).
  const std::size_t n = points.size();
  std::vector<double> theta(n), theta_ref(n), rho(n), h(n), n_rho(n), n_h(n), rho0(n), h0(n),
      n0_rho(n), n0_h(n);
  const Vec3d a = frame.axis_direction();
  for (std::size_t i = 0; i < n; ++i) {
    const RingPoint& p = points[i];
    const CylindricalCoordinates cx = frame.coordinates(p.x), cX = frame.coordinates(p.X);
    theta[i] = cx.theta;
    theta_ref[i] = cX.theta;
    rho[i] = cx.rho;
    h[i] = cx.h;
    n_rho[i] = p.normal.dot(frame.radial(cx.theta));
    n_h[i] = p.normal.dot(a);
    rho0[i] = cX.rho;
    h0[i] = cX.h;
    n0_rho[i] = p.reference_normal.dot(frame.radial(cX.theta));
    n0_h[i] = p.reference_normal.dot(a);
  }

  // Sector and grid: detected from the reference azimuths, where symmetry planes are exact.
  const DetectedSector detected = detect_sector(theta_ref);
  out.sector_deg = options.sector_deg.value_or(detected.sector_deg);
  const AzimuthGrid grid =
      make_azimuth_grid(out.sector_deg, out.sector_deg == 360.0 ? 0.0 : detected.start);
  const auto on_grid = [&](const std::vector<double>& v) {
    return resample_on_grid(theta, v, grid);
  };

  // Normal deviation of the deformed ring, minus the reference ring's own deviation scaled by
  // the mean radial stretch (W8).
  double mean_rho = 0.0;
  std::vector<double> d =
      normal_deviation(grid, on_grid(rho), on_grid(h), on_grid(n_rho), on_grid(n_h), mean_rho);
  out.mean_radius = mean_rho;
  if (options.subtract_reference) {
    double mean_rho0 = 0.0;
    const std::vector<double> d0 = normal_deviation(grid, on_grid(rho0), on_grid(h0),
                                                    on_grid(n0_rho), on_grid(n0_h), mean_rho0);
    const double stretch = mean_rho0 > 0.0 ? mean_rho / mean_rho0 : 1.0;
    for (std::size_t k = 0; k < d.size(); ++k) d[k] -= stretch * d0[k];
  }

  // Spectrum up to m_cap (W10): the ring's own sampling resolves counts up to half its
  // full-circle equivalent number of points.
  const int step = grid.count_step;
  const auto n_full_equivalent =
      static_cast<int>(std::lround(static_cast<double>(n) * 360.0 / out.sector_deg));
  const int m_cap = std::min(options.max_count, n_full_equivalent / 2);
  const int j_grid = grid.full() ? (grid.n_intervals - 1) / 2 : grid.n_intervals - 1;
  const int j_first = (options.min_count + step - 1) / step;  // smallest j with m >= min_count
  const int j_max = std::min(m_cap / step, j_grid);
  const AzimuthalSpectrum spectrum =
      compute_spectrum(grid, d, std::min(std::max(j_max, j_first - 1), j_grid));
  std::vector<int> counts;
  std::vector<double> amplitudes;
  for (int j = 0; j <= j_max; ++j) {
    counts.push_back(j * step);
    amplitudes.push_back(spectrum.amplitude(j));
    out.spectrum.emplace_back(j * step, spectrum.amplitude(j));
  }
  out.envelope = shape_envelope(counts, amplitudes);  // W15

  // The largest harmonic among m >= min_count, wrinkles or not (W11).
  const double flat = kFlatRelative * mean_rho;
  double dominant = 0.0;
  for (int j = j_first; j <= j_max; ++j)
    if (spectrum.amplitude(j) > dominant) {
      dominant = spectrum.amplitude(j);
      out.dominant_count = j * step;
    }
  if (dominant <= flat) out.dominant_count = 0;

  // Wrinkle peaks: the harmonics m >= min_count that stand out of the global shape's envelope
  // by peak_ratio; the count is the largest of them (W16). The band adds each peak's foot, its
  // contiguous neighbours m >= min_count above the envelope itself (W17).
  const auto above = [&](int j, double ratio) {
    const double A = spectrum.amplitude(j);
    return A > flat && A > ratio * out.envelope[static_cast<std::size_t>(j)];
  };
  std::vector<bool> in_band(static_cast<std::size_t>(j_max) + 1, false);
  double top = 0.0;
  bool above_envelope = false;  // a harmonic passed W16 (whether or not W18 then)
  for (int j = j_first; j <= j_max; ++j) {
    if (!above(j, options.peak_ratio)) continue;
    above_envelope = true;
    // (W18) and it must rise from a valley, or it is a local change of shape.
    if (wrinkle_valley(counts, amplitudes, static_cast<std::size_t>(j), options.peak_ratio) < 0)
      continue;
    if (spectrum.amplitude(j) > top) {
      top = spectrum.amplitude(j);
      out.count = j * step;
    }
    in_band[static_cast<std::size_t>(j)] = true;
    for (int i = j - 1; i >= j_first && above(i, 1.0); --i)
      in_band[static_cast<std::size_t>(i)] = true;
    for (int i = j + 1; i <= j_max && above(i, 1.0); ++i)
      in_band[static_cast<std::size_t>(i)] = true;
  }
  std::vector<int> band_j;
  for (int j = j_first; j <= j_max; ++j)
    if (in_band[static_cast<std::size_t>(j)]) {
      band_j.push_back(j);
      out.band.push_back(j * step);
    }
  const auto peak_to_peak = [](const std::vector<double>& g) {
    const auto [lo, hi] = std::minmax_element(g.begin(), g.end());
    return *hi - *lo;
  };
  if (!band_j.empty()) out.amplitude = peak_to_peak(harmonics_sum(grid, spectrum, band_j));  // W17
  remove_harmonics(grid, spectrum, j_first, d);
  out.residual_amplitude = peak_to_peak(d);                              // W12
  out.wavelength = out.count > 0 ? kTwoPi * mean_rho / out.count : 0.0;  // W13
  out.decision = !band_j.empty()           ? RingDecision::wrinkled
                 : out.dominant_count == 0 ? RingDecision::flat
                 : above_envelope          ? RingDecision::local_shape
                                           : RingDecision::global_shape;
  return out;
}

WrinkleReport evaluate_wrinkles(const std::vector<Vec3d>& reference_nodes,
                                const std::vector<std::array<int, 3>>& triangles,
                                const std::vector<Vec3d>& displacement,
                                const WrinkleMeasureSettings& options) {
  validate_ring_settings(options.rings);
  PLISSE_CHECK(std::isfinite(options.thickness) && options.thickness > 0.0,
               "wrinkle metrics: thickness must be > 0, got " << options.thickness);
  PLISSE_CHECK(
      std::isfinite(options.threshold_fraction) && options.threshold_fraction > 0.0,
      "wrinkle metrics: threshold_fraction must be > 0, got " << options.threshold_fraction);
  PLISSE_CHECK(displacement.size() == reference_nodes.size(),
               "wrinkle metrics: " << displacement.size() << " displacements for "
                                   << reference_nodes.size() << " nodes");
  const RingSurface surface(reference_nodes, triangles, displacement);
  WrinkleReport report;
  report.threshold = options.threshold_fraction * options.thickness;
  for (double lat : options.rings.latitudes_deg) {
    RingMetrics ring = evaluate_ring(surface, options.rings, lat);
    if (ring.decision == RingDecision::wrinkled && ring.amplitude <= report.threshold)
      ring.decision = RingDecision::below_threshold;  // W14
    report.max_amplitude = std::max(report.max_amplitude, ring.amplitude);
    report.rings.push_back(std::move(ring));
  }
  report.wrinkled = report.max_amplitude > report.threshold;
  return report;
}

WrinkleReport evaluate_wrinkles(const Mesh& mesh, const std::vector<Vec3d>& displacement,
                                const WrinkleMeasureSettings& options,
                                const std::string& outer_tag) {
  return evaluate_wrinkles(mesh.nodes, sampling_triangles(mesh, outer_tag), displacement, options);
}

std::vector<std::array<int, 3>> tagged_triangles(const Mesh& mesh, const std::string& tag) {
  const auto it = mesh.surface_tags.find(tag);
  PLISSE_CHECK(it != mesh.surface_tags.end(), "the mesh has no surface tag '" << tag << "'");
  std::vector<std::array<int, 3>> out;
  out.reserve(it->second.size());
  for (int t : it->second) {
    PLISSE_CHECK(t >= 0 && t < static_cast<int>(mesh.triangles.size()),
                 "surface tag '" << tag << "': triangle " << t << " out of range");
    out.push_back(mesh.triangles[static_cast<std::size_t>(t)]);
  }
  return out;
}

std::vector<std::array<int, 3>> sampling_triangles(const Mesh& mesh, const std::string& tag) {
  const std::vector<std::array<int, 3>> corners = tagged_triangles(mesh, tag);  // checks the tag
  if (mesh.order() == 1) return corners;
  std::vector<std::array<int, 3>> out;
  out.reserve(4 * corners.size());
  for (int t : mesh.surface_tags.at(tag)) {
    const auto& [a, b, c] = mesh.triangles[static_cast<std::size_t>(t)];
    const auto& [ab, bc, ca] = mesh.triangle_edge_nodes[static_cast<std::size_t>(t)];
    out.push_back({a, ab, ca});
    out.push_back({ab, b, bc});
    out.push_back({ca, bc, c});
    out.push_back({ab, bc, ca});
  }
  return out;
}

}  // namespace plisse
