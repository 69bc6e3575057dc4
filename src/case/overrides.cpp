#include "case/overrides.hpp"

#include <cctype>
#include <cstddef>
#include <utility>

#include "case/yaml_text.hpp"
#include "core/error.hpp"

namespace plisse::case_detail {
namespace {

/// One step of a key path: a map key or a list index.
struct PathStep {
  bool is_index = false;
  std::string key;
  std::size_t index = 0;
};

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return s.substr(first, last - first + 1);
}

[[noreturn]] void fail(const std::string& key, const std::string& rule) {
  throw InputError({"--set", 0, 0, key}, rule);
}

/// Longest key path an override may have (its parts are walked recursively); the case's deepest
/// keys have about 5.
constexpr std::size_t kMaxPathSteps = 32;

bool is_key_char(char ch) {
  return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '-';
}

/// Splits "a.b[2].c" into steps; `text` is the whole override for messages.
std::vector<PathStep> parse_path(const std::string& path, const std::string& text) {
  const std::string hint = "malformed override '" + text +
                           "': expected key.path=value with keys separated by '.' and list "
                           "indices as [N], e.g. loads[0].value=1e-3";
  std::vector<PathStep> steps;
  const auto add = [&](PathStep step) {
    if (steps.size() >= kMaxPathSteps)
      fail(path.substr(0, std::min<std::size_t>(path.size(), 200)),
           "the key path has more than " + std::to_string(kMaxPathSteps) +
               " parts; the case's deepest keys have a few");
    steps.push_back(std::move(step));
  };
  std::size_t i = 0;
  while (true) {
    const std::size_t start = i;
    while (i < path.size() && is_key_char(path[i])) ++i;
    if (i == start) fail(path, hint);
    add({false, path.substr(start, i - start), 0});
    while (i < path.size() && path[i] == '[') {
      const std::size_t close = path.find(']', i);
      const std::string digits =
          close == std::string::npos ? path.substr(i + 1) : path.substr(i + 1, close - i - 1);
      bool ok = close != std::string::npos && !digits.empty() && digits.size() < 10;
      for (char ch : digits) ok = ok && std::isdigit(static_cast<unsigned char>(ch));
      if (!ok)
        fail(path, "malformed override '" + text + "': the list index '[" + digits +
                       "]' must be a non-negative integer, e.g. [0]");
      add({true, {}, static_cast<std::size_t>(std::stoul(digits))});
      i = close + 1;
    }
    if (i == path.size()) break;
    if (path[i] != '.') fail(path, hint);
    ++i;
  }
  return steps;
}

std::string path_string(const std::vector<PathStep>& steps, std::size_t n) {
  std::string out;
  // Appended piecewise: GCC 12 warns (-Wrestrict, falsely) on "literal" + std::string here.
  for (std::size_t i = 0; i < n; ++i) {
    if (steps[i].is_index) {
      out += '[';
      out += std::to_string(steps[i].index);
      out += ']';
    } else {
      if (!out.empty()) out += '.';
      out += steps[i].key;
    }
  }
  return out;
}

std::string kind_of(const YAML::Node& node) {
  if (!node.IsDefined()) return "missing";
  switch (node.Type()) {
    case YAML::NodeType::Null:
      return "empty";
    case YAML::NodeType::Scalar:
      return "a single value";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    default:
      return "undefined";
  }
}

/// Walks `steps[i..]` below `node` (reached by steps[0..i)) and assigns `value` at the end.
/// YAML::Node is a handle: passing it by value and assigning through operator[] edits the tree.
void assign(YAML::Node node, const std::vector<PathStep>& steps, std::size_t i,
            const YAML::Node& value) {
  const std::string full = path_string(steps, steps.size());
  const std::string here = path_string(steps, i);
  const PathStep& step = steps[i];
  const bool last = i + 1 == steps.size();
  if (!step.is_index) {
    if (node.IsDefined() && !node.IsNull() && !node.IsMap())
      fail(full, "cannot set '" + full + "': '" + here + "' is " + kind_of(node) + ", not a map" +
                     (node.IsSequence() ? " (select an item, e.g. " + here + "[0]." + step.key + ")"
                                        : std::string()));
    if (last) {
      node[step.key] = value;
      return;
    }
    assign(node[step.key], steps, i + 1, value);
    return;
  }
  if (!node.IsDefined() || !node.IsSequence())
    fail(full, "cannot set '" + full + "': '" + here + "' is " + kind_of(node) +
                   ", not a list (to create a list, set it whole, e.g. " + here + "=[...])");
  if (step.index >= node.size())
    fail(full, "cannot set '" + full + "': index " + std::to_string(step.index) +
                   " is out of range, '" + here + "' has " + std::to_string(node.size()) +
                   " items (indices start at 0)");
  if (last) {
    node[step.index] = value;
    return;
  }
  assign(node[step.index], steps, i + 1, value);
}

}  // namespace

std::vector<std::string> apply_overrides(YAML::Node& root,
                                         const std::vector<std::string>& overrides) {
  std::vector<std::string> paths;
  for (const std::string& text : overrides) {
    // Checked before the text is quoted in any message: raw control bytes would reach the
    // terminal.
    if (const std::string problem = scalar_text_problem(text); !problem.empty())
      fail("", "an override " + problem + "; --set takes key.path=value as UTF-8 text");
    const std::size_t eq = text.find('=');
    if (eq == std::string::npos)
      fail("", "malformed override '" + text + "': expected key.path=value, e.g. mesh.layers=4");
    const std::string path = trim(text.substr(0, eq));
    if (path.empty())
      fail("", "malformed override '" + text + "': the key path before '=' is empty");
    const std::vector<PathStep> steps = parse_path(path, text);
    const std::string canonical = path_string(steps, steps.size());
    YAML::Node value;
    try {
      value = YAML::Load(text.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      fail(canonical, "cannot read the value of override '" + text + "' as YAML: " + e.msg);
    }
    assign(root, steps, 0, value);
    paths.push_back(canonical);
  }
  return paths;
}

}  // namespace plisse::case_detail
