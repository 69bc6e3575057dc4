// `cavities:`: a closed surface (or one closed by symmetry planes) enclosing a fluid, at a
// prescribed volume or as an ideal gas (physics/cavity.hpp).
#include "physics/cavity.hpp"

#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {
namespace {

const schema::Choices<CavityControl> kCavityControls{{"volume", CavityControl::volume},
                                                     {"gas", CavityControl::gas}};

}  // namespace

TermKind cavity_kind() {
  using namespace term_keys;
  TermDefinition<Cavity> d;
  d.section = "cavities";
  Schema<Cavity>& s = d.keys;
  s.place(&Cavity::place, false);
  name_key(s, &Cavity::name,
           "history columns `volume:<name>`, `pressure:<name>`, and `full_volume:<name>` on a "
           "model cut by symmetry planes (docs/output.md)")
      .required();
  surface_key(s, "surface", &Cavity::surface,
              "the cavity's wall: closed, or closed by symmetry planes and by the caps that tie "
              "its rims (a capped tube's `inner`; the gas then pushes on the caps too)")
      .required();
  s.variant<CavityControl>("control", &Cavity::control, kCavityControls,
                           "prescribed volume, or an ideal gas");
  ramp_key(s, &Cavity::ramp, "time ramp of the volume or the mass ratio");
  const auto target = [](VolumeTarget which, double Cavity::*member, Range range) {
    return [=](const Field& f, Cavity& c, ReadContext&) {
      c.*member = f.real(range);
      c.target = which;
      c.target_place = f.place();
    };
  };
  s.add({"volume_ratio",
         "number",
         "–",
         Range::positive().describe(),
         "1",
         {"volume"},
         "V(end of ramp) / V0; the default 1 holds the initial volume"},
        target(VolumeTarget::ratio, &Cavity::volume_ratio, Range::positive()));
  s.add({"volume",
         "number",
         "mm³",
         Range::positive().describe(),
         "",
         {"volume"},
         "V at the end of the ramp, absolute"},
        target(VolumeTarget::absolute, &Cavity::volume, Range::positive()));
  s.add({"volume_change",
         "number",
         "mm³",
         "",
         "",
         {"volume"},
         "V(end of ramp) − V0: what a cavity that starts flat (V0 = 0, e.g. under a clamped "
         "sheet) takes in; non-zero"},
        target(VolumeTarget::change, &Cavity::volume_change, Range::any()));
  s.rule("at most one of `volume_ratio`, `volume` and `volume_change`",
         [](const FieldMap& m, const Cavity&, const ReadContext&) {
           const std::vector<std::string> keys = {"volume_ratio", "volume", "volume_change"};
           std::vector<std::string> given;
           for (const std::string& key : keys)
             if (m.has(key)) given.push_back(key);
           if (given.size() > 1)
             m.require(given[1]).fail_at_key(
                 "give one of `volume_ratio`, `volume` and "
                 "`volume_change`, not both `" +
                 given[0] + "` and `" + given[1] + "`");
           if (const auto f = m.find("volume_change"); f && f->real() == 0.0)
             f->fail("must not be 0 (leave it out to hold the initial volume)");
         });
  s.real("initial_pressure", &Cavity::initial_pressure, Range::non_negative(), "MPa",
         "gauge pressure of the gas at t = 0, at the undeformed cavity volume (it fixes the "
         "amount of gas)")
      .applies({"gas"});
  s.real("mass_ratio", &Cavity::mass_ratio, Range::positive(), "–",
         "gas mass at end of ramp / initial mass")
      .applies({"gas"});
  s.real("ambient_pressure", &Cavity::ambient_pressure, Range::positive(), "MPa",
         "absolute ambient pressure")
      .applies({"gas"});
  s.real("gamma", &Cavity::gamma, Range::at_least(1.0), "–",
         "polytropic exponent: (p + p_amb) (V_gas / m)^gamma stays constant; 1 isothermal (slow "
         "loading), 1.4 adiabatic air (fast: an impact on an airbag)")
      .applies({"gas"});
  s.real("reservoir_volume", &Cavity::reservoir_volume, Range::non_negative(), "mm³",
         "a rigid volume the gas fills as well (a tank, a pipe, an inflator), of the whole body: a "
         "symmetric model's part holds its share")
      .applies({"gas"});
  d.check_mesh = [](const Cavity& cavity, const TermMeshCheck& check) {
    check.surface(cavity.surface);
  };
  d.make = [](const Cavity& cavity, const TermContext& c) -> std::unique_ptr<ModelTerm> {
    return std::make_unique<CavityTerm>(cavity, c.mesh, c.constraints, c.mirrors, c.caps(),
                                        c.imperfection);
  };
  d.history = {
      {"pressure:<cavity>", "MPa", "`cavities[]`",
       "the cavity's gauge pressure (gas law, or the multiplier of a prescribed volume); positive "
       "pushes the wall away from the cavity"},
      {"volume:<cavity>", "mm³", "`cavities[]`",
       "the cavity's volume in the deformed state, of the modelled part (an octant holds V/8)"},
      {"full_volume:<cavity>", "mm³", "`cavities[]` closed by mirror planes",
       "the whole cavity's volume: `volume:<cavity>` times 2 for each mirror plane (`symmetry` "
       "condition) that closes it"},
  };
  d.shell = true;
  return make_term_kind(std::move(d));
}

}  // namespace plisse
