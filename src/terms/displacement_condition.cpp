// `boundary:` of type displacement: prescribed components on a surface's nodes, ramped in time
// (physics/dirichlet.hpp).
#include "physics/boundary_condition.hpp"
#include "physics/dirichlet.hpp"
#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {

TermKind displacement_condition_kind() {
  using namespace term_keys;
  using S = DisplacementConditionSettings;
  TermDefinition<S> d;
  d.section = "boundary";
  d.word = "displacement";
  d.summary = "prescribed components";
  Schema<S>& s = d.keys;
  s.place(&S::place, false);
  condition_keys(s, &S::name, &S::surface);
  s.add({"value",
         "list of 3 numbers or `~`",
         "mm",
         "",
         "",
         {},
         "displacement at the end of the ramp; `~` leaves a component free; at least one "
         "component must be given"},
        [](const Field& f, S& bc, ReadContext&) {
          bc.value = optional_components(f, "displacements [ux, uy, uz] in mm");
          if (!bc.value[0] && !bc.value[1] && !bc.value[2])
            f.fail("at least one component must be prescribed (all three are ~)");
        })
      .required();
  ramp_key(s, &S::ramp, "time ramp of `value`");
  d.check_mesh = [](const S& bc, const TermMeshCheck& check) { check.condition(bc.surface); };
  d.constrain = [](const S& bc, const Mesh& mesh, ConstraintSet& set) {
    prescribe_surface(mesh, bc.surface, bc.value, bc.ramp, set);
  };
  d.surface = [](const S& bc) { return bc.surface; };
  // Its ramp matters once a component moves (a held component is 0 at every factor).
  d.ramps = [](const S& bc) {
    for (const auto& v : bc.value)
      if (v && *v != 0.0)
        return std::vector<RampUse>{{bc.ramp, bc.name.empty()
                                                  ? "the displacement of '" + bc.surface.name + "'"
                                                  : "displacement '" + bc.name + "'"}};
    return std::vector<RampUse>{};
  };
  d.history = reaction_outputs(true);
  d.shell = true;
  return make_term_kind(std::move(d));
}

}  // namespace plisse
