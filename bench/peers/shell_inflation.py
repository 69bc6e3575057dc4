"""Inflation of a thick neo-Hookean spherical shell by a follower pressure, in DOLFINx 0.5: the peer
side of bench/peer-shell, the same problem as bench/cases/peer-shell.yaml.

Units: mm, MPa (so forces in N), s.

The mesh (bench/peers/shell_mesh.py) is an octant of the shell RI = 10 <= |X| <= RO = 11 mm, the
material incompressible neo-Hookean with c1 [MPa] (mixed_solid.py). The cut planes x = 0, y = 0,
z = 0 (surfaces 11, 12, 13) hold the normal displacement at zero. The pressure p acts on the inner
surface (surface 1) in the deformed configuration, which adds to the residual
    int_inner p J F^-T N . v dA,      N the outward unit normal of the body in the reference mesh,
and rises in equal steps to its final value (default 0.95 of the limit pressure p_max of the
closed form). Each step is solved by Newton with MUMPS (mixed_solid.NewtonMumps) to rtol 1e-10 and
atol 1e-12 N.

The error of a step is (p - p(a)) / p(a), with p(a) the closed form of thick_sphere.py at the
radius a = RI + u_x of the mesh vertex (RI, 0, 0) on the inner surface.

Usage: /usr/bin/python3 bench/peers/shell_inflation.py --mesh FILE [--element mini|taylor-hood]
           [--pressure P] [--steps N] [--c1 C1] [--json FILE]
Prints one line per step and a summary; --json writes the same numbers for bench/peer-shell:
{"element", "mesh", "cells", "unknowns", "newton_iterations", "setup_s", "solve_s", "assembly_s",
 "linear_solve_s", "steps": [{"pressure", "radius", "closed_form_pressure", "error", "newton",
 "time_s"}, ...]}. Serial (one MPI process).
"""
import argparse
import json
import time

import gmsh
import numpy as np
import ufl
from dolfinx import fem
from dolfinx import mesh as dmesh
from dolfinx.io import gmshio
from mpi4py import MPI

import thick_sphere
from mixed_solid import ELEMENTS, NewtonMumps, mixed_space, n_unknowns, neo_hookean_residual
from thick_sphere import RI

INNER, PLANES = 1, (11, 12, 13)  # physical surfaces of shell_mesh.py
QUADRATURE_DEGREE = 4


def read_mesh(path):
    """The DOLFINx mesh and facet tags of a Gmsh file. Goes through the Gmsh model because
    gmshio.read_from_msh of Debian's DOLFINx 0.5.2 fails on every file (NameError in its return)."""
    gmsh.initialize()
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.open(path)
    mesh, _, facet_tags = gmshio.model_to_mesh(gmsh.model, MPI.COMM_SELF, 0, gdim=3)
    gmsh.finalize()
    return mesh, facet_tags


def symmetry_conditions(space, facet_tags):
    """u_i = 0 on the cut plane x_i = 0, for i = 0, 1, 2."""
    conditions = []
    for axis, plane in enumerate(PLANES):
        component = space.sub(0).sub(axis)
        dofs = fem.locate_dofs_topological(component, 2, facet_tags.find(plane))
        conditions.append(fem.dirichletbc(fem.Constant(space.mesh, 0.0), dofs, component))
    return conditions


def probe_dof(space):
    """The index, in the state's local array, of u_x at the mesh vertex (RI, 0, 0)."""
    mesh = space.mesh
    vertices = dmesh.locate_entities(
        mesh, 0, lambda x: np.isclose(x[0], RI) & np.isclose(x[1], 0.0) & np.isclose(x[2], 0.0))
    if len(vertices) != 1:
        raise SystemExit(f"shell_inflation: the mesh has {len(vertices)} vertices at ({RI}, 0, 0)")
    component = space.sub(0).sub(0)
    collapsed, _ = component.collapse()
    dofs = fem.locate_dofs_topological((component, collapsed), 0, vertices)[0]
    return int(dofs[0])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--mesh", required=True, help="Gmsh file of shell_mesh.py")
    parser.add_argument("--element", default="mini", choices=ELEMENTS)
    parser.add_argument("--pressure", type=float, help="final pressure [MPa] (default 0.95 p_max)")
    parser.add_argument("--steps", type=int, default=10, help="equal load steps")
    parser.add_argument("--c1", type=float, default=0.0033, help="neo-Hookean c1 [MPa]")
    parser.add_argument("--json", help="file to write the results to")
    args = parser.parse_args()
    start_of_run = time.perf_counter()
    final_pressure = args.pressure
    if final_pressure is None:
        final_pressure = 0.95 * thick_sphere.limit_pressure(args.c1)[0]

    mesh, facet_tags = read_mesh(args.mesh)
    space = mixed_space(mesh, args.element)
    state = fem.Function(space)
    residual, F, J = neo_hookean_residual(state, args.c1, QUADRATURE_DEGREE)
    pressure = fem.Constant(mesh, 0.0)
    v = ufl.TestFunctions(space)[0]
    N = ufl.FacetNormal(mesh)
    ds = ufl.Measure("ds", domain=mesh, subdomain_data=facet_tags,
                     metadata={"quadrature_degree": QUADRATURE_DEGREE})
    residual += pressure * J * ufl.dot(ufl.inv(F).T * N, v) * ds(INNER)
    newton = NewtonMumps(residual, state, symmetry_conditions(space, facet_tags))
    probe = probe_dof(space)
    cells = mesh.topology.index_map(3).size_global
    setup_s = time.perf_counter() - start_of_run
    print(f"mesh {args.mesh}, element {args.element}, {cells} tetrahedra, "
          f"{n_unknowns(space)} unknowns, set-up (mesh, forms) {setup_s:.2f} s", flush=True)
    print("step  p [MPa]       a [mm]     p(a) [MPa]    error of p  Newton  time [s]", flush=True)

    steps, solve_s, iterations = [], 0.0, 0
    for step in range(1, args.steps + 1):
        pressure.value = final_pressure * step / args.steps
        start = time.perf_counter()
        n_newton, _ = newton.solve(rtol=1e-10, atol=1e-12)
        elapsed = time.perf_counter() - start
        solve_s += elapsed
        iterations += n_newton
        p = float(pressure.value)
        a = RI + float(state.x.array[probe])
        exact = thick_sphere.pressure(a, args.c1)
        steps.append({"pressure": p, "radius": a, "closed_form_pressure": exact,
                      "error": (p - exact) / exact, "newton": n_newton, "time_s": elapsed})
        print(f"{step:4d}  {p:.6e}  {a:9.5f}  {exact:.6e}  {(p - exact) / exact:+.3e}  "
              f"{n_newton:6d}  {elapsed:8.2f}", flush=True)

    results = {"element": args.element, "mesh": args.mesh, "cells": cells,
               "unknowns": n_unknowns(space), "newton_iterations": iterations,
               "setup_s": setup_s, "solve_s": solve_s, "assembly_s": newton.assembly_time,
               "linear_solve_s": newton.linear_solve_time, "steps": steps}
    print(f"total: {iterations} Newton iterations, solve {solve_s:.2f} s (assembly "
          f"{newton.assembly_time:.2f} s, MUMPS {newton.linear_solve_time:.2f} s), "
          f"after the imports {time.perf_counter() - start_of_run:.2f} s", flush=True)
    if args.json:
        with open(args.json, "w") as out:
            json.dump(results, out, indent=1)


if __name__ == "__main__":
    main()
