#include "app/run_case.hpp"

#include <sys/resource.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <optional>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "app/wrinkling.hpp"
#include "core/error.hpp"
#include "io/case.hpp"
#include "io/atomic_file.hpp"
#include "io/checkpoint.hpp"
#include "io/history_writer.hpp"
#include "io/json_file.hpp"
#include "io/pvd_writer.hpp"
#include "io/pvtu_writer.hpp"
#include "io/run_directory.hpp"
#include "io/run_log.hpp"
#include "io/vtu_writer.hpp"
#include "material/registry.hpp"
#include "physics/dirichlet.hpp"
#include "physics/terms.hpp"
#include "solver/load_stepper.hpp"
#include "solver/petsc_call.hpp"
#include "solver/petsc_session.hpp"

namespace plisse::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t g_interrupt = 0;
extern "C" void on_interrupt(int) { g_interrupt = 1; }

/// SIGINT/SIGTERM set a flag for the duration of a run; the run checkpoints after the current step
/// and stops. The previous handlers come back at the end.
class InterruptGuard {
 public:
  InterruptGuard() {
    g_interrupt = 0;
    previous_int_ = std::signal(SIGINT, on_interrupt);
    previous_term_ = std::signal(SIGTERM, on_interrupt);
  }
  ~InterruptGuard() {
    std::signal(SIGINT, previous_int_);
    std::signal(SIGTERM, previous_term_);
  }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
  bool requested() const { return g_interrupt != 0; }

 private:
  void (*previous_int_)(int) = SIG_DFL;
  void (*previous_term_)(int) = SIG_DFL;
};

/// True when any rank passes true (collective over PETSC_COMM_WORLD).
bool any_rank(bool value) {
  int flag = value ? 1 : 0;
  PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &flag, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD));
  return flag != 0;
}

/// Every rank builds the mesh on its own (reads or generates it); they must agree, node for node.
void check_same_mesh_on_every_rank(const Mesh& mesh) {
  if (PetscSession::size() == 1) return;
  std::uint64_t hash = 1469598103934665603ull;  // FNV-1a over the bytes of nodes and tets
  const auto add = [&](const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) hash = (hash ^ p[i]) * 1099511628211ull;
  };
  for (const auto& x : mesh.nodes) add(x.data(), 3 * sizeof(double));
  for (const auto& t : mesh.tets) add(t.data(), sizeof t);
  unsigned long long low = hash, high = hash;
  PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &low, 1, MPI_UNSIGNED_LONG_LONG, MPI_MIN, PETSC_COMM_WORLD));
  PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &high, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, PETSC_COMM_WORLD));
  if (low != high)
    throw Error("the ranks built different meshes from the same case (mesh generation is not "
                "reproducible here); write the mesh once with `plisse mesh` and use mesh.file");
}

/// Ends a distributed job after an error on this rank alone: prints it, then MPI_Abort (exit
/// status 1), since the other ranks may be waiting in a collective call.
[[noreturn]] void abort_all_ranks(std::exception_ptr error) {
  std::string message = "unknown error";
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    message = e.what();
  } catch (const std::string& e) {
    message = e;
  } catch (...) {
  }
  std::fprintf(stderr, "plisse: error on rank %d: %s\n", PetscSession::rank(), message.c_str());
  std::fflush(stderr);
  MPI_Abort(PETSC_COMM_WORLD, 1);
  std::abort();
}

/// "step_NNNN.vtu" -> "step_NNNN" + suffix.
std::string with_suffix(const std::string& vtu_name, const std::string& suffix) {
  return vtu_name.substr(0, vtu_name.size() - 4) + suffix;
}

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Peak resident memory of this process [MiB].
double peak_memory_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // Linux reports KiB
}

int nearest_node(const Mesh& mesh, const Vec3d& point) {
  int best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (int v = 0; v < mesh.n_nodes(); ++v)
    if (const double d = (mesh.nodes[v] - point).squaredNorm(); d < best_distance) {
      best_distance = d;
      best = v;
    }
  return best;
}

/// The history columns beyond the standard ones, and how to fill them.
struct HistoryColumns {
  std::vector<std::string> names;
  std::vector<const BoundaryCondition*> reaction_conditions;
  std::vector<int> probe_nodes;
};

HistoryColumns history_columns(const Case& c, const Mesh& mesh, const MixedModel& model) {
  HistoryColumns h;
  for (const auto& term : model.terms())
    for (const auto& name : term->history_columns()) h.names.push_back(name);
  if (c.output.stretch_axis) h.names.push_back("stretch");
  for (const char* s : {"stretch_x", "stretch_y", "stretch_z"}) h.names.push_back(s);
  for (const char* s : {"cauchy_xx", "cauchy_yy", "cauchy_zz", "cauchy_xy", "cauchy_yz", "cauchy_xz"})
    h.names.push_back(s);
  for (const auto& bc : c.boundary) {
    if (bc.name.empty()) continue;
    h.reaction_conditions.push_back(&bc);
    for (const char* axis : {"x", "y", "z"}) h.names.push_back(std::string("force_") + axis + ":" + bc.name);
  }
  for (const auto& probe : c.probes) {
    h.probe_nodes.push_back(nearest_node(mesh, probe.point));
    for (const char* axis : {"x", "y", "z"}) h.names.push_back(std::string("u") + axis + ":" + probe.name);
  }
  h.names.push_back("volume");
  h.names.push_back("min_J");
  h.names.push_back("strain_energy");
  if (c.solver.stability.check)
    for (const char* s : {"negative_pivots", "expected_negative_pivots", "stable"}) h.names.push_back(s);
  if (c.output.wrinkles.enabled())
    for (const auto& s : WrinkleMeter::history_columns()) h.names.push_back(s);
  return h;
}

/// The displacement part of an eigenmode as a VTU vector field `mode_<k>`.
VtuField mode_field(const Mesh& mesh, const Eigenmode& mode, int k) {
  VtuField f{"mode_" + std::to_string(k), 3, std::vector<double>(3 * mesh.n_nodes())};
  for (int v = 0; v < mesh.n_nodes(); ++v)
    for (int i = 0; i < 3; ++i) f.values[3 * v + i] = mode.state[DofMap::dof(v, i)];
  return f;
}

/// Point and cell fields of the contract for one converged state (`fields`: its element fields).
void write_step_vtu(const fs::path& file, const Case& c, const MixedModel& model,
                    const std::vector<mini::ElementFields>& fields,
                    const std::vector<double>& previous_state, double dt,
                    const std::vector<VtuField>& extra_point_fields = {},
                    const std::vector<VtuField>& extra_cell_fields = {}) {
  const Mesh& mesh = model.mesh();
  const int n = mesh.n_nodes();
  const auto& x = model.state();
  VtuField displacement{"displacement", 3, std::vector<double>(3 * n)};
  VtuField velocity{"velocity", 3, std::vector<double>(3 * n)};
  VtuField pressure{"pressure", 1, std::vector<double>(n)};
  std::vector<Vec3d> points(mesh.nodes);
  for (int v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      const double u = x[DofMap::dof(v, k)];
      displacement.values[3 * v + k] = u;
      velocity.values[3 * v + k] = dt > 0 ? (u - previous_state[DofMap::dof(v, k)]) / dt : 0.0;
      if (c.output.deformed) points[v][k] += u;
    }
    pressure.values[v] = x[DofMap::dof(v, 3)];
  }
  const int n_cells = mesh.n_tets();
  std::vector<Mat3d> cauchy(n_cells);
  std::vector<double> von_mises(n_cells), jacobian(n_cells);
  for (int e = 0; e < n_cells; ++e) {
    cauchy[e] = fields[e].cauchy;
    von_mises[e] = fields[e].von_mises;
    jacobian[e] = fields[e].J;
  }
  std::vector<VtuField> point_fields = {displacement, velocity, pressure};
  point_fields.insert(point_fields.end(), extra_point_fields.begin(), extra_point_fields.end());
  std::vector<VtuField> cell_fields = {make_symmetric_tensor_field("cauchy_stress", cauchy),
                                       make_scalar_field("von_mises", von_mises),
                                       make_scalar_field("J", jacobian)};
  cell_fields.insert(cell_fields.end(), extra_cell_fields.begin(), extra_cell_fields.end());
  if (model.n_ranks() == 1) {
    write_vtu(file, mesh, points, point_fields, cell_fields);
    return;
  }
  // Distributed: each rank writes the piece of its own elements ("step_NNNN_pR.vtu"); once all
  // are written, rank 0 lists them in `file`, the .pvtu.
  const std::string stem = file.stem().string();
  const auto piece = [&](int r) { return stem + "_p" + std::to_string(r) + ".vtu"; };
  write_vtu_piece(file.parent_path() / piece(model.rank()), mesh, points, model.owned_elements(),
                  point_fields, cell_fields);
  PLISSE_PETSC(MPI_Barrier(PETSC_COMM_WORLD));
  if (model.rank() != 0) return;
  std::vector<std::string> pieces;
  for (int r = 0; r < model.n_ranks(); ++r) pieces.push_back(piece(r));
  write_pvtu(file, pieces, describe_fields(point_fields), describe_fields(cell_fields));
}

}  // namespace

std::vector<InputError> unsupported_features(const Case& c, const Mesh& mesh) {
  std::vector<InputError> out;
  if (mesh.order() != 1)
    out.emplace_back(c.mesh.file ? c.mesh.file_place : c.mesh.place,
                     "the mesh has second-order (10-node) tetrahedra; the MINI element needs "
                     "linear ones (a quadratic element is planned)");
  if (c.solver.scheme != Scheme::total_lagrangian)
    out.emplace_back(InputPlace{c.path, 0, 0, "solver.scheme"},
                     "only the total-lagrangian scheme is available yet");
  return out;
}

void check_free_displacements(const Case& c, const Mesh& mesh,
                              const std::vector<ConstrainedComponent>& constraints) {
  // collect_constraints gives one entry per constrained (node, component).
  if (constraints.size() >= 3 * static_cast<size_t>(mesh.n_nodes()))
    throw InputError({c.path, 0, 0, "boundary"},
                     "every displacement is prescribed by the boundary conditions: nothing to solve");
}

void check_solver_options(const Case& c, const std::vector<std::string>& command_line_options) {
  try {
    check_petsc_options(c.solver.newton);
  } catch (const Error& e) {
    std::string given = c.solver.petsc_options;
    for (const auto& o : command_line_options) given += (given.empty() ? "" : " ") + o;
    const InputPlace place = command_line_options.empty()
                                 ? c.solver.petsc_options_place
                                 : InputPlace{"command line", 0, 0, "--petsc"};
    throw InputError(place, "PETSc refuses the options '" + given + "': " + e.what());
  }
}

namespace {

/// Everything run_case prepared and checked before PETSc started: what solve_and_write needs.
struct PreparedRun {
  const RunOptions& options;
  const Case& c;
  Clock::time_point start;
  fs::path out_dir;
  std::uint64_t fingerprint;
  std::optional<Checkpoint>& checkpoint;
  const Mesh& mesh;
  double time_mesh;
  AnyMaterial material;
  const std::vector<ConstrainedComponent>& constraints;
  std::vector<std::unique_ptr<ModelTerm>> terms;
  const InterruptGuard& interrupts;
};

/// Builds the model, steps to the end and writes the run directory. Distributed runs: every rank
/// runs all of it; rank 0 alone writes the log, the history, the summary, the checkpoint and the
/// PVD index, every rank its own VTU pieces.
void solve_and_write(PreparedRun run) {
  const RunOptions& options = run.options;
  const Case& c = run.c;
  const auto t_start = run.start;
  const fs::path& out_dir = run.out_dir;
  const std::uint64_t fingerprint = run.fingerprint;
  std::optional<Checkpoint>& checkpoint = run.checkpoint;
  const Mesh& mesh = run.mesh;
  const double time_mesh = run.time_mesh;
  const std::vector<ConstrainedComponent>& constraints = run.constraints;
  const InterruptGuard& interrupts = run.interrupts;
  const bool root = PetscSession::rank() == 0;

  auto t0 = Clock::now();
  MixedModel model(mesh, std::move(run.material),
                   c.material.inverse_bulk_modulus(),
                   constraints, std::move(run.terms));
  LoadStepper stepper(model, c.solver);
  stepper.set_stability(stability_options(c));
  std::optional<WrinkleMeter> wrinkle_meter;
  if (c.output.wrinkles.enabled()) wrinkle_meter.emplace(c, mesh);
  const double time_setup = seconds_since(t0);

  RunDirectory dir(out_dir);
  RunLog log = root ? RunLog(dir.log_txt()) : RunLog({}, nullptr, nullptr);
  if (root && checkpoint && fs::exists(dir.log_txt())) log.prepend(read_file(dir.log_txt()));
  // A step's file: step_NNNN.vtu, or step_NNNN.pvtu listing the ranks' pieces.
  const auto step_name = [&](int step) {
    const std::string vtu = RunDirectory::step_file_name(step);
    return model.n_ranks() == 1 ? vtu : with_suffix(vtu, ".pvtu");
  };
  log.info("plisse run " + options.case_file + (c.title.empty() ? "" : "  (" + c.title + ")"));
  log.info("output: " + dir.directory().string());
  for (const auto& o : options.overrides) log.info("  --set " + o);
  {
    char line[256];
    std::snprintf(line, sizeof line,
                  "mesh: %d nodes, %d tetrahedra; unknowns: %d (%d pressure), %zu constrained",
                  mesh.n_nodes(), mesh.n_tets(), model.n_free(), model.dofs().n_free_pressure(),
                  constraints.size());
    log.info(line);
    if (model.n_ranks() > 1) {
      // Each rank evaluates the elements touching its nodes: the cut elements twice.
      const int owned = model.n_owned();
      int most = owned, fewest = owned, evaluated = static_cast<int>(model.local_elements().size());
      PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &most, 1, MPI_INT, MPI_MAX, PETSC_COMM_WORLD));
      PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &fewest, 1, MPI_INT, MPI_MIN, PETSC_COMM_WORLD));
      PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &evaluated, 1, MPI_INT, MPI_SUM, PETSC_COMM_WORLD));
      std::snprintf(line, sizeof line,
                    "distributed over %d ranks: %d to %d unknowns per rank; %d element "
                    "evaluations per assembly for %d elements (+%.1f %%)",
                    model.n_ranks(), fewest, most, evaluated, mesh.n_tets(),
                    100.0 * (evaluated - mesh.n_tets()) / std::max(1, mesh.n_tets()));
      log.info(line);
    }
  }

  HistoryColumns columns = history_columns(c, mesh, model);
  std::optional<HistoryWriter> history_file;  // rank 0's
  std::vector<PvdEntry> pvd_entries;
  if (checkpoint) {
    model.restore({checkpoint->state, checkpoint->bubbles, checkpoint->term_states});
    stepper.resume({checkpoint->steps, checkpoint->time, checkpoint->dt, checkpoint->previous_dt,
                    checkpoint->previous_state, checkpoint->negative_pivots});
    history_file.emplace(HistoryWriter::reopen(dir.history_csv()));
    std::vector<std::string> expected = HistoryWriter::standard_columns();
    expected.insert(expected.end(), columns.names.begin(), columns.names.end());
    if (history_file->columns() != expected || history_file->rows().size() < size_t(checkpoint->steps))
      throw InputError({dir.history_csv().string(), 0, 0, "--resume"},
                       "history.csv does not match the checkpoint");
    history_file->keep_first_rows(checkpoint->steps);
    for (const PvdEntry& e : read_pvd(dir.solution_pvd()))
      if (e.time <= checkpoint->time * (1.0 + 1e-12)) pvd_entries.push_back(e);
    log.info("resuming after step " + std::to_string(checkpoint->steps) + " at t = " +
             std::to_string(checkpoint->time));
    if (!root) history_file.reset();  // every rank checked the files; rank 0 writes them
  } else if (root) {
    history_file.emplace(dir.history_csv(), columns.names);
  }
  std::optional<PvdWriter> pvd;
  if (root) pvd.emplace(dir.solution_pvd(), pvd_entries);
  const auto save_checkpoint = [&] {
    const StepperState& st = stepper.state();
    const MixedModel::Snapshot snap = model.snapshot();  // collective
    if (root)
      write_checkpoint(dir.directory() / "checkpoint.bin",
                     {fingerprint, st.steps, st.time, st.dt, st.previous_dt, st.previous_state,
                      snap.state, snap.bubbles, snap.term_states, st.negative_pivots});
  };
  double time_output = 0.0;
  std::vector<double> previous_state = model.state();
  int last_written = -1;
  StepInfo last_step;

  std::optional<WrinkleMeter::Result> last_wrinkles;
  nlohmann::json instabilities = nlohmann::json::array();
  // Element fields (stress, J) of the last converged step: computed once per step, used by the
  // history, the wrinkle metrics and the VTU file.
  std::vector<mini::ElementFields> fields;
  auto write_output = [&](const StepInfo& info) {
    const auto t_out = Clock::now();
    const std::string name = step_name(info.step);
    std::vector<VtuField> point_fields, cell_fields;
    for (std::size_t k = 0; k < info.modes.size(); ++k)
      point_fields.push_back(mode_field(mesh, info.modes[k], static_cast<int>(k) + 1));
    if (last_wrinkles) {
      std::vector<double> state(last_wrinkles->tension.element_state.size());
      for (std::size_t e = 0; e < state.size(); ++e)
        state[e] = static_cast<double>(last_wrinkles->tension.element_state[e]);
      cell_fields.push_back(make_scalar_field("wrinkle_state", state));
    }
    write_step_vtu(dir.directory() / name, c, model, fields, previous_state, info.dt, point_fields,
                   cell_fields);
    if (pvd) pvd->add(info.time, name);
    last_written = info.step;
    time_output += seconds_since(t_out);
  };

  auto on_step = [&](const StepInfo& info) {
    const auto t_out = Clock::now();
    fields = model.element_fields();
    const BodyAverages avg = model.averages(fields);
    std::vector<double> row = {double(info.step), info.time, info.load_factor,
                               double(info.newton_iterations), info.residual_norm};
    for (const auto& term : model.terms())
      for (double v : term->history_values(info.time, model.state())) row.push_back(v);
    if (c.output.stretch_axis) {
      const int a = *c.output.stretch_axis - 'x';
      row.push_back(avg.F(a, a));
    }
    for (int k = 0; k < 3; ++k) row.push_back(avg.F(k, k));
    for (auto [i, j] : {std::pair{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}})
      row.push_back(avg.cauchy(i, j));
    for (const BoundaryCondition* bc : columns.reaction_conditions) {
      const Vec3d f = model.reaction(mesh.surface_tags.at(bc->surface.name));
      for (int k = 0; k < 3; ++k) row.push_back(f[k]);
    }
    for (int node : columns.probe_nodes)
      for (int k = 0; k < 3; ++k) row.push_back(model.state()[DofMap::dof(node, k)]);
    row.push_back(avg.volume);
    double min_J = std::numeric_limits<double>::infinity();
    for (const auto& f : fields) min_J = std::min(min_J, f.J);
    row.push_back(min_J);
    row.push_back(model.strain_energy());
    if (c.solver.stability.check) {
      row.push_back(info.negative_pivots);
      row.push_back(info.expected_negative_pivots);
      row.push_back(info.stable ? 1.0 : 0.0);
    }
    if (wrinkle_meter) {
      last_wrinkles = wrinkle_meter->evaluate(model, fields);
      for (double v : wrinkle_meter->history_values(*last_wrinkles)) row.push_back(v);
    }
    if (history_file) history_file->add_row(row);
    time_output += seconds_since(t_out);
    if (info.new_instability) {
      nlohmann::json eigenvalues = nlohmann::json::array();
      for (const Eigenmode& m : info.modes) eigenvalues.push_back(m.eigenvalue);
      instabilities.push_back({{"step", info.step},
                               {"time", info.time},
                               {"negative_pivots", info.unstable_negative_pivots},
                               {"expected_negative_pivots", info.expected_negative_pivots},
                               {"eigenvalues", eigenvalues},
                               {"branch_switched", info.branch_switched},
                               {"perturbation_mm", info.perturbation_mm},
                               {"file", step_name(info.step)}});
    }
    // A new instability's modes are always written (they seed `imperfection_kind: mode`).
    if (info.step % c.output.every == 0 || info.load_factor >= 1.0 || !info.modes.empty())
      write_output(info);
    previous_state = model.state();
    last_step = info;
    char line[320];
    char stability[96] = "";
    if (info.negative_pivots >= 0)
      std::snprintf(stability, sizeof stability, info.stable ? "  stable" : "  UNSTABLE (%d/%d neg. pivots)",
                    info.negative_pivots, info.expected_negative_pivots);
    std::snprintf(line, sizeof line,
                  "step %4d  t %.5g  load %.4f  dt %.3g  newton %2d  |R| %.3e%s%s%s  elapsed %.1fs",
                  info.step, info.time, info.load_factor, info.dt, info.newton_iterations,
                  info.residual_norm, stability,
                  last_wrinkles && last_wrinkles->rings.wrinkled ? "  wrinkled" : "",
                  info.cutbacks ? "  (after cut-back)" : "", seconds_since(t_start));
    log.info(line);
    if (c.output.checkpoint_every > 0 && info.step % c.output.checkpoint_every == 0) save_checkpoint();
    if (any_rank(interrupts.requested())) {
      log.warn("interrupted by a signal: writing a checkpoint and stopping after step " +
               std::to_string(info.step));
      save_checkpoint();
      stepper.request_stop();
    }
    log.flush();
  };

  const SteppingResult result = stepper.run(on_step, [&](const std::string& s) { log.warn(s); });
  if (last_step.step > 0 && last_written != last_step.step) write_output(last_step);
  // The final state stays in the run directory: `plisse wrinkles DIR` reads it.
  if (last_step.step > 0) save_checkpoint();

  nlohmann::json summary;
  summary["case"] = options.case_file;
  summary["case_path"] = fs::absolute(options.case_file).lexically_normal().string();
  summary["overrides"] = options.overrides;
  summary["title"] = c.title;
  summary["completed"] = result.completed;
  summary["interrupted"] = result.interrupted;
  if (!result.completed) summary["failure"] = result.failure;
  summary["nodes"] = mesh.n_nodes();
  summary["elements"] = mesh.n_tets();
  summary["dofs"] = model.dofs().n_dofs();
  summary["free_dofs"] = model.n_free();
  summary["pressure_dofs"] = model.dofs().n_free_pressure();
  summary["steps"] = result.steps;
  summary["newton_iterations"] = result.newton_iterations;
  summary["cutbacks"] = result.cutbacks;
  summary["final_time"] = last_step.time;
  const PhaseTimes times = stepper.times();
  summary["factorisations"] = times.factorisations;
  if (result.newton_iterations > 0) {
    const double entries = stepper.factor_entries();
    if (entries > 0) summary["factor_entries"] = entries;  // fill = entries / tangent nonzeros
  }
  summary["wall_time"] = {{"mesh", time_mesh},
                          {"setup", time_setup},
                          {"assembly", times.assembly},
                          {"linear_solve", times.linear_solve},
                          {"factorisation", times.factorisation},
                          {"triangular_solve", times.triangular_solve},
                          {"output", time_output},
                          {"total", seconds_since(t_start)}};
  // Peak resident memory: of the whole job (sum over the ranks) and of the largest rank.
  double memory_total = peak_memory_mib(), memory_largest = memory_total;
  PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &memory_total, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD));
  PLISSE_PETSC(MPI_Allreduce(MPI_IN_PLACE, &memory_largest, 1, MPI_DOUBLE, MPI_MAX, PETSC_COMM_WORLD));
  summary["ranks"] = model.n_ranks();
  summary["peak_memory_mib"] = memory_total;
  summary["peak_memory_per_rank_mib"] = memory_largest;
  if (c.solver.stability.check) {
    summary["stability"] = {{"checks", stepper.stability_checks()},
                            {"check_seconds", stepper.stability_seconds()},
                            {"eigenmode_seconds", stepper.eigenmode_seconds()},
                            {"stable_at_end", last_step.stable},
                            {"instabilities", instabilities}};
  }
  if (last_wrinkles) summary["wrinkles"] = wrinkles_json(c, *last_wrinkles);
  if (history_file && !history_file->rows().empty()) {
    nlohmann::json final_values;
    for (size_t i = 0; i < history_file->columns().size(); ++i)
      final_values[history_file->columns()[i]] = history_file->rows().back()[i];
    summary["final"] = final_values;
  }
  if (root) write_json_file(dir.summary_json(), summary);
  char line[256];
  std::snprintf(line, sizeof line,
                "%s: %d steps, %d Newton iterations, %d cut-backs, %.2fs (assembly %.2fs, "
                "linear solve %.2fs, output %.2fs), peak memory %.0f MiB",
                result.completed ? "done" : "stopped", result.steps, result.newton_iterations,
                result.cutbacks, seconds_since(t_start), times.assembly, times.linear_solve,
                time_output, memory_total);
  log.info(line);
  if (result.interrupted) {
    log.flush();
    throw SolverError("interrupted after step " + std::to_string(last_step.step) + " at t = " +
                      std::to_string(last_step.time) + "; continue with: plisse run " +
                      options.case_file + " --resume " + dir.directory().string());
  }
  if (!result.completed) {
    log.error(result.failure);
    log.flush();
    throw SolverError(result.failure + " (last converged step " + std::to_string(last_step.step) +
                      " at t = " + std::to_string(last_step.time) + " is written in " +
                      dir.directory().string() + ")");
  }
  log.flush();
}

}  // namespace

void run_case(const RunOptions& options) {
  const auto t_start = Clock::now();
  const Case c = parse_case_file(options.case_file, options.overrides);
  if (!options.resume_directory.empty() && !options.output_directory.empty() &&
      fs::weakly_canonical(options.resume_directory) != fs::weakly_canonical(options.output_directory))
    throw InputError({"command line", 0, 0, "--resume"},
                     "a resumed run writes into its own directory; -o must be omitted or the same");
  const fs::path out_dir = !options.resume_directory.empty() ? fs::path(options.resume_directory)
                           : options.output_directory.empty()
                               ? fs::path("runs") / fs::path(options.case_file).stem()
                               : fs::path(options.output_directory);
  const std::uint64_t fingerprint = case_fingerprint(options.case_file, options.overrides);
  std::optional<Checkpoint> checkpoint;
  if (!options.resume_directory.empty()) {
    checkpoint = read_checkpoint(out_dir / "checkpoint.bin");
    if (checkpoint->case_fingerprint != fingerprint)
      throw InputError({(out_dir / "checkpoint.bin").string(), 0, 0, "--resume"},
                       "the checkpoint was written for another case file or other --set values");
  }

  auto t0 = Clock::now();
  const Mesh mesh = load_perturbed_mesh(c);
  if (const auto unsupported = unsupported_features(c, mesh); !unsupported.empty())
    throw unsupported.front();
  const double time_mesh = seconds_since(t0);

  // Everything that can be rejected is checked before the run directory is touched.
  std::map<std::string, double> params = c.material.params;
  AnyMaterial material = make_material(c.material.model, params);
  const std::vector<ConstrainedComponent> constraints = collect_constraints(c, mesh);
  check_free_displacements(c, mesh, constraints);
  std::vector<std::unique_ptr<ModelTerm>> terms = make_terms(c, mesh, constraints);

  // PETSc's own signal handler would abort on SIGINT/SIGTERM; plisse checkpoints instead.
  PetscSession petsc({"-no_signal_handler", c.solver.petsc_options});
  for (const auto& o : options.petsc_options) PetscSession::insert_options(o);
  check_solver_options(c, options.petsc_options);
  InterruptGuard interrupts;
  check_same_mesh_on_every_rank(mesh);
  // Input and solver errors from here on arise on every rank alike; anything else (a failed write
  // on one rank) would leave the others waiting in a collective call, so it ends the whole job.
  try {
    solve_and_write({options, c, t_start, out_dir, fingerprint, checkpoint, mesh, time_mesh,
                     std::move(material), constraints, std::move(terms), interrupts});
  } catch (const InputError&) {
    throw;
  } catch (const SolverError&) {
    throw;
  } catch (...) {
    if (PetscSession::size() > 1) abort_all_ranks(std::current_exception());
    throw;
  }
}

}  // namespace plisse::app
