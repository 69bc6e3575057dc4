#include "case/petsc_option_text.hpp"

#include <array>
#include <cctype>
#include <sstream>
#include <string_view>
#include <vector>

namespace plisse {
namespace {

bool ends_with(std::string_view text, std::string_view end) {
  return text.size() >= end.size() && text.substr(text.size() - end.size()) == end;
}

/// Why the option `name` (without its dash) may not be given at all, or empty.
std::string name_problem(const std::string& name, bool has_value) {
  static constexpr std::array<std::string_view, 8> kFiles = {
      "options_file", "options_file_yaml", "log_trace",   "log_view_memory",
      "history",      "malloc_dump",       "malloc_view", "log_mpe"};
  for (const auto& forbidden : kFiles)
    if (name == forbidden) return "it reads or writes a file by name";
  if (name == "info" && has_value) return "its value names a file or filters classes";
  if (name == "display" || name.find("debugger") != std::string::npos)
    return "it starts a debugger or opens a display";
  for (const std::string_view end : {"_file", "_filename", "_dir", "_directory"})
    if (ends_with(name, end)) return "it names a file or directory";
  for (const std::string_view part : {"draw", "_lg_", "socket", "saws", "glvis"})
    if (name.find(part) != std::string::npos) return "it opens a window or a connection";
  return {};
}

/// Why a viewer value "type:file:format:mode" may not be given, or empty.
std::string viewer_problem(const std::string& value) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  while (true) {
    const std::size_t colon = value.find(':', begin);
    fields.push_back(value.substr(begin, colon - begin));
    if (colon == std::string::npos) break;
    begin = colon + 1;
  }
  const std::string& type = fields[0];
  if (fields.size() > 1 && !fields[1].empty())
    return "its value names the file '" + fields[1] + "'";
  if (!type.empty() && type != "ascii" && type != "stdout")
    return "its value writes a '" + type + "' view, not text to the log";
  return {};
}

}  // namespace

std::string petsc_option_problem(const std::string& options) {
  std::istringstream stream(options);
  std::vector<std::string> words;
  for (std::string word; stream >> word;) words.push_back(word);
  for (std::size_t i = 0; i < words.size(); ++i) {
    const std::string& word = words[i];
    if (word.size() < 2 || word[0] != '-') continue;
    const std::string name = word.substr(word[1] == '-' ? 2 : 1);
    const bool has_value =
        i + 1 < words.size() && !(words[i + 1].size() > 1 && words[i + 1][0] == '-' &&
                                  !std::isdigit(static_cast<unsigned char>(words[i + 1][1])));
    const std::string why_name = name_problem(name, has_value);
    const std::string why_value =
        has_value && words[i + 1].find(':') != std::string::npos ? viewer_problem(words[i + 1])
        : has_value && (ends_with(name, "_view") || name.find("monitor") != std::string::npos)
            ? viewer_problem(words[i + 1])
            : std::string();
    const std::string& why = why_name.empty() ? why_value : why_name;
    if (!why.empty())
      return "'" + word + (has_value ? " " + words[i + 1] : std::string()) +
             "' is refused: " + why +
             "; a run writes its output into its run directory (PETSc's views and monitors "
             "go to the log as text)";
  }
  return {};
}

}  // namespace plisse
