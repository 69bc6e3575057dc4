#pragma once
/// The plan of `plisse run`: every decision the command line and the run directory's earlier
/// contents settle before anything is solved: the output directory, the checkpoint a resumed run
/// continues and the state a second step (--from) starts from, with every rule between the
/// options. No PETSc, no MPI: the functions here read files at most, and each refusal is the
/// InputError `plisse run` reports (exit status 2). The driver (app/run_case) follows the plan.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "case/case.hpp"
#include "core/error.hpp"
#include "output/checkpoint.hpp"

namespace plisse::app {

/// The options of `plisse run` as given on the command line.
struct RunOptions {
  std::string case_file;
  std::string output_directory;            ///< empty: runs/<case file stem>
  std::vector<std::string> overrides;      ///< --set key.path=value
  std::vector<std::string> petsc_options;  ///< --petsc "-snes_monitor ..."
  std::string resume_directory;            ///< --resume DIR: continue from DIR/checkpoint.bin
  /// --from DIR: start from the last state of the run in DIR (a second step with this case's loads)
  std::string from_directory;
  /// --from-unfinished: --from may name a run that did not complete (killed, interrupted or
  /// failed); its last checkpoint is then the start
  bool from_unfinished = false;
  bool overwrite = false;  ///< --overwrite: replace an earlier run in the directory
  int ranks = 0;           ///< -n N: MPI ranks (run under mpiexec); 0: not given
};

/// What a run does with its directory and where it starts: plain data, decided by plan_run.
struct RunPlan {
  /// The run directory: --resume DIR, else -o DIR, else runs/<case file stem>.
  std::filesystem::path directory;
  /// The option that named the directory, for the refusals about it: key "--resume" when
  /// resuming, else "-o" (file: the directory as the run writes it, set by the driver).
  std::string directory_key;
  /// --overwrite: the earlier run's files are removed (once the case has passed every check).
  bool overwrite = false;
  /// A new run without --overwrite: a directory holding an earlier run's files is refused
  /// (earlier_run_refusal).
  bool refuse_earlier_run = true;
  /// --resume: the checkpoint read from `directory`/checkpoint.bin; its element is the case's.
  std::optional<Checkpoint> resume;
  /// --resume: the identity of that checkpoint.bin (device, inode, size, modification time) as it
  /// was before it was read, for resumed_checkpoint_refusal.
  std::string resume_identity;
  /// --from: the last state of the run in from_directory, read from its checkpoint.bin; its
  /// element is the case's.
  std::optional<Checkpoint> from;
  std::string from_directory;  ///< --from DIR as given; empty without --from
  /// Why the --from run is not a completed one (--from-unfinished); empty when it completed.
  std::string from_unfinished;
};

/// Decides the plan of `options` for the parsed case `c`, checking, in this order: each --petsc
/// option's text; --resume with --overwrite; --resume with another -o; the run directory's path
/// (output_path_problem: a file on the way, a directory under a run file's name); --from with
/// --resume; the
/// --from run's checkpoint (readable, same element), that run's completion (its summary.json says
/// `completed` at its checkpoint's time, unless --from-unfinished) and -o naming the --from
/// directory; the
/// --resume checkpoint (readable, same element). Throws the InputError of the first rule broken.
RunPlan plan_run(const RunOptions& options, const Case& c);

/// The checks that need the mesh the run solves on, through its `fingerprint`: a resumed run
/// must be the run its checkpoint belongs to, and a second step (--from) must solve the same
/// mesh as the run it continues. Throws InputError (key --resume or --from) otherwise.
void check_plan_against_mesh(const RunPlan& plan, const RunFingerprint& fingerprint);

/// A second step keeps the elements' internal values (bubbles, material history): throws
/// InputError (key --from) when the --from run holds another number of them than the model
/// (`n_internal_values`). No-op without --from.
void check_from_internal_values(const RunPlan& plan, std::size_t n_internal_values);

/// Why a resumed run may not go on once it holds the directory's lock (empty: it may): the
/// checkpoint.bin it read was replaced meanwhile, by a run that held the lock then and has ended
/// (a second --resume started while the first was ending would otherwise restore the older
/// state and undo the finished run). No-op without --resume. Call with the lock held.
std::string resumed_checkpoint_refusal(const RunPlan& plan);

/// PETSC_OPTIONS under the rules of --petsc (case/petsc_option_text.hpp), and no
/// PETSC_OPTIONS_YAML: PETSc reads both at start-up. InputError at the variable otherwise.
/// `plisse run` (plan_run) and `plisse check` call it before PETSc starts.
void check_petsc_environment();

/// Why a new run may not write into `directory` (empty: it may): the files of an earlier run,
/// the first three named.
std::string earlier_run_refusal(const std::filesystem::path& directory);

/// `word` as one word of a POSIX shell command: itself when it holds only letters, digits and
/// _./-=:,+@% and `quote` is false, else in single quotes (a path with spaces, a key such as
/// loads[0].value).
std::string shell_word(const std::string& word, bool quote = false);

/// The command that resumes an interrupted run in `directory`: the case file, -n for a run on
/// more than one rank, and every --set value, each a shell word.
std::string resume_command(const RunOptions& options, int n_ranks,
                           const std::filesystem::path& directory);
/// The same run started again in `directory` (-o DIR --overwrite): for a run interrupted before
/// it wrote a checkpoint, which --resume would refuse.
std::string rerun_command(const RunOptions& options, int n_ranks,
                          const std::filesystem::path& directory);

}  // namespace plisse::app
