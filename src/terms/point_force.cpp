// `loads:` of type point-force: a dead force on the node nearest a point (physics/dead_load.hpp).
#include <cstdio>

#include "mesh/topology.hpp"
#include "physics/dead_load.hpp"
#include "terms/keys.hpp"
#include "terms/term_kind.hpp"

namespace plisse {
namespace {

using schema::format_number;

/// The force acts on the node nearest its point: a point farther from that node than the longest
/// edge there lies off the body (a wrong coordinate or unit), and is refused.
void check_point_on_body(const PointForceSettings& load, const Mesh& mesh) {
  const int v = nearest_node(mesh, load.point);
  const double distance = (mesh.nodes[v] - load.point).norm();
  const double longest = longest_edge_at(mesh, v);
  if (distance > longest)
    throw InputError(load.point_place,
                     "point-force '" + load.name + "': the point " +
                         schema::format_vector(load.point) + " is " + format_number(distance) +
                         " mm from the nearest node " + schema::format_vector(mesh.nodes[v]) +
                         ", farther than the longest edge there (" + format_number(longest) +
                         " mm): give a point on the body");
}

}  // namespace

TermKind point_force_kind() {
  using namespace term_keys;
  using S = PointForceSettings;
  TermDefinition<S> d;
  d.section = "loads";
  d.word = "point-force";
  d.summary = "a dead force on the node nearest a point";
  Schema<S>& s = d.keys;
  s.place(&S::place, false);
  load_name_key(s, &S::name);
  s.add({"force",
         "vector",
         "N",
         "",
         "",
         {},
         "the force on the node nearest `point` at the end of the ramp (required); dead, "
         "non-zero"},
        [](const Field& f, S& load, ReadContext&) { load.force = non_zero_vector(f); });
  s.add({"point",
         "vector",
         "mm",
         "",
         "",
         {},
         "where the force acts: on the mesh node nearest this point of the undeformed body "
         "(refused when farther from it than the longest edge at that node, or when the boundary "
         "conditions prescribe every component the force pushes along there)"},
        [](const Field& f, S& load, ReadContext&) {
          load.point = f.vec3();
          load.point_place = f.place();
        })
      .required();
  load_ramp_key(s, &S::ramp);
  s.rule("a point-force load needs `force`",
         [](const FieldMap& m, const S& load, const ReadContext&) {
           if (!load.force) m.require("force");
         });
  d.check_mesh = [](const S& load, const TermMeshCheck& check) {
    check_point_on_body(load, check.mesh);
  };
  d.make = [](const S& load, const TermContext& c) -> std::unique_ptr<ModelTerm> {
    std::vector<NodalForce> forces{{nearest_node(c.mesh, load.point), *load.force}};
    refuse_load_on_held_nodes(forces, c.constraints, c.mesh, load.point_place,
                              "point-force '" + load.name + "'");
    return std::make_unique<DeadLoad>(load.name, std::move(forces), load.ramp);
  };
  d.ramps = load_ramps<S>;
  d.notes = [](const S& load, const Mesh& mesh) {
    const int v = nearest_node(mesh, load.point);
    const Vec3d& x = mesh.nodes[v];
    char line[256];
    std::snprintf(line, sizeof line,
                  "load '%s': on node %d at [%.6g, %.6g, %.6g], %.3g mm from its point",
                  load.name.c_str(), v, x.x(), x.y(), x.z(), (x - load.point).norm());
    return std::vector<std::string>{line};
  };
  d.history = load_force_outputs();
  d.shell = true;
  return make_term_kind(std::move(d));
}

}  // namespace plisse
