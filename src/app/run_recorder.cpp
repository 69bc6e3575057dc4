#include "app/run_recorder.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>
#include <utility>

#include "app/output_reference.hpp"
#include "app/progress_line.hpp"
#include "app/shell_fields.hpp"
#include "core/wall_clock.hpp"
#include "element/element_fields.hpp"
#include "output/json_file.hpp"
#include "output/pvtu_writer.hpp"
#include "output/vtu_writer.hpp"
#include "solver/collective.hpp"
#include "solver/petsc_call.hpp"
#include "solver/petsc_session.hpp"

namespace plisse::app {
namespace {

namespace fs = std::filesystem;

/// Peak resident memory of this process [MiB].
double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux reports KiB
}

/// A step's file: step_NNNN.vtu, or step_NNNN.pvtu listing the ranks' pieces.
std::string step_name(const MixedModel& model, int step) {
  const std::string vtu = RunDirectory::step_file_name(step);
  return model.n_ranks() == 1 ? vtu : vtu.substr(0, vtu.size() - 4) + ".pvtu";
}

/// The displacement part of an eigenmode as a VTU vector field `mode_<k>`.
VtuField mode_field(const Mesh& mesh, const Eigenmode& mode, int k) {
  VtuField f{"mode_" + std::to_string(k), 3, std::vector<double>(3 * mesh.n_nodes())};
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int i = 0; i < 3; ++i) f.values[3 * v + i] = mode.state[DofMap::dof(v, i)];
  return f;
}

/// Point and cell fields of the contract for one converged state (`fields`: its element fields;
/// `shell`: a shell's outputs, empty for solid elements, whose cell fields it adds).
void write_step_vtu(const fs::path& file, const Case& c, const MixedModel& model,
                    const std::vector<ElementFields>& fields,
                    const std::vector<shell::ShellOutputs>& shell, const WallThickness* wall,
                    const std::vector<double>& previous_state, double dt,
                    const std::vector<VtuField>& extra_point_fields,
                    const std::vector<VtuField>& extra_cell_fields) {
  const Mesh& mesh = model.mesh();
  const int n = mesh.n_nodes();
  const auto& x = model.state();
  VtuField displacement{"displacement", 3, std::vector<double>(3 * n)};
  VtuField velocity{"velocity", 3, std::vector<double>(3 * n)};
  VtuField pressure{"pressure", 1, model.nodal_pressures()};
  std::vector<Vec3d> points(mesh.nodes);
  for (int v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      const double u = x[DofMap::dof(v, k)];
      displacement.values[3 * v + k] = u;
      velocity.values[3 * v + k] = dt > 0 ? (u - previous_state[DofMap::dof(v, k)]) / dt : 0.0;
      if (c.output.deformed) points[v][k] += u;
    }
  }
  const int n_cells = n_mesh_cells(mesh);
  std::vector<Mat3d> cauchy(n_cells);
  std::vector<double> von_mises(n_cells), jacobian(n_cells);
  VtuField stretches{"principal_stretches", 3, std::vector<double>(3 * n_cells)};
  VtuField stresses{"principal_stresses", 3, std::vector<double>(3 * n_cells)};
  const std::vector<Mat3d> F = model.element_deformation_gradients();
  for (int e = 0; e < n_cells; ++e) {
    cauchy[e] = fields[e].cauchy;
    von_mises[e] = fields[e].von_mises;
    jacobian[e] = fields[e].J;
    const Vec3d lambda = principal_stretches(F[e]), sigma = principal_values(fields[e].cauchy);
    for (int k = 0; k < 3; ++k) {
      stretches.values[3 * e + k] = lambda[k];
      stresses.values[3 * e + k] = sigma[k];
    }
  }
  std::vector<VtuField> point_fields = {
      displacement, velocity, pressure, {"reaction", 3, model.nodal_reactions()}};
  if (wall) point_fields.push_back({"thickness", 1, (*wall)(nodal_displacements(model))});
  point_fields.insert(point_fields.end(), extra_point_fields.begin(), extra_point_fields.end());
  std::vector<VtuField> cell_fields = {make_symmetric_tensor_field("cauchy_stress", cauchy),
                                       make_scalar_field("von_mises", von_mises),
                                       make_scalar_field("J", jacobian), stretches, stresses};
  if (mesh.is_shell()) {
    const std::vector<VtuField> shell_fields = shell_cell_fields(fields, shell);
    cell_fields.insert(cell_fields.end(), shell_fields.begin(), shell_fields.end());
  } else {
    // Each element's own pressure: where regions meet, the point field holds one region's.
    std::vector<double> element_pressure(n_cells);
    for (int e = 0; e < n_cells; ++e) element_pressure[e] = fields[e].pressure;
    cell_fields.push_back(make_scalar_field("element_pressure", element_pressure));
  }
  cell_fields.insert(cell_fields.end(), extra_cell_fields.begin(), extra_cell_fields.end());
  for (const VtuField& f : point_fields) require_output_entry(OutputTable::vtu_point, f.name);
  for (const VtuField& f : cell_fields) require_output_entry(OutputTable::vtu_cell, f.name);
  if (model.n_ranks() == 1) {
    write_vtu(file, mesh, points, point_fields, cell_fields, c.output.compression);
    return;
  }
  // Distributed: each rank writes the piece of its own elements ("step_NNNN_pR.vtu"); once all
  // are written (the agreement waits for every rank), rank 0 lists them in `file`, the .pvtu.
  const std::string stem = file.stem().string();
  const auto piece = [&](int r) { return stem + "_p" + std::to_string(r) + ".vtu"; };
  on_every_rank_alike([&] {
    write_vtu_piece(file.parent_path() / piece(model.rank()), mesh, points, model.owned_elements(),
                    point_fields, cell_fields, c.output.compression);
  });
  on_every_rank_alike([&] {
    if (model.rank() != 0) return;
    std::vector<std::string> pieces;
    for (int r = 0; r < model.n_ranks(); ++r) pieces.push_back(piece(r));
    write_pvtu(file, pieces, describe_fields(point_fields), describe_fields(cell_fields));
  });
}

}  // namespace

RunRecorder::RunRecorder(const Case& c, const RunDirectory& directory, RunIdentity identity,
                         const MixedModel& model, const LoadStepper& stepper,
                         const WrinkleMeter* meter, const Checkpoint* resume)
    : case_(c),
      directory_(directory),
      identity_(std::move(identity)),
      model_(model),
      stepper_(stepper),
      meter_(meter),
      root_(PetscSession::rank() == 0),
      columns_(c, model, meter),
      previous_state_(model.state()),
      last_checkpoint_(WallClock::now()) {
  if (resume) start_time_ = resume->time;
  // Drucker's condition in principal stretches holds for isotropic models only. The model's
  // materials are the case's `material`, then one per deformable region in the case's order.
  // Past the sections' own models come only per-element copies (fibres in a shell's frame),
  // which are anisotropic.
  const ElementMaterials& materials = model.element_materials();
  std::vector<std::string> regions = {""};
  for (const Region& r : c.regions)
    if (r.material) regions.push_back(r.label());
  watch_of_material_.assign(regions.size(), -1);
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const AnyMaterial& material = materials.materials[k];
    const MaterialModelInfo* info = find_material_model(material_name(material));
    if (info == nullptr || !info->isotropic) continue;
    std::vector<StabilityRange> ranges = stability_ranges(material);
    if (std::none_of(ranges.begin(), ranges.end(), [](const StabilityRange& r) {
          return r.lower > kStabilityScanMin || r.upper < kStabilityScanMax;
        }))
      continue;
    watch_of_material_[k] = static_cast<int>(watched_.size());
    watched_.push_back({regions[k], material, std::move(ranges)});
  }
  if (!c.regions.empty()) {
    // 0 the case's material, k the k-th region with a material, -1 a rigid region.
    material_field_.assign(static_cast<std::size_t>(n_mesh_cells(model.mesh())), 0.0);
    int k = 0;
    for (const Region& r : c.regions) {
      const double value = r.rigid ? -1.0 : double(++k);
      for (int t : region_elements(r, model.mesh()))
        material_field_[static_cast<std::size_t>(t)] = value;
    }
  }
  // Rank 0 writes the files, every rank checks them on --resume: a failure is agreed by all.
  on_every_rank_alike([&] {
    std::vector<PvdEntry> pvd_entries;
    if (resume) {
      // A row per converged step: more than the case's max_steps cannot be this run's.
      history_.emplace(HistoryWriter::reopen(directory.history_csv(),
                                             static_cast<std::size_t>(c.solver.max_steps)));
      if (history_->columns() != columns_.names() ||
          history_->rows().size() < std::size_t(resume->steps))
        throw InputError({directory.history_csv().string(), 0, 0, "--resume"},
                         "history.csv does not match the checkpoint");
      // Under arc-length control the collection's times are step numbers (pvd_time).
      const bool by_step = c.solver.control == StepControl::arc_length;
      for (const PvdEntry& e : read_pvd(directory.solution_pvd()))
        if (by_step ? e.time <= resume->steps + 0.5 : e.time <= resume->time * (1.0 + 1e-12))
          pvd_entries.push_back(e);
      if (root_) {
        history_->keep_first_rows(resume->steps);
        read_wrinkling_so_far();
      } else {
        history_.reset();
      }
    } else if (root_) {
      history_.emplace(directory.history_csv(), columns_.extra_names());
    }
    if (root_) pvd_.emplace(directory.solution_pvd(), pvd_entries);
    // The rings' spectra of every written step, cut back like the history on --resume.
    if (root_ && meter_ && c.output.wrinkles.has_rings())
      spectrum_.emplace(
          resume ? WrinkleSpectrumWriter::reopen(
                       directory.directory() / WrinkleSpectrumWriter::kFileName, resume->steps)
                 : WrinkleSpectrumWriter(directory.directory() / WrinkleSpectrumWriter::kFileName));
  });
}

void RunRecorder::record_initial_state() {
  fields_ = model_.element_fields();
  shell_outputs_ = model_.shell_outputs();
  if (meter_) last_wrinkles_ = meter_->evaluate(model_, fields_);
  StepInfo initial;
  initial.time = model_.time();
  write_step_files(initial, model_.state());
  last_wrinkles_.reset();
  last_checkpoint_ = WallClock::now();
}

void RunRecorder::record(const StepInfo& info) {
  const auto t_out = WallClock::now();
  fields_ = model_.element_fields();
  shell_outputs_ = model_.shell_outputs();
  const BodyAverages averages = model_.averages(fields_);
  if (meter_) last_wrinkles_ = meter_->evaluate(model_, fields_);
  if (case_.solver.stability.check && !info.stable) stable_so_far_ = false;
  if (last_wrinkles_ && first_wrinkled_.is_null() && last_wrinkles_->wrinkled())
    note_first_wrinkled(info);
  const std::vector<double> row =
      columns_.row({info, model_, fields_, averages, last_wrinkles_ ? &*last_wrinkles_ : nullptr,
                    model_.mesh().is_shell() ? &shell_outputs_ : nullptr});
  on_every_rank_alike([&] {
    if (history_) history_->add_row(row);
  });
  accepted_newton_iterations_ += info.newton_iterations;
  output_seconds_ += seconds_since(t_out);
  if (info.new_instability) {
    nlohmann::json eigenvalues = nlohmann::json::array();
    for (const Eigenmode& m : info.modes) eigenvalues.push_back(m.eigenvalue);
    instabilities_.push_back({{"step", info.step},
                              {"time", info.time},
                              {"negative_pivots", info.unstable_negative_pivots},
                              {"expected_negative_pivots", info.expected_negative_pivots},
                              {"eigenvalues", eigenvalues},
                              {"branch_switched", info.branch_switched},
                              {"perturbation_mm", info.perturbation_mm},
                              {"file", step_name(model_, info.step)}});
  }
  if (!watched_.empty()) check_material_stability(info.step);
  if (info.step % case_.output.every == 0 || info.load_factor >= 1.0 || !info.modes.empty())
    write_step_files(info, previous_state_);
  last_step_start_ = std::move(previous_state_);
  previous_state_ = model_.state();
  last_step_ = info;
  last_row_ = row;
}

std::vector<std::pair<std::string, double>> RunRecorder::last_loads() const {
  std::vector<std::pair<std::string, double>> out;
  const std::vector<std::string>& names = columns_.names();
  for (std::size_t k = 0; k < names.size() && k < last_row_.size(); ++k)
    for (const char* prefix : {"pressure:", "load_x:", "load_y:", "load_z:", "force_x:", "force_y:",
                               "force_z:", "moment_x:", "moment_y:", "moment_z:"})
      if (names[k].starts_with(prefix)) {
        out.emplace_back(names[k], last_row_[k]);
        break;
      }
  return out;
}

void RunRecorder::check_material_stability(int step) {
  // Every rank checks every element alike (element_deformation_gradients covers the whole mesh).
  const std::vector<Mat3d> F = model_.element_deformation_gradients();
  const ElementMaterials& materials = model_.element_materials();
  int unstable = 0, first = -1;
  Vec3d first_stretches = Vec3d::Ones();
  for (std::size_t e = 0; e < F.size(); ++e) {
    const int m = materials.of(static_cast<int>(e));
    if (m < 0 || m >= static_cast<int>(watch_of_material_.size())) continue;  // rigid, or a copy
    const int w = watch_of_material_[static_cast<std::size_t>(m)];
    if (w < 0) continue;
    const Vec3d l = principal_stretches(F[e]);
    if (drucker_stable(watched_[static_cast<std::size_t>(w)].material, l)) continue;
    if (unstable++ == 0) first = static_cast<int>(e), first_stretches = l;
  }
  unstable_elements_ = unstable;
  most_unstable_elements_ = std::max(most_unstable_elements_, unstable);
  if (unstable == 0 || first_unstable_step_ >= 0) return;
  first_unstable_step_ = step;
  std::ostringstream out;
  out.precision(4);
  out << "step " << step << ": the material is not stable (Drucker) in " << unstable
      << (unstable == 1 ? " element" : " elements") << ", first element " << first
      << " with principal stretches " << first_stretches[0] << ", " << first_stretches[1] << ", "
      << first_stretches[2]
      << ": from here on a softening of the material itself may look like wrinkles or buckling "
         "(summary.json material_stability; the stable ranges are in the log's material line)";
  material_warning_ = out.str();
}

void RunRecorder::note_first_wrinkled(const StepInfo& info) {
  std::string by, what;
  char text[200];
  const LargestWrinkle largest = largest_wrinkle(&last_wrinkles_->rings, &last_wrinkles_->lines);
  if (const RingMetrics* ring = largest.ring) {
    std::snprintf(text, sizeof text, "ring %g deg", ring->latitude_deg);
    by = text;
    std::snprintf(text, sizeof text, "%d waves %.3g mm high, wavelength %.4g mm", ring->count,
                  ring->amplitude, ring->wavelength);
    what = text;
  } else if (const LineReading* line = largest.line) {
    by = "line " + line->name;
    std::snprintf(text, sizeof text, "%d crests %.3g mm high, wavelength %.4g mm",
                  line->metrics.crests, line->metrics.amplitude, line->metrics.wavelength);
    what = text;
  }
  const bool checked = case_.solver.stability.check;
  first_wrinkled_ = {{"step", info.step},
                     {"time", info.time},
                     {"by", by},
                     {"stable", checked ? nlohmann::json(stable_so_far_) : nlohmann::json()}};
  std::snprintf(text, sizeof text, "step %d (t = %.6g): the body has wrinkled: ", info.step,
                info.time);
  wrinkle_notice_ = text + by + " has " + what;
  std::snprintf(text, sizeof text, " (threshold %.3g mm)", last_wrinkles_->rings.threshold);
  wrinkle_notice_ += text;
  if (checked && stable_so_far_)
    wrinkle_notice_ +=
        ", while the stability check has found every step stable: the wrinkles grew from the "
        "imperfection or the mesh's own asymmetry without a bifurcation, which the check cannot "
        "see";
}

void RunRecorder::read_wrinkling_so_far() {
  const std::vector<std::string>& names = history_->columns();
  std::optional<std::size_t> stable;
  std::vector<std::pair<std::size_t, std::string>> counts;  // column, what it measures
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (names[k] == "stable") stable = k;
    if (names[k] == "wrinkle_count") counts.emplace_back(k, "a ring");
    if (names[k].starts_with("wrinkle_crests:"))
      counts.emplace_back(k, "line " + names[k].substr(std::string("wrinkle_crests:").size()));
  }
  for (const std::vector<double>& row : history_->rows()) {
    if (stable && row[*stable] != 1.0) stable_so_far_ = false;
    if (!first_wrinkled_.is_null()) continue;
    for (const auto& [k, by] : counts)
      if (row[k] > 0.0) {
        first_wrinkled_ = {{"step", static_cast<int>(row[0])},
                           {"time", row[1]},
                           {"by", by},
                           {"stable", stable ? nlohmann::json(stable_so_far_) : nlohmann::json()}};
        break;
      }
  }
}

std::string RunRecorder::take_material_warning() { return std::exchange(material_warning_, ""); }

void RunRecorder::write_step_files(const StepInfo& info, const std::vector<double>& step_start) {
  const auto t_out = WallClock::now();
  const std::string name = step_name(model_, info.step);
  std::vector<VtuField> point_fields, cell_fields;
  for (std::size_t k = 0; k < info.modes.size(); ++k)
    point_fields.push_back(mode_field(model_.mesh(), info.modes[k], static_cast<int>(k) + 1));
  for (const auto& term : model_.terms())
    for (const NodeField& f : term->node_fields(info.time, model_.state(), model_.mesh().n_nodes()))
      point_fields.push_back(make_scalar_field(f.name, f.values));
  if (last_wrinkles_) {
    std::vector<double> state(last_wrinkles_->tension.element_state.size());
    for (std::size_t e = 0; e < state.size(); ++e)
      state[e] = static_cast<double>(last_wrinkles_->tension.element_state[e]);
    cell_fields.push_back(make_scalar_field("wrinkle_state", state));
  }
  if (!material_field_.empty())
    cell_fields.push_back(make_scalar_field("material", material_field_));
  write_step_vtu(directory_.directory() / name, case_, model_, fields_, shell_outputs_,
                 columns_.wall_thickness(), step_start, info.dt, point_fields, cell_fields);
  on_every_rank_alike([&] {
    // ParaView orders a collection by its times: an arc-length run's load factor falls past a
    // limit load, so its steps are listed by their number.
    if (pvd_)
      pvd_->add(case_.solver.control == StepControl::arc_length ? double(info.step) : info.time,
                name);
    if (spectrum_ && last_wrinkles_ && info.step > 0)
      spectrum_->add_step(info.step, info.time, last_wrinkles_->rings);
  });
  last_written_ = info.step;
  output_seconds_ += seconds_since(t_out);
}

void RunRecorder::save_checkpoint() {
  const StepperState& st = stepper_.state();
  const MixedModel::Snapshot snap = model_.snapshot();  // collective
  on_every_rank_alike([&] {
    if (root_)
      write_checkpoint(
          directory_.directory() / "checkpoint.bin",
          {identity_.fingerprint, model_.element_family(), st.steps, st.time, st.dt, st.previous_dt,
           st.previous_state, snap.state, snap.bubbles, snap.term_states, st.negative_pivots});
  });
}

void RunRecorder::checkpoint_when_due(int step) {
  // By step count, or by wall time (decided on every rank alike: the write is collective).
  const bool by_count =
      case_.output.checkpoint_every > 0 && step % case_.output.checkpoint_every == 0;
  const bool by_time =
      case_.output.checkpoint_minutes > 0.0 &&
      any_rank(seconds_since(last_checkpoint_) >= 60.0 * case_.output.checkpoint_minutes);
  if (!by_count && !by_time) return;
  save_checkpoint();
  last_checkpoint_ = WallClock::now();
}

double RunRecorder::finish(const SteppingResult& result, const StartTimes& times) {
  // A run that stopped early has not written its last step yet.
  if (last_step_.step > 0 && last_written_ != last_step_.step)
    write_step_files(last_step_, last_step_start_);
  if (last_step_.step > 0) save_checkpoint();
  // Peak resident memory: of the whole job (sum over the ranks) and of the largest rank.
  double memory_total = peak_memory_mib(), memory_largest = memory_total;
  PLISSE_PETSC(
      MPI_Allreduce(MPI_IN_PLACE, &memory_total, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD));
  PLISSE_PETSC(
      MPI_Allreduce(MPI_IN_PLACE, &memory_largest, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD));
  on_every_rank_alike([&] {
    if (root_)
      write_json_file(directory_.summary_json(),
                      summary(result, times, memory_total, memory_largest));
  });
  return memory_total;
}

nlohmann::json RunRecorder::summary(const SteppingResult& result, const StartTimes& times,
                                    double memory_total, double memory_largest) const {
  const Case& c = case_;
  const Mesh& mesh = model_.mesh();
  nlohmann::json summary;
  summary["units"] = {{"length", "mm"}, {"force", "N"},   {"stress", "MPa"},
                      {"time", "s"},    {"energy", "mJ"}, {"density", "t/mm³"}};
  for (const std::string& column : columns_.names())
    summary["history_units"][column] = find_output_entry(OutputTable::history, column)->unit;
  summary["case"] = identity_.case_file;
  summary["case_path"] = fs::absolute(identity_.case_file).lexically_normal().string();
  summary["overrides"] = identity_.overrides;
  summary["title"] = c.title;
  summary["completed"] = result.completed;
  if (result.completed)
    summary["ended"] = result.stopped_after_limit ? "stop_load_factor"
                       : result.stopped_unstable  ? "instability"
                                                  : "end_time";
  summary["interrupted"] = result.interrupted;
  if (!result.completed) summary["failure"] = result.failure;
  // The load the run could not raise (a limit load under load control): the last converged step.
  if (result.smallest_step) {
    nlohmann::json loads = nlohmann::json::object();
    for (const auto& [name, value] : last_loads()) loads[name] = value;
    summary["limit"] = {{"time", last_step_.time},
                        {"load_factor", last_step_.load_factor},
                        {"step", last_step_.step},
                        {"loads", loads}};
  }
  summary["nodes"] = mesh.n_nodes();
  summary["elements"] = model_.n_elements();
  summary["element"] = to_string(model_.element_family());
  summary["dofs"] = model_.dofs().n_dofs();
  summary["free_dofs"] = model_.n_free();
  summary["pressure_dofs"] = model_.dofs().n_free_pressure();
  summary["pressure_twins"] = model_.pressure_twins().n_twins();
  summary["steps"] = result.steps;
  summary["newton_iterations"] = result.newton_iterations;
  summary["failed_newton_iterations"] = result.newton_iterations - accepted_newton_iterations_;
  summary["reused_factor_solves"] = result.reused_solves;
  summary["krylov_steps"] = result.krylov_steps;
  summary["cutbacks"] = result.cutbacks;
  summary["final_time"] = last_step_.step > 0 ? last_step_.time : start_time_;
  const PhaseTimes phases = stepper_.times();
  summary["factorisations"] = phases.factorisations;
  if (result.newton_iterations > 0) {
    const double entries = stepper_.factor_entries();
    if (entries > 0) summary["factor_entries"] = entries;  // fill = entries / tangent nonzeros
  }
  summary["wall_time"] = {{"mesh", times.mesh},
                          {"setup", times.setup},
                          {"assembly", phases.assembly},
                          {"linear_solve", phases.linear_solve},
                          {"factorisation", phases.factorisation},
                          {"triangular_solve", phases.triangular_solve},
                          {"output", output_seconds_},
                          {"total", seconds_since(times.start)}};
  summary["ranks"] = model_.n_ranks();
  summary["peak_memory_mib"] = memory_total;
  summary["peak_memory_per_rank_mib"] = memory_largest;
  if (c.solver.stability.check) {
    summary["stability"] = {{"checks", stepper_.stability_checks()},
                            {"check_seconds", stepper_.stability_seconds()},
                            {"eigenmode_seconds", stepper_.eigenmode_seconds()},
                            {"stable_at_end", last_step_.stable},
                            {"instabilities", instabilities_}};
  }
  if (!watched_.empty()) summary["material_stability"] = material_stability();
  // The state's metrics, which `plisse wrinkles DIR` reproduces, and the run's first wrinkled step.
  if (last_wrinkles_) summary["wrinkles"] = wrinkles_json(c, *last_wrinkles_);
  if (c.output.wrinkles.enabled()) summary["first_wrinkled"] = first_wrinkled_;
  for (const HistoryColumns::ProbePoint& p : columns_.probe_points()) {
    const auto xyz = [](const Vec3d& v) { return nlohmann::json::array({v[0], v[1], v[2]}); };
    summary["probes"].push_back({{"name", p.name},
                                 {"point", xyz(p.point)},
                                 {"position", xyz(p.at.position)},
                                 {"distance", p.at.distance},
                                 {"inside", p.at.inside},
                                 {"element", p.at.element}});
  }
  if (history_ && !history_->rows().empty()) {
    nlohmann::json final_values;
    for (std::size_t i = 0; i < history_->columns().size(); ++i)
      final_values[history_->columns()[i]] = history_->rows().back()[i];
    summary["final"] = final_values;
  }
  require_documented_summary(summary);
  return summary;
}

nlohmann::json RunRecorder::material_stability() const {
  nlohmann::json stability = {
      {"first_unstable_step",
       first_unstable_step_ >= 0 ? nlohmann::json(first_unstable_step_) : nlohmann::json()},
      {"unstable_elements", unstable_elements_},
      {"most_unstable_elements", most_unstable_elements_}};
  for (const WatchedMaterial& w : watched_) {
    nlohmann::json ranges;
    for (const StabilityRange& r : w.ranges) ranges[test_mode_name(r.mode)] = {r.lower, r.upper};
    if (w.region.empty())
      stability["stable_stretches"] = ranges;
    else
      stability["regions"][w.region] = ranges;
  }
  return stability;
}

}  // namespace plisse::app
