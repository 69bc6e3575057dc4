#pragma once
/// Wrinkle metrics along straight lines of the undeformed body (docs/theory/wrinkles.md, section
/// "Measurement lines", W20-W27): the crests of the deformed line's deviation from its smooth
/// shape, their largest crest-to-trough height and their wavelength. What rings cannot see: a
/// tube's axial wrinkles along a generator, a sheet's across its width, a film's along its length.
///
/// Typical use (mesh, displacement u per node, wall thickness t):
///   const LineGauge gauge(mesh, {0, 10, 0.01}, {50, 10, 0.01}, 200);
///   const LineSamples line = gauge.samples(u);
///   const LineMetrics m = measure_line(line.s, line.x, 3);
///   const bool wrinkled = m.crests > 0 && m.amplitude > 0.1 * t;
#include <string>
#include <vector>

#include "core/types.hpp"
#include "mesh/mesh.hpp"

namespace plisse {

/// Metrics of one line's state (wrinkles.md, W23-W26). Lengths in mm.
struct LineMetrics {
  /// Crests and troughs counted along the line (W24); 0 when fewer than the smallest count
  /// asked for (a smooth shape) or when the line is straight to round-off.
  int crests = 0;
  /// The largest height of a crest over the mean of the troughs beside it (W25); 0 when
  /// crests == 0.
  double amplitude = 0.0;
  /// Twice the mean distance between the zeros that separate the crests, along the line's deformed
  /// smooth shape (W26): the wavelength one sees; 0 when crests < 2.
  double wavelength = 0.0;
  /// The same along the undeformed line (the material wavelength); 0 when crests < 2.
  double reference_wavelength = 0.0;
  /// Peak to peak of the deviation w (W23), crests or not: how far the line is from its smooth
  /// shape.
  double deviation = 0.0;
};

/// One measurement line's metrics under the wrinkle threshold, as a run reports them.
struct LineReading {
  std::string name;
  LineMetrics metrics;
  bool wrinkled = false;  ///< crests counted and amplitude > the threshold (W27)
};

/// The metrics of a deformed line: `x` the deformed points at the increasing distances `s` along
/// the undeformed line (at least 8, equally spaced or not); `min_crests` >= 1 the smallest count
/// that makes wrinkles. Throws Error on inconsistent sizes, fewer than 8 points or s not
/// increasing.
LineMetrics measure_line(const std::vector<double>& s, const std::vector<Vec3d>& x, int min_crests);

/// Points along a line with their distances.
struct LineSamples {
  std::vector<double> s;
  std::vector<Vec3d> x;
};

/// Which end of a line lies on a mirror plane of the model, crossed at a right angle (W21).
enum class LineMirror { none, from, to };

/// A straight line of the undeformed body sampled at equally spaced points, each located once in
/// the mesh (analysis/point_location.hpp): its deformed positions for any nodal displacement.
class LineGauge {
 public:
  /// `points` >= 2 samples from `from` to `to` (distinct). A sample the mesh does not hold is
  /// still placed at its nearest point of the mesh; outside() says how far the worst one is.
  /// `mirror`: the end on a mirror plane, about which samples() continues the line.
  LineGauge(const Mesh& mesh, const Vec3d& from, const Vec3d& to, int points,
            LineMirror mirror = LineMirror::none);

  /// What measure_line takes: the deformed samples and their distances, with a mirrored end's
  /// reflection (W21): 2 points - 1 samples, the line as the whole body has it.
  LineSamples samples(const std::vector<Vec3d>& displacement) const;
  /// Distances of the samples from `from` [mm].
  const std::vector<double>& distances() const { return s_; }
  /// X + u at each sample: X its nearest point of the mesh (the sample itself inside a solid; on a
  /// shell's mid-surface, an imperfection's offset included), u interpolated there by the
  /// element's shape functions: the current shape of the body along the line.
  std::vector<Vec3d> deformed(const std::vector<Vec3d>& displacement) const;

  /// The sample farthest from the mesh: its index, the point, and its distance [mm] (0 when every
  /// sample lies in the body, or on a shell's mid-surface).
  struct Outside {
    int index = -1;
    Vec3d point = Vec3d::Zero();
    double distance = 0.0;
  };
  const Outside& outside() const { return outside_; }

 private:
  LineMirror mirror_;
  Vec3d direction_ = Vec3d::UnitX();  ///< of the undeformed line, from `from` to `to`
  std::vector<double> s_;
  std::vector<Vec3d> reference_;  ///< the samples' points of the mesh
  std::vector<std::vector<std::pair<int, double>>> weights_;
  Outside outside_;
};

}  // namespace plisse
