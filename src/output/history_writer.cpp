#include "output/history_writer.hpp"

#include <algorithm>
#include <charconv>
#include <set>
#include <utility>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "output/atomic_file.hpp"

namespace plisse {

void append_number(std::string& out, double value) {
  char text[32];  // std::to_chars round-trip guarantee: the shortest text of `value`
  const auto result = std::to_chars(text, text + sizeof text, value);
  out.append(text, result.ptr);
}

namespace {

void append_row(std::string& out, std::span<const double> values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out += ',';
    append_number(out, values[i]);
  }
  out += '\n';
}

/// Why `name` cannot be a history column (empty, or a character the plain CSV form cannot hold
/// back: ',' splits, '"' would start a quoted field, a line break ends the header), or nullptr.
const char* column_name_problem(std::string_view name) {
  if (name.empty()) return "is empty";
  if (name.find_first_of(",\"\r\n") != std::string_view::npos)
    return "contains ',', '\"' or a line break";
  return nullptr;
}

std::vector<std::string> split_commas(std::string_view line) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = line.find(',', begin);
    parts.emplace_back(line.substr(begin, comma - begin));
    if (comma == std::string_view::npos) return parts;
    begin = comma + 1;
  }
}

}  // namespace

const std::vector<std::string>& HistoryWriter::standard_columns() {
  static const std::vector<std::string> kColumns = {"step", "time", "load_factor",
                                                    "newton_iterations", "residual_norm"};
  return kColumns;
}

HistoryWriter::HistoryWriter(std::filesystem::path path,
                             const std::vector<std::string>& extra_columns)
    : path_(std::move(path)) {
  table_.columns = standard_columns();
  table_.columns.insert(table_.columns.end(), extra_columns.begin(), extra_columns.end());
  std::set<std::string_view> seen;
  for (const std::string& name : table_.columns) {
    const char* problem = column_name_problem(name);
    PLISSE_CHECK(problem == nullptr,
                 "history '" << path_.string() << "': column name '" << name << "' " << problem);
    PLISSE_CHECK(seen.insert(name).second,
                 "history '" << path_.string() << "': column '" << name << "' appears twice");
  }
  rewrite();
}

HistoryWriter HistoryWriter::reopen(std::filesystem::path path, std::size_t max_rows) {
  // A run killed inside a row's write leaves that row unterminated: it is dropped.
  const std::string text = read_file(path);
  HistoryTable table = parse_history(complete_lines(text), path, max_rows);
  const std::vector<std::string>& standard = standard_columns();
  const bool starts_with_standard =
      table.columns.size() >= standard.size() &&
      std::equal(standard.begin(), standard.end(), table.columns.begin());
  if (!starts_with_standard)
    throw InputError({path.string(), 1, 0, ""},
                     "a plisse history must start with the columns "
                     "step,time,load_factor,newton_iterations,residual_norm");
  HistoryWriter writer;
  writer.path_ = std::move(path);
  writer.table_ = std::move(table);
  if (complete_lines(text).size() != text.size()) writer.rewrite();
  return writer;
}

void HistoryWriter::add_row(std::span<const double> values) {
  PLISSE_CHECK(values.size() == n_columns(), "history '" << path_.string() << "': row has "
                                                         << values.size() << " values for "
                                                         << n_columns() << " columns");
  std::string text;
  append_row(text, values);
  if (!file_) file_.emplace(path_, false);
  file_->append(text);
  table_.rows.emplace_back(values.begin(), values.end());
}

void HistoryWriter::keep_first_rows(std::size_t n_rows) {
  if (n_rows < table_.rows.size()) table_.rows.resize(n_rows);
  rewrite();
}

std::optional<std::size_t> HistoryWriter::column_index(std::string_view name) const {
  for (std::size_t i = 0; i < table_.columns.size(); ++i)
    if (table_.columns[i] == name) return i;
  return std::nullopt;
}

void HistoryWriter::rewrite() {
  std::string text;
  for (std::size_t i = 0; i < table_.columns.size(); ++i) {
    if (i > 0) text += ',';
    text += table_.columns[i];
  }
  text += '\n';
  for (const std::vector<double>& row : table_.rows) append_row(text, row);
  file_.reset();  // the rename below replaces the file it appended to
  write_file_atomically(path_, text);
}

HistoryTable read_history(const std::filesystem::path& path) {
  return parse_history(read_file(path), path);
}

HistoryTable parse_history(std::string_view text, const std::filesystem::path& path,
                           std::size_t max_rows) {
  // The size of the table, from the text alone, before anything is allocated for it: a row per
  // line, the header's columns in each.
  const auto n_lines = static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
  const std::string_view header = text.substr(0, text.find('\n'));
  const auto n_columns =
      static_cast<std::size_t>(std::count(header.begin(), header.end(), ',')) + 1;
  if (n_lines > max_rows + 1)
    throw InputError({path.string(), 0, 0, ""}, "holds " + std::to_string(n_lines - 1) +
                                                    " rows; a run of this case writes at "
                                                    "most " +
                                                    std::to_string(max_rows) +
                                                    " (one per converged step, solver.max_steps)");
  // Each row is a vector: its values and about 48 bytes of bookkeeping.
  const std::uint64_t table_bytes = std::uint64_t{n_lines} * (8 * n_columns + 48);
  if (table_bytes > physical_memory_bytes() / 4)
    throw InputError({path.string(), 0, 0, ""},
                     "its " + std::to_string(n_lines) + " lines of " + std::to_string(n_columns) +
                         " columns need about " + std::to_string(table_bytes >> 20) +
                         " MiB to read, more than a quarter of the memory this process may use");
  HistoryTable table;
  int line_number = 0;
  for (std::size_t begin = 0; begin < text.size();) {
    const std::size_t newline = std::min(text.find('\n', begin), text.size());
    std::string line(text.substr(begin, newline - begin));
    begin = newline + 1;
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line_number == 1) {
      // The writer's rules for column names hold for the reader too, so a history that is read
      // and rewritten (a restart) reads back the same.
      table.columns = split_commas(line);
      std::set<std::string_view> seen;
      std::size_t column = 1;  // 1-based character column of the name in the line
      for (const std::string& name : table.columns) {
        if (const char* problem = column_name_problem(name))
          throw InputError({path.string(), 1, static_cast<int>(column), name},
                           std::string("column name ") + problem);
        if (!seen.insert(name).second)
          throw InputError({path.string(), 1, static_cast<int>(column), name},
                           "column name appears twice");
        column += name.size() + 1;
      }
      continue;
    }
    if (line.empty()) continue;
    const std::vector<std::string> fields = split_commas(line);
    if (fields.size() != table.columns.size())
      throw InputError({path.string(), line_number, 0, ""},
                       "row has " + std::to_string(fields.size()) + " values for " +
                           std::to_string(table.columns.size()) + " columns");
    std::vector<double>& row = table.rows.emplace_back(fields.size());
    std::size_t column = 1;  // 1-based character column of fields[i] in the line
    for (std::size_t i = 0; i < fields.size(); ++i) {
      const std::string& field = fields[i];
      const auto parsed = std::from_chars(field.data(), field.data() + field.size(), row[i]);
      if (field.empty() || parsed.ec != std::errc() || parsed.ptr != field.data() + field.size())
        throw InputError({path.string(), line_number, static_cast<int>(column), table.columns[i]},
                         "'" + field + "' is not a number");
      column += field.size() + 1;
    }
  }
  if (line_number == 0) throw InputError({path.string(), 0, 0, ""}, "empty history file");
  return table;
}

}  // namespace plisse
