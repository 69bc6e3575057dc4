// `loads:` of type gravity: a body force from the materials' densities (physics/body_force.hpp).
#include "physics/body_force.hpp"
#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {

TermKind gravity_load_kind() {
  using namespace term_keys;
  using S = GravityLoadSettings;
  TermDefinition<S> d;
  d.section = "loads";
  d.word = "gravity";
  d.summary = "a body force";
  Schema<S>& s = d.keys;
  s.place(&S::place, false);
  load_name_key(s, &S::name);
  s.vec3("acceleration", &S::acceleration, "mm/s²", "e.g. `[0, -9810, 0]`").required();
  load_ramp_key(s, &S::ramp);
  s.rule("a gravity load needs `material.density` > 0, or a region's",
         [](const FieldMap& m, const S&, const ReadContext& context) {
           if (!(context.density > 0.0))
             m.require("type").fail(
                 "a gravity load needs material.density > 0, or a region's material with a "
                 "density (got " +
                 schema::format_number(context.density) + ")");
         });
  d.check_mesh = [](const S&, const TermMeshCheck&) {};
  d.make = [](const S& load, const TermContext& c) -> std::unique_ptr<ModelTerm> {
    // The mirror image of a weight with a component normal to a mirror plane points the other
    // way: no body weighs so. A body resting on the plane is supported there, not mirrored.
    for (int k = 0; k < 3; ++k)
      if ((c.mirrors & (1 << k)) != 0 && load.acceleration[k] != 0.0) {
        const char axis = "xyz"[k];
        const std::string roller = k == 0 ? "[0, ~, ~]" : k == 1 ? "[~, 0, ~]" : "[~, ~, 0]";
        throw InputError(load.place,
                         "gravity '" + load.name + "' has a component along " + axis +
                             ", normal to the mirror plane " + axis +
                             " = 0 (a `symmetry` condition there): the mirrored half would weigh "
                             "the other way. A body resting on that plane is supported, not "
                             "mirrored: hold it with `type: displacement, value: " +
                             roller + "` (a roller), which mirrors nothing");
      }
    return std::make_unique<BodyForce>(c.mesh, load.name, load.acceleration, load.ramp,
                                       c.element_densities());
  };
  d.ramps = load_ramps<S>;
  // A body force writes no history column of its own (its total is the weight of the body).
  // On a shell, the weight of the mid-surface's triangles (loads.md, L6s).
  d.shell = true;
  return make_term_kind(std::move(d));
}

}  // namespace plisse
