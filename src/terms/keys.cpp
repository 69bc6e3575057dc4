#include "terms/keys.hpp"

#include <cmath>
#include <set>
#include <utility>

namespace plisse::term_keys {

using schema::format_number;

const std::string load_curve_help =
    "; a list of points [[t, factor], ...] is a load curve instead: the factor joins them "
    "linearly and holds the first and last values outside (load, hold, unload, cycles)";

void refuse_load_on_held_nodes(const std::vector<NodalForce>& forces,
                               const std::vector<ConstrainedComponent>& constraints,
                               const Mesh& mesh, const InputPlace& place, const std::string& what) {
  std::set<std::pair<int, int>> held;
  for (const ConstrainedComponent& c : constraints) held.emplace(c.node, c.component);
  double largest = 0.0;
  for (const NodalForce& f : forces) largest = std::max(largest, f.force.cwiseAbs().maxCoeff());
  if (!(largest > 0.0)) return;
  const char* const axes = "xyz";
  std::string first;
  for (const NodalForce& f : forces)
    for (int k = 0; k < 3; ++k) {
      // Round-off of a force along an axis (a tilted face's traction) does not count.
      if (std::abs(f.force[k]) <= 1e-12 * largest) continue;
      if (held.count({f.node, k}) == 0) return;
      if (first.empty()) {
        std::string components;
        for (int j = 0; j < 3; ++j)
          if (std::abs(f.force[j]) > 1e-12 * largest)
            components += std::string(components.empty() ? "" : ", ") + axes[j];
        first = "node " + std::to_string(f.node + 1) + " (1-based) at " +
                schema::format_vector(mesh.nodes[static_cast<std::size_t>(f.node)]) + ", " +
                components;
      }
    }
  throw InputError(place, what +
                              ": every component it pushes along is prescribed by the boundary "
                              "conditions (" +
                              first + (forces.size() > 1 ? ", and the others alike" : "") +
                              "): it would do no work and the supports would take it; load "
                              "a free node or surface, or leave the load out");
}

SurfaceRef surface_ref(const Field& f) {
  const std::string name = f.text();
  if (name.empty()) f.fail("a surface tag name must not be empty");
  return {name, f.place()};
}

Vec3d non_zero_vector(const Field& f) {
  const Vec3d v = f.vec3();
  if (v.isZero(0.0)) f.fail("must not be the zero vector (leave the load out instead)");
  return v;
}

Vec3d unit_vector(const Field& f) {
  const Vec3d v = f.vec3();
  const double norm = v.norm();
  if (!(norm > 0.0) || !std::isfinite(norm))
    f.fail("must be a non-zero direction (its length is 0)");
  return v / norm;
}

Ramp read_ramp(const Field& f) {
  if (f.node().IsSequence() && f.node().size() > 0 && f.node()[0].IsSequence()) {
    Ramp ramp;
    const std::vector<Field> points = f.items();
    if (points.size() < 2)
      f.fail("a load curve needs at least 2 points [t, factor], got " + f.describe());
    for (const Field& point : points) {
      if (!point.node().IsSequence() || point.node().size() != 2)
        point.fail("expected a point [t, factor] of 2 numbers, got " + point.describe());
      const std::vector<double> p = point.reals();
      if (p[0] < 0.0) point.fail("the time must be >= 0 (got " + format_number(p[0]) + ")");
      if (!ramp.table.empty() && !(p[0] > ramp.table.back()[0]))
        point.fail("the times must increase: " + format_number(p[0]) + " follows " +
                   format_number(ramp.table.back()[0]));
      ramp.table.push_back({p[0], p[1]});
    }
    ramp.start = ramp.table.front()[0];
    ramp.end = ramp.table.back()[0];
    return ramp;
  }
  if (!f.node().IsSequence() || f.node().size() != 2)
    f.fail(
        "expected a list of 2 numbers [start, end] in s, or a load curve [[t, factor], ...], "
        "got " +
        f.describe());
  const std::vector<double> t = f.reals();
  if (t[0] < 0.0) f.fail("ramp start must be >= 0 (got " + format_number(t[0]) + ")");
  if (!(t[1] > t[0]))
    f.fail("ramp end must be > start (got [" + format_number(t[0]) + ", " + format_number(t[1]) +
           "])");
  return {t[0], t[1]};
}

std::array<std::optional<double>, 3> optional_components(const Field& f, const std::string& what) {
  if (!f.node().IsSequence() || f.node().size() != 3)
    f.fail("expected a list of 3 " + what + ", ~ for a free component, got " + f.describe());
  std::array<std::optional<double>, 3> out;
  const std::vector<Field> items = f.items();
  for (int k = 0; k < 3; ++k)
    if (!items[k].is_null()) out[k] = items[k].real();
  return out;
}

std::vector<OutputEntry> reaction_outputs(bool whole) {
  std::vector<OutputEntry> out = {
      {"force_x:<boundary>", "N", "`boundary[]` with a `name`",
       "x component of the reaction: the force the condition exerts on the body, summed over the "
       "constrained components of its surface's nodes (a mirror plane holding a pressurised "
       "octant pulls it, negative along the plane's outward normal; likewise y, z)"},
      {"force_y:<boundary>", "N", "`boundary[]` with a `name`", "y component of the reaction"},
      {"force_z:<boundary>", "N", "`boundary[]` with a `name`", "z component of the reaction"},
      {"moment_x:<boundary>", "N mm", "`boundary[]` with a `name`",
       "x component of the reaction's moment about the origin: the sum over the condition's "
       "nodes of x × R, x the node's current position and R its reaction (a clamp's bending "
       "moment when the origin lies on the clamped section; likewise y, z)"},
      {"moment_y:<boundary>", "N mm", "`boundary[]` with a `name`",
       "y component of the reaction's moment about the origin"},
      {"moment_z:<boundary>", "N mm", "`boundary[]` with a `name`",
       "z component of the reaction's moment about the origin"},
  };
  if (!whole) return out;
  out.insert(out.end(),
             {
                 {"full_force_x:<boundary>", "N",
                  "`boundary[]` with a `name`, not `symmetry`, whose surface reaches a mirror "
                  "plane",
                  "x component of the whole body's reaction on the condition, which continues "
                  "across the plane: the mirror images summed (likewise y, z; see Symmetry)"},
                 {"full_force_y:<boundary>", "N", "as `full_force_x:<boundary>`",
                  "y component of the whole body's reaction"},
                 {"full_force_z:<boundary>", "N", "as `full_force_x:<boundary>`",
                  "z component of the whole body's reaction"},
                 {"full_moment_x:<boundary>", "N mm", "as `full_force_x:<boundary>`",
                  "x component of the whole body's reaction moment about the origin: the mirror "
                  "images summed, which leaves twice the component normal to the plane (likewise "
                  "y, z; see Symmetry)"},
                 {"full_moment_y:<boundary>", "N mm", "as `full_force_x:<boundary>`",
                  "y component of the whole body's reaction moment"},
                 {"full_moment_z:<boundary>", "N mm", "as `full_force_x:<boundary>`",
                  "z component of the whole body's reaction moment"},
             });
  return out;
}

std::vector<OutputEntry> load_force_outputs() {
  return {
      {"load_x:<load>", "N", "`loads[]` of types traction, point-force, follower-traction",
       "x component of the load's total force on the body at t (likewise `load_y`, `load_z`)"},
      {"load_y:<load>", "N", "as `load_x:<load>`", "y component of the load's total force"},
      {"load_z:<load>", "N", "as `load_x:<load>`", "z component of the load's total force"},
      {"work:<load>", "mJ", "as `load_x:<load>`",
       "work done by the load on the body since t = 0 (N mm = mJ; trapezoidal in the steps, exact "
       "while the load is held)"},
  };
}

std::vector<OutputEntry> contact_state_outputs() {
  return {
      {"contact_nodes:<die>", "–", "`dies[]`, `contacts[]`",
       "surface nodes in contact (or glued, for a sticking die) at the converged state"},
      {"penetration:<die>", "mm", "`dies[]`, `contacts[]`",
       "largest penetration of a node into the die (or the other surface); at most the contact "
       "`tolerance` once converged"},
  };
}

}  // namespace plisse::term_keys
