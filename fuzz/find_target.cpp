// Name -> fuzz target, for the regression replay and any driver that picks a target at run time.
#include "targets.hpp"

namespace plisse::fuzz {

TargetFunction find_target(const std::string& name) {
  if (name == "case") return &parse_case;
  if (name == "gmsh") return &read_mesh;
  if (name == "history") return &read_history_file;
  if (name == "checkpoint") return &read_checkpoint_file;
  if (name == "vtu") return &read_vtu_file;
  return nullptr;
}

}  // namespace plisse::fuzz
