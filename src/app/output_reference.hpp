#pragma once
/// The output reference: every history.csv column, summary.json key and VTU field a run writes,
/// with its unit, when it is there, and its meaning and sign. docs/output.md is generated from
/// these tables (`plisse outputs --update docs/output.md`), and the writers check against them:
/// HistoryColumns and the step files refuse a name that has no entry, so the reference cannot
/// fall behind what is written.
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "terms/term_kind.hpp"

namespace plisse::app {

/// The tables of the reference, one a generated block of docs/output.md.
enum class OutputTable { history, summary, vtu_point, vtu_cell };

/// "history", "summary", "vtu-point", "vtu-cell": the block names in docs/output.md.
std::vector<std::string> output_reference_sections();

/// The entries of `table`, in the order the files have them.
const std::vector<OutputEntry>& output_reference(OutputTable table);

/// The entry of `table` whose name or pattern matches `name` (the most specific: the longest
/// literal part), or nullptr. A pattern's `<...>` matches one or more characters.
const OutputEntry* find_output_entry(OutputTable table, std::string_view name);

/// Throws plisse::Error naming the table when `name` has no entry there (a quantity written
/// without being documented: a programming error).
void require_output_entry(OutputTable table, std::string_view name);

/// require_output_entry for every key of a summary.json: nested objects as `a.b`, the objects of
/// an array as `a[].b`; an array of numbers or strings, or of arrays, is one value.
void require_documented_summary(const nlohmann::json& summary);

/// The markdown table of the section `section` (output_reference_sections). Throws Error for an
/// unknown section.
std::string output_reference_markdown(const std::string& section);

}  // namespace plisse::app
