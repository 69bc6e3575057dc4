// `boundary:` of type symmetry: zero displacement normal to a planar surface, a mirror plane of
// the model when it passes through the origin (physics/dirichlet.hpp); on a shell's edge also
// zero slope across the plane (docs/theory/shell.md, KL8a).
#include "mesh/shell_surface.hpp"
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
    check.condition(bc.surface);
    if (const std::vector<int>* edges = shell_edge_tag(check.mesh, bc.surface.name)) {
      if (shell_edge_plane_axis(check.mesh, *edges) < 0)
        throw InputError(bc.surface.place,
                         "symmetry edge '" + bc.surface.name +
                             "' must lie in a plane x, y or z = const that the shell crosses, "
                             "not one it lies in");
      return;
    }
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
  // On a shell's edge the surface meets the plane at a right angle (shell.md, KL8a).
  d.hold_slope = [](const S& bc, Mesh& mesh) {
    if (const std::vector<int>* edges = shell_edge_tag(mesh, bc.surface.name)) {
      const int axis = shell_edge_plane_axis(mesh, *edges);
      const int node = mesh.edges[static_cast<std::size_t>(edges->front())][0];
      mirror_sides(mesh, *edges, axis, mesh.nodes[static_cast<std::size_t>(node)][axis]);
    }
  };
  d.shell = true;
  // Across its own plane the reaction is internal to the whole body: no full_force columns.
  d.history = reaction_outputs(false);
  return make_term_kind(std::move(d));
}

}  // namespace plisse
