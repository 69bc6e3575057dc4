"""Wrinkles of a pressurised spherical shell indented at its pole, from runs of
validation/pressurised-shell-wrinkles.yaml (docs/studies/shell-wrinkles.md).

Usage:
  scripts/shell-wrinkles --summary RUN [RUN ...]   onsets and wrinkle counts, in the theory's units
  scripts/shell-wrinkles --sweep DIR [--taus 4,8] [--depth D] [--set KEY=VALUE ...]
                                                   run the case at each tau into DIR/tau-T
  scripts/shell-wrinkles --figures DIR RUN [...]   the study's figures, into DIR

Units of the shallow-shell equations about the pressurised sphere (Vella, Ajdari, Vaziri &
Boudaoud 2011), with B = E t^3 / 9, Y = E t (nu = 1/2) and E = 6 c1:
  tau = p R^2 / (4 sqrt(B Y)),  l_p = R (p R / Y)^(1/2),  depth unit l_p^2 / R = p R^2 / Y.

Per run, from history.csv and summary.json: the inward displacement of the mid-surface pole w0
since the inflated state (probe `mid`; the inflated state is the last step before the indenter
touches), and
  - the compression onset: the first step whose `wrinkled_fraction` (area of the measured surface
    with a compressive principal membrane stress) is positive, bracketed by the step before;
  - the wrinkling onset: the first instability of summary.json (the tangent loses positive
    definiteness; the run switches branch along its mode there) or the first step with a
    wrinkled ring (amplitude above 0.1 t), whichever comes first (a mesh that is not exactly
    axisymmetric can let the wrinkles grow without a bifurcation), bracketed by the step before;
  - the wrinkle count m: `wrinkle_peak_count` of the ring with the largest amplitude at the first
    step from the onset where it has a wrinkle peak (docs/case-file.md, Wrinkle metrics), and at the last step.
The octant (mirrors x = 0, z = 0) holds only even m. --summary also fits the exponents of
w0_c and m against tau over the runs given (theory: 1 and 1/2).
"""
import math
import os
import sys

import numpy as np

from plisse_study import fits, runs, sphere, sweep
from plisse_study.sphere import inflated_pole

ROOT = sweep.ROOT
CASE = os.path.join(ROOT, "validation", "pressurised-shell-wrinkles.yaml")
RING_RADII = (0.5, 0.75, 1.0, 1.25, 1.5, 2.0)  # rings at these multiples of l_p from the axis
DEPTH = 6.0  # default indenter travel in units of p R^2 / Y (--depth)
INDENTER = 0.1  # indenter radius / l_p
CAP = 2.0  # refined cap radius / l_p


def units(pressure, c1, radius, thickness):
    """(tau, l_p, p R^2 / Y)."""
    y = 6.0 * c1 * thickness
    return (sphere.tau_of(pressure, c1, radius, thickness), radius * math.sqrt(pressure * radius / y),
            pressure * radius**2 / y)


def measure(run, c1):
    radius, thickness = sphere.shell_geometry(run)
    h = sphere.indented_history(run)
    pressure = float(h["pressure:gas"][-1])
    tau, lp, unit = units(pressure, c1, radius, thickness)
    depth = inflated_pole(run, h) - h["uy:mid"]
    touching = h["contact_nodes:indenter"] > 0
    result = {"run": run, "radius": radius, "thickness": thickness, "pressure": pressure,
              "tau": tau, "lp": lp, "unit": unit,
              "force": [(float(w), 4.0 * float(f)) for w, f in
                        zip(depth[touching], h["force_y:indenter"][touching])]}
    compressed = np.flatnonzero(h["wrinkled_fraction"] > 0.0)
    result["compression"] = fits.bracket(depth, compressed[0]) if len(compressed) else None
    events = runs.summary_instabilities(runs.read_summary(run, required=True))
    first = events[0]["step"] if events else None
    result["mode_count"] = mode_count(os.path.join(run, events[0]["file"]), lp) if events else 0
    shown = np.flatnonzero(((h["step"] == first) if first is not None else False)
                           | (h["wrinkle_amplitude"] > 0.1 * thickness))
    result["onset"] = fits.bracket(depth, shown[0]) if len(shown) else None
    counts = h["wrinkle_peak_count"].astype(int)
    counted = [k for k in range(shown[0], len(counts)) if counts[k] > 0] if len(shown) else []
    result["count"] = int(counts[counted[0]]) if counted else 0
    result["ring"] = wrinkled_ring(run, int(h["step"][counted[0]]), radius) if counted else None
    result["last_count"] = int(counts[-1])
    result["last_w0"] = float(depth[-1])
    return result


def wrinkled_ring(run, step, radius):
    """Distance from the axis of the ring with the largest wrinkle amplitude at `step` [mm]."""
    best = (0.0, None)
    for row in runs.read_spectrum(run):
        if int(row["step"]) == step and row["in_band"] == "1":
            latitude = float(row["latitude_deg"])
            amplitude = float(row["amplitude"])
            if amplitude > best[0]:
                best = (amplitude, radius * math.cos(math.radians(latitude)))
    return best[1]


def mode_count(step_file, lp):
    """Full-circle count of the critical mode (`mode_1` of the step file at the instability): the
    even harmonic cos(m theta) with the largest amplitude of the mode's normal component on the
    outer nodes of the ring 0.5 ... 2 l_p from the axis where it is largest."""
    mesh = runs.read_state(step_file).mesh
    x = mesh.points
    norm = np.linalg.norm(x, axis=1)
    normal_part = (mesh.point_data["mode_1"] * x).sum(axis=1) / norm
    distance = np.hypot(x[:, 0], x[:, 2])
    theta = np.arctan2(x[:, 2], x[:, 0])
    outer = norm > np.median(norm)
    best = (0.0, 0)
    for f in RING_RADII:
        ring = outer & (np.abs(distance - f * lp) < 0.025 * lp)
        if ring.sum() < 8:
            continue
        for m in range(2, 61, 2):
            c = np.cos(m * theta[ring])
            amplitude = abs((normal_part[ring] * c).sum() / (c * c).sum())
            if amplitude > best[0]:
                best = (amplitude, m)
    return best[1]


middle = fits.middle


def summary(run_dirs, args):
    results = sorted((measure(run, args.c1) for run in run_dirs), key=lambda m: m["tau"])
    print(f"{'run':<14} {'R/t':>5} {'tau':>6} {'l_p':>7} {'pR2/Y':>7} "
          f"{'compression w0/(pR2/Y)':>23} {'wrinkling w0/(pR2/Y)':>21} {'mode m':>6} {'m':>3} "
          f"{'m/tau^.5':>8} {'ring/l_p':>8} {'last m':>6} {'at w0/(pR2/Y)':>13}")
    for m in results:
        unit = m["unit"]
        c = m["compression"]
        b = m["onset"]
        fmt = lambda pair: f"{pair[0] / unit:9.2f} - {pair[1] / unit:5.2f}" if pair else "none"
        ring = f"{m['ring'] / m['lp']:8.2f}" if m["ring"] else f"{'-':>8}"
        print(f"{runs.run_name(m['run']):<14} "
              f"{m['radius'] / m['thickness']:5.0f} {m['tau']:6.2f} {m['lp']:7.1f} {unit:7.3f} "
              f"{fmt(c):>23} {fmt(b):>21} {m['mode_count']:6d} {m['count']:3d} "
              f"{m['count'] / math.sqrt(m['tau']):8.2f} {ring} {m['last_count']:6d} "
              f"{m['last_w0'] / unit:13.2f}")
    compression = [(m["tau"], middle(m["compression"])) for m in results if m["compression"]]
    onset = [(m["tau"], middle(m["onset"])) for m in results if m["onset"]]
    counts = [(m["tau"], m["count"]) for m in results if m["count"] > 0]
    if len(compression) > 1:
        print(f"exponent of tau in the compression onset: {fits.log_slope(compression):.3f} "
              f"(theory 1: w0 = C p R^2 / Y)")
    if len(onset) > 1:
        print(f"exponent of tau in the wrinkles' onset: {fits.log_slope(onset):.3f} "
              f"(tends to 1 as bending fades)")
    if len(counts) > 1:
        print(f"exponent of tau in the wrinkle count m: {fits.log_slope(counts):.3f} (theory 1/2)")
    return results


def sweep_points(args):
    """(name, overrides) of each tau of --taus: the pressure, the shell, the indenter of radius
    INDENTER l_p 0.05 mm above the inflated outer pole and moving --depth p R^2 / Y, the refined
    cap, the rings, and steps as fine at a larger tau's longer travel."""
    points = []
    r, t, c1 = args.radius, args.thickness, args.c1
    shell = sphere.is_shell_case(args.case or CASE)
    for tau in (float(x) for x in args.taus.split(",")):
        p = sphere.pressure_of(tau, c1, r, t)
        _, lp, unit = units(p, c1, r, t)
        pole = sphere.outer_pole(sphere.inflated_stretch(p, c1, r, t), r, t, shell)
        a = INDENTER * lp
        rings = ",".join(f"{math.degrees(math.acos(f * lp / r)):.4f}" for f in RING_RADII)
        # The case's steps move the indenter by 1.35 mm; as fine at a larger tau's longer travel.
        scale = max(1.0, tau / 8.0) * args.depth / DEPTH
        points.append((f"tau-{tau:g}", [
            f"loads[0].value={p:.6e}", f"material.c1={c1:g}",
            f"mesh.inner_radius={r - 0.5 * t:g}", f"mesh.thickness={t:g}",
            f"mesh.pole_radius={CAP * lp:.3f}", f"dies[0].radius={a:.4f}",
            f"dies[0].point=[0,{pole + 0.05 + a:.6f},0]",
            f"dies[0].move.displacement=[0,{-(args.depth * unit + 0.05):.4f},0]",
            f"probes[0].point=[0,{r:g},0]", f"output.wrinkles.rings_deg=[{rings}]",
            f"solver.steps={round(55 * scale)}", f"solver.max_step={0.02 / scale:.6g}"]
            + (args.set or [])))
    return points


def wrinkle_field(run, radius, step_file, lp):
    """Mid-surface nodes between 0.25 and 2.2 l_p from the axis: (x, z, deviation of the inward
    normal displacement since the inflated state from its axisymmetric part: the mean over bins of
    l_p / 40 in the distance from the pole, interpolated linearly between the bins)."""
    arc, w, x = sphere.mid_surface_deflection(run, radius, step_file)
    bins = np.floor(arc / (lp / 40.0)).astype(int)
    count = np.bincount(bins)
    filled = count > 0
    centre = (np.bincount(bins, weights=arc)[filled] / count[filled])
    mean = np.bincount(bins, weights=w)[filled] / count[filled]
    deviation = w - np.interp(arc, centre, mean)
    distance = np.hypot(x[:, 0], x[:, 2])
    keep = (distance > 0.25 * lp) & (distance < 2.2 * lp)
    return x[keep, 0], x[keep, 2], deviation[keep]


def figures(directory, results):
    from plisse_study.figures import disc_map, mirrored_quarter, plt, save

    os.makedirs(directory, exist_ok=True)
    # Onsets against tau, in units of p R^2 / Y.
    fig, axes = plt.subplots(1, 2, figsize=(10, 3.9))
    ax = axes[0]
    for key, label, colour in (("compression", "hoop compression (tension field)", "C0"),
                               ("onset", "wrinkles (bifurcation)", "C3")):
        pts = [(m["tau"], middle(m[key]) / m["unit"], 0.5 * (m[key][1] - m[key][0]) / m["unit"])
               for m in results if m[key]]
        if pts:
            ax.errorbar([p[0] for p in pts], [p[1] for p in pts], yerr=[p[2] for p in pts],
                        fmt="o", color=colour, capsize=3, label=label)
    ax.set_xlabel(r"$\tau = pR^2/(4\sqrt{BY})$")
    ax.set_ylabel(r"onset $w_0 \,/\, (pR^2/Y)$")
    ax.set_xlim(0, None)
    ax.set_ylim(0, None)
    ax.legend(frameon=False, fontsize=8)
    ax.grid(alpha=0.3)
    ax = axes[1]
    pts = [(m["tau"], m["count"]) for m in results if m["count"]]
    if pts:
        ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", color="C3",
                label="plisse, where the wrinkles appear")
        taus = np.linspace(0.0, max(p[0] for p in pts) * 1.5, 100)
        c = np.exp(np.mean([math.log(m / math.sqrt(t)) for t, m in pts]))
        ax.plot(taus, c * np.sqrt(taus), "k-", lw=1, label=rf"$m = {c:.2f}\,\tau^{{1/2}}$")
    ax.set_xlabel(r"$\tau$")
    ax.set_ylabel("wrinkle count m")
    ax.set_xlim(0, None)
    ax.set_ylim(0, None)
    ax.legend(frameon=False, fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, os.path.join(directory, "onset.png"))

    # The wrinkled dimple of each run at its last step, top view, full disc by mirroring.
    fig, axes = plt.subplots(1, len(results), figsize=(4.4 * len(results), 4.0), squeeze=False)
    for ax, m in zip(axes[0], results):
        files = runs.step_files(m["run"])
        x, z, dev = wrinkle_field(m["run"], m["radius"], files[-1], m["lp"])
        points = mirrored_quarter(x / m["lp"], z / m["lp"], dev / m["thickness"])
        limit = max(1e-6, np.percentile(np.abs(points[:, 2]), 99))
        c = disc_map(ax, points, np.linspace(-limit, limit, 21), "RdBu_r")
        ax.set_aspect("equal")
        ax.set_title(rf"$\tau$ = {m['tau']:.0f}, $w_0$ = {m['last_w0'] / m['unit']:.1f} $pR^2/Y$,"
                     f" m = {m['last_count']}", fontsize=9)
        ax.set_xlabel(r"$x / \ell_p$")
        ax.set_ylabel(r"$z / \ell_p$")
        fig.colorbar(c, ax=ax, label="normal deviation from the ring mean / t", shrink=0.85)
    save(fig, os.path.join(directory, "wrinkles.png"))

    # Force against indentation, in the theory's units.
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for i, m in enumerate(results):
        w = [p[0] / m["unit"] for p in m["force"]]
        f = [p[1] / (m["pressure"] * m["lp"] ** 2) for p in m["force"]]
        ax.plot(w, f, "-", color=f"C{i}", label=rf"$\tau$ = {m['tau']:.0f}")
        if m["onset"]:
            ax.axvline(middle(m["onset"]) / m["unit"], color=f"C{i}", ls=":", lw=1)
    ax.set_xlabel(r"$w_0 \,/\, (pR^2/Y)$")
    ax.set_ylabel(r"$F \,/\, (p\,\ell_p^2)$")
    ax.legend(frameon=False, fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, os.path.join(directory, "force.png"))


def main():
    parser = sphere.indentation_parser(__doc__, "4,8", 1000.0, "mesh.pole_element_size=4")
    parser.add_argument("--depth", type=float, default=DEPTH,
                        help="indenter travel in units of p R^2 / Y (--sweep)")
    args = parser.parse_args()
    if args.sweep:
        sweep.sweep(args.case or CASE, args.sweep, sweep_points(args), check=True)
        return
    if not args.runs:
        parser.error("no run directories")
    results = summary(args.runs, args)
    if args.figures:
        figures(args.figures, results)


if __name__ == "__main__":
    sys.exit(main())
