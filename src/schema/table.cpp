// Rendering the case-file schema as markdown, the names shared by the entries of a case, and
// paths relative to the case file.
#include "schema/table.hpp"

#include <filesystem>
#include <sstream>

namespace plisse::schema {

std::string ReadContext::unique_name(const Field& f) {
  const std::string name = f.name();
  // The entry is the map holding `name:`: its path is the name's path without ".name".
  const std::string& path = f.path();
  const std::size_t dot = path.rfind('.');
  const std::string entry = dot == std::string::npos ? path : path.substr(0, dot);
  const auto [it, inserted] = names.try_emplace(name, entry, f.place());
  if (!inserted) {
    const InputPlace& first = it->second.second;
    f.fail("name " + quoted_excerpt(name) + " is already used by " + it->second.first +
           (first.line > 0 ? " (line " + std::to_string(first.line) + ")" : std::string()) +
           "; names of boundary conditions, loads, cavities, dies, caps, contacts and probes must "
           "be unique");
  }
  return name;
}

std::string doc_number(double value) {
  std::string text = format_number(value);
  // "1e-08" -> "1e-8", "1e+20" -> "1e20".
  const std::size_t e = text.find('e');
  if (e == std::string::npos) return text;
  std::string mantissa = text.substr(0, e), exponent = text.substr(e + 1);
  std::string sign;
  if (!exponent.empty() && (exponent[0] == '-' || exponent[0] == '+')) {
    if (exponent[0] == '-') sign = "-";
    exponent.erase(0, 1);
  }
  while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
  return mantissa + "e" + sign + exponent;
}

std::string resolve_path(const std::string& text, const std::string& directory) {
  std::filesystem::path p(text);
  if (p.is_relative() && !directory.empty()) p = std::filesystem::path(directory) / p;
  return p.string();
}

std::string doc_choice(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words) out += (out.empty() ? "`" : " \\| `") + w + "`";
  return out;
}

std::string render_markdown(const SectionDoc& doc) {
  bool variants = false;
  for (const KeyDoc& k : doc.keys) variants = variants || !k.applies_to.empty();
  std::ostringstream md;
  md << "| key | type | unit | default | range |" << (variants ? " applies to |" : "")
     << " meaning |\n|---|---|---|---|---|" << (variants ? "---|" : "") << "---|\n";
  const auto cell = [&md](const std::string& text) {
    md << (text.empty() ? " |" : " " + text + " |");
  };
  for (const KeyDoc& k : doc.keys) {
    md << '|';
    for (const std::string& text : {"`" + k.key + "`", k.type, k.unit, k.default_value, k.range})
      cell(text);
    if (variants) cell(k.applies_to.empty() ? "all" : join(k.applies_to));
    cell(k.help);
    md << '\n';
  }
  if (!doc.rules.empty()) {
    md << "\nRules between keys:\n\n";
    for (const std::string& rule : doc.rules) md << "- " << rule << "\n";
  }
  return md.str();
}

}  // namespace plisse::schema
