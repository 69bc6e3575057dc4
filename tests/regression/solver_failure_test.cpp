// Requirement: when the step cannot be cut further, plisse stops with exit status 1, a diagnostic
// naming the step, the worst element and the reason, and the last converged state written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "io/history_writer.hpp"
#include "io/json_file.hpp"
#include "support/run_plisse.hpp"

namespace plisse {
namespace {

TEST(SolverFailure, StopsWithExitStatus1AndNamesStepElementAndReason) {
  const auto dir = test::scratch_directory("solver-failure");
  const std::string case_file = std::string(PLISSE_SOURCE_DIR) + "/tests/regression/failure-case.yaml";
  const int status = test::run_plisse("run " + case_file + " -o " + dir.string(), dir.string() + ".log");
  EXPECT_EQ(status, 1);
  std::ifstream in(dir.string() + ".log");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(text.find("solver failure"), std::string::npos) << text;
  EXPECT_NE(text.find("step "), std::string::npos) << text;
  EXPECT_NE(text.find("worst element"), std::string::npos) << text;
  EXPECT_NE(text.find("below the minimum"), std::string::npos) << text;
  const auto summary = read_json_file(dir / "summary.json");
  EXPECT_FALSE(summary["completed"].get<bool>());
  EXPECT_NE(summary["failure"].get<std::string>().find("worst element"), std::string::npos);
  // Whatever converged before the failure is in the run directory.
  const HistoryTable h = read_history(dir / "history.csv");
  if (!h.rows.empty()) {
    EXPECT_TRUE(std::filesystem::exists(dir / "step_0001.vtu"));
  }
}

}  // namespace
}  // namespace plisse
