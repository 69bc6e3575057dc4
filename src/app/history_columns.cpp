#include "app/history_columns.hpp"

#include <algorithm>
#include <limits>

#include "analysis/wall_thickness.hpp"
#include "app/output_reference.hpp"
#include "io/history_writer.hpp"
#include "mesh/topology.hpp"

namespace plisse::app {
namespace {

/// "<prefix>x:<name>", "<prefix>y:<name>", "<prefix>z:<name>".
std::vector<std::string> xyz_columns(const std::string& prefix, const std::string& name) {
  return {prefix + "x:" + name, prefix + "y:" + name, prefix + "z:" + name};
}

}  // namespace

void HistoryColumns::add(std::vector<std::string> names, Values append) {
  for (const std::string& name : names) require_output_entry(OutputTable::history, name);
  names_.insert(names_.end(), names.begin(), names.end());
  groups_.push_back({std::move(names), std::move(append)});
}

HistoryColumns::HistoryColumns(const Case& c, const MixedModel& model, const WrinkleMeter* meter) {
  add(HistoryWriter::standard_columns(), [](const StepRecord& r, std::vector<double>& row) {
    const StepInfo& i = r.info;
    row.insert(row.end(), {double(i.step), i.time, i.load_factor, double(i.newton_iterations),
                           i.residual_norm});
  });
  for (const auto& term : model.terms()) {
    const ModelTerm* t = term.get();
    add(t->history_columns(), [t](const StepRecord& r, std::vector<double>& row) {
      for (double v : t->history_values(r.info.time, r.model.state())) row.push_back(v);
    });
  }
  if (c.output.stretch_axis) {
    const int a = *c.output.stretch_axis - 'x';
    add({"stretch"},
        [a](const StepRecord& r, std::vector<double>& row) { row.push_back(r.averages.F(a, a)); });
  }
  add({"stretch_x", "stretch_y", "stretch_z"}, [](const StepRecord& r, std::vector<double>& row) {
    for (int k = 0; k < 3; ++k) row.push_back(r.averages.F(k, k));
  });
  add({"cauchy_xx", "cauchy_yy", "cauchy_zz", "cauchy_xy", "cauchy_yz", "cauchy_xz"},
      [](const StepRecord& r, std::vector<double>& row) {
        for (auto [i, j] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}})
          row.push_back(r.averages.cauchy(i, j));
      });
  const Mesh& mesh = model.mesh();
  for (const BoundaryCondition& bc : c.boundary) {
    if (bc.name.empty()) continue;
    const std::vector<int>* triangles = &mesh.surface_tags.at(bc.surface.name);
    add(xyz_columns("force_", bc.name), [triangles](const StepRecord& r, std::vector<double>& row) {
      const Vec3d f = r.model.reaction(*triangles);
      for (int k = 0; k < 3; ++k) row.push_back(f[k]);
    });
  }
  for (const Probe& probe : c.probes) {
    const int node = nearest_node(mesh, probe.point);
    add(xyz_columns("u", probe.name), [node](const StepRecord& r, std::vector<double>& row) {
      for (int k = 0; k < 3; ++k) row.push_back(r.model.state()[DofMap::dof(node, k)]);
    });
  }
  add({"volume", "min_J", "strain_energy"}, [](const StepRecord& r, std::vector<double>& row) {
    double min_J = std::numeric_limits<double>::infinity();
    for (const auto& f : r.fields) min_J = std::min(min_J, f.J);
    row.insert(row.end(), {r.averages.volume, min_J, r.model.strain_energy()});
  });
  // A wall: a shell or sheet (a cube's top and bottom are not one).
  if (const auto faces = c.mesh.wall_thickness() ? wall_faces(mesh) : std::nullopt) {
    wall_ = std::make_shared<const WallThickness>(mesh, *faces);
    add({"min_thickness"}, [wall = wall_](const StepRecord& r, std::vector<double>& row) {
      const std::vector<double> t = (*wall)(nodal_displacements(r.model));
      row.push_back(*std::min_element(t.begin(), t.end()));
    });
  }
  if (c.solver.stability.check)
    add({"negative_pivots", "expected_negative_pivots", "stable"}, [](const StepRecord& r,
                                                                      std::vector<double>& row) {
      row.insert(row.end(), {double(r.info.negative_pivots),
                             double(r.info.expected_negative_pivots), r.info.stable ? 1.0 : 0.0});
    });
  if (c.output.wrinkles.enabled()) {
    FE_CHECK(meter, "history: the wrinkle columns need a wrinkle meter");
    add(WrinkleMeter::history_columns(), [meter](const StepRecord& r, std::vector<double>& row) {
      FE_CHECK(r.wrinkles, "history: the wrinkle columns need the step's wrinkle metrics");
      for (double v : meter->history_values(*r.wrinkles)) row.push_back(v);
    });
  }
}

std::vector<std::string> HistoryColumns::extra_names() const {
  const std::size_t n_standard = HistoryWriter::standard_columns().size();
  return {names_.begin() + static_cast<std::ptrdiff_t>(n_standard), names_.end()};
}

std::vector<double> HistoryColumns::row(const StepRecord& record) const {
  std::vector<double> row;
  row.reserve(names_.size());
  for (const Group& g : groups_) {
    const std::size_t before = row.size();
    g.append(record, row);
    FE_CHECK(row.size() - before == g.names.size(),
             "history: the column group starting with '"
                 << (g.names.empty() ? std::string("(none)") : g.names.front()) << "' gave "
                 << row.size() - before << " values for " << g.names.size() << " columns");
  }
  return row;
}

}  // namespace plisse::app
