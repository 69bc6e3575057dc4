// `plisse wrinkles DIR [--step N] [--set output.wrinkles.KEY=VALUE ...]`: recomputes the wrinkle
// metrics of the last converged state of a finished (or stopped) run, or of a written step
// (docs/architecture.md, "Interface contract"). The run directory's summary.json names the case
// and its --set values; checkpoint.bin holds the final state (written at the end of every run)
// and the fingerprint the case and mesh are checked against; step N is read from its VTU file. The
// table goes to DIR/wrinkles.json, with the step measured and the --set values, and is printed;
// summary.json is not changed. The directory is locked meanwhile: a run writing into it at the same
// time is refused.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/model_builder.hpp"
#include "app/run_plan.hpp"
#include "app/run_session.hpp"
#include "app/wrinkling.hpp"
#include "core/error.hpp"
#include "output/checkpoint.hpp"
#include "output/history_writer.hpp"
#include "output/json_file.hpp"
#include "output/pvd_writer.hpp"
#include "output/run_directory.hpp"
#include "output/vtu_reader.hpp"
#include "output/vtu_writer.hpp"
#include "solver/petsc_session.hpp"

namespace plisse::app {
namespace {

namespace fs = std::filesystem;

struct WrinklesOptions {
  std::string run_directory;
  std::vector<std::string> overrides;  ///< output.wrinkles.* only
  int step = -1;                       ///< a written step (its VTU file); -1: the last state
};

/// What is measured: the state, its step and time.
struct MeasuredState {
  WrinkleMeter::Result result;
  int step = 0;
  double time = 0.0;
};

/// The metrics of written step `step` from its VTU file's displacement, cauchy_stress and J.
MeasuredState measure_step_file(const fs::path& dir, int step, const Mesh& mesh,
                                const WrinkleMeter& meter) {
  const InputPlace place{dir.string(), 0, 0, "--step"};
  const std::vector<PvdEntry> entries = read_pvd(dir / "solution.pvd");
  const std::string vtu = RunDirectory::step_file_name(step);
  const std::string pvtu = vtu.substr(0, vtu.size() - 4) + ".pvtu";
  std::string written;
  for (const PvdEntry& e : entries) {
    if (e.file == pvtu)
      throw InputError(place, "step " + std::to_string(step) +
                                  " of a distributed run is written in pieces (" + pvtu +
                                  ") whose cells carry no global numbering; measure the last "
                                  "state (without --step) instead");
    if (e.file != vtu) {
      if (written.size() < 200) written += (written.empty() ? "" : ", ") + e.file;
      continue;
    }
    const auto n_nodes = static_cast<std::size_t>(mesh.n_nodes());
    const auto n_cells = static_cast<std::size_t>(n_mesh_cells(mesh));
    const auto misfit = [&] {
      return InputError({(dir / e.file).string(), 0, 0, "--step"},
                        "the step file does not fit the case's mesh (" + std::to_string(n_nodes) +
                            " nodes, " + std::to_string(n_cells) +
                            (mesh.is_shell() ? " triangles)" : " tetrahedra)"));
    };
    // The sizes its header declares first: a step file of this run holds the case's mesh, and
    // anything larger (a compressed array that would inflate to gigabytes) is refused unread.
    VtuSummary declared;
    try {
      declared = read_vtu_summary(dir / e.file);
    } catch (const InputError&) {
      throw;
    } catch (const Error& error) {  // a file no run of plisse writes: bad input
      throw InputError({(dir / e.file).string(), 0, 0, "--step"}, error.what());
    }
    const auto components = [](const auto& fields, const std::string& name) {
      for (const auto& f : fields)
        if (f.name == name) return f.n_components;
      return 0;
    };
    if (declared.n_points != n_nodes || declared.n_cells != n_cells ||
        components(declared.point_fields, "displacement") != 3 ||
        components(declared.cell_fields, "cauchy_stress") != 6 ||
        components(declared.cell_fields, "J") != 1)
      throw misfit();
    const VtuField u = read_vtu_point_field(dir / e.file, "displacement");
    const VtuField cauchy = read_vtu_cell_field(dir / e.file, "cauchy_stress");
    const VtuField J = read_vtu_cell_field(dir / e.file, "J");
    if (u.values.size() != 3 * n_nodes || cauchy.values.size() != 6 * n_cells ||
        J.values.size() != n_cells)
      throw misfit();
    std::vector<Vec3d> displacement(n_nodes);
    for (std::size_t v = 0; v < n_nodes; ++v)
      displacement[v] = Vec3d(u.values[3 * v], u.values[3 * v + 1], u.values[3 * v + 2]);
    return {meter.evaluate(mesh, displacement, symmetric_tensors(cauchy), J.values), step, e.time};
  }
  throw InputError(place, "step " + std::to_string(step) +
                              " has no step file in solution.pvd (written: " + written +
                              "; output.every decides which steps are written)");
}

std::vector<std::string> string_list(const nlohmann::json& j) {
  std::vector<std::string> out;
  if (j.is_array())
    for (const auto& v : j)
      if (v.is_string()) out.push_back(v.get<std::string>());
  return out;
}

/// What summary.json says of the run: the case file and its --set values.
struct RunRecord {
  nlohmann::json summary;
  std::string case_path;
  std::vector<std::string> run_overrides;
};

/// Reads the run's summary.json; refuses --set values other than output.wrinkles.* and a case
/// file that is gone.
RunRecord read_run_record(const fs::path& summary_path, const WrinklesOptions& options) {
  RunRecord run;
  try {
    run.summary = read_json_file(summary_path);
  } catch (const InputError& e) {
    throw InputError({summary_path.string(), e.place().line, e.place().column, ""}, e.rule());
  } catch (const Error& e) {
    throw InputError({summary_path.string(), 0, 0, ""}, e.what());
  }
  const nlohmann::json& summary = run.summary;
  if (!summary.is_object() || !summary.contains("case_path") || !summary["case_path"].is_string())
    throw InputError({summary_path.string(), 0, 0, "case_path"},
                     "does not name the case file (written by plisse run since version 0.1)");
  run.case_path = summary["case_path"].get<std::string>();
  run.run_overrides = string_list(summary["overrides"]);
  for (const std::string& o : options.overrides)
    if (o.rfind("output.wrinkles.", 0) != 0)
      throw InputError({"command line", 0, 0, "--set"},
                       "'" + o +
                           "': only output.wrinkles.* can change after the run (anything "
                           "else would not match the computed state)");
  std::error_code ec;
  if (!fs::exists(run.case_path, ec))
    throw InputError({summary_path.string(), 0, 0, "case_path"},
                     "the case file of this run, " + run.case_path + ", no longer exists");
  return run;
}

/// The metrics of the checkpoint's state, restored into the case's model.
MeasuredState measure_last_state(const fs::path& dir, const Case& c, const Mesh& mesh,
                                 const WrinkleMeter& meter, const Checkpoint& checkpoint) {
  ModelParts parts = build_model_parts(c, mesh);
  PetscSession petsc({"-no_signal_handler"});
  const std::unique_ptr<MixedModel> model = make_model(mesh, std::move(parts));
  try {
    model->restore({checkpoint.state, checkpoint.bubbles, checkpoint.term_states});
  } catch (const Error& e) {
    throw InputError({(dir / "checkpoint.bin").string(), 0, 0, "DIR"}, e.what());
  }
  return {meter.evaluate(*model, model->element_fields()), checkpoint.steps, checkpoint.time};
}

/// The table on the terminal: the state measured, each ring's metrics and decision, each line's,
/// the tension field's counts.
void print_wrinkles(const fs::path& dir, const WrinklesOptions& options, const RunRecord& run,
                    const MeasuredState& measured, int checkpoint_steps) {
  const WrinkleMeter::Result& result = measured.result;
  const nlohmann::json& summary = run.summary;
  double largest = result.rings.max_amplitude;
  for (const LineReading& line : result.lines) largest = std::max(largest, line.metrics.amplitude);
  std::printf(
      "plisse wrinkles: %s, step %d at t = %g: %s (max amplitude %.4g mm, threshold %.4g mm)\n",
      dir.string().c_str(), measured.step, measured.time,
      result.wrinkled() ? "wrinkled" : "not wrinkled", largest, result.rings.threshold);
  std::printf("  written to %s\n", (dir / "wrinkles.json").string().c_str());
  if (options.step < 0 && summary.contains("completed") && summary["completed"] == false)
    std::printf(
        "  note: the run did not reach its end time; step %d is its last converged step%s\n",
        checkpoint_steps,
        summary.contains("failure") && summary["failure"].is_string()
            ? (" (it stopped: " + summary["failure"].get<std::string>() + ")").c_str()
            : "");
  if (!result.rings.rings.empty())
    std::printf("  %14s %7s %16s %16s %14s %7s  %s\n", "latitude [deg]", "count", "amplitude [mm]",
                "wavelength [mm]", "radius [mm]", "points", "decision (dominant m: A_m / E_m)");
  for (const RingMetrics& r : result.rings.rings) {
    // The largest harmonic m >= min_count against the global shape's envelope (wrinkles.md,
    // W15-W16): the ratio that decided, the full spectrum being in summary.json.
    std::string why = ring_decision_name(r.decision);
    for (std::size_t i = 0; i < r.spectrum.size(); ++i)
      if (r.dominant_count > 0 && r.spectrum[i].first == r.dominant_count) {
        char text[96];
        std::snprintf(text, sizeof text, " (m = %d: %.3g / %.3g mm)", r.dominant_count,
                      r.spectrum[i].second, r.envelope[i]);
        why += text;
      }
    std::printf("  %14.4g %7d %16.4g %16.4g %14.4g %7d  %s\n", r.latitude_deg, r.count, r.amplitude,
                r.wavelength, r.mean_radius, r.n_points, why.c_str());
  }
  if (!result.lines.empty())
    std::printf("  %14s %7s %16s %16s %16s  %s\n", "line", "crests", "amplitude [mm]",
                "wavelength [mm]", "deviation [mm]", "wrinkled");
  for (const LineReading& line : result.lines)
    std::printf("  %14.14s %7d %16.4g %16.4g %16.4g  %s\n", line.name.c_str(), line.metrics.crests,
                line.metrics.amplitude, line.metrics.wavelength, line.metrics.deviation,
                line.wrinkled ? "yes" : "no");
  const auto& n = result.tension.n_elements;
  std::printf("  tension field (elements): %d taut, %d wrinkled, %d slack\n", n[0], n[1], n[2]);
}

void recompute_wrinkles(const WrinklesOptions& options) {
  const fs::path dir = options.run_directory;
  const InputPlace place{dir.string(), 0, 0, "DIR"};
  // Its copies under mpirun would each take the directory's lock, and all but one be refused.
  if (const int ranks = launcher_size(); ranks > 1)
    throw InputError({"command line", 0, 0, "wrinkles"},
                     "plisse wrinkles runs on one process, not in an MPI job (here of " +
                         std::to_string(ranks) + " ranks): start it without mpirun or mpiexec");
  check_petsc_environment();  // it starts PETSc to restore the model
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw InputError(place, "is not a run directory");
  const fs::path summary_path = dir / "summary.json";
  if (!fs::exists(summary_path, ec))
    throw InputError(place, "holds no summary.json: not a finished plisse run");
  // A run still writing here would replace its files under this command, or the reverse.
  const DirectoryLock lock(dir, place);
  const RunRecord run = read_run_record(summary_path, options);
  const std::string& case_path = run.case_path;
  std::vector<std::string> overrides = run.run_overrides;
  overrides.insert(overrides.end(), options.overrides.begin(), options.overrides.end());
  const Case c = parse_case_file(case_path, overrides);

  const Checkpoint checkpoint = read_checkpoint(dir / "checkpoint.bin");
  if (!c.output.wrinkles.enabled())
    throw InputError({case_path, 0, 0, "output.wrinkles.rings_deg"},
                     "no rings or lines to measure: give the rings' latitudes, e.g. --set "
                     "output.wrinkles.rings_deg=[0,30,60], or measurement lines, e.g. --set "
                     "'output.wrinkles.lines=[{name: a, from: [0,0,0], to: [10,0,0]}]'");

  const Mesh mesh = load_perturbed_mesh(c);
  // After the mesh file has passed its reader's checks (type, size): it is hashed whole.
  if (const std::string changes = fingerprint_changes(
          checkpoint.fingerprint,
          run_fingerprint(case_path, run.run_overrides, c.mesh.file.value_or(""), mesh));
      !changes.empty())
    throw InputError({(dir / "checkpoint.bin").string(), 0, 0, "DIR"},
                     "the run's state no longer matches its case (" + case_path + "): " + changes);
  const WrinkleMeter meter(c, mesh);
  MeasuredState measured = options.step >= 0 ? measure_step_file(dir, options.step, mesh, meter)
                                             : measure_last_state(dir, c, mesh, meter, checkpoint);
  // Under arc-length control solution.pvd lists the step files by step number (the load falls
  // past a limit point): the step's time is history.csv's.
  if (options.step >= 0 && c.solver.control == StepControl::arc_length) {
    const HistoryTable history = read_history(dir / "history.csv");
    for (const std::vector<double>& row : history.rows)
      if (!row.empty() && row[0] == options.step) measured.time = row[1];
  }
  // Its own file: summary.json stays the run's, matching history.csv.
  const nlohmann::json table = {{"case", case_path},
                                {"run_overrides", run.run_overrides},
                                {"step", measured.step},
                                {"time", measured.time},
                                {"overrides", options.overrides},
                                {"wrinkles", wrinkles_json(c, measured.result)}};
  write_json_file(dir / "wrinkles.json", table);
  print_wrinkles(dir, options, run, measured, checkpoint.steps);
}

}  // namespace

void add_wrinkles_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "wrinkles",
      "Recompute the wrinkle metrics of a run's last converged state, or of a written step with "
      "--step N (writes DIR/wrinkles.json)");
  auto options = std::make_shared<WrinklesOptions>();
  cmd->add_option("dir", options->run_directory, "Run directory written by plisse run")->required();
  cmd->add_option("--set", options->overrides,
                  "Change a wrinkle setting, e.g. --set output.wrinkles.rings_deg=[0,45] or "
                  "--set output.wrinkles.axis=z (output.wrinkles.* only; repeatable)")
      ->take_all()
      ->allow_extra_args(false);
  cmd->add_option("--step", options->step,
                  "Measure this written step (its step file: displacement, cauchy_stress, J) "
                  "instead of the last state; 0 is the undeformed body")
      ->check(CLI::NonNegativeNumber);
  cmd->callback([options] { recompute_wrinkles(*options); });
}

}  // namespace plisse::app
