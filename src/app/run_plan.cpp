#include "app/run_plan.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>

#include "case/petsc_option_text.hpp"
#include "output/json_file.hpp"
#include "output/run_directory.hpp"

namespace plisse::app {
namespace {

namespace fs = std::filesystem;

/// A rule broken by the command line's option `key`.
InputPlace command_line_option(const std::string& key) { return {"command line", 0, 0, key}; }

/// The run directory the options name.
fs::path run_directory_of(const RunOptions& options) {
  if (!options.resume_directory.empty()) return options.resume_directory;
  if (options.output_directory.empty())
    return fs::path("runs") / fs::path(options.case_file).stem();
  return options.output_directory;
}

}  // namespace

void check_petsc_environment() {
  // PETSc reads these at start-up as if given on the command line: the same rules apply. (Its
  // .petscrc files are not read at all: PetscSession passes -skip_petscrc.)
  if (const char* text = std::getenv("PETSC_OPTIONS"); text != nullptr && *text != '\0')
    if (const std::string problem = petsc_option_problem(text); !problem.empty())
      throw InputError({"environment", 0, 0, "PETSC_OPTIONS"},
                       problem + " (PETSc reads PETSC_OPTIONS as options of the run)");
  if (const char* text = std::getenv("PETSC_OPTIONS_YAML"); text != nullptr && *text != '\0')
    throw InputError({"environment", 0, 0, "PETSC_OPTIONS_YAML"},
                     "PETSc would read it as options of the run, which plisse checks only as "
                     "text: unset it and give the options with --petsc or solver.petsc_options");
}

namespace {

/// Rules between the options alone, before any file is read.
void check_option_rules(const RunOptions& options) {
  for (const std::string& o : options.petsc_options)
    if (const std::string problem = petsc_option_problem(o); !problem.empty())
      throw InputError(command_line_option("--petsc"), problem);
  check_petsc_environment();
  const bool resume = !options.resume_directory.empty();
  if (resume && options.overwrite)
    throw InputError(command_line_option("--overwrite"),
                     "a resumed run continues the run in its directory; --overwrite would "
                     "replace it: give one of them");
  if (resume && !options.output_directory.empty() &&
      fs::weakly_canonical(options.resume_directory) !=
          fs::weakly_canonical(options.output_directory))
    throw InputError(command_line_option("--resume"),
                     "a resumed run writes into its own directory; -o must be omitted or the same");
}

/// Why the run in `directory`, whose checkpoint is `from`, did not complete (empty: it did): no
/// summary.json (killed, or still running), one that says it was interrupted or failed, or one
/// whose final time is not the checkpoint's (a later attempt wrote the checkpoint).
std::string unfinished_run(const fs::path& directory, const Checkpoint& from) {
  const fs::path file = directory / "summary.json";
  std::error_code error;
  if (!fs::exists(file, error)) return "has no summary.json (it was killed, or is still running)";
  nlohmann::json summary;
  try {
    summary = read_json_file(file);
  } catch (const Error& e) {
    return std::string("has a summary.json that cannot be read (") + e.what() + ")";
  }
  if (!summary.is_object() || !summary.contains("completed") || !summary["completed"].is_boolean())
    return "has a summary.json without `completed`";
  if (!summary["completed"].get<bool>()) {
    if (summary.contains("interrupted") && summary["interrupted"].is_boolean() &&
        summary["interrupted"].get<bool>())
      return "was interrupted before its end time";
    return "stopped before its end time" +
           (summary.contains("failure") && summary["failure"].is_string()
                ? " (" + summary["failure"].get<std::string>() + ")"
                : std::string());
  }
  if (!summary.contains("final_time") || !summary["final_time"].is_number() ||
      summary["final_time"].get<double>() != from.time)
    return "has a checkpoint.bin that is not of its last step (t = " + std::to_string(from.time) +
           ")";
  return {};
}

/// --from DIR: the finished run's last state, which must be of the case's element, in another
/// directory than the new run's.
Checkpoint read_from_state(const RunOptions& options, const Case& c) {
  if (!options.resume_directory.empty())
    throw InputError(command_line_option("--from"),
                     "--from starts a new run from a finished one, --resume continues an "
                     "interrupted run in its own directory: give one of them");
  const fs::path file = fs::path(options.from_directory) / "checkpoint.bin";
  Checkpoint from;
  try {
    from = read_checkpoint(file);
  } catch (const InputError& e) {
    throw InputError({file.string(), 0, 0, "--from"}, e.rule());
  }
  if (from.element != c.element)
    throw InputError({file.string(), 0, 0, "--from"},
                     "the run in " + options.from_directory +
                         " used `element: " + to_string(from.element) +
                         "`, this case has `element: " + to_string(c.element) +
                         "`; a second step keeps the element family");
  if (const std::string why = unfinished_run(options.from_directory, from); !why.empty()) {
    if (!options.from_unfinished)
      throw InputError({file.string(), 0, 0, "--from"},
                       "the run in " + options.from_directory + " " + why +
                           ": a second step starts from a completed run; give --from-unfinished "
                           "to start from its last checkpoint (step " +
                           std::to_string(from.steps) + " at t = " + std::to_string(from.time) +
                           ") all the same");
  }
  if (!options.output_directory.empty() && fs::weakly_canonical(options.from_directory) ==
                                               fs::weakly_canonical(options.output_directory))
    throw InputError(command_line_option("--from"),
                     "the second step writes a new run directory: -o must differ from --from, "
                     "whose run stays as it is");
  return from;
}

/// --resume DIR: the checkpoint in DIR, which must be of the case's element.
Checkpoint read_resume_checkpoint(const fs::path& directory, const Case& c) {
  Checkpoint checkpoint = read_checkpoint(directory / "checkpoint.bin");
  if (checkpoint.element != c.element)
    throw InputError(
        {(directory / "checkpoint.bin").string(), 0, 0, "--resume"},
        "the checkpoint was written by a run with `element: " + to_string(checkpoint.element) +
            "`, this case has `element: " + to_string(c.element) +
            "`; a run cannot change its element family");
  return checkpoint;
}

/// "device:inode:size:mtime" of `file`, or empty when it cannot be read. A checkpoint is replaced
/// by rename, so a new one has a new inode.
std::string file_identity(const fs::path& file) {
  struct stat s {};
  if (::stat(file.c_str(), &s) != 0) return {};
  return std::to_string(s.st_dev) + ':' + std::to_string(s.st_ino) + ':' +
         std::to_string(s.st_size) + ':' + std::to_string(s.st_mtim.tv_sec) + '.' +
         std::to_string(s.st_mtim.tv_nsec);
}

InputPlace resume_place(const RunPlan& plan) {
  return {(plan.directory / "checkpoint.bin").string(), 0, 0, "--resume"};
}

InputPlace from_place(const RunPlan& plan) {
  return {(fs::path(plan.from_directory) / "checkpoint.bin").string(), 0, 0, "--from"};
}

}  // namespace

RunPlan plan_run(const RunOptions& options, const Case& c) {
  check_option_rules(options);
  RunPlan plan;
  plan.directory = run_directory_of(options);
  const bool resume = !options.resume_directory.empty();
  plan.directory_key = resume ? "--resume" : "-o";
  plan.overwrite = options.overwrite;
  plan.refuse_earlier_run = !resume && !options.overwrite;
  // Before any work: a path the run could not write (a file on the way, a directory under the
  // name of one of its files) would fail it after the solve, or after --overwrite removed the
  // earlier run.
  if (const std::string problem = output_path_problem(plan.directory); !problem.empty())
    throw InputError({plan.directory.string(), 0, 0, plan.directory_key}, problem);
  if (!options.from_directory.empty()) {
    plan.from = read_from_state(options, c);
    plan.from_directory = options.from_directory;
    plan.from_unfinished = unfinished_run(options.from_directory, *plan.from);
  }
  if (resume) {
    // Taken before the read: a file replaced in between then differs when the lock is held.
    plan.resume_identity = file_identity(plan.directory / "checkpoint.bin");
    plan.resume = read_resume_checkpoint(plan.directory, c);
  }
  return plan;
}

void check_plan_against_mesh(const RunPlan& plan, const RunFingerprint& fingerprint) {
  if (plan.resume) {
    if (const std::string changes = fingerprint_changes(plan.resume->fingerprint, fingerprint);
        !changes.empty())
      throw InputError(resume_place(plan),
                       "the checkpoint belongs to another run: " + changes +
                           "; resume with the case, --set values and mesh it was written for, "
                           "or start a new run");
  }
  if (plan.from && plan.from->fingerprint.geometry != fingerprint.geometry)
    throw InputError(from_place(plan),
                     "the run in " + plan.from_directory +
                         " solved another mesh (its nodes or their coordinates differ from this "
                         "case's): a second step needs the same mesh");
}

void check_from_internal_values(const RunPlan& plan, std::size_t n_internal_values) {
  if (!plan.from || plan.from->bubbles.size() == n_internal_values) return;
  throw InputError(from_place(plan),
                   "the run in " + plan.from_directory + " carries " +
                       std::to_string(plan.from->bubbles.size()) +
                       " internal values (element bubbles, material history), this case " +
                       std::to_string(n_internal_values) +
                       ": a second step keeps the materials' viscoelasticity and Mullins "
                       "softening, or their absence");
}

std::string resumed_checkpoint_refusal(const RunPlan& plan) {
  if (!plan.resume || file_identity(plan.directory / "checkpoint.bin") == plan.resume_identity)
    return {};
  return "its checkpoint.bin was replaced after this run read it, by a plisse process that held "
         "the directory then and has ended; resuming the older state would undo that run's "
         "steps: resume again to continue from the checkpoint it wrote";
}

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

std::string shell_word(const std::string& word, bool quote) {
  const bool plain = !word.empty() && word.find_first_not_of(
                                          "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz"
                                          "0123456789_./-=:,+@%") == std::string::npos;
  if (plain && !quote) return word;
  std::string quoted = "'";
  for (char ch : word) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

namespace {

/// plisse run CASE [-n N] [--set ...]: the start of the commands below.
std::string run_command(const RunOptions& options, int n_ranks) {
  std::string command = "plisse run " + shell_word(options.case_file);
  if (n_ranks > 1) command += " -n " + std::to_string(n_ranks);
  // --set values always in quotes: they are what a user edits before pasting the line.
  for (const std::string& o : options.overrides) command += " --set " + shell_word(o, true);
  return command;
}

}  // namespace

std::string resume_command(const RunOptions& options, int n_ranks, const fs::path& directory) {
  return run_command(options, n_ranks) + " --resume " + shell_word(directory.string());
}

std::string rerun_command(const RunOptions& options, int n_ranks, const fs::path& directory) {
  return run_command(options, n_ranks) + " -o " + shell_word(directory.string()) + " --overwrite";
}

}  // namespace plisse::app
