#pragma once
/// history.csv: one row per converged step, one column per scalar quantity (docs/architecture.md,
/// "Interface contract"). The first columns are always `step,time,load_factor,newton_iterations,
/// residual_norm`; the caller adds named columns such as `pressure:gas`, `volume:cavity`,
/// `force_y:punch`, `ux:inner`, `negative_pivots`, `stable` when the file is created, and the set
/// is fixed afterwards.
///
/// Numbers are written as the shortest text that reads back to the same double (std::to_chars),
/// so a reader recovers every value bit for bit; integers print without a decimal point (12),
/// flags as 0/1, non-finite values as nan, inf, -inf. The header is written atomically; each row is
/// then appended in one write (output/append_file.hpp), so the file holds whole rows only, and a
/// restart drops a row a killed run left unterminated.
#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "output/append_file.hpp"

namespace plisse {

/// Appends the shortest text that reads back to the same double (std::to_chars), as history.csv
/// writes its numbers; for other CSV files of a run (wrinkle_spectrum.csv).
void append_number(std::string& out, double value);

/// The content of a history.csv: column names and rows of numbers (rows[i].size() ==
/// columns.size()).
struct HistoryTable {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
};

/// Reads a history.csv written by HistoryWriter (or any CSV of that shape: a header line of column
/// names as the writer accepts them, then comma-separated numbers; a CR before each LF is
/// allowed). Throws plisse::InputError with the file, line, column number and column name of the
/// first malformed entry.
HistoryTable read_history(const std::filesystem::path& path);

/// Most rows a history is read with unless told otherwise: the steps of the longest run.
inline constexpr std::size_t kMaxHistoryRows = 100000000;

/// The same, from the file's text; `path` names it in errors.
/// A text of more than `max_rows` rows, or whose table would need more than a quarter of the
/// memory this process may use (physical_memory_bytes), is refused before it is parsed
/// (InputError naming `path`).
HistoryTable parse_history(std::string_view text, const std::filesystem::path& path,
                           std::size_t max_rows = kMaxHistoryRows);

class HistoryWriter {
 public:
  /// `step,time,load_factor,newton_iterations,residual_norm`, in this order.
  static const std::vector<std::string>& standard_columns();

  /// Creates (or replaces, atomically) `path` with the header standard_columns() +
  /// `extra_columns` and no rows. Column names must be non-empty, unique and free of ',', '"' and
  /// line breaks (plisse::Error otherwise). Throws plisse::Error naming the path if it cannot be
  /// written.
  HistoryWriter(std::filesystem::path path, const std::vector<std::string>& extra_columns);

  /// Continues an existing history (restart): reads its columns and rows as read_history() does,
  /// without an unterminated last line (a row the interrupted run was killed writing). Throws
  /// plisse::InputError if it is malformed, does not start with standard_columns() or holds more
  /// than `max_rows` rows (parse_history: what a run of the case can have written).
  static HistoryWriter reopen(std::filesystem::path path, std::size_t max_rows = kMaxHistoryRows);

  /// Appends one row to the file. values.size() must equal n_columns(), in the order
  /// of columns() (plisse::Error otherwise, and nothing is written).
  void add_row(std::span<const double> values);
  void add_row(std::initializer_list<double> values) {
    add_row(std::span<const double>(values.begin(), values.size()));
  }

  /// Keeps only the first `n_rows` rows (a restart from an earlier step) and rewrites the file
  /// atomically.
  void keep_first_rows(std::size_t n_rows);

  std::size_t n_columns() const { return table_.columns.size(); }
  const std::vector<std::string>& columns() const { return table_.columns; }
  /// Position of column `name` in a row, or nullopt if there is no such column.
  std::optional<std::size_t> column_index(std::string_view name) const;
  const std::vector<std::vector<double>>& rows() const { return table_.rows; }
  const std::filesystem::path& path() const { return path_; }

 private:
  HistoryWriter() = default;  // for reopen()
  /// Writes table_ (header and all rows) to the file atomically.
  void rewrite();

  std::filesystem::path path_;
  HistoryTable table_;
  std::optional<AppendFile> file_;  ///< opened at the first row after a rewrite
};

}  // namespace plisse
