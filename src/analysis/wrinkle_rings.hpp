#pragma once
/// Wrinkle metrics on material rings of the deformed outer surface: dominant full-circle wrinkle
/// count, peak-to-peak amplitude and wavelength per ring (docs/theory/wrinkles.md).
///
/// Typical call from a solver step (mesh, displacements u per node, thickness t):
///   WrinkleMeasureSettings opt;
///   opt.rings.axis = 1;  opt.rings.latitudes_deg = {0, 30, 60};  opt.thickness = t;
///   const WrinkleReport r = evaluate_wrinkles(mesh, u, opt);   // outer tag "outer"
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "analysis/ring_surface.hpp"
#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// Where and how rings are taken. Invalid values throw Error (see validate_ring_settings).
struct RingSettings {
  int axis = 1;                       ///< 0 x, 1 y, 2 z: the wrinkle axis
  Vec3d center = Vec3d::Zero();       ///< a point on the axis [mm]
  std::vector<double> latitudes_deg;  ///< rings, each in (-90, 90) [deg]
  int min_count = 3;                  ///< full-circle counts below this are global shape modes
  int max_count = 200;                ///< largest full-circle count searched and reported
  /// A harmonic m >= min_count is part of the wrinkles only if its amplitude exceeds this times
  /// the global shape's envelope at m (wrinkles.md, W15-W16); >= 1.
  double peak_ratio = 2.0;
  std::optional<double> sector_deg;  ///< 360/180/90/45; default: detected from the mesh
  /// Subtract the reference ring's own deviation from its mean shape, scaled by the ring's mean
  /// radial stretch (wrinkles.md, W8): facets of the linear surface (sag ~ h^2 / 8R) and
  /// reference imperfections are then not counted as wrinkles.
  bool subtract_reference = true;
};

/// Why a ring is or is not wrinkled (wrinkles.md, W16-W17), in the order the rules are applied.
enum class RingDecision {
  empty,            ///< fewer than 4 points: the ring misses the surface
  flat,             ///< no harmonic m >= min_count above round-off (10^-10 mean radius): the
                    ///< ring is round, shifted or purely oval
  global_shape,     ///< harmonics m >= min_count exist, but none stands out of the envelope of
                    ///< the global shape by peak_ratio: a smooth change of the whole ring
  local_shape,      ///< harmonics stand out of the envelope, but none is separated from the
                    ///< lower counts by a valley (W18): a local change of shape (a flat patch,
                    ///< a dent), whose spectrum is broad and flat
  below_threshold,  ///< a wrinkle peak, of amplitude <= threshold_fraction * thickness (W14)
  wrinkled,         ///< a wrinkle peak above the threshold
};

/// "empty", "flat", "global_shape", "local_shape", "below_threshold", "wrinkled" (the
/// summary.json spelling).
const char* ring_decision_name(RingDecision decision);

/// Metrics of one ring (wrinkles.md, W11-W17). Lengths in mm.
struct RingMetrics {
  double latitude_deg = 0.0;
  /// Wrinkle count: the harmonic of the wrinkle band with the largest amplitude (W16); 0 when
  /// the band is empty (empty, flat or global_shape).
  int count = 0;
  /// Peak-to-peak of the harmonics of the wrinkle band alone (W17) [mm]; 0 when it is empty.
  double amplitude = 0.0;
  double wavelength = 0.0;  ///< 2 pi mean_radius / count; 0 when count == 0
  /// The largest harmonic m >= min_count whether or not it stands out (W11); 0 if empty or flat.
  int dominant_count = 0;
  /// Peak-to-peak normal deviation without the modes m < min_count (W12), wrinkles or not.
  double residual_amplitude = 0.0;
  /// The rule that decided (evaluate_ring gives `wrinkled` to every ring with a wrinkle peak;
  /// evaluate_wrinkles turns those at or below the threshold into `below_threshold`).
  RingDecision decision = RingDecision::empty;
  double mean_radius = 0.0;  ///< rho-bar of the deformed ring
  int n_points = 0;          ///< sampled ring points (0: the ring misses the surface)
  double sector_deg = 0.0;   ///< sector used (360, 180, 90, 45); 0 if n_points < 4
  /// (m, A_m) for the full-circle counts m = 0, s, 2s, ... <= m_cap (s = 180 / sector_deg on a
  /// sector, 1 on a full circle; m_cap = min(max_count, half the full-circle equivalent number
  /// of ring points)). A_m is the amplitude (half peak-to-peak) of harmonic m [mm].
  std::vector<std::pair<int, double>> spectrum;
  /// The global shape's envelope E_m at each count of `spectrum` (W15) [mm]; 0 for m <= 2.
  std::vector<double> envelope;
  /// The counts of the wrinkle band, increasing: the peaks m >= min_count with
  /// A_m > peak_ratio E_m (W16) and a valley below them (W18), and the foot of each, its contiguous
  /// neighbours m >= min_count with A_m > E_m (W17); all above round-off. Empty: no wrinkles.
  std::vector<int> band;
};

/// Ring settings plus the wrinkled/unwrinkled criterion.
struct WrinkleMeasureSettings {
  RingSettings rings;
  double thickness = 0.0;           ///< membrane thickness [mm], > 0
  double threshold_fraction = 0.1;  ///< wrinkled when max amplitude > this * thickness; > 0
};

struct WrinkleReport {
  std::vector<RingMetrics> rings;  ///< in the order of RingSettings::latitudes_deg
  double max_amplitude = 0.0;      ///< largest ring amplitude [mm]
  double threshold = 0.0;          ///< threshold_fraction * thickness [mm]
  bool wrinkled = false;           ///< max_amplitude > threshold (wrinkles.md, W14)
};

/// The global shape's envelope at each entry of `amplitudes` (wrinkles.md, W15): for the count
/// m_i = counts[i], E_i = max over the entries with 2 <= m_k <= max(2, m_i / 2), m_k < m_i, of
/// A_k (m_k / m_i)^2; 0 when there is none. `counts` increasing, positive except a leading 0.
std::vector<double> shape_envelope(const std::vector<int>& counts,
                                   const std::vector<double>& amplitudes);

/// The valley below the harmonic at index `peak` (wrinkles.md, W18): the smallest count m with
/// max(floor(m*/2), 1) <= m < m* (m* = counts[peak]) whose amplitude, and that of m + 1 when m + 1
/// is a count below m*, are both below amplitudes[peak] / ratio; -1 when there is none (the
/// harmonic is not separated from the lower counts: no wrinkle peak); 0 when m* <= 2 (only
/// with min_count <= 2: no global band below to separate from). `counts` increasing.
int wrinkle_valley(const std::vector<int>& counts, const std::vector<double>& amplitudes,
                   std::size_t peak, double ratio);

/// Throws Error naming the rule if: axis not in 0..2, a latitude not in (-90, 90) or not finite,
/// min_count < 1, max_count < min_count, sector_deg not one of 45, 90, 180, 360, peak_ratio
/// not finite or < 1.
void validate_ring_settings(const RingSettings& options);

/// Sector of a ring from the reference azimuths of its points [rad]: the span 2 pi - (largest
/// gap between consecutive azimuths, cyclically), rounded to the nearest of 45, 90, 180, 360
/// degrees in ratio; `start` is the azimuth after the largest gap (0 for 360). Needs >= 2 angles.
struct DetectedSector {
  double sector_deg = 360.0;
  double start = 0.0;  ///< [rad]
};
DetectedSector detect_sector(std::vector<double> theta);

/// Metrics of the ring at `latitude_deg` on `surface` (wrinkles.md, sections 2-5). A ring that
/// misses the surface or has fewer than 4 points gets count 0, amplitude 0, sector_deg 0 and
/// the decision `empty`. A ring with a wrinkle peak gets `wrinkled` whatever its amplitude (the
/// threshold is evaluate_wrinkles' business).
RingMetrics evaluate_ring(const RingSurface& surface, const RingSettings& options,
                          double latitude_deg);

/// All rings of `options.rings` on the outer surface given by `triangles` (node indices into
/// `reference_nodes`, outward right-hand orientation), with nodal `displacement` (one per node,
/// mm), and the wrinkled flag. A ring whose wrinkle amplitude is at most the threshold has the
/// decision `below_threshold`. Throws Error on invalid options or inconsistent sizes.
WrinkleReport evaluate_wrinkles(const std::vector<Vec3d>& reference_nodes,
                                const std::vector<std::array<int, 3>>& triangles,
                                const std::vector<Vec3d>& displacement,
                                const WrinkleMeasureSettings& options);

/// Same, on the sampling_triangles of `mesh` tagged `outer_tag`. Throws Error if the tag is
/// missing.
WrinkleReport evaluate_wrinkles(const Mesh& mesh, const std::vector<Vec3d>& displacement,
                                const WrinkleMeasureSettings& options,
                                const std::string& outer_tag = "outer");

/// The corner triples of the triangles of `mesh` tagged `tag`. Throws Error if the tag is missing.
std::vector<std::array<int, 3>> tagged_triangles(const Mesh& mesh, const std::string& tag);

/// The triangles the rings are sampled on (wrinkles.md, W4): those of tagged_triangles on a linear
/// mesh; on a second-order mesh each 6-node face split into its 4 corner and middle triangles
/// through the edge nodes, in the face's orientation, so the rings see the quadratic surface at
/// its nodes (twice the resolution of the corners alone).
std::vector<std::array<int, 3>> sampling_triangles(const Mesh& mesh, const std::string& tag);

}  // namespace plisse
