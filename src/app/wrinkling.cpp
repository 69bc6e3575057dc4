#include "app/wrinkling.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <set>
#include <utility>

#include "analysis/surface_columns.hpp"
#include "core/error.hpp"
#include "mesh/bounding_box.hpp"
#include "mesh/imperfection.hpp"
#include "mesh/shell_surface.hpp"
#include "mesh/topology.hpp"
#include "output/atomic_file.hpp"
#include "output/history_writer.hpp"
#include "output/pvd_writer.hpp"
#include "output/vtu_reader.hpp"
#include "physics/dirichlet.hpp"
#include "solver/dof_map.hpp"
#include "terms/term_kind.hpp"

namespace plisse::app {
namespace {

namespace fs = std::filesystem;

InputPlace imperfection_place(const Case& c) {
  InputPlace place = c.solver.stability.place;
  place.key = "solver.stability.imperfection";
  return place;
}

/// The VTU file holding the point field `field`: the file itself, or the first step of the run
/// directory's solution.pvd that has it (the step where the stability check found an instability).
fs::path find_mode_file(const Case& c, const std::string& field) {
  const fs::path from = c.solver.stability.imperfection_from;
  InputPlace place = c.solver.stability.place;
  place.key = "solver.stability.imperfection_from";
  std::error_code ec;
  if (!fs::exists(from, ec))
    throw InputError(place,
                     "'" + from.string() + "' does not exist (a run directory or a .vtu file)");
  if (!fs::is_directory(from, ec)) return from;
  const fs::path pvd = from / "solution.pvd";
  if (!fs::exists(pvd, ec))
    throw InputError(place,
                     "'" + from.string() + "' holds no solution.pvd: not a plisse run directory");
  std::vector<PvdEntry> entries;
  try {
    entries = read_pvd(pvd);
  } catch (const Error& e) {
    throw InputError(place, std::string("cannot read ") + pvd.string() + ": " + e.what());
  }
  for (const PvdEntry& entry : entries) {
    const fs::path file = from / entry.file;
    try {
      for (const VtuArrayInfo& info : read_vtu_summary(file).point_fields)
        if (info.name == field) return file;
    } catch (const Error&) {
      // A damaged step file cannot hold the mode; keep looking.
    }
  }
  throw InputError(place,
                   "no step of the run in '" + from.string() + "' holds the field '" + field +
                       "' (modes are written at the step where the stability check finds "
                       "a new instability: run that case with solver.stability.check: true)");
}

std::vector<Vec3d> mode_shape(const Case& c, const Mesh& mesh) {
  const std::string field = "mode_" + std::to_string(c.solver.stability.imperfection_mode);
  const fs::path file = find_mode_file(c, field);
  InputPlace place = c.solver.stability.place;
  place.key = "solver.stability.imperfection_from";
  VtuField values;
  try {
    values = read_vtu_point_field(file, field);
  } catch (const Error& e) {
    throw InputError(place,
                     "cannot read the field '" + field + "' of " + file.string() + ": " + e.what());
  }
  if (values.n_components != 3 ||
      values.values.size() != 3 * static_cast<std::size_t>(mesh.n_nodes()))
    throw InputError(
        place, file.string() + " has " +
                   std::to_string(values.values.size() / std::max(values.n_components, 1)) +
                   " points with " + std::to_string(values.n_components) + " components in '" +
                   field + "'; this case's mesh has " + std::to_string(mesh.n_nodes()) +
                   " nodes (the mode must come from a run on the same mesh)");
  std::vector<Vec3d> shape(mesh.n_nodes());
  for (int v = 0; v < mesh.n_nodes(); ++v)
    shape[v] = Vec3d(values.values[3 * v], values.values[3 * v + 1], values.values[3 * v + 2]);
  return shape;
}

double triangle_area(const Mesh& mesh, const std::array<int, 3>& t) {
  return 0.5 *
         (mesh.nodes[t[1]] - mesh.nodes[t[0]]).cross(mesh.nodes[t[2]] - mesh.nodes[t[0]]).norm();
}

}  // namespace

namespace {

/// Nodes of a symmetry surface within rounding (1e-9 of the body's extent) of its plane are put
/// on it exactly, at the median of their coordinates. The pressure and cavity terms tell a
/// symmetric tangent by exact coordinates on the planes (pressure_stiffness_is_symmetric): a node
/// at 1e-16 from x = 0 made the tangent unsymmetric and the factorisation LU. Surfaces that are
/// not a coordinate plane are left to the boundary condition's own check.
void snap_to_symmetry_planes(const Case& c, Mesh& mesh) {
  if (mesh.nodes.empty()) return;
  const BoundingBox box = bounding_box(mesh.nodes);
  const double rounding = 1e-9 * std::max((box.high - box.low).maxCoeff(), 1e-300);
  for (const std::string& surface : mirror_surfaces(c.terms)) {
    int axis = -1;
    std::set<int> nodes;
    if (const std::vector<int>* edges = shell_edge_tag(mesh, surface)) {
      axis = shell_edge_plane_axis(mesh, *edges, 1e-6);
      nodes = edge_nodes(mesh, *edges);
    } else if (const auto tag = mesh.surface_tags.find(surface); tag != mesh.surface_tags.end()) {
      axis = coordinate_plane_axis(mesh, tag->second);
      nodes = triangle_nodes(mesh, tag->second);
    }
    if (axis < 0) continue;
    std::vector<double> values;
    for (const int v : nodes) values.push_back(mesh.nodes[v][axis]);
    std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
    const double plane = values[values.size() / 2];
    for (const int v : nodes)
      if (std::abs(mesh.nodes[v][axis] - plane) <= rounding) mesh.nodes[v][axis] = plane;
  }
}

/// The nodes a shell's symmetry conditions hold in their planes, with the planes' normals: the
/// nodes of each symmetry edge and the axis its condition holds (shell_edge_plane_axis, as
/// hold_in_plane decides it), or of a symmetry surface tag in a coordinate plane. A condition
/// whose plane cannot be decided is left out here; the model builder refuses it at its key.
std::vector<HeldPlane> shell_symmetry_planes(const Case& c, const Mesh& mesh) {
  std::vector<HeldPlane> planes;
  for (const std::string& surface : mirror_surfaces(c.terms)) {
    int axis = -1;
    std::set<int> nodes;
    if (const std::vector<int>* edges = shell_edge_tag(mesh, surface)) {
      axis = shell_edge_plane_axis(mesh, *edges);
      nodes = edge_nodes(mesh, *edges);
    } else if (const auto tag = mesh.surface_tags.find(surface); tag != mesh.surface_tags.end()) {
      axis = coordinate_plane_axis(mesh, tag->second);
      nodes = triangle_nodes(mesh, tag->second);
    }
    if (axis < 0) continue;
    planes.push_back({std::vector<int>(nodes.begin(), nodes.end()), Vec3d::Unit(axis)});
  }
  return planes;
}

/// The components a shell's `displacement` conditions prescribe, as planes their nodes stay in:
/// a seam held on a mid-plane (`value: [~, 0, ~]`) stays on it under a random imperfection,
/// which would otherwise lift it along the flat wall's normal, off the plane that closes a
/// cavity. (Fully held edges move with the wall, as a solid's supports do.)
std::vector<HeldPlane> shell_prescribed_planes(const Case& c, const Mesh& mesh) {
  std::vector<HeldPlane> planes;
  for (const TermEntry& entry : c.terms) {
    if (entry.kind->word != "displacement" || !entry.kind->constrain) continue;
    std::array<std::vector<int>, 3> held;
    for (const ConstrainedComponent& cc : collect_constraints({entry}, mesh))
      held[static_cast<std::size_t>(cc.component)].push_back(cc.node);
    for (int k = 0; k < 3; ++k)
      if (!held[static_cast<std::size_t>(k)].empty())
        planes.push_back({held[static_cast<std::size_t>(k)], Vec3d::Unit(k)});
  }
  return planes;
}

/// The sides of a shell's clamped and symmetry edges (Mesh::side_mirrors), from the reference
/// positions the model starts from, and the sides where it meets a rigid region, which are
/// clamped to it (clamp_to_rigid: a rigid region only translates).
void hold_shell_slopes(const Case& c, Mesh& mesh) {
  if (!mesh.is_shell()) return;
  for (const TermEntry& entry : c.terms)
    if (entry.kind->hold_slope) entry.kind->hold_slope(entry, mesh);
  std::vector<char> rigid(mesh.triangles.size(), 0);
  bool any = false;
  for (const Region& r : c.regions) {
    if (!r.rigid) continue;
    for (int t : region_elements(r, mesh)) rigid[static_cast<std::size_t>(t)] = 1;
    any = true;
  }
  if (any) clamp_to_rigid(mesh, rigid);
}

}  // namespace

double imperfection_amplitude(const Case& c) {
  const double relative = c.solver.stability.imperfection;
  return relative > 0.0 ? relative * *c.mesh.wall_thickness() : 0.0;
}

Mesh load_perturbed_mesh(const Case& c) {
  Mesh mesh = load_case_mesh(c);
  check_case_against_mesh(c, mesh);
  snap_to_symmetry_planes(c, mesh);
  const StabilitySettings& st = c.solver.stability;
  if (st.imperfection <= 0.0) {
    hold_shell_slopes(c, mesh);
    return mesh;
  }
  const double amplitude = imperfection_amplitude(c);
  std::vector<Vec3d> field;
  try {
    if (st.imperfection_kind == "mode") {
      field = compute_mode_imperfection(mesh, mode_shape(c, mesh), amplitude);
    } else {
      const std::string& tag = c.output.wrinkles.surface;
      if (!mesh.surface_tags.count(tag))
        throw InputError(imperfection_place(c),
                         "a random imperfection moves the wall along the normals of the surface '" +
                             tag + "' (output.wrinkles.surface), which the mesh does not have");
      if (mesh.is_shell()) {
        std::vector<HeldPlane> held = shell_symmetry_planes(c, mesh);
        for (HeldPlane& plane : shell_prescribed_planes(c, mesh)) held.push_back(std::move(plane));
        field = compute_random_imperfection(mesh, tagged_triangles(mesh, tag), amplitude,
                                            static_cast<std::uint64_t>(st.seed), {}, held);
      } else
        field = compute_random_imperfection(mesh, tagged_triangles(mesh, tag), amplitude,
                                            static_cast<std::uint64_t>(st.seed),
                                            mirror_surfaces(c.terms));
    }
    apply_imperfection(mesh, field);
    snap_to_symmetry_planes(c, mesh);  // the imperfection keeps plane nodes in their plane
  } catch (const InputError&) {
    throw;
  } catch (const Error& e) {
    throw InputError(imperfection_place(c), e.what());
  }
  hold_shell_slopes(c, mesh);
  return mesh;
}

StabilityCheckSettings stability_check_settings(const Case& c) {
  const StabilitySettings& st = c.solver.stability;
  StabilityCheckSettings o;
  o.check = st.check;
  o.branch_switch = st.branch_switch;
  o.modes = st.modes;
  o.stop_when_unstable = st.stop_when_unstable;
  o.koiter_start = st.branch_start == "koiter";
  if (st.branch_switch) o.perturbation_mm = st.branch_amplitude * *c.mesh.wall_thickness();
  return o;
}

WrinkleMeter::WrinkleMeter(const Case& c, const Mesh& mesh)
    : rings_(c.output.wrinkles.has_rings()), surface_(c.output.wrinkles.surface) {
  const WrinkleSettings& w = c.output.wrinkles;
  options_.rings.axis = w.axis - 'x';
  options_.rings.center = w.center;
  options_.rings.latitudes_deg = w.rings_deg;
  options_.rings.min_count = w.min_count;
  options_.rings.peak_ratio = w.peak_ratio;
  options_.thickness = *c.mesh.wall_thickness();
  options_.threshold_fraction = w.threshold;
  triangles_ = tagged_triangles(mesh, surface_);
  ring_triangles_ = sampling_triangles(mesh, surface_);
  // A shell's triangles are its elements and each is its own column (wrinkles.md, T1s).
  if (mesh.is_shell())
    shell_surface_ = mesh.surface_tags.at(surface_);
  else
    columns_ = assign_columns(mesh.nodes, mesh.tets, triangles_);
  triangle_area_.reserve(triangles_.size());
  for (const auto& t : triangles_) triangle_area_.push_back(triangle_area(mesh, t));
  for (const WrinkleLine& line : w.lines)
    lines_.push_back({line.name, line.min_crests,
                      LineGauge(mesh, line.from, line.to, line.points, line.mirror)});
}

bool WrinkleMeter::Result::wrinkled() const {
  return rings.wrinkled || std::any_of(lines.begin(), lines.end(),
                                       [](const LineReading& line) { return line.wrinkled; });
}

WrinkleMeter::Result WrinkleMeter::evaluate(const MixedModel& model,
                                            const std::vector<ElementFields>& fields) const {
  std::vector<Mat3d> sigma(fields.size());
  std::vector<double> J(fields.size());
  for (std::size_t e = 0; e < fields.size(); ++e) {
    sigma[e] = fields[e].cauchy;
    J[e] = fields[e].J;
  }
  return evaluate(model.mesh(), nodal_displacements(model), sigma, J);
}

WrinkleMeter::Result WrinkleMeter::evaluate(const Mesh& mesh, const std::vector<Vec3d>& u,
                                            const std::vector<Mat3d>& sigma,
                                            const std::vector<double>& J) const {
  Result r;
  if (rings_) {
    r.rings = evaluate_wrinkles(mesh.nodes, ring_triangles_, u, options_);
  } else {
    r.rings.threshold = options_.threshold_fraction * options_.thickness;
  }
  // W27: a line is wrinkled when it has crests and their height passes the rings' threshold.
  for (const Line& line : lines_) {
    const LineSamples samples = line.gauge.samples(u);
    const LineMetrics m = measure_line(samples.s, samples.x, line.min_crests);
    r.lines.push_back({line.name, m, m.crests > 0 && m.amplitude > r.rings.threshold});
  }
  if (mesh.is_shell())
    r.tension = compute_shell_tension_field(mesh.nodes, mesh.triangles, shell_surface_, u, sigma);
  else
    r.tension = compute_tension_field(mesh.nodes, mesh.tets, triangles_, columns_, u, sigma, J);
  return r;
}

std::vector<std::string> WrinkleMeter::history_columns() const {
  std::vector<std::string> names;
  if (rings_) names = {"wrinkle_amplitude", "wrinkle_count", "wrinkle_peak_count"};
  names.insert(names.end(), {"wrinkled_fraction", "slack_fraction"});
  for (const Line& line : lines_)
    for (const char* stem :
         {"wrinkle_crests:", "wrinkle_peak_crests:", "wrinkle_amplitude:", "wrinkle_wavelength:"})
      names.push_back(stem + line.name);
  return names;
}

std::vector<double> WrinkleMeter::history_values(const Result& r) const {
  int count = 0;
  double best = -1.0;
  for (const RingMetrics& ring : r.rings.rings)
    if (ring.amplitude > best) {
      best = ring.amplitude;
      count = ring.count;
    }
  // Below the threshold the largest peak is a count of mesh noise or of wrinkles not yet grown:
  // wrinkle_count says 0, wrinkle_peak_count keeps it (an instability's onset reads it).
  const int wrinkled_count = r.rings.wrinkled ? count : 0;
  double total = 0.0, wrinkled = 0.0, slack = 0.0;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    total += triangle_area_[t];
    if (r.tension.triangle_state[t] == MembraneState::wrinkled) wrinkled += triangle_area_[t];
    if (r.tension.triangle_state[t] == MembraneState::slack) slack += triangle_area_[t];
  }
  const double scale = total > 0.0 ? 1.0 / total : 0.0;
  std::vector<double> values;
  if (rings_)
    values = {r.rings.max_amplitude, static_cast<double>(wrinkled_count),
              static_cast<double>(count)};
  values.insert(values.end(), {wrinkled * scale, slack * scale});
  for (const LineReading& line : r.lines)
    values.insert(values.end(), {line.wrinkled ? static_cast<double>(line.metrics.crests) : 0.0,
                                 static_cast<double>(line.metrics.crests), line.metrics.amplitude,
                                 line.metrics.wavelength});
  return values;
}

nlohmann::json wrinkles_json(const Case& c, const WrinkleMeter::Result& r) {
  nlohmann::json rings = nlohmann::json::array();
  for (const RingMetrics& ring : r.rings.rings) {
    // [m, A_m, E_m] per harmonic (wrinkles.md, W10, W15): why the ring is or is not wrinkled.
    nlohmann::json spectrum = nlohmann::json::array();
    for (std::size_t i = 0; i < ring.spectrum.size(); ++i)
      spectrum.push_back({ring.spectrum[i].first, ring.spectrum[i].second, ring.envelope[i]});
    rings.push_back({{"latitude_deg", ring.latitude_deg},
                     {"decision", ring_decision_name(ring.decision)},
                     {"count", ring.count},
                     {"amplitude", ring.amplitude},
                     {"wavelength", ring.wavelength},
                     {"dominant_count", ring.dominant_count},
                     {"residual_amplitude", ring.residual_amplitude},
                     {"band", ring.band},
                     {"mean_radius", ring.mean_radius},
                     {"points", ring.n_points},
                     {"sector_deg", ring.sector_deg},
                     {"spectrum", spectrum}});
  }
  nlohmann::json lines = nlohmann::json::array();
  for (std::size_t k = 0; k < r.lines.size(); ++k) {
    const WrinkleLine& line = c.output.wrinkles.lines[k];
    const LineMetrics& m = r.lines[k].metrics;
    lines.push_back({{"name", line.name},
                     {"wrinkled", r.lines[k].wrinkled},
                     {"crests", m.crests},
                     {"amplitude", m.amplitude},
                     {"wavelength", m.wavelength},
                     {"reference_wavelength", m.reference_wavelength},
                     {"deviation", m.deviation},
                     {"from", {line.from.x(), line.from.y(), line.from.z()}},
                     {"to", {line.to.x(), line.to.y(), line.to.z()}},
                     {"points", line.points},
                     {"min_crests", line.min_crests},
                     {"mirror", line.mirror == LineMirror::from ? "from"
                                : line.mirror == LineMirror::to ? "to"
                                                                : "none"}});
  }
  const auto& n = r.tension.n_elements;
  return {{"wrinkled", r.wrinkled()},
          {"max_amplitude", r.rings.max_amplitude},
          {"threshold", r.rings.threshold},
          {"peak_ratio", c.output.wrinkles.peak_ratio},
          {"min_count", c.output.wrinkles.min_count},
          {"thickness", *c.mesh.wall_thickness()},
          {"axis", std::string(1, c.output.wrinkles.axis)},
          {"surface", c.output.wrinkles.surface},
          {"rings", rings},
          {"lines", lines},
          {"tension_field",
           {{"taut", n[static_cast<int>(MembraneState::taut)]},
            {"wrinkled", n[static_cast<int>(MembraneState::wrinkled)]},
            {"slack", n[static_cast<int>(MembraneState::slack)]}}}};
}

std::vector<Vec3d> nodal_displacements(const MixedModel& model) {
  const auto& x = model.state();
  std::vector<Vec3d> u(model.mesh().n_nodes());
  for (int v = 0; v < model.mesh().n_nodes(); ++v)
    u[v] = Vec3d(x[DofMap::dof(v, 0)], x[DofMap::dof(v, 1)], x[DofMap::dof(v, 2)]);
  return u;
}

const char* WrinkleSpectrumWriter::header() {
  return "step,time,latitude_deg,m,amplitude,envelope,in_band,decision";
}

WrinkleSpectrumWriter::WrinkleSpectrumWriter(fs::path path) : path_(std::move(path)) {
  write_file_atomically(path_, std::string(header()) + "\n");
}

WrinkleSpectrumWriter WrinkleSpectrumWriter::reopen(fs::path path, int last_step) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return WrinkleSpectrumWriter(std::move(path));
  // A run killed inside a step's write leaves its last line unterminated: it is dropped.
  const std::string text(complete_lines(read_file(path)));
  const std::size_t first = text.find('\n');
  std::string head = text.substr(0, first);
  if (!head.empty() && head.back() == '\r') head.pop_back();
  if (head != header())
    throw InputError(
        {path.string(), 1, 0, "--resume"},
        std::string("wrinkle_spectrum.csv does not start with the header ") + header());
  WrinkleSpectrumWriter writer;
  writer.path_ = std::move(path);
  std::string kept = std::string(header()) + "\n";
  for (std::size_t begin = first == std::string::npos ? text.size() : first + 1;
       begin < text.size();) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    const std::string line = text.substr(begin, end - begin);
    begin = end + 1;
    int step = -1;
    const auto parsed = std::from_chars(line.data(), line.data() + line.size(), step);
    if (parsed.ec == std::errc() && step <= last_step) kept += line + "\n";
  }
  write_file_atomically(writer.path_, kept);
  return writer;
}

void WrinkleSpectrumWriter::add_step(int step, double time, const WrinkleReport& report) {
  std::string text;
  for (const RingMetrics& ring : report.rings) {
    const char* decision = ring_decision_name(ring.decision);
    for (std::size_t i = 0; i < ring.spectrum.size(); ++i) {
      const int m = ring.spectrum[i].first;
      text += std::to_string(step);
      text += ',';
      append_number(text, time);
      text += ',';
      append_number(text, ring.latitude_deg);
      text += ',' + std::to_string(m) + ',';
      append_number(text, ring.spectrum[i].second);
      text += ',';
      append_number(text, ring.envelope[i]);
      text += std::find(ring.band.begin(), ring.band.end(), m) != ring.band.end() ? ",1," : ",0,";
      text += decision;
      text += '\n';
    }
  }
  if (!file_) file_.emplace(path_, false);
  file_->append(text);
}

}  // namespace plisse::app
