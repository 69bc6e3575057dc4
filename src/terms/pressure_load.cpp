// `loads:` of type pressure: a follower pressure on a surface (physics/pressure_load.hpp).
#include "physics/pressure_load.hpp"

#include <algorithm>

#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {

TermKind pressure_load_kind() {
  using namespace term_keys;
  using S = PressureLoadSettings;
  TermDefinition<S> d;
  d.section = "loads";
  d.word = "pressure";
  d.summary = "a follower pressure on a surface";
  Schema<S>& s = d.keys;
  s.place(&S::place, false);
  load_name_key(s, &S::name);
  surface_key(s, "surface", &S::surface, "the loaded surface").required();
  s.real("value", &S::value, Range::any(), "MPa",
         "follower pressure at the end of the ramp; positive pushes against the outward normal "
         "of the body (inflates from `inner`)")
      .required();
  s.add({"caps",
         "list of names",
         "–",
         "names of `caps[]` entries, each tying a rim of the surface",
         "[]",
         {},
         "the caps that close the loaded surface's rims, so that the pressure pushes on them "
         "too, p times the area each rim encloses (a capped tube's end thrust); "
         "docs/theory/cavities.md, C14"},
        [](const Field& f, S& load, ReadContext&) {
          load.caps_place = f.place();
          for (const Field& item : f.items()) load.caps.push_back(item.name());
        });
  load_ramp_key(s, &S::ramp);
  d.check_mesh = [](const S& load, const TermMeshCheck& check) { check.surface(load.surface); };
  d.make = [](const S& load, const TermContext& c) -> std::unique_ptr<ModelTerm> {
    std::vector<CapNodes> caps;
    const std::vector<CapNodes> all = c.caps();
    for (const std::string& name : load.caps) {
      const auto cap = std::find_if(all.begin(), all.end(), [&](const CapNodes& candidate) {
        return candidate.name == name;
      });
      if (cap == all.end()) {
        std::vector<std::string> names;
        for (const CapNodes& candidate : all) names.push_back("'" + candidate.name + "'");
        throw InputError(load.caps_place,
                         "no cap is named '" + name + "'" +
                             (names.empty() ? std::string(" (the case has no caps)")
                                            : " (caps: " + schema::join(names) + ")"));
      }
      if (std::find_if(caps.begin(), caps.end(),
                       [&](const CapNodes& c2) { return c2.name == name; }) != caps.end())
        throw InputError(load.caps_place, "cap '" + name + "' is named twice");
      caps.push_back(*cap);
    }
    return std::make_unique<PressureLoad>(c.mesh, load.name, load.surface.name, load.value,
                                          load.ramp, c.constraints, c.mirrors, caps,
                                          load.caps_place);
  };
  d.ramps = load_ramps<S>;
  d.history = {
      {"pressure:<load>", "MPa", "`loads[]` of type pressure",
       "the pressure at t, `value` times its ramp; positive pushes against the body's outward "
       "normal (on a balloon's `inner` surface it inflates)"},
      {"volume:<load>", "mm³",
       "a pressure load whose surface is closed, or closed by the planes "
       "x = 0, y = 0, z = 0 and the caps of its `caps`",
       "the volume the loaded surface encloses in the deformed state (of the modelled part), "
       "positive; with `pressure:<load>` the pressure–volume curve"},
      {"full_volume:<load>", "mm³", "as `volume:<load>`, on a surface closed by mirror planes",
       "the whole body's: `volume:<load>` times 2 for each mirror plane (`symmetry` condition) "
       "that closes it"},
  };
  d.shell = true;
  return make_term_kind(std::move(d));
}

}  // namespace plisse
