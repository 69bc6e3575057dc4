#include "app/history_columns.hpp"

#include <algorithm>
#include <limits>
#include <memory>
#include <set>

#include "analysis/point_location.hpp"
#include "analysis/wall_thickness.hpp"
#include "app/model_builder.hpp"
#include "app/output_reference.hpp"
#include "mesh/topology.hpp"
#include "output/history_writer.hpp"
#include "physics/dirichlet.hpp"
#include "terms/term_kind.hpp"

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
  add_reactions(c, mesh);
  // A wall: a shell or sheet (a cube's top and bottom are not one). A shell's mid-surface carries
  // its faces' tags on the same triangles: its thickness is the elements' own.
  if (const auto faces =
          c.mesh.wall_thickness() && !mesh.is_shell() ? wall_faces(mesh) : std::nullopt)
    wall_ = std::make_shared<const WallThickness>(mesh, *faces);
  add_probes(c.probes, mesh);
  add({"volume", "min_J", "strain_energy"}, [](const StepRecord& r, std::vector<double>& row) {
    double min_J = std::numeric_limits<double>::infinity();
    for (const auto& f : r.fields) min_J = std::min(min_J, f.J);
    row.insert(row.end(), {r.averages.volume, min_J, r.model.strain_energy()});
  });
  if (wall_) {
    add({"min_thickness"}, [wall = wall_](const StepRecord& r, std::vector<double>& row) {
      const std::vector<double> t = (*wall)(nodal_displacements(r.model));
      row.push_back(*std::min_element(t.begin(), t.end()));
    });
  }
  if (mesh.is_shell()) {
    add({"min_thickness"}, [](const StepRecord& r, std::vector<double>& row) {
      PLISSE_CHECK(r.shell, "history: min_thickness of a shell needs the step's shell outputs");
      double smallest = std::numeric_limits<double>::infinity();
      for (const shell::ShellOutputs& s : *r.shell) smallest = std::min(smallest, s.thickness);
      row.push_back(smallest);
    });
  }
  if (c.solver.stability.check)
    add({"negative_pivots", "expected_negative_pivots", "stable"}, [](const StepRecord& r,
                                                                      std::vector<double>& row) {
      row.insert(row.end(), {double(r.info.negative_pivots),
                             double(r.info.expected_negative_pivots), r.info.stable ? 1.0 : 0.0});
    });
  if (c.output.wrinkles.enabled()) {
    PLISSE_CHECK(meter, "history: the wrinkle columns need a wrinkle meter");
    add(meter->history_columns(), [meter](const StepRecord& r, std::vector<double>& row) {
      PLISSE_CHECK(r.wrinkles, "history: the wrinkle columns need the step's wrinkle metrics");
      for (double v : meter->history_values(*r.wrinkles)) row.push_back(v);
    });
  }
}

void HistoryColumns::add_reactions(const Case& c, const Mesh& mesh) {
  const int mirrors = mirror_planes(mirror_surfaces(c.terms), mesh);
  for (const TermEntry& entry : c.terms) {
    if (!entry.kind->constrain || entry.name.empty()) continue;
    const auto nodes =
        std::make_shared<const std::set<int>>(condition_nodes(mesh, entry.kind->surface(entry)));
    // Reaching a mirror plane, the condition continues across it: the whole body's reaction sums
    // the images (a symmetry condition's reaction is internal to the whole body).
    const int cut = entry.kind->mirror ? 0 : planes_reached(mesh, *nodes, mirrors);
    std::vector<std::string> names = xyz_columns("force_", entry.name);
    const std::vector<std::string> moments = xyz_columns("moment_", entry.name);
    names.insert(names.end(), moments.begin(), moments.end());
    if (cut != 0)
      for (const char* stem : {"full_force_", "full_moment_"}) {
        const std::vector<std::string> whole = xyz_columns(stem, entry.name);
        names.insert(names.end(), whole.begin(), whole.end());
      }
    add(names, [nodes, cut](const StepRecord& r, std::vector<double>& row) {
      const Vec3d f = r.model.node_reaction(*nodes);
      const Vec3d m = r.model.node_reaction_moment(*nodes);
      for (const Vec3d& v : {f, m})
        for (int k = 0; k < 3; ++k) row.push_back(v[k]);
      if (cut == 0) return;
      for (const Vec3d& v : {whole_body_force(f, cut), whole_body_moment(m, cut)})
        for (int k = 0; k < 3; ++k) row.push_back(v[k]);
    });
  }
  for (const Region& region : c.regions) {
    if (!region.rigid || region.name.empty()) continue;
    auto nodes = std::make_shared<const std::set<int>>(
        nodes_of_elements(mesh, region_elements(region, mesh)));
    add(xyz_columns("force_", region.name), [nodes](const StepRecord& r, std::vector<double>& row) {
      const Vec3d f = r.model.node_reaction(*nodes);
      for (int k = 0; k < 3; ++k) row.push_back(f[k]);
    });
  }
}

std::vector<std::string> probe_columns(ProbeField field, const std::string& probe) {
  std::vector<std::string> stems;
  switch (field) {
    case ProbeField::displacement:
      stems = {"ux", "uy", "uz"};
      break;
    case ProbeField::position:
      stems = {"x", "y", "z"};
      break;
    case ProbeField::pressure:
      stems = {"pressure"};
      break;
    case ProbeField::cauchy:
      stems = {"cauchy_xx", "cauchy_yy", "cauchy_zz", "cauchy_xy", "cauchy_yz", "cauchy_xz"};
      break;
    case ProbeField::von_mises:
      stems = {"von_mises"};
      break;
    case ProbeField::principal_stretches:
      stems = {"stretch_1", "stretch_2", "stretch_3"};
      break;
    case ProbeField::principal_stresses:
      stems = {"stress_1", "stress_2", "stress_3"};
      break;
    case ProbeField::J:
      stems = {"J"};
      break;
    case ProbeField::thickness:
      stems = {"thickness"};
      break;
  }
  for (std::string& stem : stems) stem += ":" + probe;
  return stems;
}

void HistoryColumns::add_probes(const std::vector<Probe>& probes, const Mesh& mesh) {
  if (probes.empty()) return;
  struct Located {
    std::vector<ProbeField> fields;
    int element;
    std::vector<std::pair<int, double>> weights;
  };
  std::vector<Located> located;
  std::vector<std::string> names;
  bool needs_F = false, needs_thickness = false;
  for (const Probe& probe : probes) {
    const MeshPoint at = locate_point(mesh, probe.point);
    probe_points_.push_back({probe.name, probe.point, at});
    located.push_back({probe.fields, at.element, interpolation_weights(mesh, at)});
    for (ProbeField f : probe.fields) {
      const std::vector<std::string> columns = probe_columns(f, probe.name);
      names.insert(names.end(), columns.begin(), columns.end());
      needs_F |= f == ProbeField::principal_stretches;
      needs_thickness |= f == ProbeField::thickness;
    }
  }
  const bool shell = mesh.is_shell();
  PLISSE_CHECK(!needs_thickness || wall_ || shell,
               "history: a probe of the thickness needs a wall");
  add(std::move(names), [located = std::move(located), needs_F, needs_thickness, shell, &mesh,
                         wall = wall_](const StepRecord& r, std::vector<double>& row) {
    // What several probes share, computed once a row.
    const std::vector<Vec3d> u = nodal_displacements(r.model);
    const std::vector<Mat3d> F =
        needs_F ? r.model.element_deformation_gradients() : std::vector<Mat3d>{};
    // A wall's thickness is a nodal field (interpolated at the point); a shell's, its
    // triangle's.
    const std::vector<double> thickness =
        needs_thickness && !shell ? (*wall)(u) : std::vector<double>{};
    PLISSE_CHECK(!(needs_thickness && shell) || r.shell != nullptr,
                 "history: a shell's thickness probe needs the step's shell outputs");
    for (const Located& at : located) {
      const ElementFields& cell = r.fields[static_cast<std::size_t>(at.element)];
      const auto push = [&row](const Vec3d& v) { row.insert(row.end(), {v[0], v[1], v[2]}); };
      for (ProbeField field : at.fields) switch (field) {
          case ProbeField::displacement:
            push(interpolate(at.weights, u));
            break;
          case ProbeField::position:
            push(interpolate(at.weights, mesh.nodes) + interpolate(at.weights, u));
            break;
          case ProbeField::pressure: {
            // The element's own pressures: where regions meet, its region's (twins).
            double p = 0.0;
            for (const auto& [node, weight] : at.weights)
              p += weight * r.model.element_pressure(at.element, node);
            row.push_back(p);
            break;
          }
          case ProbeField::cauchy:
            for (auto [i, j] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}})
              row.push_back(cell.cauchy(i, j));
            break;
          case ProbeField::von_mises:
            row.push_back(cell.von_mises);
            break;
          case ProbeField::principal_stretches:
            push(principal_stretches(F[static_cast<std::size_t>(at.element)]));
            break;
          case ProbeField::principal_stresses:
            push(principal_values(cell.cauchy));
            break;
          case ProbeField::J:
            row.push_back(cell.J);
            break;
          case ProbeField::thickness:
            row.push_back(shell ? (*r.shell)[static_cast<std::size_t>(at.element)].thickness
                                : interpolate(at.weights, thickness));
            break;
        }
    }
  });
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
    PLISSE_CHECK(row.size() - before == g.names.size(),
                 "history: the column group starting with '"
                     << (g.names.empty() ? std::string("(none)") : g.names.front()) << "' gave "
                     << row.size() - before << " values for " << g.names.size() << " columns");
  }
  return row;
}

}  // namespace plisse::app
