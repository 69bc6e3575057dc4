#pragma once
/// The raw text of a case file, before and around yaml-cpp (internal to src/case): reading the file
/// with a size limit, refusing bytes that are not YAML text, finding what yaml-cpp lets through
/// silently (an unclosed quote, a second document) and explaining its syntax errors (a tab in the
/// indentation). Every problem is an InputError naming the file, line and column; the key path is
/// empty since no key has been read yet.
#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>

namespace plisse::case_detail {

/// Largest case file read [bytes]; real ones are a few kB.
constexpr std::size_t kMaxCaseFileBytes = std::size_t{16} << 20;

/// The bytes of the case file at `path`. Throws InputError when it does not exist, is a directory,
/// cannot be opened or is larger than kMaxCaseFileBytes (reading stops there, so a device such as
/// /dev/zero cannot fill the memory).
std::string read_case_text(const std::string& path);

/// The one YAML document of `text` (a null node for an empty or comment-only text); `name` stands
/// for the file in messages. Throws InputError for a byte that is not printable UTF-8, a YAML
/// syntax error, a quoted scalar that is never closed, or a second document.
YAML::Node load_case_document(const std::string& text, const std::string& name);

/// Why `text` (a key or value after YAML's escapes, from the file or from --set) cannot be case
/// text, or empty: bytes that are not well-formed UTF-8, or a control character other than tab
/// and line feed (C0, DEL, C1: they rewrite terminals and logs), e.g. "holds the control character
/// U+001B".
std::string scalar_text_problem(const std::string& text);

}  // namespace plisse::case_detail
