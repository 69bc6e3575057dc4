// `boundary:` of types clamped and hinged: the edges of a shell (element: shell) held in place or
// moved together by a prescribed displacement (a grip), with the slope across the edge held
// (clamped) or free (hinged) (docs/theory/shell.md, KL8 and KL8a).
#include "mesh/shell_surface.hpp"
#include "physics/boundary_condition.hpp"
#include "physics/dirichlet.hpp"
#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {
namespace {

/// The kind `word` on a shell's edge: its nodes held or moved by `value`, and with `clamped` its
/// sides mirrored.
TermKind shell_edge_kind(const std::string& word, const std::string& summary, bool clamped) {
  using namespace term_keys;
  using S = ShellEdgeConditionSettings;
  TermDefinition<S> d;
  d.section = "boundary";
  d.word = word;
  d.summary = summary;
  Schema<S>& s = d.keys;
  s.place(&S::place, false);
  condition_keys(s, &S::name, &S::surface);
  s.vec3("value", &S::value, "mm",
         "the edge's displacement at the end of the ramp, the same at every node of it (a grip "
         "that moves); default [0, 0, 0], the edge held");
  ramp_key(s, &S::ramp, "time ramp of `value`");
  d.check_mesh = [word](const S& bc, const TermMeshCheck& check) {
    check.condition(bc.surface);
    if (!shell_edge_tag(check.mesh, bc.surface.name))
      throw InputError(bc.surface.place, "a " + word + " condition acts on an edge of a shell: '" +
                                             bc.surface.name + "' is a surface tag");
  };
  d.constrain = [](const S& bc, const Mesh& mesh, ConstraintSet& set) {
    prescribe_surface(mesh, bc.surface, {bc.value.x(), bc.value.y(), bc.value.z()}, bc.ramp, set);
  };
  // Its ramp matters for a grip that moves.
  d.ramps = [word](const S& bc) {
    if (bc.value.isZero(0.0)) return std::vector<RampUse>{};
    return std::vector<RampUse>{
        {bc.ramp, "the " + word + " edge " +
                      (bc.name.empty() ? "'" + bc.surface.name + "'" : "'" + bc.name + "'")}};
  };
  if (clamped)
    d.hold_slope = [](const S& bc, Mesh& mesh) {
      clamp_sides(mesh, *shell_edge_tag(mesh, bc.surface.name));
    };
  d.surface = [](const S& bc) { return bc.surface; };
  d.history = reaction_outputs(true);
  d.solid = false;
  d.shell = true;
  return make_term_kind(std::move(d));
}

}  // namespace

TermKind clamped_condition_kind() {
  return shell_edge_kind("clamped",
                         "shell edge: held, or moved by `value`, and no turn about the edge", true);
}

TermKind hinged_condition_kind() {
  return shell_edge_kind(
      "hinged", "shell edge: held, or moved by `value`, free to turn about the edge", false);
}

}  // namespace plisse
