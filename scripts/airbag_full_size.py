"""A driver airbag at full size, from runs of examples/airbag-full-size.yaml
(docs/studies/airbag-full-size.md).

Usage:
  scripts/airbag-full-size --summary RUN [RUN ...]   the table of the study page, one row a run
  scripts/airbag-full-size --ensemble RUN [RUN ...]  runs of several seeds, one row a mesh: the
                                                     median and the range of the seam's folds
  scripts/airbag-full-size --figures DIR RUN [...]   the study's figures, into DIR

The bag is two flat round panels of radius r joined at their rims; the case models one quarter of
one panel. Its inextensible limit is Paulsen's Mylar balloon (Paulsen 1994, "What is the shape of
a Mylar balloon?", Amer. Math. Monthly 101(10), 953-958): the profile z(x) of the upper panel with
z' = -x^2 / sqrt(a^4 - x^4), whose meridian keeps the panel's radius r as its length, so that
  r = a I0,  I0 = int_0^1 du / sqrt(1 - u^4) = Gamma(1/4)^2 / (4 sqrt(2 pi)) = 1.31103,
  half height h = a int_0^1 u^2 du / sqrt(1 - u^4) = (pi / 4) a / I0,
  volume V = 2 pi a^3 int_0^1 u^4 du / sqrt(1 - u^4) = (2 pi / 3) I0 a^3.

The seam's folds, from the last written step: the rim nodes' distance from the axis against their
angle over the quarter; a fold is a maximum of that distance that rises at least FOLD_PROMINENCE
(in wall thicknesses) above the minima on both sides; their number over the full circle is four
times the quarter's, the wavelength the mean rim's circumference over that count, and the depth
the largest rise of a fold over its neighbouring minima. The large folds are those that rise at
least LARGE_FOLD of the deepest: the seam's few deep folds among its fine crimps; their mean rise
is the large folds' depth, which depends less on the one deepest fold than the depth does. The
folds' total depth is the sum of all the folds' rises over the full circle: the length the seam's
folds store radially, whichever folds store it. The seam's reach is its largest less its least
distance from the axis: how far in the deepest fold pulls the seam, measured from the seam's
outermost point rather than from the fold's neighbouring minima.
"""
import argparse
import math
import os
import sys

import numpy as np

from plisse_study import figures, runs

FOLD_PROMINENCE = 1.0  # wall thicknesses
LARGE_FOLD = 0.2  # a large fold rises at least this share of the deepest one


def paulsen(r):
    """(a, h, V) of the Mylar balloon made of two discs of radius r: rim radius, half height,
    volume of the whole bag."""
    i0 = math.gamma(0.25) ** 2 / (4.0 * math.sqrt(2.0 * math.pi))
    a = r / i0
    return a, math.pi / 4.0 * a / i0, 2.0 * math.pi / 3.0 * i0 * a**3


def paulsen_profile(r, n=400):
    """(x, z) of the upper panel's profile: z(x) = int_x^a u^2 du / sqrt(a^4 - u^4), by the
    substitution u = a (1 - s^2) that removes the root's singularity at the rim."""
    a, h, _ = paulsen(r)
    x = a * (1.0 - np.linspace(0.0, 1.0, n) ** 2)
    z = np.empty_like(x)
    for k, xk in enumerate(x):
        smax = math.sqrt(1.0 - xk / a)
        s = np.linspace(0.0, smax, 400)
        u = 1.0 - s**2
        f = u**2 * 2.0 * s / np.sqrt(np.maximum((1.0 - u) * (1.0 + u) * (1.0 + u**2), 1e-300))
        f[0] = 2.0 * 1.0 / math.sqrt(2.0 * 2.0)  # the limit s -> 0: 2 s / (s sqrt(4)) = 1
        z[k] = a * np.trapz(f, s)
    return x, z


def panel(run):
    """(radius, thickness) of the run's panel, from summary.json's `--set` overrides or the case."""
    summary = runs.read_summary(run, required=True)
    sets = runs.set_values(summary)
    return float(sets.get("mesh.radius", 350.0)), float(sets.get("mesh.thickness", 0.35))


def seam(path, radius, thickness):
    """(angle [deg], distance from the axis [mm]) of the rim's nodes at the step file `path`, by
    angle, and the folds: their count over the full circle, wavelength [mm], depth [mm] (the
    deepest rise), the mean radius [mm], the count of the large folds over the full circle, the
    large folds' mean depth [mm], the folds' total depth over the full circle [mm] and the seam's
    reach [mm] (its largest less its least distance from the axis)."""
    mesh = runs.read_raw_vtu(path)
    X = mesh.points
    x = X + mesh.point_data["displacement"]
    on_rim = np.abs(np.hypot(X[:, 0], X[:, 2]) - radius) < 1e-6 * radius
    angle = np.degrees(np.arctan2(X[on_rim, 2], X[on_rim, 0]))
    order = np.argsort(angle)
    angle = angle[order]
    r = np.hypot(x[on_rim, 0], x[on_rim, 2])[order]
    peaks, depths = folds(r, FOLD_PROMINENCE * thickness)
    count = 4 * len(peaks)
    mean = float(np.mean(r))
    wavelength = 2.0 * math.pi * mean / count if count else float("nan")
    deepest, large = large_folds(depths)
    return angle, r, {"folds": count, "wavelength": wavelength, "depth": deepest, "mean": mean,
                      "large folds": 4 * len(large),
                      "large depth": float(np.mean(large)) if large else 0.0,
                      "total depth": 4.0 * float(np.sum(depths)),
                      "reach": float(np.max(r) - np.min(r))}


def large_folds(rises):
    """(the deepest rise, the rises of the large folds: at least LARGE_FOLD of the deepest)."""
    deepest = max(rises, default=0.0)
    return deepest, [d for d in rises if d >= LARGE_FOLD * deepest]


def folds(r, prominence):
    """Indices of the maxima of r that rise at least `prominence` above the lowest value between
    them and the next higher point (or the end) on each side, and those rises."""
    peaks, rises = [], []
    n = len(r)
    for i in range(1, n - 1):
        if not (r[i] > r[i - 1] and r[i] >= r[i + 1]):
            continue
        left = i
        low_left = r[i]
        while left > 0 and r[left - 1] <= r[i]:
            left -= 1
            low_left = min(low_left, r[left])
        right = i
        low_right = r[i]
        while right < n - 1 and r[right + 1] <= r[i]:
            right += 1
            low_right = min(low_right, r[right])
        rise = r[i] - max(low_left, low_right)
        if rise >= prominence:
            peaks.append(i)
            rises.append(float(rise))
    return peaks, rises


def summary_row(run):
    radius, thickness = panel(run)
    s = runs.read_summary(run, required=True)
    h = runs.read_history(run, required=True)
    a, half, volume = paulsen(radius)
    last = len(h["time"]) - 1
    _, _, f = seam(runs.last_vtu(run), radius, thickness)
    bag = 2.0 * h["full_volume:gas"][last]  # the quarter's mirrors make half the bag
    return {"run": runs.run_name(run), "unknowns": s.get("free_dofs"), "steps": s.get("steps"),
            "wall [s]": (s.get("wall_time") or {}).get("total"),
            "peak [MiB]": s.get("peak_memory_mib"),
            "p [kPa]": 1e3 * h["pressure:gas"][last], "V / V_P": bag / volume,
            "crown / h_P": (h["uy:crown"][last]) / half, "seam / a_P": f["mean"] / a,
            "folds": f["folds"], "wavelength [mm]": f["wavelength"], "depth [mm]": f["depth"],
            "large folds": f["large folds"], "large folds' depth [mm]": f["large depth"],
            "total depth [mm]": f["total depth"], "reach [mm]": f["reach"]}


def print_summary(paths):
    rows = [summary_row(run) for run in paths]
    keys = list(rows[0])
    print("| " + " | ".join(keys) + " |")
    print("|" + "---|" * len(keys))
    for row in rows:
        print("| " + " | ".join(f"{v:.4g}" if isinstance(v, float) else str(v)
                                for v in row.values()) + " |")


ENSEMBLE_KEYS = ("folds", "depth [mm]", "large folds", "large folds' depth [mm]",
                 "total depth [mm]", "reach [mm]")


def seed(run):
    """The seed of the run's imperfection: its `--set solver.stability.seed`, or the example's 1."""
    return int(runs.set_values(runs.read_summary(run, required=True)).get(
        "solver.stability.seed", 1))


def ensemble(rows):
    """One row a mesh (the runs of equal unknowns, coarsest first): its runs' seeds, and the
    median, the least and the largest of each of ENSEMBLE_KEYS over them."""
    meshes = {}
    for row in rows:
        meshes.setdefault(row["unknowns"], []).append(row)
    table = []
    for unknowns, group in sorted(meshes.items()):
        out = {"unknowns": unknowns, "seeds": ",".join(str(r["seed"]) for r in group)}
        for key in ENSEMBLE_KEYS:
            values = np.array([r[key] for r in group], dtype=float)
            out[key] = (float(np.median(values)), float(values.min()), float(values.max()))
        table.append(out)
    return table


def print_ensemble(paths):
    rows = []
    for run in paths:
        row = summary_row(run)
        row["seed"] = seed(run)
        rows.append(row)
    table = ensemble(rows)
    print("| unknowns | seeds | " + " | ".join(ENSEMBLE_KEYS) + " |")
    print("|" + "---|" * (2 + len(ENSEMBLE_KEYS)))
    for out in table:
        cells = [f"{m:.4g} [{lo:.4g}, {hi:.4g}]" for m, lo, hi in (out[k] for k in ENSEMBLE_KEYS)]
        print(f"| {out['unknowns']} | {out['seeds']} | " + " | ".join(cells) + " |")
    print()
    for out in table:
        spread = ", ".join(f"{k} {out[k][2] / out[k][1] - 1.0:+.1%}" if out[k][1] > 0 else f"{k} -"
                           for k in ENSEMBLE_KEYS)
        print(f"over the seeds of {out['unknowns']} unknowns (largest / least - 1): {spread}")
    for coarse, fine, change in mesh_steps(table):
        ratio = ", ".join(f"{k} {change[k]:+.1%}" for k in ENSEMBLE_KEYS)
        print(f"medians, {fine} against {coarse} unknowns: {ratio}")


def mesh_steps(table):
    """From each mesh of `ensemble`'s table to the next finer: the two meshes' unknowns and the
    relative change of each of ENSEMBLE_KEYS' medians (the finer over the coarser, less 1)."""
    return [(coarse["unknowns"], fine["unknowns"],
             {k: fine[k][0] / coarse[k][0] - 1.0 for k in ENSEMBLE_KEYS})
            for coarse, fine in zip(table, table[1:])]


def draw(folder, paths):
    import matplotlib.pyplot as plt

    os.makedirs(folder, exist_ok=True)
    fig, (pv, profile, rim) = plt.subplots(1, 3, figsize=(14, 4.2))
    for run in paths:
        radius, thickness = panel(run)
        h = runs.read_history(run, required=True)
        name = runs.run_name(run)
        pv.plot(2e-6 * np.asarray(h["full_volume:gas"]), 1e3 * np.asarray(h["pressure:gas"]),
                label=name)
        mesh = runs.read_raw_vtu(runs.last_vtu(run))
        x = mesh.points + mesh.point_data["displacement"]
        profile.plot(np.hypot(x[:, 0], x[:, 2]), x[:, 1], ".", ms=1, label=name)
        angle, r, f = seam(runs.last_vtu(run), radius, thickness)
        rim.plot(angle, r, label=f"{name}: {f['folds']} folds, {f['large folds']} large")
    a, half, volume = paulsen(radius)
    pv.axvline(1e-6 * volume, color="k", ls=":", label="Paulsen's volume")
    pv.set_xlabel("volume of the whole bag [L]")
    pv.set_ylabel("gas pressure [kPa]")
    pv.set_title("pressure against volume (the damped path)")
    px, pz = paulsen_profile(radius)
    profile.plot(px, pz, "k-", label="Paulsen 1994 (inextensible)")
    profile.set_aspect("equal")
    profile.set_xlabel("distance from the axis [mm]")
    profile.set_ylabel("height above the seam [mm]")
    profile.set_title("the panel at the end")
    rim.axhline(a, color="k", ls=":", label="Paulsen's rim radius")
    rim.set_xlabel("angle about the axis [deg]")
    rim.set_ylabel("seam's distance from the axis [mm]")
    rim.set_title("the seam's folds (a quarter)")
    for ax in (pv, profile, rim):
        ax.legend(fontsize=7)
    figures.save(fig, os.path.join(folder, "airbag-full-size.png"))
    print(f"wrote {os.path.join(folder, 'airbag-full-size.png')}")


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--summary", nargs="+", metavar="RUN")
    mode.add_argument("--ensemble", nargs="+", metavar="RUN")
    mode.add_argument("--figures", nargs="+", metavar=("DIR", "RUN"))
    args = parser.parse_args(argv)
    if args.summary:
        print_summary(args.summary)
    elif args.ensemble:
        print_ensemble(args.ensemble)
    else:
        if len(args.figures) < 2:
            parser.error("--figures DIR RUN [RUN ...]")
        draw(args.figures[0], args.figures[1:])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
