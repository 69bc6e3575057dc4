#pragma once
/// What `plisse run`, `plisse check` and `plisse wrinkles` share about wrinkling: the case's mesh
/// with its imperfection, the stepper's stability options, and the wrinkle metrics of a converged
/// state (rings, tension-field state) in the form of history columns, VTU fields and the
/// summary.json table (docs/architecture.md, "Stability and wrinkling"; docs/theory/wrinkles.md).
#include <array>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/tension_field.hpp"
#include "analysis/wrinkle_lines.hpp"
#include "analysis/wrinkle_rings.hpp"
#include "case/case.hpp"
#include "mesh/mesh.hpp"
#include "output/append_file.hpp"
#include "solver/load_stepper.hpp"
#include "solver/mixed_model.hpp"

namespace plisse::app {

/// The case's mesh, checked against the case, with the geometric imperfection of
/// solver.stability applied (random, or the shape of an earlier run's eigenmode). An imperfection
/// that cannot be applied (amplitude inverting elements, missing or mismatched mode file) is an
/// InputError at its key.
Mesh load_perturbed_mesh(const Case& c);

/// The largest distance [mm] load_perturbed_mesh's imperfection moves a node: the relative
/// amplitude solver.stability.imperfection × the wall's thickness (imperfections.md, I1-I2); 0
/// without an imperfection.
double imperfection_amplitude(const Case& c);

/// solver.stability mapped to the stepper's options (the perturbation in mm: branch_amplitude x
/// wall thickness).
StabilityCheckSettings stability_check_settings(const Case& c);

/// Wrinkle metrics of converged states of one model (output.wrinkles). Holds the outer
/// triangles and the through-thickness columns, computed once; on a shell mesh the rings lie on
/// the mid-surface triangles of the surface tag and each triangle is its own column.
class WrinkleMeter {
 public:
  /// Requires c.output.wrinkles.enabled() and a wall thickness (checked with the case).
  WrinkleMeter(const Case& c, const Mesh& mesh);

  struct Result {
    WrinkleReport rings;             ///< no rings without output.wrinkles.rings_deg
    std::vector<LineReading> lines;  ///< in the order of output.wrinkles.lines
    TensionField tension;
    /// A ring or a line is wrinkled (wrinkles.md, W14, W27).
    bool wrinkled() const;
  };
  /// Metrics of the model's current state, whose element_fields() are `fields`.
  Result evaluate(const MixedModel& model, const std::vector<ElementFields>& fields) const;
  /// The same from a state given by its nodal displacements `u` and per-element Cauchy stress
  /// and J (a step file's fields) on `mesh`, the mesh this meter was made for (on a shell, one
  /// stress per triangle, its thickness average; J is not used).
  Result evaluate(const Mesh& mesh, const std::vector<Vec3d>& u, const std::vector<Mat3d>& sigma,
                  const std::vector<double>& J) const;

  /// History columns and their values. With rings: wrinkle_amplitude (largest ring wrinkle
  /// amplitude, mm; 0 when no ring has a wrinkle peak), wrinkle_count (count of that ring when its
  /// amplitude is above the threshold, else 0), wrinkle_peak_count (count of that ring, threshold
  /// or not; 0 when no ring has a wrinkle peak). Always: wrinkled_fraction (outer area fraction in
  /// the wrinkled state), slack_fraction. Per line: wrinkle_crests:<line> (its crests when it is
  /// wrinkled, else 0), wrinkle_peak_crests:<line> (threshold or not), wrinkle_amplitude:<line>,
  /// wrinkle_wavelength:<line> (mm, along the deformed line).
  std::vector<std::string> history_columns() const;
  std::vector<double> history_values(const Result& r) const;

 private:
  WrinkleMeasureSettings options_;
  bool rings_ = false;  ///< the case measures rings
  std::string surface_;
  struct Line {
    std::string name;
    int min_crests = 4;
    LineGauge gauge;
  };
  std::vector<Line> lines_;
  std::vector<std::array<int, 3>> triangles_;       ///< the surface's corner triangles
  std::vector<std::array<int, 3>> ring_triangles_;  ///< sampling_triangles of the surface
  std::vector<int> columns_;        ///< solid meshes: the triangle of each tetrahedron's column
  std::vector<int> shell_surface_;  ///< shell meshes: the surface's triangles (= elements)
  std::vector<double> triangle_area_;
};

/// The summary.json table: {"wrinkled", "max_amplitude", "threshold", "peak_ratio",
/// "min_count", "thickness", "axis", "surface", "rings": [{"latitude_deg", "decision", "count",
/// "amplitude", "wavelength", "dominant_count", "residual_amplitude", "band", "mean_radius",
/// "points", "sector_deg", "spectrum": [[m, A_m, E_m], ...]}], "lines": [{"name", "wrinkled",
/// "crests", "amplitude", "wavelength", "reference_wavelength", "deviation", "from", "to",
/// "points", "min_crests"}], "tension_field": {"taut", "wrinkled", "slack"} (element counts)}
/// (docs/case-file.md, "Wrinkle metrics").
nlohmann::json wrinkles_json(const Case& c, const WrinkleMeter::Result& r);

/// wrinkle_spectrum.csv of a run directory (docs/case-file.md, "Wrinkle metrics"): each ring's
/// spectrum at every written step, one row per step, ring and count m, with the columns
///   step,time,latitude_deg,m,amplitude,envelope,in_band,decision
/// (A_m and E_m in mm, wrinkles.md W10 and W15; in_band 1 for the counts of the wrinkle band,
/// W17; decision the ring's, W16-W18), so a user sees how each ring's decision evolved. Numbers
/// are written as the shortest text that reads back to the same double. Like history.csv, the
/// file grows by one append per written step (output/append_file.hpp), so it holds whole lines.
class WrinkleSpectrumWriter {
 public:
  static constexpr const char* kFileName = "wrinkle_spectrum.csv";
  static const char* header();
  /// Creates (or replaces) `path` with the header and no rows.
  explicit WrinkleSpectrumWriter(std::filesystem::path path);
  /// Continues the file of a resumed run: keeps the rows of steps <= `last_step` (the
  /// checkpoint's), without an unterminated last line, and rewrites it atomically. A missing file
  /// (a run from before this file existed) is started anew; a file with another header throws
  /// InputError (key --resume).
  static WrinkleSpectrumWriter reopen(std::filesystem::path path, int last_step);
  /// Appends the rows of every ring of `report` at (step, time) to the file, in one write.
  void add_step(int step, double time, const WrinkleReport& report);
  const std::filesystem::path& path() const { return path_; }

 private:
  WrinkleSpectrumWriter() = default;  // for reopen()
  std::filesystem::path path_;
  std::optional<AppendFile> file_;  ///< opened by the first add_step
};

/// Displacements of every node of the model's current state.
std::vector<Vec3d> nodal_displacements(const MixedModel& model);

}  // namespace plisse::app
