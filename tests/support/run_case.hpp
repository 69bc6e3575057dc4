#pragma once
/// Test helpers that run a case given as YAML text through the built `plisse` executable and read
/// its history.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "output/history_writer.hpp"
#include "support/run_plisse.hpp"

namespace plisse::test {

/// Writes `yaml` as `dir`/case.yaml, runs it into `dir`/run (output in `dir`/log.txt) and returns
/// the history: an empty table, with a test failure, when the run fails.
inline HistoryTable run_case_text(const std::filesystem::path& dir, const std::string& yaml) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "case.yaml") << yaml;
  const int status = run_plisse(
      "run " + (dir / "case.yaml").string() + " -o " + (dir / "run").string(), dir / "log.txt");
  EXPECT_EQ(status, 0) << "see " << (dir / "log.txt").string();
  if (status != 0) return {};
  return read_history(dir / "run" / "history.csv");
}

/// The index of the history column `name` (0, with a test failure, when there is none).
inline std::size_t history_column(const HistoryTable& h, const std::string& name) {
  for (std::size_t i = 0; i < h.columns.size(); ++i)
    if (h.columns[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

/// The row of `h` whose column `c_time` is `time` (within 1e-9: step files and history rows carry
/// the same value), or h.rows.end().
inline auto history_row_at(const HistoryTable& h, std::size_t c_time, double time) {
  return std::find_if(h.rows.begin(), h.rows.end(),
                      [&](const auto& r) { return std::abs(r[c_time] - time) < 1e-9; });
}

}  // namespace plisse::test
