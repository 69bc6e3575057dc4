"""Gmsh mesh of one octant (x, y, z >= 0) of a thick spherical shell, for bench/peer-shell.

Units: mm. The shell has inner radius RI and outer radius RO (default 10 and 11 mm); the mesh has
linear tetrahedra of target size H everywhere (no refinement by curvature). Both programs of the
peer benchmark read the file this writes (MSH 2.2, ASCII), so they solve on the same mesh.

Physical groups (plisse reads a surface group k as the tag "2:k"):
  volume 1: the shell;
  surface 1: the inner sphere (where the pressure acts), surface 2: the outer sphere;
  surfaces 11, 12, 13: the cut planes x = 0, y = 0, z = 0 (symmetry).

Usage: /usr/bin/python3 bench/peers/shell_mesh.py --h H [--ri RI] [--ro RO] [-o FILE]
       (default FILE: shell_hH.msh in the current folder). Needs python3-gmsh.
Prints one line "tetrahedra N nodes M file FILE".
"""
import argparse

import gmsh

INNER, OUTER, PLANE_X, PLANE_Y, PLANE_Z = 1, 2, 11, 12, 13


def octant_of_shell(ri, ro):
    """Builds the solid {ri <= |x| <= ro, x, y, z >= 0} with OpenCASCADE; returns its volumes."""
    occ = gmsh.model.occ
    outer = occ.addSphere(0.0, 0.0, 0.0, ro)
    inner = occ.addSphere(0.0, 0.0, 0.0, ri)
    hollow, _ = occ.cut([(3, outer)], [(3, inner)])
    box = occ.addBox(0.0, 0.0, 0.0, ro, ro, ro)
    octant, _ = occ.intersect(hollow, [(3, box)])
    occ.synchronize()
    return [tag for _, tag in octant]


def surface_group(tag, ri, ro):
    """The physical group of a boundary surface, told apart by its bounding box [mm]: a cut plane
    is flat in one coordinate; of the two spherical caps, the inner one reaches at most ri."""
    box = gmsh.model.getBoundingBox(2, tag)
    low, high = box[:3], box[3:]
    tolerance = 1e-6 * ro
    for axis, group in enumerate((PLANE_X, PLANE_Y, PLANE_Z)):
        if high[axis] - low[axis] < tolerance:
            return group
    reach = max(high)
    return INNER if abs(reach - ri) < abs(reach - ro) else OUTER


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--h", type=float, required=True, help="element size [mm]")
    parser.add_argument("--ri", type=float, default=10.0, help="inner radius [mm]")
    parser.add_argument("--ro", type=float, default=11.0, help="outer radius [mm]")
    parser.add_argument("-o", "--output", help="mesh file to write (default shell_hH.msh)")
    args = parser.parse_args()
    output = args.output or f"shell_h{args.h:g}.msh"

    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    volumes = octant_of_shell(args.ri, args.ro)
    groups = {INNER: [], OUTER: [], PLANE_X: [], PLANE_Y: [], PLANE_Z: []}
    for _, tag in gmsh.model.getEntities(2):
        groups[surface_group(tag, args.ri, args.ro)].append(tag)
    gmsh.model.addPhysicalGroup(3, volumes, 1)
    for group, tags in groups.items():
        if not tags:
            raise SystemExit(f"shell_mesh: no surface found for physical group {group}")
        gmsh.model.addPhysicalGroup(2, tags, group)

    gmsh.option.setNumber("Mesh.MeshSizeMin", args.h)
    gmsh.option.setNumber("Mesh.MeshSizeMax", args.h)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
    gmsh.model.mesh.generate(3)
    gmsh.option.setNumber("Mesh.MshFileVersion", 2.2)
    gmsh.write(output)
    n_tetrahedra = len(gmsh.model.mesh.getElementsByType(4)[0])
    n_nodes = len(gmsh.model.mesh.getNodes()[0])
    gmsh.finalize()
    print(f"tetrahedra {n_tetrahedra} nodes {n_nodes} file {output}")


if __name__ == "__main__":
    main()
