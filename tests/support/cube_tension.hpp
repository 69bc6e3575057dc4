#pragma once
/// The constraints of the cube tension test on a generated cube (tags sym_x, sym_y, sym_z, top):
/// symmetry planes x = 0, y = 0, z = 0 and the top face's uz prescribed, ramped over t in [0, 1].
#include <set>
#include <string>
#include <vector>

#include "mesh/mesh.hpp"
#include "physics/dirichlet.hpp"

namespace plisse::test {

/// `top_uz` [mm]: the displacement of the top face at t = 1 (stretch 1 + top_uz / edge).
inline std::vector<ConstrainedComponent> cube_tension_constraints(const Mesh& mesh, double top_uz) {
  std::vector<ConstrainedComponent> constraints;
  const auto constrain = [&](const std::string& tag, int component, double value) {
    std::set<int> nodes;
    for (int t : mesh.surface_tags.at(tag))
      for (int v : mesh.triangles[t]) nodes.insert(v);
    for (int v : nodes) constraints.push_back({v, component, value, Ramp{0.0, 1.0}});
  };
  constrain("sym_x", 0, 0.0);
  constrain("sym_y", 1, 0.0);
  constrain("sym_z", 2, 0.0);
  constrain("top", 2, top_uz);
  return constraints;
}

}  // namespace plisse::test
