#include "io/generated_blocks.hpp"

#include "core/error.hpp"

namespace plisse {

std::string refresh_generated_blocks(
    const std::string& doc, const std::function<std::string(const std::string&)>& markdown) {
  const std::string open = "<!-- generated: ", close = "<!-- end generated -->";
  std::string out;
  std::size_t at = 0;
  for (std::size_t start; (start = doc.find(open, at)) != std::string::npos;) {
    const std::size_t name_end = doc.find(" -->\n", start);
    if (name_end == std::string::npos)
      throw Error("a '" + open + "' line of the manual does not end with ' -->'");
    const std::string name = doc.substr(start + open.size(), name_end - start - open.size());
    const std::size_t body = name_end + 5;
    const std::size_t end = doc.find(close, body);
    if (end == std::string::npos)
      throw Error("the generated block '" + name + "' has no '" + close + "' line");
    out += doc.substr(at, body - at) + markdown(name);
    at = end;
  }
  return out + doc.substr(at);
}

}  // namespace plisse
