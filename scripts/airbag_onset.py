"""The radius at which the round airbag's rim wrinkles, without viscous damping, from runs of
validation/airbag-onset.yaml scaled in size (docs/studies/airbag-onset.md).

Usage:
  scripts/airbag-onset --sweep DIR [--radii 150,100,70,50] [--cells 15] [--minutes M]
                       [--set KEY=VALUE ...]  run the perfect bag at each radius into DIR/a-A-nN
  scripts/airbag-onset --summary RUN [RUN ...]
                                              onset pressure, waves, the threshold
  scripts/airbag-onset --figures DIR RUN [...]
                                              onset.png and surface_A.png into DIR

The bag is examples/airbag.yaml's at every size: an oblate spheroid of mid-surface semi-axes a and
c = a / 5 (height 0.4 a), the same wall (t = 1 mm), material and pressure (4.4e-5 MPa), quarter
model, glued to its floor at the lower pole. The case (validation/airbag-onset.yaml) makes it
perfect (no imperfection) and undamped, with quadratic tetrahedra (Taylor-Hood, one through the
wall) and the stability check at every step; the sweep sets the in-plane size a / N
(--cells N). Newton takes full steps (line_search basic): without damping, the backtracking
search accepts only a few thousandths of the first steps, whose full step first raises the
residual while the faces bend, and stalls.

Per run, from history.csv:
  - the onset: the first step whose state is unstable (column stable: more negative pivots than
    a stable state) or whose largest ring amplitude exceeds 0.1 t (the example's threshold),
    bracketed in pressure by the step before it and the step itself (column pressure:gas);
  - the wave count m around the whole rim at the onset (history.csv wrinkle_peak_count: the ring
    with the largest amplitude, above the threshold or not; even only, the quarter model's mirrors hold no other), and the ring
    (latitude) whose harmonic is largest in wrinkle_spectrum.csv at the first step written from
    the onset on.
--summary gives d log p_c / d log a between neighbouring radii (the dimensional argument of the
study, O3: -2) and the radii between which the onset passes the example's pressure.
"""
import argparse
import os
import sys

import numpy as np

from plisse_study import fits, runs, sweep

ROOT = sweep.ROOT
CASE = os.path.join(ROOT, "validation", "airbag-onset.yaml")
PRESSURE = 4.4e-5  # the example's (the paper's) pressure [MPa]
E = 6.0 * 0.0033  # the example's small-strain Young's modulus, 6 c1 [MPa]
ASPECT = 5.0  # a / c of the example (150 / 30)
THRESHOLD = 0.1  # a ring is wrinkled above this amplitude [mm]: 0.1 x the wall, as in the example
AFTER = 3  # steps a sweep's run goes on past the onset


def geometry(run):
    """(a, t): the undeformed mid-surface's equatorial radius and the wall, from the first step
    file: the equator's inner and outer nodes of a solid, a shell's equator (its nodes are the
    mid-surface's) and the reference thickness of its triangles."""
    state = runs.read_state(os.path.join(run, "step_0000.vtu"))
    x = state.points
    rho = np.hypot(x[:, 0], x[:, 2])[np.abs(x[:, 1]) < 1e-9]
    if state.cells is None and "triangle" in state.mesh.cells_dict:  # element: shell
        return float(rho.max()), float(np.max(state.mesh.cell_data_dict["thickness"]["triangle"]))
    return 0.5 * (rho.max() + rho.min()), rho.max() - rho.min()


def onset_index(h):
    """Index of the first step of the history columns `h` (runs.read_history) whose state is
    unstable or whose largest ring amplitude exceeds THRESHOLD, or None."""
    if not h:
        return None
    hits = h["wrinkle_amplitude"] > THRESHOLD
    if "stable" in h:
        hits |= h["stable"] == 0
    index = np.flatnonzero(hits)
    return int(index[0]) if len(index) else None


def steps_past_onset(run):
    """Steps a running run has written past its onset, or -1 (read while plisse writes: the
    reader leaves out a row still being written)."""
    h = runs.read_history(run)
    index = onset_index(h)
    return -1 if index is None else len(h["step"]) - 1 - index


def spectrum_peak(run, step):
    """(latitude [deg], m, amplitude [mm]) of the largest harmonic in wrinkle_spectrum.csv at the
    first step at or after `step` that the file holds (it has the steps written to disk)."""
    best, first = None, None
    for row in runs.read_spectrum(run):
        k = int(row["step"])
        if k < step or (first is not None and k != first):
            continue
        first = k
        candidate = (float(row["latitude_deg"]), int(row["m"]), float(row["amplitude"]))
        if best is None or candidate[2] > best[2]:
            best = candidate
    return best


def measure(run):
    a, t = geometry(run)
    h = runs.read_history(run)
    if not h:
        sys.exit(f"{run}: history.csv has no complete step")
    p = h["pressure:gas"]
    result = {"run": run, "a": a, "t": t, "onset": None, "kind": None, "count": 0,
              "peak": None, "limit": float(p.max()), "steps": len(p),
              "unknowns": runs.read_summary(run).get("free_dofs")}
    index = onset_index(h)
    if index is not None:
        result["onset"] = fits.bracket(p, index)
        unstable = "stable" in h and h["stable"][index] == 0
        result["kind"] = "instability" if unstable else "folds"
        result["count"] = int(h["wrinkle_peak_count"][index])
        result["peak"] = spectrum_peak(run, int(h["step"][index]))
    return result


def cells_of(run):
    """N of a sweep's run directory DIR/a-A-nN (elements of a / N), or 0 for another name."""
    tail = runs.run_name(run).rsplit("-n", 1)
    try:
        return float(tail[1]) if len(tail) == 2 else 0.0
    except ValueError:
        return 0.0


def by_cells(results):
    groups = {}
    for m in results:
        groups.setdefault(cells_of(m["run"]), []).append(m)
    return groups


middle = fits.middle


def estimate(a, t):
    """The onset pressure of the dimensional argument (docs/studies/airbag-onset.md, O1-O3):
    membrane hoop compression of the undeformed rim against the axial buckling stress of a
    cylinder of the rim's meridian radius c^2 / a."""
    return (2.0 / 3.0) * E * t**2 * ASPECT**2 / (0.5 * a**2 * (ASPECT**2 - 2.0))


def threshold(results):
    """(largest radius without an onset up to PRESSURE, smallest radius with one), either None
    when the runs given do not have it."""
    below = [m["a"] for m in results if m["onset"] and m["onset"][1] <= PRESSURE]
    above = [m["a"] for m in results
             if not (m["onset"] and m["onset"][1] <= PRESSURE) and m["limit"] >= PRESSURE]
    smooth = [a for a in above if not below or a < min(below)]
    return (max(smooth) if smooth else None, min(below) if below else None)


def summary(run_dirs):
    results = sorted((measure(run) for run in run_dirs), key=lambda m: (m["a"], m["unknowns"] or 0))
    print(f"{'run':<14} {'a [mm]':>6} {'unknowns':>8} {'onset p [MPa]':>21} {'kind':>11} "
          f"{'p_c a^2/(E t^2)':>15} {'m':>3} {'ring [deg]':>10} "
          f"{'largest p [MPa]':>15} {'steps':>5}")
    for m in results:
        if m["onset"]:
            onset = f"{m['onset'][0]:.3e} - {m['onset'][1]:.3e}"
            scaled = f"{middle(m['onset']) * m['a'] ** 2 / (E * m['t'] ** 2):15.3f}"
        else:
            onset, scaled = "none", f"{'-':>15}"
        ring = f"{m['peak'][0]:10.0f}" if m["peak"] else f"{'-':>10}"
        print(f"{runs.run_name(m['run']):<14} {m['a']:6.1f} "
              f"{m['unknowns'] or 0:8d} {onset:>21} {m['kind'] or '-':>11} {scaled} "
              f"{m['count']:3d} {ring} {m['limit']:15.3e} {m['steps']:5d}")
    for cells, group in sorted(by_cells(results).items()):
        points = [(m["a"], middle(m["onset"])) for m in group if m["onset"]]
        for a0, a1, k in fits.local_slopes(points):
            print(f"elements a/{cells:g}: d log p_c / d log a between a = {a0:g} and {a1:g} mm: "
                  f"{k:.2f} (dimensional argument: -2)")
    smooth, wrinkled = threshold(results)
    print(f"the rim wrinkles before {PRESSURE:g} MPa for a >= {wrinkled or '?'} mm and stays "
          f"smooth for a <= {smooth or '?'} mm (wall {results[0]['t']:g} mm)")
    return results


def run_sweep(directory, args):
    os.makedirs(directory, exist_ok=True)
    for a in (float(x) for x in args.radii.split(",")):
        c = a / ASPECT
        run = os.path.join(directory, f"a-{a:g}-n{args.cells:g}")
        overrides = [f"mesh.radius={a:g}", f"mesh.height={2 * c:g}",
                     f"mesh.element_size={a / args.cells:.4g}",
                     f"dies[0].point=[0,{-(c + 0.5):g},0]",
                     f"probes[0].point=[{a + 0.5:g},0,0]", f"probes[1].point=[0,{c + 0.5:g},0]"]
        # Without damping the steps shrink towards nothing once the folds grow (the quasi-static
        # path snaps there): a few steps past the onset say all this study needs, so the run is
        # stopped there (SIGTERM: plisse ends the step, writes its files and says `interrupted`),
        # or after --minutes.
        outcome = sweep.run_case(CASE, run, overrides + (args.set or []), minutes=args.minutes,
                                 stop=lambda: steps_past_onset(run) >= AFTER)
        # A run that ends at the snap (exit status 1: the load could not be raised) after its
        # onset has given what the study needs, as a stopped one has.
        snapped = outcome.returncode == 1 and steps_past_onset(run) >= 0
        if outcome.returncode not in (0, 130, 143) and not outcome.stopped and not snapped:
            sys.exit(f"plisse run failed for a = {a:g} mm (exit status {outcome.returncode})")


def figures(directory, results):
    from plisse_study.figures import plt, save

    os.makedirs(directory, exist_ok=True)
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    for cells, group in sorted(by_cells(results).items()):
        group = sorted((m for m in group if m["onset"]), key=lambda m: m["a"])
        if not group:
            continue
        a = [m["a"] for m in group]
        ax.errorbar(a, [middle(m["onset"]) for m in group],
                    yerr=[[middle(m["onset"]) - m["onset"][0] for m in group],
                          [m["onset"][1] - middle(m["onset"]) for m in group]],
                    marker="o", capsize=3, label=f"plisse, elements a/{cells:g}")
    smooth_runs = [m for m in results if not m["onset"]]
    if smooth_runs:
        ax.plot([m["a"] for m in smooth_runs], [m["limit"] for m in smooth_runs], "v",
                color="tab:green", label="no wrinkles up to this pressure")
    radii = sorted({m["a"] for m in results})
    xs = [radii[0] * (radii[-1] / radii[0]) ** (i / 40) for i in range(41)]
    ax.plot(xs, [estimate(x, results[0]["t"]) for x in xs], "k--", lw=1,
            label="dimensional argument (O3)")
    ax.axhline(PRESSURE, color="tab:red", lw=1, label="the example's pressure 4.4e-5 MPa")
    smooth, wrinkled = threshold(results)
    if smooth and wrinkled:
        ax.axvspan(smooth, wrinkled, color="tab:red", alpha=0.15, label="a* bracketed")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("mid-surface radius a [mm] (wall 1 mm, height 0.4 a)")
    ax.set_ylabel("pressure at the rim's wrinkling onset [MPa]")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    save(fig, os.path.join(directory, "onset.png"))
    surfaces(directory, results)


def surfaces(directory, results):
    """surface_A.png: the last state of the largest and the smallest wrinkled bag and of the
    largest smooth one (runs of the coarsest in-plane size), coloured by the normal deviation
    from the mean axisymmetric shape, with the rings."""
    from plisse_study.figures import surface_figure

    settings = runs.case_wrinkle_settings(CASE)
    groups = by_cells(results)
    coarsest = groups[min(groups)]
    wrinkled = [m for m in coarsest if m["onset"]]
    smooth = [m for m in coarsest if not m["onset"]]
    chosen = []
    if wrinkled:
        chosen += [max(wrinkled, key=lambda m: m["a"]), min(wrinkled, key=lambda m: m["a"])]
    if smooth:
        chosen.append(max(smooth, key=lambda m: m["a"]))
    for m in {id(m): m for m in chosen}.values():
        vtu = runs.last_vtu(m["run"])
        if not vtu:
            continue
        state = (f"onset at {middle(m['onset']):.2e} MPa" if m["onset"]
                 else "no wrinkles")
        surface_figure(vtu, settings, os.path.join(directory, f"surface_{m['a']:g}.png"),
                       f"a = {m['a']:g} mm, last state p = {m['limit']:.2e} MPa ({state})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("runs", nargs="*")
    parser.add_argument("--summary", action="store_true")
    parser.add_argument("--sweep", metavar="DIR")
    parser.add_argument("--radii", default="150,100,70,50", help="mid-surface radii a [mm]")
    parser.add_argument("--cells", type=float, default=15.0,
                        help="in-plane element size a / CELLS (--sweep)")
    parser.add_argument("--set", action="append", metavar="KEY=VALUE",
                        help="passed on to plisse run (e.g. solver.stability.modes=2)")
    parser.add_argument("--minutes", type=float, default=40.0,
                        help="stop a sweep's run after this long (--sweep)")
    parser.add_argument("--figures", metavar="DIR")
    args = parser.parse_args()
    if args.sweep:
        run_sweep(args.sweep, args)
        return
    if not args.runs:
        parser.error("no run directories")
    results = summary(args.runs)
    if args.figures:
        figures(args.figures, results)


if __name__ == "__main__":
    sys.exit(main())
