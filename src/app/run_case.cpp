#include "app/run_case.hpp"

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <sstream>

#include "analysis/point_location.hpp"
#include "app/model_builder.hpp"
#include "app/progress_line.hpp"
#include "app/run_recorder.hpp"
#include "app/wrinkling.hpp"
#include "core/error.hpp"
#include "core/wall_clock.hpp"
#include "io/atomic_file.hpp"
#include "io/case.hpp"
#include "io/checkpoint.hpp"
#include "io/petsc_option_text.hpp"
#include "io/run_directory.hpp"
#include "io/run_log.hpp"
#include "mesh/topology.hpp"
#include "solver/collective.hpp"
#include "solver/linear_solver.hpp"
#include "solver/load_stepper.hpp"
#include "solver/petsc_call.hpp"
#include "solver/petsc_session.hpp"
#include "solver/thread_counts.hpp"

namespace plisse::app {
namespace {

namespace fs = std::filesystem;

volatile std::sig_atomic_t g_interrupt = 0;
/// The first SIGINT/SIGTERM asks the run to stop; a second one ends the process at once. What
/// was written stays whole: files are replaced by rename or grow by whole lines, and the next run
/// or resume in the directory removes the temporaries and takes over the lock.
extern "C" void on_interrupt(int) {
  if (g_interrupt != 0) {
    static const char kMessage[] =
        "\nplisse: second interrupt: stopping at once; the files written so far are whole, the "
        "last checkpoint is the place to resume from\n";
    const ssize_t written = ::write(STDERR_FILENO, kMessage, sizeof kMessage - 1);
    (void)written;
    ::_exit(1);
  }
  g_interrupt = 1;
}

/// SIGINT/SIGTERM set a flag for the duration of a run; the stepper asks it before every step and
/// after every Newton iteration, stops with the last converged step and the run checkpoints it. A
/// second signal ends the process at once (on_interrupt). The previous handlers come back at the
/// end.
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

/// Every rank builds the mesh on its own (reads or generates it); they must agree, node for node.
void check_same_mesh_on_every_rank(const Mesh& mesh) {
  if (PetscSession::size() == 1) return;
  unsigned long long low = geometry_hash(mesh), high = low;
  PLISSE_PETSC(
      MPI_Allreduce(MPI_IN_PLACE, &low, 1, MPI_UNSIGNED_LONG_LONG, MPI_MIN, PETSC_COMM_WORLD));
  PLISSE_PETSC(
      MPI_Allreduce(MPI_IN_PLACE, &high, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, PETSC_COMM_WORLD));
  if (low != high)
    throw Error(
        "the ranks built different meshes from the same case (mesh generation is not "
        "reproducible here); write the mesh once with `plisse mesh` and use mesh.file");
}

/// Why a new run may not write into `directory` (empty: it may): the files of an earlier run.
std::string earlier_run_refusal(const fs::path& directory) {
  const std::vector<fs::path> files = run_files(directory);
  if (files.empty()) return {};
  std::string names;
  for (std::size_t i = 0; i < std::min<std::size_t>(files.size(), 3); ++i)
    names += (i > 0 ? ", " : "") + files[i].filename().string();
  if (files.size() > 3) names += " and " + std::to_string(files.size() - 3) + " more";
  return "holds an earlier run (" + names +
         "); continue it with --resume, replace it with --overwrite, or choose another -o";
}

}  // namespace

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
  WallClock::time_point start;
  fs::path out_dir;
  const RunFingerprint& fingerprint;
  const std::optional<Checkpoint>& checkpoint;
  const std::optional<Checkpoint>& from;  ///< --from: the earlier run's last state
  const Mesh& mesh;
  double time_mesh;
  ModelParts parts;
  const InterruptGuard& interrupts;
  std::string threads;  ///< describe(apply_thread_counts(...)), for the log
};

/// The log's opening lines: the case, the output directory, the sizes and (distributed) the
/// split of the work among the ranks. Collective.
void log_header(RunLog& log, const PreparedRun& run, const fs::path& directory,
                const MixedModel& model, std::size_t n_constrained) {
  const Case& c = run.c;
  const Mesh& mesh = run.mesh;
  log.info("plisse run " + run.options.case_file + (c.title.empty() ? "" : "  (" + c.title + ")"));
  log.info("output: " + directory.string());
  for (const auto& o : run.options.overrides) log.info("  --set " + o);
  char line[256];
  std::snprintf(line, sizeof line,
                "mesh: %d nodes, %d tetrahedra (%s); unknowns: %d (%d pressure), %zu constrained",
                mesh.n_nodes(), mesh.n_tets(), to_string(model.element_family()).c_str(),
                model.n_free(), model.dofs().n_free_pressure(), n_constrained);
  log.info(line);
  log.info("threads: " + run.threads);
  log.info(
      "units: the case's, consistent (mm, N, MPa, s in plisse's docs); history.csv's "
      "columns: summary.json history_units, plisse outputs");
  for (const InputError& e : setup_warnings(c)) log.warn(e.what());
  for (const Load& load : c.loads) {
    if (load.type != LoadType::point_force) continue;
    const int v = nearest_node(mesh, load.point);
    const Vec3d& x = mesh.nodes[v];
    std::snprintf(line, sizeof line,
                  "load '%s': on node %d at [%.6g, %.6g, %.6g], %.3g mm from its point",
                  load.name.c_str(), v, x.x(), x.y(), x.z(), (x - load.point).norm());
    log.info(line);
  }
  for (const Probe& probe : c.probes) {
    const MeshPoint at = locate_point(mesh, probe.point);
    std::snprintf(line, sizeof line,
                  "probe '%s': %s element %d at [%.6g, %.6g, %.6g], %.3g mm from its point",
                  probe.name.c_str(), at.inside ? "in" : "on the surface of", at.element,
                  at.position.x(), at.position.y(), at.position.z(), at.distance);
    log.info(line);
  }
  if (model.n_ranks() == 1) return;
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

/// Builds the model, steps to the end and writes the run directory through a RunRecorder.
/// Distributed runs: every rank runs all of it; rank 0 alone writes the log.
void solve_and_write(PreparedRun run) {
  const Case& c = run.c;
  const std::optional<Checkpoint>& checkpoint = run.checkpoint;
  const bool root = PetscSession::rank() == 0;

  const auto t0 = WallClock::now();
  const std::size_t n_constrained = run.parts.constraints.size();
  // A rigid cap borders the tangent with one multiplier per tied component: MUMPS needs more
  // working space than it estimates (linear_solver.hpp, request_factor_workspace).
  if (!c.caps.empty()) request_factor_workspace(100);
  const std::unique_ptr<MixedModel> model = make_model(run.mesh, std::move(run.parts));
  LoadStepper stepper(*model, c.solver);
  stepper.set_stability(stability_options(c));
  std::optional<WrinkleMeter> wrinkle_meter;
  if (c.output.wrinkles.enabled()) wrinkle_meter.emplace(c, run.mesh);
  const StartTimes times{run.start, run.time_mesh, seconds_since(t0)};

  const RunDirectory dir(run.out_dir);
  // The directory is this run's alone while it runs, and a new run neither mixes its files with
  // an earlier run's nor replaces them unless asked to. Rank 0 decides for all.
  const InputPlace place{dir.directory().string(), 0, 0, checkpoint ? "--resume" : "-o"};
  std::optional<DirectoryLock> lock;
  std::string refusal;
  if (root) {
    try {
      lock.emplace(dir.directory(), place);
      if (!checkpoint && !run.options.overwrite) refusal = earlier_run_refusal(dir.directory());
    } catch (const InputError& e) {
      refusal = e.rule();
    }
  }
  refusal = from_root(refusal);
  if (!refusal.empty()) throw InputError(place, refusal);
  // --overwrite: the earlier run's files go; otherwise what a run killed mid-write left behind
  // (its files themselves are whole: atomic writes and whole-line appends).
  // Rank 0's files: a failure there is agreed by all ranks, which then unwind together.
  int removed = 0;
  std::optional<RunLog> root_log;  // other ranks: a log that writes nowhere
  on_every_rank_alike([&] {
    if (!root) return;
    removed = run.options.overwrite ? remove_run_files(dir.directory())
                                    : remove_stale_temporaries(dir.directory());
    root_log.emplace(dir.log_txt(), checkpoint ? LogStart::append : LogStart::replace);
  });
  if (!root) root_log.emplace(fs::path{}, nullptr, nullptr);
  RunLog& log = *root_log;
  const auto flush_log = [&] { on_every_rank_alike([&] { log.flush(); }); };
  log_header(log, run, dir.directory(), *model, n_constrained);
  if (removed > 0)
    log.info("removed " + std::to_string(removed) +
             (run.options.overwrite ? " file(s) of the earlier run (--overwrite)"
                                    : " temporary file(s) an interrupted run left"));
  if (checkpoint) {
    try {
      model->restore({checkpoint->state, checkpoint->bubbles, checkpoint->term_states});
    } catch (const InputError&) {
      throw;
    } catch (const Error& e) {
      throw InputError({(dir.directory() / "checkpoint.bin").string(), 0, 0, "--resume"}, e.what());
    }
    stepper.resume({checkpoint->steps, checkpoint->time, checkpoint->dt, checkpoint->previous_dt,
                    checkpoint->previous_state, checkpoint->negative_pivots});
  }
  RunRecorder recorder(c, dir, {run.options.case_file, run.options.overrides, run.fingerprint},
                       *model, stepper, wrinkle_meter ? &*wrinkle_meter : nullptr,
                       checkpoint ? &*checkpoint : nullptr);
  if (run.from) {
    // A second load step: the nodal values and the elements' internal state carry over; the
    // terms (loads, cavities, dies, contacts, caps) and the clock start afresh from this case.
    if (run.from->bubbles.size() != model->n_internal_values())
      throw InputError(
          {(fs::path(run.options.from_directory) / "checkpoint.bin").string(), 0, 0, "--from"},
          "the run in " + run.options.from_directory + " carries " +
              std::to_string(run.from->bubbles.size()) +
              " internal values (element bubbles, material history), this case " +
              std::to_string(model->n_internal_values()) +
              ": a second step keeps the materials' viscoelasticity and Mullins "
              "softening, or their absence");
    model->continue_from(run.from->state, run.from->bubbles);
    log.info("starting from the last state of " + run.options.from_directory + " (step " +
             std::to_string(run.from->steps) + " at t = " + std::to_string(run.from->time) +
             "); this case's time starts at 0");
  }
  if (checkpoint)
    log.info("resuming after step " + std::to_string(checkpoint->steps) +
             " at t = " + std::to_string(checkpoint->time));
  else
    recorder.record_initial_state();
  for (const RunRecorder::WatchedMaterial& w : recorder.watched_materials()) {
    std::ostringstream line;
    line.precision(3);
    line << (w.region.empty() ? "material" : "region " + w.region + " material")
         << ": stable (Drucker) for stretches";
    for (const StabilityRange& r : w.ranges)
      line << ' ' << test_mode_name(r.mode) << ' ' << r.lower << " to " << r.upper;
    line << "; every step checks each element, and the log warns at the first that is not";
    log.info(line.str());
  }

  WallClock::time_point last_checkpoint = WallClock::now();
  const WallClock::time_point stepping_start = WallClock::now();
  const auto on_step = [&](const StepInfo& info) {
    recorder.record(info);
    if (const std::string w = recorder.take_material_warning(); !w.empty()) log.warn(w);
    const auto& wrinkles = recorder.last_wrinkles();
    log.info(progress_line(info, wrinkles ? &wrinkles->rings : nullptr,
                           {seconds_since(run.start), seconds_since(stepping_start),
                            checkpoint ? checkpoint->time : 0.0, c.solver.end_time}));
    // By step count, or by wall time (decided on every rank alike: the write is collective).
    const bool by_count =
        c.output.checkpoint_every > 0 && info.step % c.output.checkpoint_every == 0;
    const bool by_time =
        c.output.checkpoint_minutes > 0.0 &&
        any_rank(seconds_since(last_checkpoint) >= 60.0 * c.output.checkpoint_minutes);
    if (by_count || by_time) {
      recorder.save_checkpoint();
      last_checkpoint = WallClock::now();
    }
    flush_log();
  };
  // SIGINT/SIGTERM stop the stepper before the next step or within the current one (Newton
  // iterations, cut-backs, multiplier updates); the model is back at the last converged step,
  // whose checkpoint recorder.finish writes.
  stepper.set_interrupt([&] { return any_rank(run.interrupts.requested()); });
  const SteppingResult result = stepper.run(on_step, [&](const std::string& s) { log.warn(s); });
  if (result.interrupted)
    log.warn("interrupted by a signal during step " + std::to_string(result.steps + 1) +
             ": stopping; the checkpoint holds step " + std::to_string(result.steps));
  const double memory = recorder.finish(result, times);

  const PhaseTimes phases = stepper.times();
  char line[256];
  std::snprintf(line, sizeof line,
                "%s: %d steps, %d Newton iterations and %d Krylov steps (+%d solves with a reused "
                "factorisation), %d cut-backs, %.2fs (assembly %.2fs, linear solve %.2fs, output "
                "%.2fs), peak memory %.0f MiB",
                result.completed ? "done" : "stopped", result.steps, result.newton_iterations,
                result.krylov_steps, result.reused_solves, result.cutbacks,
                seconds_since(run.start), phases.assembly, phases.linear_solve,
                recorder.output_seconds(), memory);
  log.info(line);
  const StepInfo& last = recorder.last_step();
  if (result.interrupted) {
    flush_log();
    // The full command: a resume must repeat the --set values (the checkpoint's fingerprint
    // holds them), each quoted for the shell (keys such as loads[0].value hold brackets).
    // A distributed run is resumed on as many ranks.
    std::string command = "plisse run " + run.options.case_file;
    if (model->n_ranks() > 1) command += " -n " + std::to_string(model->n_ranks());
    for (const auto& o : run.options.overrides) {
      std::string quoted = "'";
      for (char ch : o) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
      command += " --set " + quoted + "'";
    }
    throw SolverError("interrupted after step " + std::to_string(last.step) +
                      " at t = " + std::to_string(last.time) + "; continue with: " + command +
                      " --resume " + dir.directory().string());
  }
  if (!result.completed) {
    log.error(result.failure);
    flush_log();
    throw SolverError(result.failure + " (last converged step " + std::to_string(last.step) +
                      " at t = " + std::to_string(last.time) + " is written in " +
                      dir.directory().string() + ")");
  }
  flush_log();
}

}  // namespace

void run_case(const RunOptions& options) {
  const auto t_start = WallClock::now();
  const Case c = parse_case_file(options.case_file, options.overrides);
  for (const std::string& o : options.petsc_options)
    if (const std::string problem = petsc_option_problem(o); !problem.empty())
      throw InputError({"command line", 0, 0, "--petsc"}, problem);
  if (!options.resume_directory.empty() && options.overwrite)
    throw InputError({"command line", 0, 0, "--overwrite"},
                     "a resumed run continues the run in its directory; --overwrite would "
                     "replace it: give one of them");
  if (!options.resume_directory.empty() && !options.output_directory.empty() &&
      fs::weakly_canonical(options.resume_directory) !=
          fs::weakly_canonical(options.output_directory))
    throw InputError({"command line", 0, 0, "--resume"},
                     "a resumed run writes into its own directory; -o must be omitted or the same");
  const fs::path out_dir = !options.resume_directory.empty() ? fs::path(options.resume_directory)
                           : options.output_directory.empty()
                               ? fs::path("runs") / fs::path(options.case_file).stem()
                               : fs::path(options.output_directory);
  std::optional<Checkpoint> from;
  const InputPlace from_place{"command line", 0, 0, "--from"};
  if (!options.from_directory.empty()) {
    if (!options.resume_directory.empty())
      throw InputError(from_place,
                       "--from starts a new run from a finished one, --resume continues an "
                       "interrupted run in its own directory: give one of them");
    const fs::path file = fs::path(options.from_directory) / "checkpoint.bin";
    try {
      from = read_checkpoint(file);
    } catch (const InputError& e) {
      throw InputError({file.string(), 0, 0, "--from"}, e.rule());
    }
    if (from->element != c.element)
      throw InputError({file.string(), 0, 0, "--from"},
                       "the run in " + options.from_directory +
                           " used `element: " + to_string(from->element) +
                           "`, this case has `element: " + to_string(c.element) +
                           "`; a second step keeps the element family");
    if (!options.output_directory.empty() && fs::weakly_canonical(options.from_directory) ==
                                                 fs::weakly_canonical(options.output_directory))
      throw InputError(from_place,
                       "the second step writes a new run directory: -o must differ from --from, "
                       "whose run stays as it is");
  }
  std::optional<Checkpoint> checkpoint;
  if (!options.resume_directory.empty()) {
    checkpoint = read_checkpoint(out_dir / "checkpoint.bin");
    if (checkpoint->element != c.element)
      throw InputError(
          {(out_dir / "checkpoint.bin").string(), 0, 0, "--resume"},
          "the checkpoint was written by a run with `element: " + to_string(checkpoint->element) +
              "`, this case has `element: " + to_string(c.element) +
              "`; a run cannot change its element family");
  }

  auto t0 = WallClock::now();
  const Mesh mesh = load_perturbed_mesh(c);
  if (const auto unsupported = unsupported_features(c, mesh); !unsupported.empty())
    throw unsupported.front();
  const double time_mesh = seconds_since(t0);
  // After the mesh file has passed its reader's checks (type, size): it is hashed whole.
  const RunFingerprint fingerprint =
      run_fingerprint(options.case_file, options.overrides, c.mesh.file.value_or(""), mesh);
  if (checkpoint) {
    if (const std::string changes = fingerprint_changes(checkpoint->fingerprint, fingerprint);
        !changes.empty())
      throw InputError({(out_dir / "checkpoint.bin").string(), 0, 0, "--resume"},
                       "the checkpoint belongs to another run: " + changes +
                           "; resume with the case, --set values and mesh it was written for, "
                           "or start a new run");
  }

  if (from && from->fingerprint.geometry != fingerprint.geometry)
    throw InputError(
        {(fs::path(options.from_directory) / "checkpoint.bin").string(), 0, 0, "--from"},
        "the run in " + options.from_directory +
            " solved another mesh (its nodes or their coordinates differ from this "
            "case's): a second step needs the same mesh");

  // Everything that can be rejected is checked before the run directory is touched.
  ModelParts parts = build_model_parts(c, mesh);
  check_rigid_pieces(c, mesh, parts.constraints);

  // PETSc's own signal handler would abort on SIGINT/SIGTERM; plisse checkpoints instead.
  PetscSession petsc({"-no_signal_handler", c.solver.petsc_options});
  for (const auto& o : options.petsc_options) PetscSession::insert_options(o);
  check_solver_options(c, options.petsc_options);
  const ThreadCounts threads = apply_thread_counts(PETSC_COMM_WORLD);
  InterruptGuard interrupts;
  end_with_launcher();
  abort_job_when_memory_runs_out();
  check_same_mesh_on_every_rank(mesh);
  // Input and solver errors from here on arise on every rank alike, and so do failed writes
  // (on_every_rank_alike); anything else on one rank would leave the others waiting in a
  // collective call, so it ends the whole job.
  try {
    solve_and_write({options, c, t_start, out_dir, fingerprint, checkpoint, from, mesh, time_mesh,
                     std::move(parts), interrupts, describe(threads)});
  } catch (const InputError&) {
    throw;
  } catch (const SolverError&) {
    throw;
  } catch (const SharedError&) {
    throw;
  } catch (...) {
    if (PetscSession::size() > 1) abort_all_ranks(std::current_exception());
    throw;
  }
}

}  // namespace plisse::app
