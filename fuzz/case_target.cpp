// Fuzz target "case": the case-file parser and the `--set` override parser.
#include <string>
#include <string_view>
#include <vector>

#include "case/case.hpp"
#include "core/error.hpp"
#include "targets.hpp"

namespace plisse::fuzz {

Outcome parse_case(Bytes data) {
  const std::string text(reinterpret_cast<const char*>(data.data()), data.size());
  // "#set key=value" lines are YAML comments, so they do not change the case text itself.
  std::vector<std::string> overrides;
  constexpr std::string_view kPrefix = "#set ";
  for (std::size_t begin = 0; begin < text.size();) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    const std::string_view line(text.data() + begin, end - begin);
    if (line.starts_with(kPrefix)) overrides.emplace_back(line.substr(kPrefix.size()));
    begin = end + 1;
  }
  try {
    const Case c = parse_case_string(text, "fuzz.yaml", overrides);
    // Postconditions the rest of plisse relies on without checking again.
    if (!c.mesh.file.has_value() && !c.mesh.generate.has_value())
      throw Finding("accepted case has neither mesh.file nor mesh.generate");
    if (!(c.solver.end_time > 0.0) || c.solver.steps < 1 || c.output.every < 1)
      throw Finding("accepted case violates solver.end_time > 0, steps >= 1 or every >= 1");
    for (const TermEntry& entry : c.terms)
      for (const RampUse& use : entry.kind->ramps(entry))
        if (!(use.ramp.end > use.ramp.start) || use.ramp.start < 0.0)
          throw Finding("accepted " + use.what + " has a ramp with end <= start or start < 0");
    return Outcome::accepted;
  } catch (const Error&) {  // InputError derives from Error
    return Outcome::rejected;
  }
}

}  // namespace plisse::fuzz
