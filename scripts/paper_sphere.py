"""Where the paper's pressurised sphere wrinkles under a plate: runs and reads
validation/paper-sphere-squeeze.yaml over the dimensionless groups R/t, p/p_max and d/R
(docs/studies/paper-sphere.md).

Usage:
  scripts/paper-sphere --sweep DIR [--slenderness 25,50,100] [--ratios 0.03,0.1,0.3]
                       [--cell 0.2] [--depth 0.2] [--tag NAME] [--set KEY=VALUE ...]
        run the case at every (R/t, p/p_max) into DIR/rt-<R/t>_p-<ratio>[_<tag>]
  scripts/paper-sphere --summary RUN [RUN ...]     one line per run (--markdown: a table)
  scripts/paper-sphere --figures DIR RUN [...]     map.png and surface_<run>.png, into DIR

Geometry of a point: mid-surface radius R (--radius, 25 mm), wall t = R / (R/t), neo-Hookean c1
(--c1, 0.0033 MPa, the paper's), pressure p = ratio * p_max with the thin sphere's limit pressure
p_max = 2.479 c1 t / R. The plate starts 0.2 t above the inflated outer pole (stretch lambda of
p = (4 c1 t / R)(1/lambda - 1/lambda^7)) and moves down by that gap + depth * R. Elements of
cell * sqrt(R t) within 0.75 R of the pole (the plate's contact and the ridge around it) and 2.5 mm
elsewhere (at most R / 10).

Per run, from history.csv and summary.json: the flattening d (inward displacement of the
mid-surface pole since the last step before contact), the first step the stability check calls
unstable (negative pivots beyond the pressure unknowns', a bifurcation or limit point) and d / R
there, the wrinkle verdict and the largest ring amplitude and count at the last step, and the
tension-field state (fractions of elements taut, wrinkled and slack by membrane theory).
"""
import argparse
import math
import os
import sys

import numpy as np

from plisse_study import runs, sphere, sweep

ROOT = sweep.ROOT
CASE = os.path.join(ROOT, "validation", "paper-sphere-squeeze.yaml")
LIMIT = 2.479  # p_max = LIMIT c1 t / R (thin neo-Hookean sphere)
GAP = 0.2  # plate above the inflated pole, in wall thicknesses
POLE_ZONE = 0.75  # refined within POLE_ZONE * R of the pole
ZERO = 3e-3  # where the map draws p = 0 (its axis is logarithmic)


def limit_pressure(c1, radius, thickness):
    return LIMIT * c1 * thickness / radius


def point_settings(slenderness, ratio, args):
    r = args.radius
    t = r / slenderness
    p = ratio * limit_pressure(args.c1, r, t)
    plate = sphere.outer_pole(sphere.inflated_stretch(p, args.c1, r, t), r, t) + GAP * t
    cell = args.cell * math.sqrt(r * t)
    far = min(2.5, r / 10.0)
    return [f"mesh.inner_radius={r - 0.5 * t:.6g}", f"mesh.thickness={t:.6g}",
            f"mesh.pole_element_size={cell:.4g}", f"mesh.element_size={max(far, cell):.4g}",
            f"mesh.pole_radius={POLE_ZONE * r:.6g}", f"material.c1={args.c1:g}",
            f"loads[0].value={p:.6e}", f"dies[0].point=[0,{plate:.6f},0]",
            f"dies[0].move.displacement=[0,{-(GAP * t + args.depth * r):.6f},0]",
            f"probes[0].point=[0,{r:.6g},0]"]


def run_name(slenderness, ratio, tag):
    name = f"rt-{slenderness:g}_p-{ratio:g}"
    return f"{name}_{tag}" if tag else name


def run_sweep(directory, args):
    points = [(run_name(slenderness, ratio, args.tag),
               point_settings(slenderness, ratio, args) + (args.set or []))
              for slenderness in (float(v) for v in args.slenderness.split(","))
              for ratio in (float(v) for v in args.ratios.split(","))]
    # A point that stops (no equilibrium, a snap it cannot pass) is part of the map.
    sweep.sweep(CASE, directory, points, reuse=args.reuse)


def geometry(run, summary):
    """(mid-surface radius, wall thickness) of the run's shell: from its --set values, else from
    its first step file (the case file's own values; an imperfection would blur them)."""
    overrides = runs.set_values(summary)
    if "mesh.inner_radius" in overrides and "mesh.thickness" in overrides:
        thickness = float(overrides["mesh.thickness"])
        return float(overrides["mesh.inner_radius"]) + 0.5 * thickness, thickness
    files = runs.step_files(run)
    if not files:
        raise ValueError("no step files")
    return sphere.mid_surface(files[0])


def hoop_compression(run):
    """Most compressive hoop membrane stress at the last written step, on the plate and in the
    free wall, over the classical buckling stress of a sphere E t / (R sqrt(3 (1 - nu^2))) =
    (2/3) E t / R (E = 6 c1, nu = 1/2): the hoop Cauchy stress minus the stress along the
    deformed radial direction, per tetrahedron; on the plate means a node in contact."""
    state = runs.read_state(runs.step_files(run)[-1])
    x0, tets, x = state.points, state.corners, state.deformed
    centre, current = x0[tets].mean(axis=1), x[tets].mean(axis=1)
    phi = np.arctan2(centre[:, 2], centre[:, 0])
    hoop = np.c_[-np.sin(phi), np.zeros_like(phi), np.cos(phi)]
    normal = current / np.linalg.norm(current, axis=1)[:, None]
    sigma = state.stress()
    membrane = (np.einsum("ei,eij,ej->e", hoop, sigma, hoop)
                - np.einsum("ei,eij,ej->e", normal, sigma, normal))
    nodes = state.cells  # a 6-node face carries contact at edge nodes
    touching = (state.mesh.point_data["contact_punch"].reshape(-1)[nodes] > 0).any(axis=1)
    return membrane[touching].min(initial=np.inf), membrane[~touching].min(initial=np.inf)


def flattening(h):
    """Per history row, the inward displacement of the probe `top` since the last step before the
    plate touches (0 before it touches) [mm]."""
    i = sphere.before_contact(h, "contact_nodes:punch")
    rest = float(h["uy:top"][i]) if i is not None else 0.0
    return np.where(h["contact_nodes:punch"] > 0, rest - h["uy:top"], 0.0)


def measure(run, c1):
    summary = runs.read_summary(run, required=True)
    h = runs.read_history(run, required=True)
    radius, thickness = geometry(run, summary)
    pressure = float(max(h["pressure:gas"]))
    depth = flattening(h) / radius
    unstable = np.flatnonzero(h["stable"] == 0) if "stable" in h else []
    wrinkles = summary.get("wrinkles", {})
    rings = wrinkles.get("rings", [])
    largest = max(rings, key=lambda g: g.get("residual_amplitude") or 0.0) if rings else {}
    field = wrinkles.get("tension_field", {})
    elements = sum(field.values()) or 1
    plate, free_wall = hoop_compression(run)
    critical = 2.0 / 3.0 * 6.0 * c1 * thickness / radius
    return {
        "hoop_plate": plate / critical, "hoop_free": free_wall / critical,
        "run": run, "name": runs.run_name(run),
        "radius": radius, "thickness": thickness, "slenderness": radius / thickness,
        "pressure": pressure, "ratio": pressure / limit_pressure(c1, radius, thickness),
        "tau": sphere.tau_of(pressure, c1, radius, thickness),
        "completed": bool(summary.get("completed")), "depth": float(depth.max()),
        "unstable_depth": float(depth[unstable[0]]) if len(unstable) else None,
        "unstable_steps": len(unstable), "wrinkled": bool(wrinkles.get("wrinkled")),
        "amplitude": (largest.get("residual_amplitude") or 0.0) / thickness,
        "count": largest.get("dominant_count"), "latitude": largest.get("latitude_deg"),
        "compressed": field.get("wrinkled", 0) / elements, "slack": field.get("slack", 0) / elements,
        "force": 4.0 * float(max(h["force_y:punch"])),
        "dofs": summary.get("free_dofs"), "wall_time": (summary.get("wall_time") or {}).get("total"),
        "newton": summary.get("newton_iterations"), "steps": summary.get("steps"),
    }


def summary(run_dirs, args):
    results = []
    for run in run_dirs:
        try:
            results.append(measure(run, args.c1))
        except (OSError, KeyError, ValueError) as error:
            print(f"{run}: not read ({error})", file=sys.stderr)
    results.sort(key=lambda m: (m["slenderness"], m["ratio"], m["name"]))
    header = ["run", "R/t", "p/p_max", "tau", "completed", "d/R reached", "unstable at d/R",
              "wrinkled", "A/t", "m", "ring [deg]", "compressed", "slack", "hoop free/cr",
              "hoop plate/cr", "F [N]", "unknowns", "time [s]"]
    rows = []
    for m in results:
        rows.append([m["name"], f"{m['slenderness']:.0f}", f"{m['ratio']:.3g}",
                     f"{m['tau']:.2f}", "yes" if m["completed"] else "no", f"{m['depth']:.3f}",
                     "-" if m["unstable_depth"] is None else f"{m['unstable_depth']:.4f}",
                     "yes" if m["wrinkled"] else "no", f"{m['amplitude']:.3f}",
                     "-" if m["count"] is None else str(m["count"]),
                     "-" if m["latitude"] is None else f"{m['latitude']:g}",
                     f"{m['compressed']:.2f}", f"{m['slack']:.2f}", f"{m['hoop_free']:.2f}",
                     f"{m['hoop_plate']:.2f}", f"{m['force']:.4g}", str(m["dofs"] or 0),
                     f"{m['wall_time'] or 0:.0f}"])
    if args.markdown:
        print("| " + " | ".join(header) + " |")
        print("|" + "---|" * len(header))
        for row in rows:
            print("| " + " | ".join(row) + " |")
    else:
        widths = [max(len(r[k]) for r in rows + [header]) for k in range(len(header))]
        for row in [header] + rows:
            print(" ".join(v.rjust(w) if k else v.ljust(w)
                           for k, (v, w) in enumerate(zip(row, widths))))
    return results


def figures(directory, results, args):
    from plisse_study.figures import plt, save, surface_figure

    os.makedirs(directory, exist_ok=True)
    fig, ax = plt.subplots(figsize=(8.4, 4.8))
    slender = np.geomspace(5.0, 200.0, 100)
    # The paper's three pressures on a 1 mm wall of unknown radius R = (R/t) mm.
    for i, p in enumerate((1e-4, 1e-3, 1e-2)):
        ratio = p * slender / (LIMIT * args.c1)
        ax.plot(slender, ratio, "--", color=f"C{i + 2}", lw=1,
                label=f"paper's {p:g} MPa, t = 1 mm")
    ax.axhline(1.0, color="k", lw=0.8)
    ax.text(5.5, 1.25, "p > p_max: no inflated equilibrium", fontsize=8)
    ax.axhline(ZERO, color="0.6", lw=0.5)
    ax.text(5.5, ZERO * 1.15, "p = 0", fontsize=8, color="0.4")
    # The map holds the base runs (no tag) and the paper's own values (tag "paper"); the other
    # tagged runs vary contact, element or mesh at a map point and are in the summary table.
    for m in (m for m in results if "_" not in m["name"].split("_p-")[1] or
              m["name"].endswith("_paper")):
        if not m["completed"] and m["unstable_depth"] is None:
            style = dict(marker="s", color="0.5", mfc="none")
        elif m["wrinkled"] or m["unstable_depth"] is not None:
            style = dict(marker="X", color="C3")
        else:
            style = dict(marker="o", color="C0")
        ratio = m["ratio"] if m["ratio"] > 0.0 else ZERO
        ax.plot(m["slenderness"], ratio, ms=8, ls="none", **style)
        note = f"{m['depth']:.2f}" if m["unstable_depth"] is None else f"{m['unstable_depth']:.3f}"
        ax.annotate(note, (m["slenderness"], ratio), textcoords="offset points", xytext=(6, 4),
                    fontsize=7)
    ax.plot([], [], "o", color="C0", label="no wrinkles up to d/R (number)")
    ax.plot([], [], "X", color="C3", label="unstable or wrinkled at d/R (number)")
    ax.plot([], [], "s", color="0.5", mfc="none", label="stopped, stable")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlim(5, 200)
    ax.set_ylim(2e-3, 100.0)
    ax.set_xlabel("R / t")
    ax.set_ylabel(r"$p / p_{max}$")
    ax.legend(fontsize=8, frameon=False, loc="upper left", bbox_to_anchor=(1.01, 1.0))
    ax.grid(alpha=0.3, which="both")
    save(fig, os.path.join(directory, "map.png"))
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for i, m in enumerate(sorted(results, key=lambda m: (m["slenderness"], m["ratio"]))):
        h = runs.read_history(m["run"])
        keep = (h["contact_nodes:punch"] > 0) & ~np.isnan(h["wrinkle_amplitude"])
        points = list(zip(flattening(h)[keep] / m["radius"],
                          h["wrinkle_amplitude"][keep] / m["thickness"]))
        if points:
            ax.plot(*zip(*points), marker="o", ms=3, lw=1, color=f"C{i % 10}",
                    ls="-" if "_" not in m["name"].split("_p-")[1] else ":",
                    label=m["name"])
    ax.axhline(0.1, color="k", lw=0.8)
    ax.text(0.005, 0.105, "wrinkle threshold 0.1 t", fontsize=8)
    ax.set_xlabel("d / R")
    ax.set_ylabel("largest ring amplitude / t")
    ax.set_yscale("log")
    ax.legend(fontsize=6, frameon=False, ncol=2)
    ax.grid(alpha=0.3, which="both")
    save(fig, os.path.join(directory, "amplitude.png"))
    wrinkles = runs.case_wrinkle_settings(CASE)
    for m in results:
        vtu = runs.last_vtu(m["run"])
        if vtu:
            surface_figure(vtu, wrinkles, os.path.join(directory, f"surface_{m['name']}.png"),
                           f"R/t = {m['slenderness']:.0f}, p = {m['ratio']:.2g} p_max, "
                           f"d = {m['depth']:.3f} R")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="*", help="run directories")
    parser.add_argument("--summary", action="store_true", help="one line per run")
    parser.add_argument("--markdown", action="store_true", help="the summary as a Markdown table")
    parser.add_argument("--sweep", metavar="DIR", help="run every (R/t, p/p_max) into DIR")
    parser.add_argument("--slenderness", default="25,50,100", help="R/t values")
    parser.add_argument("--ratios", default="0.03,0.1,0.3", help="p/p_max values")
    parser.add_argument("--cell", type=float, default=0.2,
                        help="element size near the pole over sqrt(R t)")
    parser.add_argument("--depth", type=float, default=0.2, help="largest d / R")
    parser.add_argument("--tag", default="", help="suffix of the run folders")
    parser.add_argument("--reuse", action="store_true", help="keep runs with a summary.json")
    parser.add_argument("--set", action="append", metavar="KEY=VALUE",
                        help="passed on to plisse run (e.g. dies[0].contact=sticking)")
    parser.add_argument("--figures", metavar="DIR", help="map, amplitudes and surfaces into DIR")
    parser.add_argument("--c1", type=float, default=0.0033, help="neo-Hookean c1 [MPa]")
    parser.add_argument("--radius", type=float, default=25.0, help="mid-surface radius [mm]")
    args = parser.parse_args()
    if args.sweep:
        run_sweep(args.sweep, args)
        return
    if not args.runs:
        parser.error("no run directories")
    results = summary(args.runs, args)
    if args.figures:
        figures(args.figures, results, args)


if __name__ == "__main__":
    sys.exit(main())
