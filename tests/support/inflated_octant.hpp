#pragma once
// The small case the run-directory tests run: an octant of a neo-Hookean spherical shell
// (c1 = 0.5 MPa) on its three symmetry planes, inflated by 0.02 MPa on `inner`, MINI elements.
#include <string>

namespace plisse::test {

/// `mesh_line` (the `mesh:` entry, YAML text ending in a newline), then `element: mini`, the
/// material, the symmetry planes and the pressure, then `rest` (solver, output, ...).
inline std::string inflated_octant_case(const std::string& mesh_line, const std::string& rest) {
  return mesh_line +
         "element: mini\n"
         "material: {model: neo-hookean, c1: 0.5}\n"
         "boundary:\n"
         "  - {type: symmetry, surface: sym_x}\n"
         "  - {type: symmetry, surface: sym_y}\n"
         "  - {type: symmetry, surface: sym_z}\n"
         "loads:\n"
         "  - {type: pressure, name: p, surface: inner, value: 0.02}\n" +
         rest;
}

/// The generated octant: inner radius 10 mm, thickness 1 mm, one layer, edges of 4 mm.
inline const std::string kSmallOctantMesh =
    "mesh: {generate: spherical-shell, inner_radius: 10.0, thickness: 1.0, layers: 1,\n"
    "       element_size: 4.0, symmetry: octant}\n";

}  // namespace plisse::test
