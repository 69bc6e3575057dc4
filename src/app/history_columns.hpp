#pragma once
/// The columns of history.csv as one table: each entry is a group of column names together with
/// the function that gives their values, so a header and its rows cannot drift apart.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "analysis/point_location.hpp"
#include "analysis/wall_thickness.hpp"
#include "app/wrinkling.hpp"
#include "case/case.hpp"
#include "solver/load_stepper.hpp"
#include "solver/mixed_model.hpp"

namespace plisse::app {

/// What one history row is computed from: a converged step and the model's state after it.
/// Everything is borrowed for the duration of HistoryColumns::row.
struct StepRecord {
  const StepInfo& info;
  const MixedModel& model;
  const std::vector<ElementFields>& fields;  ///< model.element_fields() of the state
  const BodyAverages& averages;              ///< model.averages(fields)
  const WrinkleMeter::Result* wrinkles;      ///< null without output.wrinkles
  /// model.shell_outputs() of the state for a shell (Mesh::is_shell), else null.
  const std::vector<shell::ShellOutputs>* shell = nullptr;
};

class HistoryColumns {
 public:
  /// The columns of a run of `c` on `model` (borrowed; its terms and mesh must outlive this), in
  /// the order of the contract: the standard ones (HistoryWriter::standard_columns), each term's
  /// columns, stretch, the averaged stretches and Cauchy stresses, reactions of named boundary
  /// conditions, the probes' fields (add_probes), volume, min_J, strain_energy, min_thickness (a
  /// mesh with a wall: wall_faces; a shell: its elements' thickness, StepRecord::shell), the
  /// stability columns (solver.stability.check) and the wrinkle columns (output.wrinkles,
  /// measured by `meter`, borrowed; required then).
  HistoryColumns(const Case& c, const MixedModel& model, const WrinkleMeter* meter);

  /// All column names, in row order.
  const std::vector<std::string>& names() const { return names_; }
  /// The names after the standard columns (what HistoryWriter's constructor takes).
  std::vector<std::string> extra_names() const;
  /// The wall's thickness measure (analysis/wall_thickness.hpp), or null when the case has no
  /// wall (a cube, a file mesh without `thickness`) or its mesh no wall_faces, and for a shell,
  /// whose faces are one mid-surface (its thickness is ShellOutputs::thickness).
  const WallThickness* wall_thickness() const { return wall_.get(); }
  /// The values of one row, in the order of names(). Throws plisse::Error when a group gives
  /// another count of values than it has names (a programming error, never a user's).
  std::vector<double> row(const StepRecord& record) const;

  /// Where each probe of the case lies in the mesh (analysis/point_location.hpp), in the case's
  /// order.
  struct ProbePoint {
    std::string name;
    Vec3d point;  ///< as given [mm]
    MeshPoint at;
  };
  const std::vector<ProbePoint>& probe_points() const { return probe_points_; }

 private:
  using Values = std::function<void(const StepRecord&, std::vector<double>&)>;
  struct Group {
    std::vector<std::string> names;
    Values append;  ///< appends exactly names.size() values
  };
  void add(std::vector<std::string> names, Values append);
  /// The probes' columns, one group for all (they share the nodal fields of a row).
  void add_probes(const std::vector<Probe>& probes, const Mesh& mesh);
  /// The reactions of the named boundary conditions (`force_x:<name>` ..., and
  /// `full_force_x:<name>`
  /// ... for one that reaches a mirror plane) and of the named rigid regions.
  void add_reactions(const Case& c, const Mesh& mesh);

  std::vector<Group> groups_;
  std::vector<std::string> names_;
  std::shared_ptr<const WallThickness> wall_;
  std::vector<ProbePoint> probe_points_;
};

/// The history columns of one field of the probe named `probe`, in row order (`ux:<probe>`, ...).
std::vector<std::string> probe_columns(ProbeField field, const std::string& probe);

}  // namespace plisse::app
