// The table of term kinds: one line per kind, each defined in its own file of this folder.
#include "terms/term_kind.hpp"

namespace plisse {

TermKind fixed_condition_kind();
TermKind symmetry_condition_kind();
TermKind displacement_condition_kind();
TermKind clamped_condition_kind();
TermKind hinged_condition_kind();
TermKind pressure_load_kind();
TermKind gravity_load_kind();
TermKind traction_load_kind();
TermKind point_force_kind();
TermKind follower_traction_kind();
TermKind cavity_kind();
TermKind cap_kind();
TermKind die_kind();
TermKind surface_contact_kind();

const std::vector<TermSection>& term_sections() {
  static const std::vector<TermSection> sections = {
      {"boundary", "type", "Dirichlet conditions"},
      {"loads", "type", "pressure, gravity, traction and point-force loads"},
      {"cavities", "", "fluid-filled cavities"},
      {"caps", "", "rigid end caps"},
      {"dies", "", "rigid dies"},
      {"contacts", "", "contact between surfaces of the body, or of a surface with itself"},
  };
  return sections;
}

const std::vector<TermKind>& term_kinds() {
  static const std::vector<TermKind> kinds = {
      fixed_condition_kind(),
      symmetry_condition_kind(),
      displacement_condition_kind(),
      clamped_condition_kind(),
      hinged_condition_kind(),
      pressure_load_kind(),
      gravity_load_kind(),
      traction_load_kind(),
      point_force_kind(),
      follower_traction_kind(),
      cavity_kind(),
      cap_kind(),
      die_kind(),
      surface_contact_kind(),
  };
  return kinds;
}

}  // namespace plisse
