#pragma once
/// `--set key.path=value` overrides of a case file (internal to src/case).
///
/// Syntax: a key path of map keys separated by '.', each optionally followed by list indices
/// "[N]" (0-based), then '=', then a YAML value: "mesh.layers=4", "loads[0].value=1e-3",
/// "dies[0].move.displacement=[0, -5, 0]", "material={model: neo-hookean, c1: 0.003}".
/// Missing map keys are created; list indices must exist. Overrides are applied in order to the
/// parsed YAML tree, before any validation, so an override is checked like the file itself.
#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

namespace plisse::case_detail {

/// Applies `overrides` to `root` (a map). Returns the canonical key path of each override (e.g.
/// "loads[0].value"), in order. Throws InputError with file "--set" for a malformed override, a
/// value that is not valid YAML, a path through something that is not a map or list, or an index
/// out of range.
std::vector<std::string> apply_overrides(YAML::Node& root,
                                         const std::vector<std::string>& overrides);

}  // namespace plisse::case_detail
