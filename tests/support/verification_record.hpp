#pragma once
/// docs/verification/record.json, the numbers docs/verification.md prints (scripts/verification-
/// report writes both): the verification tests that rerun a row's case read the row from it, so
/// that the page and the test cannot drift apart.
#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "output/history_writer.hpp"
#include "output/json_file.hpp"
#include "support/run_case.hpp"

namespace plisse::test {

/// The table `table` of docs/verification/record.json.
inline nlohmann::json verification_table(const std::string& table) {
  const nlohmann::json record = read_json_file(std::filesystem::path(PLISSE_SOURCE_DIR) / "docs" /
                                               "verification" / "record.json");
  if (!record["tables"].contains(table)) {
    ADD_FAILURE() << "docs/verification/record.json has no table " << table;
    return nlohmann::json::object();
  }
  return record["tables"][table];
}

/// The row of the table whose keys have the given values (strings or numbers, as JSON); a failure
/// and an empty object when no row, or more than one, matches.
inline nlohmann::json verification_row(
    const std::string& table, const std::vector<std::pair<std::string, nlohmann::json>>& match) {
  const nlohmann::json t = verification_table(table);
  nlohmann::json found = nlohmann::json::object();
  int count = 0;
  for (const nlohmann::json& row : t.value("rows", nlohmann::json::array())) {
    bool all = true;
    for (const auto& [key, value] : match) all = all && row.contains(key) && row[key] == value;
    if (all) {
      found = row;
      ++count;
    }
  }
  if (count != 1) ADD_FAILURE() << count << " rows of " << table << " match";
  return found;
}

/// Regression guard (plisse's own earlier output, not a validation): the run took the steps and
/// the Newton iterations that the page prints for it (`row`'s steps and newton_iterations).
inline void expect_newton_as_printed(std::size_t steps, double iterations,
                                     const nlohmann::json& row, const std::string& what) {
  if (!row.contains("steps") || !row.contains("newton_iterations")) {
    ADD_FAILURE() << what << ": the row prints no steps or Newton iterations";
    return;
  }
  EXPECT_EQ(steps, row["steps"].get<std::size_t>()) << what << ": steps";
  EXPECT_EQ(iterations, row["newton_iterations"].get<double>()) << what << ": Newton iterations";
}

/// The same for the converged steps of history.csv, with their Newton iterations summed (the
/// tables of the cubes count these).
inline void expect_newton_as_printed(const HistoryTable& h, const nlohmann::json& row,
                                     const std::string& what) {
  const std::size_t it = history_column(h, "newton_iterations");  // a failure when missing
  double total = 0.0;
  for (const auto& r : h.rows) total += r[it];
  expect_newton_as_printed(h.rows.size(), total, row, what);
}

/// The same for summary.json's steps and newton_iterations (every iteration, those of steps cut
/// back included: the tables of the balloons count these).
inline void expect_newton_as_printed(const nlohmann::json& summary, const nlohmann::json& row,
                                     const std::string& what) {
  expect_newton_as_printed(summary.value("steps", std::size_t{0}),
                           summary.value("newton_iterations", 0.0), row, what);
}

}  // namespace plisse::test
