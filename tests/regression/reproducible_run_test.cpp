// The same case, on the same build, ranks and BLAS threads, writes the same results to the bit
// (docs/output.md, "Reproducibility"):
//  - two runs of one case started at once (a MINI sphere pressed between a frictionless and a
//    sticking plate, tests/regression/cases/sphere-flattened.yaml) write the same history,
//    step files, checkpoint and wrinkle spectrum, and the same summary but for its times and
//    memory: nothing a run computes depends on the clock, the load of the machine, the run's
//    directory or another process;
//  - the element loops' thread count changes no bit (performance.md, "How the assembly works
//    now", 3): the driver airbag's shell on a coarse mesh (a cavity at prescribed volume, a
//    seeded random imperfection, damping, 15 cut-backs) on one and on two assembly threads.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/run_plisse.hpp"

namespace plisse {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  EXPECT_TRUE(in) << "cannot read " << file;
  return {std::istreambuf_iterator<char>(in), {}};
}

/// The files of `a` that hold results (history.csv, solution.pvd, the step files, the wrinkle
/// spectrum, the checkpoint) have the same bytes in `b`; returns how many were compared.
int expect_same_result_files(const fs::path& a, const fs::path& b) {
  int compared = 0;
  for (const auto& entry : fs::directory_iterator(a)) {
    const std::string name = entry.path().filename().string();
    if (name == "log.txt" || name == "summary.json") continue;  // times, the run's own path
    EXPECT_TRUE(fs::exists(b / name)) << name << " is missing from " << b;
    if (!fs::exists(b / name)) continue;
    EXPECT_TRUE(bytes_of(entry.path()) == bytes_of(b / name)) << name << " differs";
    ++compared;
  }
  return compared;
}

/// summary.json of both runs without what measures the process: its times and memory.
void expect_same_summary(const fs::path& a, const fs::path& b) {
  auto read = [](const fs::path& dir) {
    nlohmann::json j = nlohmann::json::parse(bytes_of(dir / "summary.json"));
    for (const char* key : {"wall_time", "peak_memory_mib", "peak_memory_per_rank_mib"}) {
      EXPECT_TRUE(j.contains(key)) << "summary.json has no '" << key << "'";
      j.erase(key);
    }
    return j;
  };
  EXPECT_EQ(read(a), read(b));
}

TEST(ReproducibleRun, TwoRunsOfACaseAtOnceWriteTheSameResults) {
  const std::string kase =
      std::string(PLISSE_SOURCE_DIR) + "/tests/regression/cases/sphere-flattened.yaml";
  const fs::path first = test::scratch_directory("first"),
                 second = test::scratch_directory("second");
  const pid_t a = test::start_plisse({"run", kase, "-o", first.string()}, first.string() + ".log");
  const pid_t b =
      test::start_plisse({"run", kase, "-o", second.string()}, second.string() + ".log");
  for (const pid_t pid : {a, b}) {
    int status = -1;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "see " << first << ".log";
  }
  // history.csv, solution.pvd, 11 step files, wrinkle_spectrum.csv and checkpoint.bin.
  EXPECT_GE(expect_same_result_files(first, second), 15);
  expect_same_summary(first, second);
}

TEST(ReproducibleRun, TheElementLoopsThreadCountChangesNoBit) {
  const std::string args = "run " + test::example("airbag-full-size.yaml") +
                           " --set mesh.element_size=40 --set mesh.rim_element_size=20"
                           " --set solver.end_time=0.5 -o ";
  const fs::path one = test::scratch_directory("one-thread"), two = test::scratch_directory("two");
  for (const auto& [dir, threads] : {std::pair{one, "1"}, std::pair{two, "2"}}) {
    const test::PlisseResult r = test::run_plisse_captured(
        args + dir.string(),
        test::limits(300) + "env OMP_NUM_THREADS=" + threads + " OPENBLAS_NUM_THREADS=1 ");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find(std::string("threads: ") + threads + " assembly thread"),
              std::string::npos)
        << r.output;
  }
  // The coarse bag folds: its path has cut-backs, which any difference of round-off would move.
  EXPECT_GT(nlohmann::json::parse(bytes_of(one / "summary.json")).value("cutbacks", 0), 0);
  EXPECT_GE(expect_same_result_files(one, two), 5);
  expect_same_summary(one, two);
}

}  // namespace
}  // namespace plisse
