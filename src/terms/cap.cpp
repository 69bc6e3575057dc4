// `caps:`: rigid end caps, nodes tied to a reference point that moves and turns
// (physics/rigid_cap.hpp).
#include <cmath>

#include "physics/rigid_cap.hpp"
#include "physics/rotation.hpp"
#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {

TermKind cap_kind() {
  using namespace term_keys;
  using schema::format_number;
  TermDefinition<Cap> d;
  d.section = "caps";
  Schema<Cap>& s = d.keys;
  s.place(&Cap::place, false);
  name_key(s, &Cap::name,
           "history columns `force_x:<name>` ... (the cap's force on the body, N), "
           "`moment_x:<name>` ... (its moment about the moved reference point, N mm), "
           "`ux:<name>` ... (the reference point's displacement) and `rx:<name>` ... (the "
           "rotation vector, rad)")
      .required();
  surface_key(s, "surface", &Cap::surface,
              "the nodes tied to the cap; on a shell an edge tag (the rim the cap closes) or a "
              "face tag")
      .required();
  s.add({"point",
         "vector",
         "mm",
         "",
         "mean of the nodes",
         {},
         "the reference point the cap moves and turns about"},
        [](const Field& f, Cap& c, ReadContext&) { c.point = f.vec3(); });
  s.add({"displacement",
         "list of 3 numbers or `~`",
         "mm",
         "",
         "[~, ~, ~]",
         {},
         "the reference point's displacement at the end of the ramp; `~` leaves a component "
         "free (loaded by `force`)"},
        [](const Field& f, Cap& c, ReadContext&) {
          c.displacement = optional_components(f, "displacements");
        });
  s.add({"rotation",
         "list of 3 numbers or `~`",
         "rad",
         "angle < 2π",
         "[~, ~, ~]",
         {},
         "rotation vector at the end of the ramp (axis times angle); `~` leaves a component "
         "free (loaded by `moment`)"},
        [](const Field& f, Cap& c, ReadContext&) {
          c.rotation = optional_components(f, "rotation components");
          double s2 = 0.0;
          for (const auto& r : c.rotation) s2 += r ? *r * *r : 0.0;
          if (!(std::sqrt(s2) < kMaxRotationAngle))
            f.fail("the rotation angle " + format_number(std::sqrt(s2)) +
                   " rad must be below 2π (a rotation vector cannot describe more)");
        });
  s.vec3("force", &Cap::force, "N",
         "force on the cap at the end of the ramp, on its free displacement components");
  s.vec3("moment", &Cap::moment, "N mm",
         "moment on the cap at the end of the ramp, on its free rotation components (work "
         "conjugate to the rotation vector: about a fixed axis, the moment about that axis)");
  ramp_key(s, &Cap::ramp, "time ramp of the prescribed motion, force and moment");
  s.rule("`force` and `moment` only on free components (`~` in `displacement`, `rotation`)",
         [](const FieldMap& m, const Cap& c, const ReadContext&) {
           const char* axes = "xyz";
           for (int k = 0; k < 3; ++k) {
             if (c.displacement[k] && c.force[k] != 0.0)
               m.require("force").fail(std::string("force component ") + axes[k] +
                                       " acts on a prescribed displacement: give `~` for it "
                                       "in `displacement`, or no force");
             if (c.rotation[k] && c.moment[k] != 0.0)
               m.require("moment").fail(std::string("moment component ") + axes[k] +
                                        " acts on a prescribed rotation: give `~` for it in "
                                        "`rotation`, or no moment");
           }
         });
  // On a shell the cap holds an edge tag's nodes (its rim) or a face tag's (caps.md, G8).
  d.check_mesh = [](const Cap& cap, const TermMeshCheck& check) { check.condition(cap.surface); };
  d.shell = true;
  // Its ramp matters once it moves, turns or pushes.
  d.ramps = [](const Cap& cap) {
    bool acts = !cap.force.isZero(0.0) || !cap.moment.isZero(0.0);
    for (int k = 0; k < 3; ++k)
      acts = acts || (cap.displacement[k] && *cap.displacement[k] != 0.0) ||
             (cap.rotation[k] && *cap.rotation[k] != 0.0);
    if (!acts) return std::vector<RampUse>{};
    return std::vector<RampUse>{{cap.ramp, "cap '" + cap.name + "'"}};
  };
  d.make = [](const Cap& cap, const TermContext& c) -> std::unique_ptr<ModelTerm> {
    return std::make_unique<RigidCap>(cap, c.mesh, c.constraints);
  };
  d.history = {
      {"force_x:<cap>", "N", "`caps[]`",
       "x component of the force the cap exerts on the body (likewise y, z)"},
      {"force_y:<cap>", "N", "`caps[]`", "y component of the cap's force on the body"},
      {"force_z:<cap>", "N", "`caps[]`", "z component of the cap's force on the body"},
      {"moment_x:<cap>", "N mm", "`caps[]`",
       "x component of the cap's moment on the body about its moved reference point (likewise y, "
       "z)"},
      {"moment_y:<cap>", "N mm", "`caps[]`", "y component of the cap's moment"},
      {"moment_z:<cap>", "N mm", "`caps[]`", "z component of the cap's moment"},
      {"ux:<cap>", "mm", "`caps[]`", "x displacement of the cap's reference point (likewise y, z)"},
      {"uy:<cap>", "mm", "`caps[]`", "y displacement of the cap's reference point"},
      {"uz:<cap>", "mm", "`caps[]`", "z displacement of the cap's reference point"},
      {"rx:<cap>", "rad", "`caps[]`", "x component of the cap's rotation vector (likewise y, z)"},
      {"ry:<cap>", "rad", "`caps[]`", "y component of the cap's rotation vector"},
      {"rz:<cap>", "rad", "`caps[]`", "z component of the cap's rotation vector"},
  };
  return make_term_kind(std::move(d));
}

}  // namespace plisse
