// `loads:` of type follower-traction: normal and shear tractions that turn with the deformed
// surface (physics/follower_traction.hpp).
#include "physics/follower_traction.hpp"

#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {

TermKind follower_traction_kind() {
  using namespace term_keys;
  using S = FollowerTractionSettings;
  TermDefinition<S> d;
  d.section = "loads";
  d.word = "follower-traction";
  d.summary = "normal and shear tractions that turn with the deformed surface";
  Schema<S>& s = d.keys;
  s.place(&S::place, false);
  load_name_key(s, &S::name);
  surface_key(s, "surface", &S::surface, "the loaded surface").required();
  s.real("normal", &S::normal, Range::any(), "MPa",
         "traction per unit deformed area along the deformed outward normal at the end of the "
         "ramp (a negative value pushes inwards, as a pressure)");
  s.real("shear", &S::shear, Range::any(), "MPa",
         "traction per unit deformed area along `direction` projected onto the deformed surface, "
         "at the end of the ramp");
  s.add({"direction",
         "vector",
         "–",
         "",
         "",
         {},
         "the shear's direction, normalised: the shear acts along its projection onto the "
         "deformed surface (nowhere where the surface is normal to it); required with a shear"},
        [](const Field& f, S& load, ReadContext&) { load.direction = unit_vector(f); });
  load_ramp_key(s, &S::ramp);
  s.rule(
      "a follower-traction load needs a non-zero `normal` or `shear`, and `direction` with a "
      "shear",
      [](const FieldMap& m, const S& load, const ReadContext&) {
        if (load.normal == 0.0 && load.shear == 0.0)
          m.self().fail_at_key(
              "a follower traction needs a non-zero `normal` or `shear` (MPa per unit "
              "deformed area)");
        if (load.shear != 0.0 && !load.direction) m.require("direction");
      });
  d.check_mesh = [](const S& load, const TermMeshCheck& check) { check.surface(load.surface); };
  d.make = [](const S& load, const TermContext& c) -> std::unique_ptr<ModelTerm> {
    FollowerTractionValues values;
    values.normal = load.normal;
    values.shear = load.shear;
    if (load.direction) values.direction = *load.direction;
    return std::make_unique<FollowerTraction>(c.mesh, load.name, load.surface.name, values,
                                              load.ramp, c.constraints);
  };
  d.ramps = load_ramps<S>;
  d.history = load_force_outputs();
  d.shell = true;
  return make_term_kind(std::move(d));
}

}  // namespace plisse
