// `contacts:`: contact between two tagged surfaces of the body, or of one surface with itself
// (physics/surface_contact.hpp, docs/theory/surface-contact.md); on a shell, between faces of the
// shell, half its thickness off the mid-surface (N14).
#include "physics/surface_contact.hpp"

#include "physics/die_contact.hpp"
#include "physics/die_surface.hpp"
#include "physics/surface.hpp"
#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {
namespace {

/// The term of a `contacts:` item; penalty and search distance default to the surfaces' mean
/// edge length h (surface-contact.md, N8): the penalty the dies' 10 mu / h (contact.md, D11) with
/// the material's small-strain shear modulus.
std::unique_ptr<ModelTerm> make_surface_contact_term(const ContactPairSettings& pair,
                                                     const TermContext& c) {
  const Mesh& mesh = c.mesh;
  const bool self = pair.self.has_value();
  const auto first = outward_triangles(mesh, self ? pair.self->name : pair.first->name);
  const auto second = self ? first : outward_triangles(mesh, pair.second->name);
  std::vector<std::array<int, 3>> both = first;
  if (!self) both.insert(both.end(), second.begin(), second.end());
  const double h = mean_edge_length(mesh, both);
  SurfaceContactSettings settings;
  settings.name = pair.name;
  settings.tolerance = pair.tolerance;
  settings.penalty = pair.penalty > 0.0 ? pair.penalty : default_die_penalty(c.shear_modulus(), h);
  settings.search_distance = pair.search_distance > 0.0 ? pair.search_distance : h;
  return std::make_unique<SurfaceContact>(mesh, settings, first, second, self);
}

}  // namespace

TermKind surface_contact_kind() {
  using namespace term_keys;
  TermDefinition<ContactPairSettings> d;
  d.section = "contacts";
  using Pair = ContactPairSettings;
  Schema<Pair>& s = d.keys;
  s.place(&Pair::place, false);
  name_key(
      s, &Pair::name,
      "history columns `force_x:<name>`, `force_y:<name>`, `force_z:<name>` (force of the "
      "second surface on the first, N), `contact_nodes:<name>`, `penetration:<name>` "
      "(largest penetration, mm); point field `contact_<name>` (contact pressure per reference "
      "area at the nodes of the first surface, MPa)")
      .required();
  s.add({"surfaces",
         "list of 2 surface tags",
         "–",
         "two different tags",
         "",
         {},
         "the nodes of the first surface are kept out of the faces of the second (give the more "
         "finely meshed one first)"},
        [](const Field& f, Pair& p, ReadContext&) {
          if (!f.node().IsSequence() || f.node().size() != 2)
            f.fail("expected a list of 2 surface tags, got " + f.describe());
          const std::vector<Field> items = f.items();
          p.first = surface_ref(items[0]);
          p.second = surface_ref(items[1]);
          if (p.first->name == p.second->name)
            items[1].fail(
                "names the surface '" + p.first->name +
                "' twice: for contact of a surface with itself give `self: " + p.first->name + "`");
        });
  optional_surface_key(s, "self", &Pair::self, "none",
                       "a surface in contact with itself (folds, faces pressed together)");
  s.rule("exactly one of `surfaces` and `self`",
         [](const FieldMap& m, const Pair&, const ReadContext&) {
           if (m.has("surfaces") && m.has("self"))
             m.require("self").fail_at_key("give `surfaces` or `self`, not both");
           if (!m.has("surfaces") && !m.has("self"))
             m.self().fail_at_key("give `surfaces: [first, second]` or `self: <surface>`");
         });
  s.real("penalty", &Pair::penalty, Range::non_negative(), "MPa/mm",
         "contact penalty; 0 chooses 10 μ / h (μ the small-strain shear modulus, h the mean edge "
         "length of the surfaces; docs/theory/surface-contact.md)");
  s.real("tolerance", &Pair::tolerance, Range::positive(), "mm",
         "allowed penetration: the multipliers are updated until no node penetrates more (at "
         "most `solver.max_augmentations` times per step)");
  s.real("search_distance", &Pair::search_distance, Range::non_negative(), "mm",
         "a node pairs with a face when it lies within this distance of the face's plane; 0 "
         "chooses the mean edge length of the surfaces. A node that penetrates deeper in one "
         "Newton iteration is not seen");
  d.check_mesh = [](const Pair& p, const TermMeshCheck& check) {
    for (const auto* ref : {&p.first, &p.second, &p.self})
      if (*ref) check.surface(**ref);
  };
  d.make = make_surface_contact_term;
  d.shell = true;
  d.history = contact_state_outputs();
  d.history.insert(
      d.history.end(),
      {
          {"force_x:<contact>", "N", "`contacts[]`",
           "x component of the force of the second surface on the first (likewise y, z); a "
           "self-contact "
           "reports the force across it"},
          {"force_y:<contact>", "N", "`contacts[]`", "as `force_x:<contact>`, y component"},
          {"force_z:<contact>", "N", "`contacts[]`", "as `force_x:<contact>`, z component"},
      });
  d.point_fields = {
      {"contact_<contact>", "MPa", "`contacts[]`",
       "the contact pressure per reference area at the nodes of the first surface"},
  };
  return make_term_kind(std::move(d));
}

}  // namespace plisse
