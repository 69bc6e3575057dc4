// `loads:` of type traction: a dead traction on a surface, per unit area or as a total force
// (physics/dead_load.hpp).
#include "physics/dead_load.hpp"
#include "physics/surface.hpp"
#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {

TermKind traction_load_kind() {
  using namespace term_keys;
  using S = TractionLoadSettings;
  TermDefinition<S> d;
  d.section = "loads";
  d.word = "traction";
  d.summary = "a dead traction on a surface";
  Schema<S>& s = d.keys;
  s.place(&S::place, false);
  load_name_key(s, &S::name);
  surface_key(s, "surface", &S::surface, "the loaded surface").required();
  s.add({"traction",
         "vector",
         "MPa",
         "",
         "",
         {},
         "traction per unit undeformed area at the end of the ramp, fixed in direction and "
         "magnitude (a dead load); non-zero"},
        [](const Field& f, S& load, ReadContext&) { load.traction = non_zero_vector(f); });
  s.add({"force",
         "vector",
         "N",
         "",
         "",
         {},
         "the total force at the end of the ramp, spread over the surface in proportion to "
         "undeformed area; dead, non-zero"},
        [](const Field& f, S& load, ReadContext&) { load.force = non_zero_vector(f); });
  load_ramp_key(s, &S::ramp);
  s.rule("a traction load needs exactly one of `traction` and `force`",
         [](const FieldMap& m, const S& load, const ReadContext&) {
           if (load.traction && load.force)
             m.require("force").fail_at_key(
                 "give either `traction` (per unit area) or `force` (in total), not both");
           if (!load.traction && !load.force)
             m.self().fail_at_key(
                 "a traction load needs `traction` (MPa, per unit undeformed area) or `force` "
                 "(N, in total)");
         });
  d.check_mesh = [](const S& load, const TermMeshCheck& check) { check.surface(load.surface); };
  d.make = [](const S& load, const TermContext& c) -> std::unique_ptr<ModelTerm> {
    const auto faces = outward_faces(c.mesh, load.surface.name);
    std::vector<NodalForce> forces = load.traction ? traction_forces(c.mesh, faces, *load.traction)
                                                   : total_force(c.mesh, faces, *load.force);
    refuse_load_on_held_nodes(forces, c.constraints, c.mesh,
                              load.surface.place.line > 0 ? load.surface.place : load.place,
                              "traction '" + load.name + "' on '" + load.surface.name + "'");
    return std::make_unique<DeadLoad>(load.name, std::move(forces), load.ramp);
  };
  d.ramps = load_ramps<S>;
  d.history = load_force_outputs();
  d.shell = true;
  return make_term_kind(std::move(d));
}

}  // namespace plisse
