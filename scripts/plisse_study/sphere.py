"""The pressurised spherical shell of the indentation and squeeze studies: the thin sphere's
inflation, Vella et al.'s dimensionless pressure, the shell's mid-surface and its deflection.
The indented shell's runs (validation/pressurised-shell-*.yaml) have the die `indenter` and the
probe `mid` on the mid-surface pole.

Neo-Hookean wall of coefficient c1 [MPa], mid-surface radius R and thickness t [mm], pressure p
[MPa]; at small strain E = 6 c1 and nu = 1/2, so B = E t^3 / 9 and Y = E t.
"""
import argparse

import numpy as np

from . import runs


def inflated_stretch(pressure, c1, radius, thickness):
    """The stretch lambda of a thin neo-Hookean sphere under `pressure`, the root of
    p = (4 c1 t / R)(1/lambda - 1/lambda^7) below the limit point lambda = 7^(1/6) (bisection to
    machine precision). Stops the script (SystemExit) above the limit pressure."""
    f = lambda s: 4.0 * c1 * thickness / radius * (1.0 / s - s**-7) - pressure
    lo, hi = 1.0, 7.0 ** (1.0 / 6.0)
    if f(hi) < 0.0:
        raise SystemExit("pressure above the sphere's limit point")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) < 0.0 else (lo, mid)
    return 0.5 * (lo + hi)


def outer_pole(stretch, radius, thickness, shell=False):
    """Distance of the inflated sphere's outer pole from the centre: lambda R + t / (2 lambda^2)
    (the mid-surface stretched by lambda, the wall thinned to t / lambda^2, its volume kept). A
    shell (`element: shell`) meets a die with its face at half the reference thickness from the
    mid-surface (docs/theory/contact.md, D23): lambda R + t / 2."""
    return stretch * radius + 0.5 * thickness / (1.0 if shell else stretch**2)


def tau_of(pressure, c1, radius, thickness):
    """Vella et al.'s dimensionless pressure tau = p R^2 / (4 sqrt(B Y)) = p R^2 / (8 c1 t^2)."""
    return 3.0 * pressure * radius**2 / (4.0 * 6.0 * c1 * thickness**2)


def pressure_of(tau, c1, radius, thickness):
    """The pressure of a dimensionless pressure tau (tau_of inverted) [MPa]."""
    return tau * 4.0 * 6.0 * c1 * thickness**2 / (3.0 * radius**2)


def mid_surface(step_file):
    """(mid-surface radius, wall thickness) of a spherical shell centred at the origin, from the
    distances of the nodes of a step file (the undeformed one: step 0); of a shell's mid-surface
    (triangles), their mean and the cells' mean `thickness`."""
    state = runs.read_state(step_file)
    norm = np.linalg.norm(state.points, axis=1)
    if state.cells is None and "thickness" in state.mesh.cell_data:
        return float(norm.mean()), float(np.mean(state.mesh.cell_data["thickness"][0]))
    return 0.5 * (norm.max() + norm.min()), norm.max() - norm.min()


def is_shell_case(path):
    """Whether the case file at `path` says `element: shell`."""
    import yaml

    with open(path, encoding="utf-8") as f:
        return (yaml.safe_load(f) or {}).get("element") == "shell"


def before_contact(h, contact):
    """Index of the last row of the history columns `h` in which the die `contact` (a column
    contact_nodes:<die>) touches no node, or None when it touches in every row."""
    free = np.flatnonzero(h[contact] == 0)
    return int(free[-1]) if len(free) else None


def mid_surface_deflection(run, radius, step_file, contact="contact_nodes:indenter"):
    """(arc length from the pole, inward normal displacement since the inflated state, reference
    points) of the mid-surface nodes of `step_file`, in order of arc length; the inflated state is
    the last written step before the die `contact` touches (the last without contact nodes)."""
    h = runs.read_history(run)
    free = {int(s) for s, n in zip(h["step"], h[contact]) if n == 0}
    rest = [path for step, path in runs.written_steps(run, initial=True) if step in free][-1]
    a, b = runs.read_state(rest), runs.read_state(step_file)
    x = a.points
    norm = np.linalg.norm(x, axis=1)
    on_mid = np.abs(norm - radius) < 1e-6 * radius
    normal = x[on_mid] / norm[on_mid, None]
    du = b.displacement[on_mid] - a.displacement[on_mid]
    w = -(du * normal).sum(axis=1)
    arc = radius * np.arccos(np.clip(normal[:, 1], -1.0, 1.0))
    order = np.argsort(arc)
    return arc[order], w[order], x[on_mid][order]


def indented_history(run):
    """The history columns of an indented shell's run; stops the script when it has no step."""
    h = runs.read_history(run, required=True)
    if not h:
        raise SystemExit(f"{run}: history.csv has no steps")
    return h


def inflated_pole(run, h):
    """uy:mid of the last step before the indenter touches, from the history columns `h` of an
    indented shell's run: the inflated state the indentation w0 is measured from. Stops the
    script when the indenter never touched or touched from the start."""
    i = before_contact(h, "contact_nodes:indenter")
    if i is None or not (h["contact_nodes:indenter"] > 0).any():
        raise SystemExit(f"{run}: the indenter never touched (or touched from the start)")
    return float(h["uy:mid"][i])


def shell_geometry(run):
    """(mid-surface radius, wall thickness) of an indented shell's run, from its first step file;
    stops the script when it has none."""
    files = runs.step_files(run)
    if not files:
        raise SystemExit(f"{run}: no step files")
    return mid_surface(files[0])


def indentation_parser(doc, taus, radius, set_example):
    """The options of the indented-shell scripts: runs, --summary, --sweep with --taus and --set,
    --figures, and the shell's c1, mid-surface radius and wall thickness."""
    parser = argparse.ArgumentParser(description=doc.split("\n")[0])
    parser.add_argument("runs", nargs="*")
    parser.add_argument("--summary", action="store_true")
    parser.add_argument("--sweep", metavar="DIR")
    parser.add_argument("--taus", default=taus)
    parser.add_argument("--set", action="append", metavar="KEY=VALUE",
                        help=f"passed on to plisse run (e.g. {set_example})")
    parser.add_argument("--figures", metavar="DIR")
    parser.add_argument("--c1", type=float, default=1.0)
    parser.add_argument("--radius", type=float, default=radius, help="mid-surface radius [mm]")
    parser.add_argument("--thickness", type=float, default=1.0)
    parser.add_argument("--case", help="the case file --sweep runs (default: the study's solid "
                        "case; a case with `element: shell` has the one probe `mid`)")
    return parser
