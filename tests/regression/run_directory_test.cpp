// Requirement: a run directory is never lost or mixed (README, "Run directories"). A run into a
// directory holding an earlier run is refused with exit status 2 and leaves it byte for byte,
// unless --overwrite, which removes the earlier run's files (only those) first; a directory is
// locked while a run or `plisse wrinkles` uses it, so a second process is refused, and the lock
// goes with its holder, also after SIGKILL; history.csv and log.txt grow by appending, and a run
// killed at any moment leaves them whole, line for line.
#include "output/run_directory.hpp"

#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "core/error.hpp"
#include "output/history_writer.hpp"
#include "output/json_file.hpp"
#include "output/pvd_writer.hpp"
#include "output/vtu_reader.hpp"
#include "support/inflated_octant.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;

const std::string kCase = std::string(PLISSE_SOURCE_DIR) + "/tests/regression/restart-case.yaml";

std::string contents(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

/// Every file of `dir` by name, with its bytes.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  for (const auto& entry : fs::directory_iterator(dir))
    files[entry.path().filename().string()] = contents(entry.path());
  return files;
}

test::PlisseResult run(const std::string& args) { return test::run_plisse_captured(args); }

pid_t start(const std::vector<std::string>& args, const fs::path& log) {
  return test::start_plisse(args, log);
}

bool wait_for_rows(const fs::path& dir, std::size_t n) {
  return test::wait_for_history_rows(dir, n);
}

TEST(RunDirectory, RerunIntoAFinishedRunIsRefusedAndLeavesItByteForByte) {
  const fs::path dir = test::scratch_directory("rundir-refused");
  ASSERT_EQ(run("run " + kCase + " -o " + dir.string()).status, 0);
  const auto before = snapshot(dir);
  ASSERT_TRUE(before.count("history.csv") && before.count("summary.json"));
  EXPECT_EQ(before.count(DirectoryLock::kFileName), 0u) << "the lock file goes with the run";

  const auto r = run("run " + kCase + " -o " + dir.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(dir.string() + ": key '-o': holds an earlier run (checkpoint.bin, "
                                         "history.csv, log.txt and "),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("--overwrite"), std::string::npos) << r.output;
  // A bad rerun is refused before the directory is looked at, and leaves it too.
  EXPECT_EQ(run("run " + kCase + " --set solver.steps=0 -o " + dir.string()).status, 2);
  EXPECT_EQ(snapshot(dir), before);
  // --overwrite and --resume contradict each other.
  const auto both = run("run " + kCase + " --overwrite --resume " + dir.string());
  EXPECT_EQ(both.status, 2) << both.output;
  EXPECT_NE(both.output.find("'--overwrite'"), std::string::npos) << both.output;
  EXPECT_EQ(snapshot(dir), before);
}

TEST(RunDirectory, OverwriteRemovesTheEarlierRunsFilesAndKeepsTheUsersOwn) {
  const fs::path dir = test::scratch_directory("rundir-overwrite");
  ASSERT_EQ(run("run " + kCase + " -o " + dir.string()).status, 0);  // 16 steps, all written
  ASSERT_TRUE(fs::exists(dir / "step_0016.vtu"));
  std::ofstream(dir / "notes.txt") << "mine\n";
  // A temporary file a killed writer left (process 2^22 + 1 does not exist: above pid_max's
  // default of 2^22).
  std::ofstream(dir / ".history.csv.tmp.4194305.0") << "half";

  const auto r = run("run " + kCase + " --overwrite --set solver.steps=3 -o " + dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("file(s) of the earlier run (--overwrite)"), std::string::npos)
      << r.output;
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename());
  const std::set<std::string> expected = {
      "checkpoint.bin", "history.csv",   "log.txt",       "notes.txt",     "solution.pvd",
      "summary.json",   "step_0000.vtu", "step_0001.vtu", "step_0002.vtu", "step_0003.vtu"};
  EXPECT_EQ(names, expected);
  EXPECT_EQ(contents(dir / "notes.txt"), "mine\n");
  EXPECT_EQ(read_history(dir / "history.csv").rows.size(), 3u);
  // Step 0, the undeformed body, then the three steps.
  const std::vector<PvdEntry> pvd = read_pvd(dir / "solution.pvd");
  ASSERT_EQ(pvd.size(), 4u);
  EXPECT_EQ(pvd.front().file, "step_0000.vtu");
  EXPECT_EQ(pvd.front().time, 0.0);
  const VtuField u0 = read_vtu_point_field(dir / "step_0000.vtu", "displacement");
  for (double u : u0.values) EXPECT_EQ(u, 0.0);
  EXPECT_EQ(read_json_file(dir / "summary.json")["steps"].get<int>(), 3);
  // The log is this run's alone.
  const std::string log = contents(dir / "log.txt");
  EXPECT_EQ(log.find("plisse run"), log.rfind("plisse run")) << log;
}

TEST(RunDirectory, AnOverwriteRefusedByALateCheckLeavesTheEarlierRun) {
  const fs::path dir = test::scratch_directory("rundir-late-refusal");
  const fs::path earlier = dir / "earlier", first = dir / "first";
  ASSERT_EQ(run("run " + kCase + " --set solver.steps=2 -o " + earlier.string()).status, 0);
  ASSERT_EQ(run("run " + kCase + " --set solver.steps=2 -o " + first.string()).status, 0);
  const auto before = snapshot(earlier);
  // A second step whose material keeps a history the first run did not have: the --from state
  // does not fit the model, which is known only once the model is made.
  auto r = run("run " + kCase + " --set solver.steps=2 --set material.viscoelastic.beta1=0.5" +
               " --set material.viscoelastic.tau1=1.0 --from " + first.string() +
               " --overwrite -o " + earlier.string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("internal values"), std::string::npos) << r.output;
  EXPECT_EQ(snapshot(earlier), before);
  // Wrinkle rings asked to count from beyond the largest count their spectra reach.
  const fs::path shell = dir / "shell.yaml";
  std::ofstream(shell) << test::inflated_octant_case(
      test::kSmallOctantMesh,
      "solver: {steps: 1}\n"
      "output: {wrinkles: {axis: y, rings_deg: [45], min_count: 201}}\n");
  for (const std::string& args :
       {"check " + shell.string(),
        "run " + shell.string() + " --overwrite -o " + earlier.string()}) {
    r = run(args);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find("key 'output.wrinkles.min_count'"), std::string::npos) << r.output;
  }
  EXPECT_EQ(snapshot(earlier), before);
}

TEST(RunDirectory, ADirectoryInUseRefusesRunsResumesAndWrinkleMeasurements) {
  const fs::path dir = test::scratch_directory("rundir-locked");
  ASSERT_EQ(run("run " + kCase + " -o " + dir.string()).status, 0);
  const auto before = snapshot(dir);
  {
    // This process holds the directory, as a running plisse would.
    const DirectoryLock lock(dir, {dir.string(), 0, 0, "-o"});
    const std::string holder = "(pid " + std::to_string(getpid()) + " on ";
    for (const std::string& args :
         {"run " + kCase + " --overwrite -o " + dir.string(),
          "run " + kCase + " --resume " + dir.string(), "wrinkles " + dir.string()}) {
      const auto r = run(args);
      EXPECT_EQ(r.status, 2) << args << "\n" << r.output;
      EXPECT_NE(r.output.find("is in use by another plisse process " + holder), std::string::npos)
          << args << "\n"
          << r.output;
    }
  }
  auto after = snapshot(dir);
  EXPECT_EQ(after, before);
  // Released: the directory can be replaced again.
  EXPECT_EQ(run("run " + kCase + " --overwrite --set solver.steps=2 -o " + dir.string()).status, 0);
}

TEST(RunDirectory, TwoRunsStartedIntoOneDirectoryDoNotMix) {
  const fs::path dir = test::scratch_directory("rundir-two");
  // 400 steps of the small cube: long enough to be running when the second starts.
  const pid_t first = start({"run", kCase, "-o", dir.string(), "--set", "solver.steps=400", "--set",
                             "output.checkpoint_every=0", "--set", "output.every=1000"},
                            dir.string() + ".first.log");
  ASSERT_TRUE(wait_for_rows(dir, 1)) << contents(dir.string() + ".first.log");
  const auto second = run("run " + kCase + " --overwrite -o " + dir.string());
  EXPECT_EQ(second.status, 2) << second.output;
  EXPECT_NE(second.output.find("is in use by another plisse process (pid " + std::to_string(first) +
                               " on "),
            std::string::npos)
      << second.output;
  int status = 0;
  waitpid(first, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << contents(dir.string() + ".first.log");
  const HistoryTable history = read_history(dir / "history.csv");
  ASSERT_EQ(history.rows.size(), 400u);
  for (std::size_t i = 0; i < history.rows.size(); ++i)
    EXPECT_EQ(history.rows[i][0], static_cast<double>(i + 1));
  EXPECT_FALSE(fs::exists(dir / DirectoryLock::kFileName));
}

TEST(RunDirectory, AKilledRunLeavesWholeLinesAndItsResumeTakesTheDirectoryBack) {
  const fs::path dir = test::scratch_directory("rundir-killed");
  const std::vector<std::string> sets = {"--set", "solver.steps=300", "--set", "output.every=1000"};
  std::vector<std::string> args = {"run", kCase, "-o", dir.string()};
  args.insert(args.end(), sets.begin(), sets.end());
  const pid_t pid = start(args, dir.string() + ".log");
  ASSERT_TRUE(wait_for_rows(dir, 20)) << contents(dir.string() + ".log");
  // history.csv and log.txt are appended to, not replaced: the file a reader opened keeps growing.
  struct stat history_before {
  }, log_before{};
  ASSERT_EQ(stat((dir / "history.csv").c_str(), &history_before), 0);
  ASSERT_EQ(stat((dir / "log.txt").c_str(), &log_before), 0);
  ASSERT_TRUE(wait_for_rows(dir, 25));
  struct stat history_after {
  }, log_after{};
  ASSERT_EQ(stat((dir / "history.csv").c_str(), &history_after), 0);
  ASSERT_EQ(stat((dir / "log.txt").c_str(), &log_after), 0);
  EXPECT_EQ(history_after.st_ino, history_before.st_ino);
  EXPECT_EQ(log_after.st_ino, log_before.st_ino);
  EXPECT_GT(log_after.st_size, log_before.st_size);

  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the run ended before it could be killed";
  EXPECT_TRUE(fs::exists(dir / DirectoryLock::kFileName)) << "SIGKILL leaves the file";
  const std::string history = contents(dir / "history.csv"), log = contents(dir / "log.txt");
  // Whole lines up to the kill (a kill inside the one write of a line is the only exception,
  // and the resume drops that line).
  if (!history.empty() && history.back() == '\n') {
    EXPECT_NO_THROW(read_history(dir / "history.csv"));
  }

  std::vector<std::string> resume = {"run", kCase, "--resume", dir.string()};
  resume.insert(resume.end(), sets.begin(), sets.end());
  std::string command;
  for (const auto& a : resume) command += (command.empty() ? "" : " ") + a;
  const auto r = run(command);
  ASSERT_EQ(r.status, 0) << r.output;
  const HistoryTable resumed = read_history(dir / "history.csv");
  ASSERT_EQ(resumed.rows.size(), 300u);
  for (std::size_t i = 0; i < resumed.rows.size(); ++i)
    EXPECT_EQ(resumed.rows[i][0], static_cast<double>(i + 1));
  // The resumed log continues the killed run's: its first lines are still there.
  const std::string resumed_log = contents(dir / "log.txt");
  EXPECT_EQ(resumed_log.substr(0, 200), log.substr(0, 200));
  EXPECT_NE(resumed_log.find("resuming after step"), std::string::npos);
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename();
    EXPECT_EQ(name.find(".tmp"), std::string::npos) << name;
    EXPECT_NE(name, DirectoryLock::kFileName);
  }
}

/// Waits (at most a minute) until a process closes dir/checkpoint.bin after reading it; false if
/// none does. `watch` is an inotify descriptor watching `dir` for IN_CLOSE_NOWRITE.
bool wait_for_checkpoint_read(int watch) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  alignas(inotify_event) char buffer[4096];
  while (std::chrono::steady_clock::now() < deadline) {
    pollfd p{watch, POLLIN, 0};
    if (poll(&p, 1, 1000) <= 0) continue;
    const ssize_t n = read(watch, buffer, sizeof buffer);
    for (ssize_t at = 0; at < n;) {
      const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
      if (event->len > 0 && std::string(event->name) == "checkpoint.bin") return true;
      at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
    }
  }
  return false;
}

TEST(RunDirectory, ASecondResumeThatReadTheCheckpointBeforeTheFirstEndedUndoesNothing) {
  const fs::path dir = test::scratch_directory("rundir-two-resumes");
  const std::vector<std::string> sets = {"--set", "solver.steps=120", "--set", "output.every=1000"};
  std::vector<std::string> args = {"run", kCase, "-o", dir.string()};
  args.insert(args.end(), sets.begin(), sets.end());
  // An interrupted run: SIGTERM stops it at a converged step with its checkpoint.
  const pid_t interrupted = start(args, dir.string() + ".log");
  ASSERT_TRUE(wait_for_rows(dir, 10)) << contents(dir.string() + ".log");
  kill(interrupted, SIGTERM);
  int status = 0;
  waitpid(interrupted, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << contents(dir.string() + ".log");
  const std::size_t stopped_at = test::history_rows(dir);

  std::vector<std::string> resume = {"run", kCase, "--resume", dir.string()};
  resume.insert(resume.end(), sets.begin(), sets.end());
  // The first resume runs, holding the directory, and is held still (SIGSTOP) meanwhile.
  const pid_t first = start(resume, dir.string() + ".first.log");
  ASSERT_TRUE(wait_for_rows(dir, stopped_at + 3)) << contents(dir.string() + ".first.log");
  kill(first, SIGSTOP);
  // The second reads the same checkpoint, and is held still before it gets to the lock.
  const int watch = inotify_init1(IN_CLOEXEC);
  ASSERT_GE(watch, 0);
  ASSERT_GE(inotify_add_watch(watch, dir.c_str(), IN_CLOSE_NOWRITE), 0);
  const pid_t second = start(resume, dir.string() + ".second.log");
  const bool read_it = wait_for_checkpoint_read(watch);
  kill(second, SIGSTOP);
  close(watch);
  ASSERT_TRUE(read_it) << contents(dir.string() + ".second.log");
  // The first ends, with its last checkpoint, and lets the directory go.
  kill(first, SIGCONT);
  waitpid(first, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0)
      << contents(dir.string() + ".first.log");
  const auto finished = snapshot(dir);
  // The second then holds the lock, but its checkpoint is no longer the directory's.
  kill(second, SIGCONT);
  waitpid(second, &status, 0);
  const std::string second_log = contents(dir.string() + ".second.log");
  ASSERT_TRUE(WIFEXITED(status)) << second_log;
  EXPECT_EQ(WEXITSTATUS(status), 2) << second_log;
  EXPECT_NE(second_log.find("key '--resume': its checkpoint.bin was replaced after this run read "
                            "it"),
            std::string::npos)
      << second_log;
  const auto after = snapshot(dir);
  for (const auto& [name, bytes] : finished) {
    ASSERT_TRUE(after.count(name)) << name;
    EXPECT_TRUE(after.at(name) == bytes) << name << " changed";  // not printed: binary files
  }
  EXPECT_EQ(after.size(), finished.size());
  EXPECT_EQ(read_history(dir / "history.csv").rows.size(), 120u);
}

}  // namespace
}  // namespace plisse
