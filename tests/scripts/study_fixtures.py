"""Synthetic run directories for the tests of scripts/plisse_study: the files plisse writes
(history.csv, summary.json, solution.pvd with step_NNNN.vtu, log.txt, wrinkle_spectrum.csv),
small enough to check by hand. Importing this module puts scripts/ on the import path."""
import json
import os
import sys

import numpy as np

SCRIPTS = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(
    __file__)))), "scripts")
sys.path.insert(0, SCRIPTS)


def write_history(run, header, rows, tail=""):
    """history.csv with `header` (a list of names) and `rows` (lists of values written as given);
    `tail` is appended as is (e.g. an unterminated line)."""
    os.makedirs(run, exist_ok=True)
    with open(os.path.join(run, "history.csv"), "w") as f:
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join(str(v) for v in r) + "\n")
        f.write(tail)


def write_summary(run, summary):
    os.makedirs(run, exist_ok=True)
    with open(os.path.join(run, "summary.json"), "w") as f:
        json.dump(summary, f)


def write_pvd(run, entries):
    """solution.pvd listing (time, file) entries."""
    os.makedirs(run, exist_ok=True)
    with open(os.path.join(run, "solution.pvd"), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n')
        for t, name in entries:
            f.write(f'  <DataSet timestep="{t}" part="0" file="{name}"/>\n')
        f.write("</Collection>\n</VTKFile>\n")


def write_vtu(path, points, cells, point_data=None, cell_data=None, kind="tetra"):
    """A VTU file of one block of cells of `kind` (meshio)."""
    import meshio

    mesh = meshio.Mesh(np.asarray(points, dtype=float), [(kind, np.asarray(cells))],
                       point_data=point_data or {},
                       cell_data={k: [np.asarray(v)] for k, v in (cell_data or {}).items()})
    meshio.write(path, mesh)


def write_steps(run, states):
    """step_NNNN.vtu for each (points, cells, point_data, cell_data) of `states` (step 0 first)
    and solution.pvd listing them at times 0, 1, 2, ..."""
    os.makedirs(run, exist_ok=True)
    entries = []
    for k, (points, cells, point_data, cell_data) in enumerate(states):
        name = f"step_{k:04d}.vtu"
        write_vtu(os.path.join(run, name), points, cells, point_data, cell_data)
        entries.append((float(k), name))
    write_pvd(run, entries)


def shell_octant(radius, thickness, n=8):
    """Nodes and tetrahedra of a part of a spherical shell's octant (x, y, z >= 0, latitude up to
    72 deg) of mid-surface `radius` and wall `thickness`: three spheres of nodes (inner, mid, outer) on an n x n grid of
    latitude and azimuth, each cell of two neighbouring spheres cut into prisms and those into 3
    tetrahedra. Returns (points, tets, mid) with `mid` the indices of the mid-surface nodes."""
    lat = np.linspace(0.0, 0.4 * np.pi, n)  # short of the pole, where the azimuths meet
    lon = np.linspace(0.0, 0.5 * np.pi, n)
    directions = []
    for a in lat:
        for b in lon:
            directions.append([np.cos(a) * np.cos(b), np.sin(a), np.cos(a) * np.sin(b)])
    directions = np.array(directions)
    radii = [radius - 0.5 * thickness, radius, radius + 0.5 * thickness]
    points = np.concatenate([r * directions for r in radii])
    m = len(directions)

    def node(layer, i, j):
        return layer * m + i * n + j

    tets = []
    for layer in range(2):
        for i in range(n - 1):
            for j in range(n - 1):
                for tri in ([(i, j), (i + 1, j), (i, j + 1)],
                            [(i + 1, j), (i + 1, j + 1), (i, j + 1)]):
                    a, b, c = (node(layer, *p) for p in tri)
                    d, e, f = (node(layer + 1, *p) for p in tri)
                    tets += [[a, b, c, d], [b, c, d, e], [c, d, e, f]]
    tets = np.array(tets)
    # Positive orientation (the order of the VTK tetrahedron): swap two nodes where it is not.
    p = points[tets]
    volume = np.einsum("ij,ij->i", np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), p[:, 3] - p[:, 0])
    tets[volume < 0] = tets[volume < 0][:, [1, 0, 2, 3]]
    return points, tets, np.arange(m, 2 * m)
