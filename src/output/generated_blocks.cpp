#include "output/generated_blocks.hpp"

#include "core/error.hpp"
#include "output/atomic_file.hpp"

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

std::string generated_blocks(const std::vector<std::string>& names,
                             const std::function<std::string(const std::string&)>& markdown) {
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) text += '\n';
    text += "<!-- generated: ";
    text += names[i];
    text += " -->\n";
    text += markdown(names[i]);
    text += "<!-- end generated -->\n";
  }
  return text;
}

bool update_generated_blocks(const std::string& path,
                             const std::function<std::string(const std::string&)>& markdown) {
  const std::string doc = read_file(path);
  // A file without a block would be left as it is and reported up to date: the wrong file.
  if (doc.find("<!-- generated: ") == std::string::npos)
    throw InputError(InputPlace{path, 0, 0, ""},
                     "has no generated block (a line '<!-- generated: NAME -->'): it is not the "
                     "manual this command writes (docs/case-file.md or docs/output.md)");
  const std::string fresh = refresh_generated_blocks(doc, markdown);
  if (fresh == doc) return false;
  write_file_atomically(path, fresh);
  return true;
}

}  // namespace plisse
