// Fuzz target "history": read_history and the restart path HistoryWriter::reopen.
#include <cmath>
#include <cstring>

#include "core/error.hpp"
#include "output/append_file.hpp"
#include "output/history_writer.hpp"
#include "scratch_file.hpp"
#include "targets.hpp"

namespace plisse::fuzz {
namespace {

/// Same value: bit for bit, except that any NaN equals any NaN (the text "nan" keeps no payload).
bool same_value(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same_table(const HistoryTable& a, const HistoryTable& b) {
  if (a.columns != b.columns || a.rows.size() != b.rows.size()) return false;
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    if (a.rows[i].size() != b.rows[i].size()) return false;
    for (std::size_t j = 0; j < a.rows[i].size(); ++j)
      if (!same_value(a.rows[i][j], b.rows[i][j])) return false;
  }
  return true;
}

}  // namespace

Outcome read_history_file(Bytes data) {
  const auto path = write_scratch_file("history.csv", data);
  HistoryTable table;
  try {
    table = read_history(path);
  } catch (const Error&) {  // InputError derives from Error
    return Outcome::rejected;
  }
  for (const auto& row : table.rows)
    if (row.size() != table.columns.size()) throw Finding("accepted row of the wrong length");
  // A restart keeps the complete lines only: a last row without its line break is one a killed
  // run was writing, and reopen drops it. That table is what the rewrite must read back as.
  HistoryTable kept;
  try {
    HistoryWriter writer = HistoryWriter::reopen(path);
    kept.columns = writer.columns();
    kept.rows = writer.rows();
    writer.keep_first_rows(writer.rows().size());  // rewrites the file from the parsed table
  } catch (const Error&) {  // not a plisse history (columns), which read_history allows
    return Outcome::accepted;
  }
  const std::string_view text(reinterpret_cast<const char*>(data.data()), data.size());
  if (complete_lines(text).size() == text.size() && !same_table(kept, table))
    throw Finding("reopen parsed a complete history differently from read_history");
  if (!same_table(read_history(path), kept))
    throw Finding("history does not read back identically after HistoryWriter rewrote it");
  return Outcome::accepted;
}

}  // namespace plisse::fuzz
