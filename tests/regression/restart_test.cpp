// Requirement: a run killed at any moment (SIGKILL) and resumed with --resume gives the same
// history as an uninterrupted run (relative difference < 1e-10), and leaves no truncated file;
// SIGTERM stops a run cleanly with a checkpoint and exit status 1, also while its steps fail and
// are cut back (within one Newton iteration, not after the next converged step).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "output/history_writer.hpp"
#include "output/json_file.hpp"
#include "output/pvd_writer.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;

const std::string kCase = std::string(PLISSE_SOURCE_DIR) + "/tests/regression/restart-case.yaml";

/// Starts `plisse run case_file -o dir [--set S ...]` in the background (output in dir.log);
/// returns its pid.
pid_t start_run(const fs::path& dir, const std::string& case_file = kCase,
                const std::vector<std::string>& sets = {}) {
  std::vector<std::string> args = {"run", case_file, "-o", dir.string()};
  for (const auto& set : sets) args.insert(args.end(), {"--set", set});
  return test::start_plisse(args, dir.string() + ".log");
}

void wait_for_rows(const fs::path& dir, size_t rows) {
  ASSERT_TRUE(test::wait_for_history_rows(dir, rows)) << "the run did not get far enough";
}

/// Every file of the run directory parses whole (no truncated output). A run killed mid-write
/// leaves the temporary of that write (`allow_temporaries`); the next run into the directory
/// removes it.
void expect_readable(const fs::path& dir, bool allow_temporaries = false) {
  EXPECT_NO_THROW(read_history(dir / "history.csv"));
  EXPECT_NO_THROW(read_pvd(dir / "solution.pvd"));
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (!allow_temporaries) {
      EXPECT_EQ(name.find(".tmp"), std::string::npos) << "temporary file left: " << name;
    }
    if (entry.path().extension() == ".vtu") {
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(in)), {});
      EXPECT_NE(text.rfind("</VTKFile>"), std::string::npos) << name << " is truncated";
    }
  }
}

void expect_same_history(const fs::path& a, const fs::path& b, double tolerance = 1e-8) {
  const HistoryTable ha = read_history(a / "history.csv"), hb = read_history(b / "history.csv");
  ASSERT_EQ(ha.columns, hb.columns);
  ASSERT_EQ(ha.rows.size(), hb.rows.size());
  for (size_t r = 0; r < ha.rows.size(); ++r)
    for (size_t k = 0; k < ha.columns.size(); ++k) {
      const double x = ha.rows[r][k], y = hb.rows[r][k];
      if (ha.columns[k] == "residual_norm") continue;  // round-off level, not a result
      // A cost, not a result: the resumed process starts without the factorisation that the
      // uninterrupted one reuses at the next step (solver/newton_solver.hpp, factor reuse).
      if (ha.columns[k] == "newton_iterations") continue;
      // The resumed process has no factorisation to start from or keep (chord steps), so its
      // Newton takes another path to the same tolerance: the states agree to what rtol leaves
      // (1e-10 in these cases; 3.7e-10 mm seen on the sticking sphere's penetration).
      EXPECT_LE(std::abs(x - y), tolerance * std::max(1.0, std::abs(x)))
          << "row " << r << ", column " << ha.columns[k];
    }
}

/// Runs kCase (with `--set set` when not empty) uninterrupted into `name`-reference, and again
/// into `name`-killed, killed by SIGKILL after 6 steps and resumed; both must give the same
/// history and readable files. Returns the killed-and-resumed directory.
fs::path expect_kill_and_resume(const std::string& name, const std::string& set = "") {
  const std::string options = set.empty() ? "" : " --set '" + set + "'";
  const fs::path reference = test::scratch_directory(name + "-reference");
  EXPECT_EQ(test::run_plisse("run " + kCase + " -o " + reference.string() + options,
                             reference.string() + ".log"),
            0);
  const fs::path killed = test::scratch_directory(name + "-killed");
  const pid_t pid = start_run(
      killed, kCase, set.empty() ? std::vector<std::string>{} : std::vector<std::string>{set});
  wait_for_rows(killed, 6);
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";
  expect_readable(killed, true);
  EXPECT_EQ(test::run_plisse("run " + kCase + options + " --resume " + killed.string(),
                             killed.string() + ".resume.log"),
            0)
      << "see " << killed.string() << ".resume.log";
  expect_same_history(reference, killed);
  expect_readable(killed);
  EXPECT_TRUE(read_json_file(killed / "summary.json")["completed"].get<bool>());
  // summary.json's steps are the whole run's, as docs/output.md says: the rows of history.csv.
  EXPECT_EQ(read_json_file(killed / "summary.json")["steps"].get<std::size_t>(),
            read_history(killed / "history.csv").rows.size());
  EXPECT_EQ(read_json_file(killed / "summary.json")["steps"],
            read_json_file(reference / "summary.json")["steps"]);
  EXPECT_EQ(read_pvd(killed / "solution.pvd").size(), read_pvd(reference / "solution.pvd").size());
  return killed;
}

TEST(Restart, KilledRunResumesToTheUninterruptedHistory) { expect_kill_and_resume("restart"); }

TEST(Restart, AnArcLengthRunResumesOnItsArc) {
  // Under arc-length control the checkpoint's next step size is an arc length, and the increment
  // before it (the previous state) orients the next predictor; the step files are listed by step
  // number (a falling load would disorder them by time), and the resume keeps the first ones.
  expect_kill_and_resume("restart-arc", "solver.control=arc-length");
}

TEST(Restart, ViscoelasticAndMullinsHistorySurvivesAKill) {
  // The points' internal variables (the Maxwell elements' overstresses, the largest energy
  // reached) are part of the checkpoint, and the resumed run's first step measures its time step
  // from the checkpoint's time: a relaxation time of the order of the run's steps shows either.
  expect_kill_and_resume(
      "restart-inelastic",
      "material={model: mooney-rivlin, c1: 0.2, c2: 0.05, viscoelastic: "
      "{beta1: 0.8, tau1: 0.3, beta2: 0.4, tau2: 0.05}, mullins: {r: 2, m: 0.1}}");
}

TEST(Restart, ContactHistorySurvivesAKill) {
  // Sticking and frictionless dies carry glue points and multipliers from step to step: they are
  // part of the checkpoint.
  const std::string case_file =
      std::string(PLISSE_SOURCE_DIR) + "/tests/verification/contact/sphere-between-plates.yaml";
  const std::string every = "output.checkpoint_every=1";
  const fs::path reference = test::scratch_directory("restart-contact-reference");
  ASSERT_EQ(test::run_plisse("run " + case_file + " --set " + every + " -o " + reference.string(),
                             reference.string() + ".log"),
            0);
  const size_t total = read_history(reference / "history.csv").rows.size();
  const fs::path killed = test::scratch_directory("restart-contact-killed");
  const pid_t pid = start_run(killed, case_file, {every});
  wait_for_rows(killed, total / 2 + 1);
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";
  ASSERT_EQ(
      test::run_plisse("run " + case_file + " --set " + every + " --resume " + killed.string(),
                       killed.string() + ".resume.log"),
      0)
      << "see " << killed.string() << ".resume.log";
  expect_same_history(reference, killed);
}

TEST(Restart, TheFirstWrinkledStepSurvivesAKill) {
  // summary.json's wrinkles.first_wrinkled of a run killed after it and resumed comes from the
  // history's kept rows, with whether every step up to it was stable; the resumed run does not say
  // again that the body has wrinkled (docs/theory/wrinkles.md, W27).
  const std::string case_file = test::example("sheet-wrinkles-line.yaml");
  const std::string every = "output.checkpoint_every=1";
  const fs::path reference = test::scratch_directory("restart-wrinkled-reference");
  ASSERT_EQ(test::run_plisse("run " + case_file + " --set " + every + " -o " + reference.string(),
                             reference.string() + ".log"),
            0);
  const nlohmann::json first = read_json_file(reference / "summary.json")["first_wrinkled"];
  ASSERT_TRUE(first.is_object());
  const fs::path killed = test::scratch_directory("restart-wrinkled-killed");
  const pid_t pid = start_run(killed, case_file, {every});
  wait_for_rows(killed, first["step"].get<std::size_t>() + 5);
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";
  const fs::path resume_log = killed.string() + ".resume.log";
  ASSERT_EQ(
      test::run_plisse("run " + case_file + " --set " + every + " --resume " + killed.string(),
                       resume_log),
      0)
      << "see " << resume_log;
  const nlohmann::json resumed = read_json_file(killed / "summary.json")["first_wrinkled"];
  EXPECT_EQ(resumed["step"], first["step"]);
  EXPECT_EQ(resumed["by"], first["by"]);
  EXPECT_EQ(resumed["stable"], true);
  EXPECT_NEAR(resumed["time"].get<double>(), first["time"].get<double>(), 1e-12);
  std::ifstream log(resume_log);
  const std::string text((std::istreambuf_iterator<char>(log)), {});
  EXPECT_EQ(text.find("the body has wrinkled"), std::string::npos);
  // The example's Newton rtol is 1e-8 (the other cases' 1e-10): its states agree to about 3e-8 mm,
  // and a crest height, the difference of crest values, to 5e-8 mm (measured).
  expect_same_history(reference, killed, 1e-6);
}

TEST(Restart, TerminatedRunStopsWithCheckpointAndExitStatus1) {
  const fs::path dir = test::scratch_directory("restart-terminated");
  const pid_t pid = start_run(dir);
  wait_for_rows(dir, 3);
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_TRUE(fs::exists(dir / "checkpoint.bin"));
  const auto summary = read_json_file(dir / "summary.json");
  EXPECT_TRUE(summary["interrupted"].get<bool>());
  expect_readable(dir);
  ASSERT_EQ(
      test::run_plisse("run " + kCase + " --resume " + dir.string(), dir.string() + ".resume.log"),
      0);
  EXPECT_TRUE(read_json_file(dir / "summary.json")["completed"].get<bool>());
}

TEST(Restart, ASecondSignalStopsAtOnceAndLosesNothingWritten) {
  const fs::path dir = test::scratch_directory("restart-second-signal");
  const pid_t pid = start_run(dir, kCase, {"solver.steps=300"});
  wait_for_rows(dir, 5);
  // Both signals pending at once (the process is stopped while they are sent), so the second
  // reaches the handler while the first is still being answered: the user's double Ctrl-C.
  kill(pid, SIGSTOP);
  kill(pid, SIGTERM);
  kill(pid, SIGINT);
  const auto sent = std::chrono::steady_clock::now();
  kill(pid, SIGCONT);
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count(), 2.0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  std::ifstream in(dir.string() + ".log");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("second interrupt: stopping at once"), std::string::npos) << text;
  // Whole files (a temporary of a write cut short may remain), and the run resumes from its last
  // checkpoint to the end.
  expect_readable(dir, true);
  ASSERT_EQ(test::run_plisse("run " + kCase + " --set solver.steps=300 --resume " + dir.string(),
                             dir.string() + ".resume.log"),
            0);
  expect_readable(dir);
  EXPECT_EQ(read_history(dir / "history.csv").rows.size(), 300u);
}

TEST(Restart, TerminatedWhileStepsFailStopsAtOnceKeepingTheLastConvergedStep) {
  // The thick sphere under 10 times its limit pressure: steps fail and are cut back from the
  // first one on (each failed attempt takes seconds), and with solver.min_step = 1e-14 the run
  // would go on cutting back for minutes at the limit point.
  const fs::path dir = test::scratch_directory("restart-terminated-failing");
  const std::string case_file = std::string(PLISSE_SOURCE_DIR) + "/examples/sphere-inflation.yaml";
  const pid_t pid = start_run(dir, case_file, {"loads[0].value=5", "solver.min_step=1e-14"});
  // Wait for a failed attempt: the run is then retrying a step.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  std::string log;
  while (log.find("failed after") == std::string::npos &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    std::ifstream in(dir / "log.txt");
    log.assign(std::istreambuf_iterator<char>(in), {});
  }
  ASSERT_NE(log.find("failed after"), std::string::npos) << "no step failed within 2 minutes";
  const auto sent = std::chrono::steady_clock::now();
  kill(pid, SIGTERM);
  int status = 0;
  waitpid(pid, &status, 0);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  // One Newton iteration of this 2 000-unknown model takes well under a second; the next
  // converged step would have taken several failed attempts of seconds each.
  EXPECT_LT(seconds, 5.0);
  std::ifstream in(dir / "log.txt");
  log.assign(std::istreambuf_iterator<char>(in), {});
  EXPECT_NE(log.find("interrupted by a signal during step"), std::string::npos) << log;
  const auto summary = read_json_file(dir / "summary.json");
  EXPECT_TRUE(summary["interrupted"].get<bool>());
  const size_t steps = test::history_rows(dir);
  EXPECT_EQ(summary["steps"].get<size_t>(), steps);
  if (steps > 0) {
    EXPECT_TRUE(fs::exists(dir / "checkpoint.bin"));
  }
  expect_readable(dir);
  // The hint is the whole command, --set values included, quoted for the shell.
  std::ifstream out(dir.string() + ".log");
  const std::string printed((std::istreambuf_iterator<char>(out)), {});
  EXPECT_NE(printed.find("--set 'loads[0].value=5' --set 'solver.min_step=1e-14' --resume"),
            std::string::npos)
      << printed;
}

TEST(Restart, WallTimeCheckpointsBoundTheWorkLostWithoutAStepCount) {
  // Step-count checkpoints off: with output.checkpoint_minutes a run killed after a few steps can
  // still be resumed; without it (0) nothing is there to resume from.
  for (const std::string minutes : {"1e-9", "0"}) {
    const fs::path dir = test::scratch_directory("restart-wall-time-" + minutes);
    const pid_t pid = start_run(
        dir, kCase, {"output.checkpoint_every=0", "output.checkpoint_minutes=" + minutes});
    wait_for_rows(dir, 4);
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";
    if (minutes == "0") {
      EXPECT_FALSE(fs::exists(dir / "checkpoint.bin"));
      continue;
    }
    ASSERT_TRUE(fs::exists(dir / "checkpoint.bin"));
    EXPECT_EQ(test::run_plisse("run " + kCase +
                                   " --set output.checkpoint_every=0 --set "
                                   "output.checkpoint_minutes=1e-9 --resume " +
                                   dir.string(),
                               dir.string() + ".resume.log"),
              0)
        << "see " << dir.string() << ".resume.log";
    EXPECT_TRUE(read_json_file(dir / "summary.json")["completed"].get<bool>());
  }
}

TEST(Restart, KilledTaylorHoodRunResumesToTheUninterruptedHistory) {
  const fs::path killed = expect_kill_and_resume("restart-th", "element=taylor-hood");
  EXPECT_EQ(read_json_file(killed / "summary.json")["element"].get<std::string>(), "taylor-hood");
}

TEST(Restart, ResumeWithAnotherElementFamilyIsRefusedByName) {
  const fs::path dir = test::scratch_directory("restart-other-element");
  ASSERT_EQ(test::run_plisse("run " + kCase + " -o " + dir.string() + " --set element=taylor-hood",
                             dir.string() + ".log"),
            0);
  const int status =
      test::run_plisse("run " + kCase + " --resume " + dir.string(), dir.string() + ".bad.log");
  EXPECT_EQ(status, 2);
  std::ifstream in(dir.string() + ".bad.log");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("checkpoint.bin"), std::string::npos) << text;
  EXPECT_NE(text.find("`element: taylor-hood`"), std::string::npos) << text;
  EXPECT_NE(text.find("`element: mini`"), std::string::npos) << text;
}

TEST(Restart, CheckpointOfAnotherCaseIsRefused) {
  const fs::path dir = test::scratch_directory("restart-other-case");
  ASSERT_EQ(test::run_plisse("run " + kCase + " -o " + dir.string(), dir.string() + ".log"), 0);
  const int status =
      test::run_plisse("run " + kCase + " --set material.c1=0.3 --resume " + dir.string(),
                       dir.string() + ".bad.log");
  EXPECT_EQ(status, 2);
  std::ifstream in(dir.string() + ".bad.log");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("checkpoint.bin"), std::string::npos) << text;
  EXPECT_NE(text.find("the checkpoint belongs to another run: the --set values differ "
                      "(checkpoint: none; now: material.c1=0.3)"),
            std::string::npos)
      << text;
}

TEST(Restart, ChangedMeshFileOrDamagedCheckpointIsRefusedSayingWhat) {
  const fs::path dir = test::scratch_directory("restart-changed-mesh");
  fs::create_directories(dir);
  const fs::path mesh = dir / "cube.msh", run = dir / "run";
  ASSERT_EQ(test::run_plisse("mesh cube --order 1 --edge 5 --divisions 3 -o " + mesh.string(),
                             dir / "mesh.log"),
            0);
  // The restart case on that mesh file.
  std::string text;
  {
    std::ifstream in(kCase);
    for (std::string line; std::getline(in, line);)
      text += (line.rfind("mesh:", 0) == 0 ? "mesh: {file: cube.msh}" : line) + "\n";
  }
  const fs::path case_file = dir / "case.yaml";
  std::ofstream(case_file) << text;
  ASSERT_EQ(test::run_plisse("run " + case_file.string() + " -o " + run.string(), dir / "run.log"),
            0);
  const auto resume = [&] {
    return test::run_plisse_captured("run " + case_file.string() + " --resume " + run.string());
  };
  // The same mesh written again: the same bytes, so the checkpoint still belongs to the run.
  ASSERT_EQ(test::run_plisse("mesh cube --order 1 --edge 5 --divisions 3 -o " + mesh.string(),
                             dir / "mesh.log"),
            0);
  EXPECT_EQ(resume().status, 0);
  // Same node count, other coordinates: a state that fits the arrays but not the body.
  ASSERT_EQ(test::run_plisse("mesh cube --order 1 --edge 6 --divisions 3 -o " + mesh.string(),
                             dir / "mesh.log"),
            0);
  auto r = resume();
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(
      r.output.find("the mesh file " + mesh.string() + " changed since the checkpoint was written"),
      std::string::npos)
      << r.output;
  ASSERT_EQ(test::run_plisse("mesh cube --order 1 --edge 5 --divisions 3 -o " + mesh.string(),
                             dir / "mesh.log"),
            0);
  // One flipped bit in the middle of the checkpoint.
  std::string bytes;
  {
    std::ifstream in(run / "checkpoint.bin", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  bytes[bytes.size() / 2] ^= 0x01;
  std::ofstream(run / "checkpoint.bin", std::ios::binary) << bytes;
  r = resume();
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("checkpoint.bin: key '--resume': not a usable plisse checkpoint: "
                          "damaged: its checksum does not match its content"),
            std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace plisse
