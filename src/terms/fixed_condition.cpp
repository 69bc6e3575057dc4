// `boundary:` of type fixed: every displacement component of a surface's nodes is zero
// (physics/dirichlet.hpp); on a shell's edge the edge turns freely about itself, as `hinged`.
#include "physics/boundary_condition.hpp"
#include "physics/dirichlet.hpp"
#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {

TermKind fixed_condition_kind() {
  using namespace term_keys;
  using S = SurfaceConditionSettings;
  TermDefinition<S> d;
  d.section = "boundary";
  d.word = "fixed";
  d.summary = "u = 0";
  Schema<S>& s = d.keys;
  s.place(&S::place, false);
  condition_keys(s, &S::name, &S::surface);
  d.check_mesh = [](const S& bc, const TermMeshCheck& check) { check.condition(bc.surface); };
  d.constrain = [](const S& bc, const Mesh& mesh, ConstraintSet& set) {
    fix_surface(mesh, bc.surface, set);
  };
  d.surface = [](const S& bc) { return bc.surface; };
  d.history = reaction_outputs(true);
  d.shell = true;
  return make_term_kind(std::move(d));
}

}  // namespace plisse
