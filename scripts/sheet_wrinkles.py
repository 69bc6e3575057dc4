"""Wrinkles of a stretched sheet, read from a run of validation/sheet-tension-wrinkling.yaml.

Usage:
  scripts/sheet-wrinkles RUN [RUN ...]             one table per run (every written step)
  scripts/sheet-wrinkles --figures DIR RUN [...]   also the study's figures, into DIR
  scripts/sheet-wrinkles --summary RUN [...]       onset, vanishing, wavelength at fixed strains
  scripts/sheet-wrinkles --costs RUN [...]         element, unknowns, steps, iterations, wall
                                                   time and peak memory, from summary.json

The model is the quarter [0, L/2] x [0, W/2] of the sheet (x = 0 the moved clamp, x = L/2 and
y = 0 mirror planes). Per written step, on the top surface along the mirror line x = L/2 (the
middle of the sheet), with the profile mirrored about y = 0 to the full width; a run of
validation/sheet-tension-wrinkling-shell.yaml (element: shell, step files of triangles only) has
only the mid-surface's nodes, and is measured there, with the thickness of its step 0:

  strain      nominal strain of the sheet, -u_x(clamp) / (L/2)
  amplitude   largest |u_z| on the line [mm] (the centre's out-of-plane deflection)
  crests      extrema of u_z across the full width, alternating in sign, each with |u_z| at
              least 10 % of the amplitude (smaller undulations near the free edges are not counted)
  wavelength  twice the mean distance between the zero crossings of u_z that separate the counted
              crests (linear interpolation between nodes) [mm]; 0 with fewer than two crests

A profile lower than 1e-4 t is flat, with no crests: a shell that has flattened again is flat to
round-off (1e-16 t) and to what is left of the mode it followed (1e-7 t and falling), whose
undulations would otherwise count as crests of 10 % of nothing; a solid's flat sheet keeps a
bulge of 0.07 to 0.2 t with one crest, far above. A step is wrinkled when it has at least 5
crests (two waves). --summary gives per run the onset
bracket (the step where log.txt reports a new instability and the step before it), the
vanishing bracket (the last wrinkled written step and the next), the largest wrinkled amplitude
over t, the wavelength at fixed strains (interpolated between wrinkled steps) and its ratio to
Cerda & Mahadevan's; with runs of several thicknesses, the fitted exponent of t at each strain.

The same definitions are asserted by tests/verification/wrinkling/sheet_tension_slow_test.cpp.
"""
import argparse
import functools
import math
import os
import sys

import numpy as np

from plisse_study import fits, runs
from plisse_study.figures import plt, save

CREST_FRACTION = 0.1  # crests below this fraction of the amplitude are not counted
WRINKLED_CRESTS = 5  # a profile with at least this many crests (two waves) is wrinkled
FLAT_FRACTION = 1e-4  # a profile lower than this fraction of the thickness is flat: no crests
SUMMARY_STRAINS = (0.05, 0.10, 0.15, 0.20, 0.25)


def crests(y, w, flat=0.0):
    """Alternating extrema of w(y) with |w| >= CREST_FRACTION * max|w|: list of (y, w); none when
    max|w| <= `flat` [mm]."""
    amplitude = np.abs(w).max()
    if amplitude <= flat:
        return []
    found = []
    for k in range(len(w)):
        left = w[k - 1] if k > 0 else -np.inf * np.sign(w[k])
        right = w[k + 1] if k + 1 < len(w) else -np.inf * np.sign(w[k])
        is_max = w[k] > 0 and w[k] >= left and w[k] >= right
        is_min = w[k] < 0 and w[k] <= left and w[k] <= right
        if (is_max or is_min) and abs(w[k]) >= CREST_FRACTION * amplitude:
            if found and np.sign(found[-1][1]) == np.sign(w[k]):
                if abs(w[k]) > abs(found[-1][1]):  # two crests of one sign: keep the larger
                    found[-1] = (y[k], w[k])
                continue
            found.append((y[k], w[k]))
    return found


def wavelength(y, w, found):
    """Twice the mean spacing of the zero crossings between consecutive crests of `found`."""
    zeros = []
    for (ya, wa), (yb, wb) in zip(found, found[1:]):
        inside = np.flatnonzero((y >= ya) & (y <= yb))
        for k in inside[:-1]:
            if np.sign(w[k]) != np.sign(w[k + 1]) and w[k + 1] != 0.0:
                zeros.append(y[k] - w[k] * (y[k + 1] - y[k]) / (w[k + 1] - w[k]))
                break
    return 2.0 * (zeros[-1] - zeros[0]) / (len(zeros) - 1) if len(zeros) >= 2 else 0.0


def is_shell(state):
    """True for a step file of a shell run (runs.State): triangles, no tetrahedra."""
    return state.cells is None and "triangle" in state.mesh.cells_dict


def measured_nodes(state):
    """Mask of the nodes measured: the top surface's (z above the middle of the sheet) of a solid
    run, every node (the mid-surface) of a shell run."""
    z = state.points[:, 2]
    if is_shell(state):
        return np.ones(len(z), dtype=bool)
    return z > 0.5 * (z.max() + z.min())


def profile(state):
    """(strain, y, w) of one written step (runs.State): the mirrored profile of the top surface
    (the mid-surface of a shell) along x = L/2."""
    X = state.points
    u = state.displacement
    half_length = X[:, 0].max()
    clamp = X[:, 0] < 1e-9 * half_length
    strain = -u[clamp, 0].mean() / half_length
    line = measured_nodes(state) & (np.abs(X[:, 0] - half_length) < 1e-6 * half_length)
    y = X[line, 1]
    w = u[line, 2]
    order = np.argsort(y)
    y, w = y[order], w[order]
    keep = y > 1e-9  # the node on the mirror line appears once
    y_full = np.concatenate([-y[keep][::-1], y])
    w_full = np.concatenate([w[keep][::-1], w])
    return strain, y_full, w_full


def measure(run):
    """Rows (step, strain, amplitude, crests, wavelength) and the last profile of a run."""
    rows, profiles = [], {}
    flat = FLAT_FRACTION * run_geometry(run)[1]
    for step, path in runs.written_steps(run):  # not step 0, the sheet before the first step
        strain, y, w = profile(runs.read_state(path))
        c = crests(y, w, flat)
        rows.append((step, strain, np.abs(w).max(), len(c), wavelength(y, w, c)))
        profiles[step] = (y, w)
    return rows, profiles


def print_table(run, rows):
    print(f"# {run}")
    print("step,strain,amplitude_mm,crests,wavelength_mm")
    for step, strain, amplitude, n, wavelength in rows:
        print(f"{step},{strain:.5f},{amplitude:.6e},{n},{wavelength:.4f}")


def cerda_mahadevan(strain, length, thickness, poisson=0.5):
    """Cerda & Mahadevan (2003): wavelength (2 pi L t)^(1/2) / (3 (1 - nu^2) strain)^(1/4)."""
    return math.sqrt(2.0 * math.pi * length * thickness) / (
        3.0 * (1.0 - poisson**2) * strain) ** 0.25


@functools.lru_cache(maxsize=None)
def run_geometry(run):
    """(full length L, thickness t) of a run, from its first VTU: the clamp's nodes of a solid
    (an imperfection leaves the clamped edge where it was), the reference `thickness` of a shell's
    triangles."""
    state = runs.read_state(runs.step_files(run)[0])
    X = state.points
    if is_shell(state):
        thickness = state.mesh.cell_data_dict["thickness"]["triangle"]
        return 2.0 * X[:, 0].max(), float(np.max(thickness))
    clamp = X[:, 0] < 1e-9 * X[:, 0].max()
    return 2.0 * X[:, 0].max(), X[clamp, 2].max() - X[clamp, 2].min()


def surface_figure(run, rows, path, title):
    """Top view of the whole deformed sheet (the quarter mirrored twice), coloured by u_z, at the
    written step of largest centre deflection (`rows` from measure(run))."""
    step = max(rows, key=lambda r: r[2])[0]
    state = runs.read_state(dict(runs.written_steps(run))[step])
    X, u = state.points, state.displacement
    top = measured_nodes(state)
    half_length = X[:, 0].max()
    x, y, w = X[top, 0] + u[top, 0], X[top, 1] + u[top, 1], u[top, 2]
    fig, ax = plt.subplots(figsize=(7, 3.2))
    limit = np.abs(w).max()
    for sx in (1, -1):
        for sy in (1, -1):
            xs = x if sx == 1 else 2.0 * half_length - x
            im = ax.tripcolor(xs, sy * y, w, shading="gouraud", cmap="RdBu_r", vmin=-limit,
                              vmax=limit)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm] (deformed)")
    ax.set_ylabel("y [mm]")
    strain = [r[1] for r in rows if r[0] == step][0]
    ax.set_title(f"{title}: u_z at {100 * strain:.1f} % strain", fontsize=9)
    fig.colorbar(im, ax=ax, label="u_z [mm]", shrink=0.8)
    save(fig, path, dpi=120)


def run_label(run, profiles):
    """"t = 0.02, h = 0.5" for a run ("..., shell" for a shell): thickness, and the in-plane
    element size from the node spacing along the middle line (two nodes per quadratic element
    edge, one per shell triangle's)."""
    _, t = run_geometry(run)
    y, _ = next(iter(profiles.values()))
    shell = is_shell(runs.read_state(runs.step_files(run)[0]))
    h = (1.0 if shell else 2.0) * np.median(np.diff(y))
    return f"t = {t:.2g} mm, h = {h:.3g} mm" + (", shell" if shell else "")


def finish(fig, ax, path, xlabel, ylabel):
    """Labels, legend, and the figure written to `path`."""
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.legend(fontsize=7)
    save(fig, path, dpi=120)


def figures(results, folder, prefix=""):
    """<prefix>amplitude.png, <prefix>wavelength.png, and per run profiles_<run>.png and
    surface_<run>.png."""
    os.makedirs(folder, exist_ok=True)
    fig, ax = plt.subplots(figsize=(6, 3.6))
    for run, (rows, profiles) in results.items():
        _, t = run_geometry(run)
        ax.plot([100 * r[1] for r in rows], [r[2] / t for r in rows], ".-", markersize=3,
                label=run_label(run, profiles))
    finish(fig, ax, os.path.join(folder, prefix + "amplitude.png"), "nominal strain [%]",
           "centre deflection / t")

    fig, ax = plt.subplots(figsize=(6, 3.6))
    for run, (rows, profiles) in results.items():
        length, t = run_geometry(run)
        keep = [r for r in rows if r[3] >= WRINKLED_CRESTS and r[2] >= t]
        ax.plot([100 * r[1] for r in keep], [r[4] / math.sqrt(length * t) for r in keep], ".",
                label=run_label(run, profiles))
    strains = np.linspace(0.02, 0.35, 100)
    ax.plot(100 * strains, [cerda_mahadevan(e, 1.0, 1.0) for e in strains], "k-",
            label="Cerda & Mahadevan 2003")
    ax.set_xscale("log")
    ax.set_yscale("log")
    finish(fig, ax, os.path.join(folder, prefix + "wavelength.png"), "nominal strain [%]",
           "wavelength / (L t)^(1/2)")

    for run, (rows, profiles) in results.items():
        name = os.path.basename(run.rstrip("/"))
        surface_figure(run, rows, os.path.join(folder, f"surface_{name}.png"),
                       run_label(run, profiles))
        _, t = run_geometry(run)
        fig, ax = plt.subplots(figsize=(6, 3.2))
        wrinkled = [r for r in rows if r[3] >= WRINKLED_CRESTS]
        for r in wrinkled[:: max(1, len(wrinkled) // 5)]:
            y, w = profiles[r[0]]
            ax.plot(y, w / t, "-", label=f"{100 * r[1]:.1f} %")
        finish(fig, ax, os.path.join(folder, f"profiles_{name}.png"),
               "y [mm] (across the middle of the sheet)", "u_z / t")


def instability_steps(run):
    """{step: time} of every converged step (history.csv) and the steps at which log.txt reports
    a new instability ("step N: t = ...: new instability")."""
    h = runs.read_history(run, required=True)
    times = {int(k): float(t) for k, t in zip(h["step"], h["time"])}
    return times, [step for step, _ in runs.log_instabilities(run)]


def wavelength_at(wrinkled, strain):
    """The wavelength [mm] at `strain`, interpolated linearly between the two wrinkled rows of
    measure() (step, strain, amplitude, crests, wavelength) around it; None when no two wrinkled
    rows enclose it."""
    points = [(r[1], r[4]) for r in wrinkled]
    for (e0, l0), (e1, l1) in zip(points, points[1:]):
        if e0 <= strain <= e1:
            return l0 + (l1 - l0) * (strain - e0) / (e1 - e0)
    return None


def summary(results):
    """Per run: onset bracket (stability check), vanishing bracket, wavelength at fixed strains;
    then the exponent of t in the wavelength across runs of different thickness."""
    by_strain = {e: [] for e in SUMMARY_STRAINS}
    print("run,thickness_mm,onset_low,onset_high,vanish_low,vanish_high,peak_amplitude_over_t,"
          + ",".join(f"lambda_at_{e:g}" for e in SUMMARY_STRAINS)
          + "," + ",".join(f"ratio_cm_at_{e:g}" for e in SUMMARY_STRAINS))
    for run, (rows, _) in results.items():
        length, t = run_geometry(run)
        # The clamp moves linearly in time: strain = time x (strain / time of the last VTU step).
        times, onsets = instability_steps(run)
        scale = rows[-1][1] / times[rows[-1][0]]
        onset = ("", "")
        if onsets:
            step = onsets[0]
            onset = (f"{scale * times.get(step - 1, 0.0):.4f}", f"{scale * times[step]:.4f}")
        wrinkled = [r for r in rows if r[3] >= WRINKLED_CRESTS]
        vanish = ("", "")
        if wrinkled:
            last = rows.index(wrinkled[-1])
            vanish = (f"{rows[last][1]:.4f}",
                      f"{rows[last + 1][1]:.4f}" if last + 1 < len(rows) else "")
        peak = max((r[2] for r in wrinkled), default=0.0) / t
        lambdas, ratios = [], []
        for e in SUMMARY_STRAINS:
            value = wavelength_at(wrinkled, e)
            if value is None:
                lambdas.append("")
                ratios.append("")
                continue
            lambdas.append(f"{value:.4f}")
            ratios.append(f"{value / cerda_mahadevan(e, length, t):.4f}")
            by_strain[e].append((t, value))
        print(f"{os.path.basename(run.rstrip('/'))},{t:g},{onset[0]},{onset[1]},{vanish[0]},"
              f"{vanish[1]},{peak:.3f}," + ",".join(lambdas) + "," + ",".join(ratios))
    for e, pts in by_strain.items():
        if len({t for t, _ in pts}) >= 2:
            slope = fits.log_slope(pts)
            print(f"# strain {e:g}: wavelength ~ t^{slope:.3f} over {len(pts)} runs")


def costs(run_dirs):
    """Per run, from its summary.json: element family, unknowns solved for, converged steps and
    the strain reached, Newton iterations and Krylov steps (Newton steps without a new
    factorisation), wall time and peak memory."""
    print("run,element,unknowns,steps,final_strain,newton_iterations,krylov_steps,wall_time_s,"
          "peak_memory_mib,completed")
    for run in run_dirs:
        s = runs.read_summary(run)
        if not s:
            print(f"{runs.run_name(run)},no summary.json")
            continue
        rows, _ = measure(run)
        print(f"{runs.run_name(run)},{s['element']},{s['free_dofs']},{s['steps']},"
              f"{rows[-1][1]:.4f},{s['newton_iterations']},{s.get('krylov_steps', 0)},"
              f"{s['wall_time']['total']:.1f},{s['peak_memory_mib']:.0f},{s['completed']}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+", help="run directories")
    parser.add_argument("--figures", help="write amplitude and profile figures into this folder")
    parser.add_argument("--prefix", default="", help="prefix of the amplitude and wavelength figures")
    parser.add_argument("--summary", action="store_true",
                        help="print onset, vanishing and wavelength at fixed strains per run")
    parser.add_argument("--costs", action="store_true",
                        help="print unknowns, steps, iterations, wall time and memory per run")
    args = parser.parse_args()
    if args.costs:
        costs(args.runs)
        return
    results = {}
    for run in args.runs:
        if not runs.step_files(run):
            sys.exit(f"sheet-wrinkles: {run}: no step_*.vtu files (not a run directory?)")
        rows, profiles = measure(run)
        if not args.summary:
            print_table(run, rows)
        results[run] = (rows, profiles)
    if args.summary:
        summary(results)
    if args.figures:
        figures(results, args.figures, args.prefix)


if __name__ == "__main__":
    main()
