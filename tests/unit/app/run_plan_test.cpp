// The plan of `plisse run`: one test per rule of the command line and of the checkpoints a run
// starts from, each asserting the decision or the exact message the user reads (exit status 2).
// No PETSc: the plan is decided before a run starts it.
#include "app/run_plan.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "output/checkpoint.hpp"
#include "output/json_file.hpp"
#include "unit/output/output_test_support.hpp"

namespace plisse::app {
namespace {

namespace fs = std::filesystem;
using test::ScratchDir;

Case mini_case() {
  Case c;
  c.element = ElementFamily::mini;
  return c;
}

RunOptions options_for(const std::string& case_file) {
  RunOptions options;
  options.case_file = case_file;
  return options;
}

/// A run directory `directory` holding a checkpoint of `element` with `fingerprint` and
/// `n_internal` internal values, and the summary.json of a completed run at its time.
void write_run(const fs::path& directory, ElementFamily element,
               const RunFingerprint& fingerprint = {}, std::size_t n_internal = 0) {
  fs::create_directories(directory);
  Checkpoint c;
  c.fingerprint = fingerprint;
  c.element = element;
  c.steps = 3;
  c.time = 0.375;
  c.dt = 0.125;
  c.previous_dt = 0.125;
  c.state = {0.0, 0.5, 1.0, 0.25};
  c.previous_state = c.state;
  c.bubbles.assign(n_internal, 0.0);
  write_checkpoint(directory / "checkpoint.bin", c);
  write_json_file(directory / "summary.json",
                  {{"completed", true}, {"interrupted", false}, {"final_time", 0.375}});
}

/// The message `plisse run` prints for the plan of `options` (empty when the plan is made).
std::string refusal(const RunOptions& options, const Case& c = mini_case()) {
  try {
    (void)plan_run(options, c);
  } catch (const InputError& e) {
    return e.what();
  }
  return {};
}

TEST(RunPlan, ANewRunWritesIntoRunsCaseStemAndRefusesAnEarlierRun) {
  const RunPlan plan = plan_run(options_for("cases/cube.yaml"), mini_case());
  EXPECT_EQ(plan.directory, fs::path("runs/cube"));
  EXPECT_EQ(plan.directory_key, "-o");
  EXPECT_TRUE(plan.refuse_earlier_run);
  EXPECT_FALSE(plan.overwrite);
  EXPECT_FALSE(plan.resume);
  EXPECT_FALSE(plan.from);
}

TEST(RunPlan, DashOChoosesTheDirectory) {
  RunOptions options = options_for("cube.yaml");
  options.output_directory = "out/here";
  EXPECT_EQ(plan_run(options, mini_case()).directory, fs::path("out/here"));
}

TEST(RunPlan, OverwriteReplacesAnEarlierRunInsteadOfRefusingIt) {
  RunOptions options = options_for("cube.yaml");
  options.overwrite = true;
  const RunPlan plan = plan_run(options, mini_case());
  EXPECT_TRUE(plan.overwrite);
  EXPECT_FALSE(plan.refuse_earlier_run);
}

TEST(RunPlan, APetscOptionThatNamesAFileIsRefused) {
  RunOptions options = options_for("cube.yaml");
  options.petsc_options = {"-snes_monitor", "-options_file more.txt"};
  EXPECT_EQ(refusal(options),
            "command line: key '--petsc': '-options_file more.txt' is refused: -options_file is "
            "not among the solver options plisse accepts (docs/case-file.md, \"PETSc options\"); "
            "every option that names a file, writes a view or monitor other than text to the log, "
            "reads options (-options_file, -prefix_push) or starts another program is refused");
}

TEST(RunPlan, ResumeWithOverwriteIsRefused) {
  RunOptions options = options_for("cube.yaml");
  options.resume_directory = "runs/cube";
  options.overwrite = true;
  EXPECT_EQ(refusal(options),
            "command line: key '--overwrite': a resumed run continues the run in its directory; "
            "--overwrite would replace it: give one of them");
}

TEST(RunPlan, ThePetscOptionsAreCheckedBeforeTheOtherRules) {
  RunOptions options = options_for("cube.yaml");
  options.petsc_options = {"-ksp_view draw"};
  options.resume_directory = "runs/cube";
  options.overwrite = true;
  EXPECT_EQ(refusal(options).rfind("command line: key '--petsc': ", 0), 0u) << refusal(options);
}

TEST(RunPlan, ResumeIntoAnotherOutputDirectoryIsRefused) {
  RunOptions options = options_for("cube.yaml");
  options.resume_directory = "runs/cube";
  options.output_directory = "runs/other";
  EXPECT_EQ(refusal(options),
            "command line: key '--resume': a resumed run writes into its own directory; -o must "
            "be omitted or the same");
}

TEST(RunPlan, ResumeContinuesTheCheckpointInItsDirectory) {
  const ScratchDir dir;
  write_run(dir / "run", ElementFamily::mini);
  RunOptions options = options_for("cube.yaml");
  options.resume_directory = (dir / "run").string();
  options.output_directory = (dir.path() / "." / "run").string();  // the same, spelled otherwise
  const RunPlan plan = plan_run(options, mini_case());
  EXPECT_EQ(plan.directory, dir / "run");
  EXPECT_EQ(plan.directory_key, "--resume");
  EXPECT_FALSE(plan.refuse_earlier_run);
  ASSERT_TRUE(plan.resume);
  EXPECT_EQ(plan.resume->steps, 3);
  EXPECT_EQ(plan.resume->time, 0.375);
}

TEST(RunPlan, ResumeWithoutACheckpointIsRefused) {
  const ScratchDir dir;
  RunOptions options = options_for("cube.yaml");
  options.resume_directory = dir.path().string();
  EXPECT_EQ(refusal(options), (dir / "checkpoint.bin").string() +
                                  ": key '--resume': no checkpoint.bin in the run directory");
}

TEST(RunPlan, ResumeWithAnotherElementFamilyIsRefused) {
  const ScratchDir dir;
  write_run(dir.path(), ElementFamily::taylor_hood);
  RunOptions options = options_for("cube.yaml");
  options.resume_directory = dir.path().string();
  EXPECT_EQ(refusal(options), (dir / "checkpoint.bin").string() +
                                  ": key '--resume': the checkpoint was written by a run with "
                                  "`element: taylor-hood`, this case has `element: mini`; a run "
                                  "cannot change its element family");
}

TEST(RunPlan, ResumeOfAnotherRunIsRefusedSayingWhatChanged) {
  const ScratchDir dir;
  RunFingerprint saved;
  saved.overrides = {"mesh.layers=3"};
  write_run(dir.path(), ElementFamily::mini, saved);
  RunOptions options = options_for("cube.yaml");
  options.resume_directory = dir.path().string();
  const RunPlan plan = plan_run(options, mini_case());
  EXPECT_NO_THROW(check_plan_against_mesh(plan, saved));
  RunFingerprint now = saved;
  now.overrides = {"mesh.layers=4"};
  try {
    check_plan_against_mesh(plan, now);
    ADD_FAILURE() << "a checkpoint of other --set values was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "checkpoint.bin").string() +
                  ": key '--resume': the checkpoint belongs to another run: the --set values "
                  "differ (checkpoint: mesh.layers=3; now: mesh.layers=4); resume with the case, "
                  "--set values and mesh it was written for, or start a new run");
  }
}

TEST(RunPlan, FromStartsANewRunFromTheLastStateOfAnother) {
  const ScratchDir dir;
  write_run(dir / "first", ElementFamily::mini);
  RunOptions options = options_for("unload.yaml");
  options.from_directory = (dir / "first").string();
  options.output_directory = (dir / "second").string();
  const RunPlan plan = plan_run(options, mini_case());
  EXPECT_EQ(plan.directory, dir / "second");
  EXPECT_TRUE(plan.refuse_earlier_run);
  EXPECT_FALSE(plan.resume);
  ASSERT_TRUE(plan.from);
  EXPECT_EQ(plan.from->steps, 3);
  EXPECT_EQ(plan.from_directory, options.from_directory);
}

TEST(RunPlan, FromAnUnfinishedRunIsRefusedUnlessAsked) {
  const ScratchDir dir;
  write_run(dir.path(), ElementFamily::mini);
  RunOptions options = options_for("unload.yaml");
  options.from_directory = dir.path().string();
  options.output_directory = (dir / "second").string();
  const std::string start =
      (dir / "checkpoint.bin").string() + ": key '--from': the run in " + dir.path().string() + " ";
  const std::string end =
      ": a second step starts from a completed run; give --from-unfinished to start from its "
      "last checkpoint (step 3 at t = 0.375000) all the same";
  EXPECT_EQ(refusal(options), "");
  // Killed (no summary), interrupted, failed, or a checkpoint of another step than the last.
  write_json_file(dir / "summary.json",
                  {{"completed", false}, {"interrupted", true}, {"final_time", 0.375}});
  EXPECT_EQ(refusal(options), start + "was interrupted before its end time" + end);
  write_json_file(dir / "summary.json", {{"completed", false},
                                         {"interrupted", false},
                                         {"failure", "step size below min_step"},
                                         {"final_time", 0.375}});
  EXPECT_EQ(refusal(options),
            start + "stopped before its end time (step size below min_step)" + end);
  write_json_file(dir / "summary.json",
                  {{"completed", true}, {"interrupted", false}, {"final_time", 1.0}});
  EXPECT_EQ(refusal(options),
            start + "has a checkpoint.bin that is not of its last step (t = 0.375000)" + end);
  fs::remove(dir / "summary.json");
  EXPECT_EQ(refusal(options),
            start + "has no summary.json (it was killed, or is still running)" + end);
  // Asked for: the plan says why, for the log.
  options.from_unfinished = true;
  const RunPlan plan = plan_run(options, mini_case());
  ASSERT_TRUE(plan.from);
  EXPECT_EQ(plan.from_unfinished, "has no summary.json (it was killed, or is still running)");
}

TEST(RunPlan, FromWithResumeIsRefused) {
  RunOptions options = options_for("cube.yaml");
  options.from_directory = "runs/first";
  options.resume_directory = "runs/cube";
  EXPECT_EQ(refusal(options),
            "command line: key '--from': --from starts a new run from a finished one, --resume "
            "continues an interrupted run in its own directory: give one of them");
}

TEST(RunPlan, FromWithoutACheckpointIsRefusedAtFrom) {
  const ScratchDir dir;
  RunOptions options = options_for("cube.yaml");
  options.from_directory = dir.path().string();
  EXPECT_EQ(refusal(options), (dir / "checkpoint.bin").string() +
                                  ": key '--from': no checkpoint.bin in the run directory");
}

TEST(RunPlan, FromARunOfAnotherElementFamilyIsRefused) {
  const ScratchDir dir;
  write_run(dir.path(), ElementFamily::taylor_hood);
  RunOptions options = options_for("cube.yaml");
  options.from_directory = dir.path().string();
  EXPECT_EQ(refusal(options), (dir / "checkpoint.bin").string() + ": key '--from': the run in " +
                                  dir.path().string() +
                                  " used `element: taylor-hood`, this case has `element: mini`; "
                                  "a second step keeps the element family");
}

TEST(RunPlan, FromIntoItsOwnDirectoryIsRefused) {
  const ScratchDir dir;
  write_run(dir.path(), ElementFamily::mini);
  RunOptions options = options_for("cube.yaml");
  options.from_directory = dir.path().string();
  options.output_directory = (dir.path() / ".").string();
  EXPECT_EQ(refusal(options),
            "command line: key '--from': the second step writes a new run directory: -o must "
            "differ from --from, whose run stays as it is");
}

TEST(RunPlan, FromARunOnAnotherMeshIsRefused) {
  const ScratchDir dir;
  RunFingerprint first;
  first.geometry = 11;
  write_run(dir.path(), ElementFamily::mini, first);
  RunOptions options = options_for("cube.yaml");
  options.from_directory = dir.path().string();
  const RunPlan plan = plan_run(options, mini_case());
  RunFingerprint now;
  now.case_text = 5;  // another case is the point of a second step
  now.geometry = 11;
  EXPECT_NO_THROW(check_plan_against_mesh(plan, now));
  now.geometry = 12;
  try {
    check_plan_against_mesh(plan, now);
    ADD_FAILURE() << "a --from run on another mesh was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "checkpoint.bin").string() + ": key '--from': the run in " +
                  dir.path().string() +
                  " solved another mesh (its nodes or their coordinates differ from this "
                  "case's): a second step needs the same mesh");
  }
}

TEST(RunPlan, FromKeepsTheNumberOfInternalValues) {
  const ScratchDir dir;
  write_run(dir.path(), ElementFamily::mini, {}, 6);
  RunOptions options = options_for("cube.yaml");
  options.from_directory = dir.path().string();
  const RunPlan plan = plan_run(options, mini_case());
  EXPECT_NO_THROW(check_from_internal_values(plan, 6));
  try {
    check_from_internal_values(plan, 8);
    ADD_FAILURE() << "another number of internal values was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "checkpoint.bin").string() + ": key '--from': the run in " +
                  dir.path().string() +
                  " carries 6 internal values (element bubbles, material history), this case 8: "
                  "a second step keeps the materials' viscoelasticity and Mullins softening, or "
                  "their absence");
  }
  EXPECT_NO_THROW(check_from_internal_values(plan_run(options_for("cube.yaml"), mini_case()), 8));
}

TEST(RunPlan, AnEarlierRunIsNamedByItsFirstThreeFiles) {
  const ScratchDir dir;
  EXPECT_EQ(earlier_run_refusal(dir.path()), "");
  std::ofstream(dir / "notes.txt") << "the user's own";
  EXPECT_EQ(earlier_run_refusal(dir.path()), "");
  for (const char* name :
       {"history.csv", "log.txt", "summary.json", "step_0000.vtu", "solution.pvd"})
    std::ofstream(dir / name) << "x";
  EXPECT_EQ(earlier_run_refusal(dir.path()),
            "holds an earlier run (history.csv, log.txt, solution.pvd and 2 more); continue it "
            "with --resume, replace it with --overwrite, or choose another -o");
}

TEST(RunPlan, TheResumeCommandQuotesEverySetValueForTheShell) {
  RunOptions options = options_for("cases/cube.yaml");
  options.overrides = {"loads[0].value=2", "title=it's"};
  EXPECT_EQ(resume_command(options, 1, "runs/cube"),
            "plisse run cases/cube.yaml --set 'loads[0].value=2' --set 'title=it'\\''s' "
            "--resume runs/cube");
  EXPECT_EQ(resume_command(options_for("cube.yaml"), 2, "out"),
            "plisse run cube.yaml -n 2 --resume out");
}

TEST(RunPlan, PathsWithSpacesAreQuotedAndARunWithoutACheckpointIsStartedAgain) {
  // Pasted into a shell, each command gives plisse the same words: the paths with a space or a
  // quote in one word each.
  RunOptions options = options_for("my cases/cube.yaml");
  options.overrides = {"mesh.divisions=2"};
  EXPECT_EQ(resume_command(options, 1, "runs/it's here"),
            "plisse run 'my cases/cube.yaml' --set 'mesh.divisions=2' --resume 'runs/it'\\''s "
            "here'");
  EXPECT_EQ(rerun_command(options, 2, "runs/a b"),
            "plisse run 'my cases/cube.yaml' -n 2 --set 'mesh.divisions=2' -o 'runs/a b' "
            "--overwrite");
  EXPECT_EQ(shell_word(""), "''");
  EXPECT_EQ(shell_word("a$b"), "'a$b'");
  EXPECT_EQ(shell_word("runs/cube"), "runs/cube");
}

}  // namespace
}  // namespace plisse::app
