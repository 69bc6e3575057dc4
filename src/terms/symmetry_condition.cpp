// `boundary:` of type symmetry: zero displacement normal to a planar surface, a mirror plane of
// the model when it passes through the origin (physics/dirichlet.hpp).
#include "physics/boundary_condition.hpp"
#include "physics/dirichlet.hpp"
#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {

TermKind symmetry_condition_kind() {
  using namespace term_keys;
  using S = SurfaceConditionSettings;
  TermDefinition<S> d;
  d.section = "boundary";
  d.word = "symmetry";
  d.summary = "zero normal displacement (the surface must be planar)";
  Schema<S>& s = d.keys;
  s.place(&S::place, false);
  condition_keys(s, &S::name, &S::surface);
  d.check_mesh = [](const S& bc, const TermMeshCheck& check) {
    check.surface(bc.surface);
    const Planarity p = planarity(check.mesh, check.mesh.surface_tags.at(bc.surface.name));
    if (p.deviation > p.tolerance)
      throw InputError(
          bc.surface.place,
          "symmetry surface '" + bc.surface.name + "' is not planar: its nodes lie up to " +
              schema::format_number(p.deviation) + " mm from their best-fit plane (tolerance " +
              schema::format_number(p.tolerance) +
              " mm = " + schema::format_number(kPlanarityTolerance) + " x mean edge length)");
  };
  d.constrain = [](const S& bc, const Mesh& mesh, ConstraintSet& set) {
    hold_in_plane(mesh, bc.surface, set);
  };
  d.surface = [](const S& bc) { return bc.surface; };
  d.mirror = true;
  // Across its own plane the reaction is internal to the whole body: no full_force columns.
  d.history = reaction_outputs(false);
  return make_term_kind(std::move(d));
}

}  // namespace plisse
