// Refreshing the generated key tables of docs/case-file.md from the case-file schema.
#include "io/case_keys.hpp"

#include "core/error.hpp"

namespace plisse {

std::string refresh_case_key_blocks(const std::string& doc) {
  const std::string open = "<!-- generated: ", close = "<!-- end generated -->";
  std::string out;
  std::size_t at = 0;
  for (std::size_t start; (start = doc.find(open, at)) != std::string::npos;) {
    const std::size_t name_end = doc.find(" -->\n", start);
    if (name_end == std::string::npos)
      throw Error("a '" + open + "' line of the manual does not end with ' -->'");
    const std::string section = doc.substr(start + open.size(), name_end - start - open.size());
    const std::size_t body = name_end + 5;
    const std::size_t end = doc.find(close, body);
    if (end == std::string::npos)
      throw Error("the generated block '" + section + "' has no '" + close + "' line");
    out += doc.substr(at, body - at) + case_keys_markdown(section);
    at = end;
  }
  return out + doc.substr(at);
}

}  // namespace plisse
