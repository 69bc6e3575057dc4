// `dies:`: rigid analytic dies with prescribed motion, frictionless, sticking or with Coulomb
// friction (physics/die_contact.hpp, docs/theory/contact.md).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>

#include "core/error.hpp"
#include "physics/die_contact.hpp"
#include "physics/die_surface.hpp"
#include "physics/surface.hpp"
#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {
namespace {

const schema::Choices<DieShape> kDieShapes{
    {"plane", DieShape::plane}, {"sphere", DieShape::sphere}, {"cylinder", DieShape::cylinder}};
const schema::Choices<ContactKind> kContactKinds{{"frictionless", ContactKind::frictionless},
                                                 {"sticking", ContactKind::sticking},
                                                 {"coulomb", ContactKind::coulomb}};

/// The signed gap at t = 0 of the node of `triangles` farthest from the die on the side that
/// `worse` prefers (the most penetrating one: worse(a, b) = a < b; the farthest: |a| > |b|).
struct NodeGap {
  int node = -1;
  double g = 0.0;
};
template <class Worse>
NodeGap extreme_gap(const DieGeometry& geometry, const Mesh& mesh,
                    const std::vector<std::array<int, 3>>& triangles, Worse worse) {
  NodeGap extreme;
  for (const auto& t : triangles)
    for (const int v : t) {
      double g = 0.0;
      try {
        g = geometry.gap(mesh.nodes[v], 0.0).g;
      } catch (const Error&) {  // on a sphere's centre or a cylinder's axis: deep inside anyway
        g = -std::numeric_limits<double>::infinity();
      }
      if (extreme.node < 0 || worse(g, extreme.g)) extreme = {v, g};
    }
  return extreme;
}

/// Where a die starts (t = 0) against the body: no node of its contact surface may be inside it
/// (the first step would have to push the whole penetration out at once, and a deep one pulls the
/// body through the die), and a sticking region glued from the start must touch it, or the glue
/// would drag the region across the gap. "Inside" and "touching" allow the larger of the die's
/// tolerance and a tenth of the surface's mean edge length `h`. InputError at the die otherwise.
void check_die_start(const DieSettings& die, const DieGeometry& geometry, const Mesh& mesh,
                     const std::vector<std::array<int, 3>>& candidates,
                     const std::vector<std::array<int, 3>>& region, double h) {
  const auto where = [&](const NodeGap& n) {
    const Vec3d& x = mesh.nodes[n.node];
    char text[160];
    std::snprintf(text, sizeof text, "node %d at [%.6g, %.6g, %.6g]", n.node, x.x(), x.y(), x.z());
    return std::string(text);
  };
  const auto mm = [](double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g mm", value);
    return std::string(text);
  };
  // A die placed on the nominal geometry touches a faceted or generated surface only within a
  // fraction of an element: that much is taken as touching.
  const double allowed = std::max(die.tolerance, 0.1 * h);
  const NodeGap deepest =
      extreme_gap(geometry, mesh, candidates, [](double a, double b) { return a < b; });
  if (deepest.node >= 0 && deepest.g < -allowed)
    throw InputError(die.place,
                     "the die starts inside the body: " + where(deepest) +
                         " of its contact "
                         "surface is " +
                         (std::isfinite(deepest.g) ? mm(-deepest.g) : std::string("deep")) +
                         " inside it at t = 0 (at most " + mm(allowed) +
                         " is taken as touching); place the die outside the body");
  if (region.empty()) return;
  const NodeGap farthest = extreme_gap(
      geometry, mesh, region, [](double a, double b) { return std::abs(a) > std::abs(b); });
  if (farthest.node >= 0 && std::abs(farthest.g) > allowed)
    throw InputError(die.place, "the sticking region '" + die.region->name +
                                    "' is glued to the die from the start, but " + where(farthest) +
                                    " is " + mm(std::abs(farthest.g)) +
                                    " from it at t = 0 (at most " + mm(allowed) +
                                    " is taken as touching); place the die against the region");
}

/// Half the reference thickness of a shell's `candidates` [mm] (triangles of the shell, as node
/// triples in any order): how far the shell's faces lie from the mid-surface nodes that carry its
/// contact (contact.md, D23), each triangle's own (Mesh::triangle_thickness: a region's).
/// InputError at the die when the thickness varies over them, which the offset die does not
/// represent.
double half_shell_thickness(const DieSettings& die, const Mesh& mesh,
                            const std::vector<std::array<int, 3>>& candidates) {
  const std::vector<double> thickness = shell_thickness(mesh, candidates);
  const auto [lo, hi] = std::minmax_element(thickness.begin(), thickness.end());
  if (*hi - *lo > 1e-12 * *hi)
    throw InputError(die.place,
                     "the shell's thickness varies over the die's contact surface (from " +
                         std::to_string(*lo) + " to " + std::to_string(*hi) +
                         " mm): a die on a shell needs a uniform thickness there");
  return 0.5 * *hi;
}

/// The die that a shell's mid-surface nodes meet: `die` moved out by `offset` towards the body, so
/// that the gap of a mid-surface node is that of the shell's face (contact.md, D23). A plane's
/// point moves along its normal; a sphere's or cylinder's radius grows.
DieGeometry offset_die(const DieSettings& die, double offset) {
  Vec3d point = die.point;
  double radius = die.radius;
  if (die.shape == DieShape::plane)
    point += offset * die.normal;
  else
    radius += offset;
  return DieGeometry(die.shape, point, die.normal, die.axis, radius, die.displacement, die.ramp);
}

/// The contact term of `die`: candidates are the nodes of `die.surface`, or the context's default
/// faces; the penalty defaults to contact.md (D11) with the material's small-strain shear modulus.
/// On a shell the die meets the shell's faces, half the thickness from its nodes (D23).
/// Throws InputError (at the die) when the surface is empty.
std::unique_ptr<ModelTerm> make_die_term(const DieSettings& die, const TermContext& c) {
  const Mesh& mesh = c.mesh;
  const auto candidates =
      die.surface ? outward_triangles(mesh, die.surface->name) : c.default_die_faces();
  if (candidates.empty()) throw InputError(die.place, "the die's contact surface is empty");
  const auto region =
      die.region ? outward_triangles(mesh, die.region->name) : std::vector<std::array<int, 3>>{};
  const double h = mean_edge_length(mesh, candidates);
  DieContactSettings settings;
  settings.name = die.name;
  settings.contact = die.contact;
  settings.tolerance = die.tolerance;
  settings.friction = die.friction;
  settings.touch_slack = 1e-9 * h;
  settings.penalty = die.penalty > 0.0 ? die.penalty : default_die_penalty(c.shear_modulus(), h);
  const DieGeometry geometry =
      offset_die(die, mesh.is_shell() ? half_shell_thickness(die, mesh, candidates) : 0.0);
  check_die_start(die, geometry, mesh, candidates, region, h);
  return std::make_unique<DieContact>(mesh, geometry, settings, candidates, region, c.mirrors);
}

}  // namespace

TermKind die_kind() {
  using namespace term_keys;
  TermDefinition<DieSettings> d;
  d.section = "dies";
  Schema<DieSettings> move;
  move.vec3("displacement", &DieSettings::displacement, "mm",
            "displacement reached at the end of `ramp`");
  ramp_key(move, &DieSettings::ramp, "time ramp of the motion");

  Schema<DieSettings>& s = d.keys;
  s.place(&DieSettings::place, false);
  name_key(s, &DieSettings::name,
           "history columns `force_x:<name>`, `force_y:<name>`, `force_z:<name>` (force of the "
           "body on the die, N), `contact_nodes:<name>` (nodes in contact or glued), "
           "`penetration:<name>` (largest penetration, mm); Coulomb: `stick_nodes:<name>`, "
           "`slip_nodes:<name>`. Point fields in the step files: `contact_<name>` (0 free, 1 "
           "sliding, 2 sticking), `contact_pressure_<name>` (MPa per reference area), "
           "`gap_<name>` (signed gap to the die, mm)")
      .required();
  s.variant<DieShape>("shape", &DieSettings::shape, kDieShapes, "the die's surface").required();
  s.vec3("point", &DieSettings::point, "mm",
         "plane: a point of it; sphere: centre; cylinder: a point of the axis")
      .required();
  s.variant<ContactKind>("contact", &DieSettings::contact, kContactKinds,
                         "unilateral sliding contact; nodes that touch stay glued; or Coulomb "
                         "friction: a node sticks while its tangential traction is below "
                         "`friction` times its contact pressure, else slides");
  optional_surface_key(s, "surface", &DieSettings::surface,
                       "whole boundary except the faces on symmetry planes",
                       "candidate contact surface");
  s.nested_here("move", move)
      .when_absent([](const FieldMap&, DieSettings& d, ReadContext& context) {
        d.ramp = {0.0, context.end_time};  // a die without `move` stays put; its ramp is unused
      });
  s.real("penalty", &DieSettings::penalty, Range::non_negative(), "MPa/mm",
         "contact penalty; 0 chooses 10 μ / h (μ the small-strain shear modulus, h the mean edge "
         "length of the contact surface; docs/theory/contact.md, D11)");
  s.real("tolerance", &DieSettings::tolerance, Range::positive(), "mm",
         "allowed penetration (and, for a sticking node of a Coulomb die, tangential slip in "
         "a step): the augmented-Lagrangian multipliers are updated until no node exceeds it "
         "(at most `solver.max_augmentations` times per step)");
  s.add({"normal",
         "vector",
         "–",
         "non-zero",
         "",
         {"plane"},
         "normal pointing towards the body; normalised"},
        [](const Field& f, DieSettings& d, ReadContext&) { d.normal = unit_vector(f); })
      .required();
  s.add({"axis", "vector", "–", "non-zero", "", {"cylinder"}, "axis direction; normalised"},
        [](const Field& f, DieSettings& d, ReadContext&) { d.axis = unit_vector(f); })
      .required();
  s.real("radius", &DieSettings::radius, Range::positive(), "mm",
         "radius of the sphere or cylinder")
      .required()
      .applies({"sphere", "cylinder"});
  optional_surface_key(s, "region", &DieSettings::region, "none", "glued to the die from the start")
      .applies({"sticking"});
  s.real("friction", &DieSettings::friction, Range::non_negative(), "–",
         "Coulomb friction coefficient (0 slides without friction)")
      .required()
      .applies({"coulomb"});
  d.check_mesh = [](const DieSettings& die, const TermMeshCheck& check) {
    if (die.region) check.surface(*die.region);
    if (die.surface) check.surface(*die.surface);
  };
  d.make = make_die_term;
  d.shell = true;
  d.ramps = [](const DieSettings& die) {
    std::vector<RampUse> out;
    if (die.displacement != Vec3d::Zero())
      out.push_back({die.ramp, "the motion of die '" + die.name + "'"});
    return out;
  };
  d.history = {
      {"force_x:<die>", "N", "`dies[]`",
       "x component of the force of the body on the die (a die pushing down, −y, on a body has "
       "`force_y` > 0); of the modelled part (likewise `force_y`, `force_z`)"},
      {"force_y:<die>", "N", "`dies[]`", "y component of the force of the body on the die"},
      {"force_z:<die>", "N", "`dies[]`", "z component of the force of the body on the die"},
      {"full_force_x:<die>", "N", "`dies[]` symmetric about a mirror plane",
       "x component of the whole body's force on the die: its mirror images summed, 0 along a "
       "mirror plane's normal and doubled per plane along the others (likewise y, z; see "
       "Symmetry)"},
      {"full_force_y:<die>", "N", "as `full_force_x:<die>`",
       "y component of the whole body's force"},
      {"full_force_z:<die>", "N", "as `full_force_x:<die>`",
       "z component of the whole body's force"},
  };
  for (const OutputEntry& e : contact_state_outputs()) d.history.push_back(e);
  d.history.insert(
      d.history.end(),
      {
          {"stick_nodes:<die>", "–", "`dies[]` with `contact: coulomb`",
           "contact nodes that stick"},
          {"slip_nodes:<die>", "–", "`dies[]` with `contact: coulomb`", "contact nodes that slip"},
      });
  d.point_fields = {
      {"contact_<die>", "–", "`dies[]`",
       "the node's contact state with the die: 0 free, 1 sliding, 2 sticking"},
      {"contact_pressure_<die>", "MPa", "`dies[]`",
       "the normal part of the die's force on the node per reference area, positive pushing the "
       "body away from the die; 0 off the die's surface `dies[].surface`"},
      {"gap_<die>", "mm", "`dies[]`",
       "the signed normal distance from the die to the node, negative when it penetrates; 0 off "
       "the die's surface"},
  };
  return make_term_kind(std::move(d));
}

}  // namespace plisse
