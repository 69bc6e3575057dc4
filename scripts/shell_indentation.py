"""Indentation stiffness of a pressurised spherical shell, from runs of
validation/pressurised-shell-indentation.yaml (docs/studies/shell-indentation.md).

Usage:
  scripts/shell-indentation --summary RUN [RUN ...]   stiffness per run against shell theory
  scripts/shell-indentation --sweep DIR [--taus 0,1,2,4,8] [--set KEY=VALUE ...]
                                                      run the case at each tau into DIR/tau-T
  scripts/shell-indentation --figures DIR RUN [...]   the study's figures, into DIR

Per run, from history.csv: the pressure p (column pressure:gas at the end), the force on the
whole sphere F = 4 force_y:indenter (the octant holds a quarter of the azimuth) and the inward
displacement of the mid-surface pole w0 = uy:mid(inflated) - uy:mid, with the inflated position
that of the last step before the indenter touches. The stiffness k is the linear coefficient of a
least-squares fit F = k w0 + c w0^2 over the steps in contact with w0 <= 0.2 t.

Shell theory (shallow shell with an isotropic prestress pR/2, point force at the pole):
  B = E t^3 / (12 (1 - nu^2)), Y = E t, tau = p R^2 / (4 sqrt(B Y)),
  k0 = 8 sqrt(B Y) / R                                          (Reissner 1946)
  k  = k0 (pi/2) sqrt(tau^2 - 1) / artanh(sqrt(1 - tau^-2))      tau > 1
     = k0 (pi/2) sqrt(1 - tau^2) / arctan(sqrt(tau^-2 - 1))      tau < 1
                                          (Vella, Ajdari, Vaziri & Boudaoud 2012, J. R. Soc.
                                           Interface 9, 448-455)
with E = 6 c1 and nu = 1/2 for a neo-Hookean material at small strain (--c1, the case's 1 MPa by
default), R the mid-surface radius and t the wall thickness of the undeformed shell, read from
the run's first step file (--radius and --thickness set them for --sweep only). --figures draws
stiffness.png, force-indentation.png, profiles.png (the dimple against theory, S5 of the study)
and surface.png from the runs of the most frequent R/t, and thickness.png (the difference from
theory against t/R) from runs at several R/t. The same definitions are asserted by
tests/verification/indentation/shell_indentation_slow_test.cpp.
"""
import math
import os
import sys

import numpy as np

from plisse_study import runs, sphere, sweep
from plisse_study.sphere import inflated_pole, pressure_of, tau_of

FIT_DEPTH = 0.2  # fit over w0 <= FIT_DEPTH * t
SYMMETRY_FACTOR = 4.0  # octant: a quarter of the azimuth
ROOT = sweep.ROOT
CASE = os.path.join(ROOT, "validation", "pressurised-shell-indentation.yaml")


def theory(tau, c1, radius, thickness):
    """Point-force stiffness of the shell at dimensionless pressure tau [N/mm]."""
    e = 6.0 * c1
    k0 = 8.0 / 3.0 * e * thickness**2 / radius  # 8 sqrt(BY)/R with nu = 1/2
    if tau < 1e-9:
        return k0
    if abs(tau - 1.0) < 1e-9:
        return k0 * math.pi / 2.0  # the limit of both branches
    if tau > 1.0:
        s = math.sqrt(tau * tau - 1.0)
        return k0 * math.pi / 2.0 * s / math.atanh(math.sqrt(1.0 - 1.0 / tau**2))
    s = math.sqrt(1.0 - tau * tau)
    return k0 * math.pi / 2.0 * s / math.atan(math.sqrt(1.0 / tau**2 - 1.0))


def measure(run, c1):
    radius, thickness = sphere.shell_geometry(run)
    h = sphere.indented_history(run)
    pressure = float(h["pressure:gas"][-1])
    touching = h["contact_nodes:indenter"] > 0
    rest = inflated_pole(run, h)
    points = [(rest - float(u), SYMMETRY_FACTOR * float(f))
              for u, f in zip(h["uy:mid"][touching], h["force_y:indenter"][touching])]
    fit = [(w, f) for w, f in points if 0.0 < w <= FIT_DEPTH * thickness]
    if len(fit) < 3:
        raise SystemExit(f"{run}: fewer than 3 steps with 0 < w0 <= {FIT_DEPTH} t")
    # Least squares F = k w + c w^2 (normal equations of the 2 x 2 system).
    s2 = sum(w**2 for w, _ in fit)
    s3 = sum(w**3 for w, _ in fit)
    s4 = sum(w**4 for w, _ in fit)
    b1 = sum(w * f for w, f in fit)
    b2 = sum(w * w * f for w, f in fit)
    det = s2 * s4 - s3 * s3
    k = (b1 * s4 - b2 * s3) / det
    c = (s2 * b2 - s3 * b1) / det
    tau = tau_of(pressure, c1, radius, thickness)
    return {"run": run, "pressure": pressure, "tau": tau, "k": k, "curvature": c,
            "theory": theory(tau, c1, radius, thickness), "points": points, "n_fit": len(fit),
            "max_w0": max(w for w, _ in points), "radius": radius, "thickness": thickness,
            "k0": theory(0.0, c1, radius, thickness)}


def summary(run_dirs, args):
    print(f"{'run':<24} {'R/t':>5} {'p [MPa]':>10} {'tau':>6} {'k [N/mm]':>10} {'theory':>10} "
          f"{'k/k_th':>7} {'k/k0':>7} {'fit':>4}")
    results = [measure(run, args.c1) for run in run_dirs]
    for m in sorted(results, key=lambda m: (m["radius"] / m["thickness"], m["tau"])):
        print(f"{runs.run_name(m['run']):<24} "
              f"{m['radius'] / m['thickness']:5.0f} {m['pressure']:10.3e} "
              f"{m['tau']:6.2f} {m['k']:10.5f} {m['theory']:10.5f} "
              f"{m['k'] / m['theory']:7.4f} {m['k'] / m['k0']:7.3f} {m['n_fit']:4d}")
    return results


def sweep_points(args):
    """(name, overrides) of each tau of --taus: the pressure, the indenter 0.05 mm above the
    inflated outer pole (its radius is 1 mm), the shell and its probes."""
    points = []
    r, t = args.radius, args.thickness
    shell = sphere.is_shell_case(args.case or CASE)
    for tau in (float(x) for x in args.taus.split(",")):
        p = pressure_of(tau, args.c1, r, t)
        pole = sphere.outer_pole(sphere.inflated_stretch(p, args.c1, r, t), r, t, shell)
        inner = [] if shell else [f"probes[1].point=[0,{r - 0.5 * t:g},0]"]
        points.append((f"tau-{tau:g}", [
            f"loads[0].value={p:.6e}", f"dies[0].point=[0,{pole + 0.05 + 1.0:.6f},0]",
            f"material.c1={args.c1:g}", f"mesh.inner_radius={r - 0.5 * t:g}",
            f"mesh.thickness={t:g}", f"probes[0].point=[0,{r:g},0]"] + inner + (args.set or [])))
    return points


def slenderness(m):
    return round(m["radius"] / m["thickness"])


def figures(directory, results, args):
    """stiffness.png, force-indentation.png, profiles.png and surface.png for the runs of the
    most frequent R/t; thickness.png for the runs at every R/t."""
    import collections

    from plisse_study.figures import plt, save

    os.makedirs(directory, exist_ok=True)
    main_ratio = collections.Counter(slenderness(m) for m in results).most_common(1)[0][0]
    main = sorted((m for m in results if slenderness(m) == main_ratio), key=lambda m: m["tau"])
    fig, ax = plt.subplots(figsize=(5.5, 4))
    taus = [0.02 * i for i in range(0, 901)]
    ax.plot(taus, [theory(t, 1.0, 1.0, 1.0) / theory(0.0, 1.0, 1.0, 1.0) for t in taus], "k-",
            label="shell theory (Reissner 1946; Vella et al. 2012)")
    ax.plot([m["tau"] for m in main], [m["k"] / m["k0"] for m in main], "o", color="C3",
            label=f"plisse, R/t = {main_ratio}")
    ax.set_xlabel(r"$\tau = pR^2/(4\sqrt{BY})$")
    ax.set_ylabel(r"$k / k_0$,  $k_0 = 8\sqrt{BY}/R$")
    ax.set_xlim(0, 18)
    ax.set_ylim(0, None)
    ax.legend(loc="upper left", frameon=False)
    ax.grid(alpha=0.3)
    save(fig, os.path.join(directory, "stiffness.png"))

    fig, ax = plt.subplots(figsize=(5.5, 4))
    for i, m in enumerate(main):
        t = m["thickness"]
        w = [p[0] / t for p in m["points"]]
        f = [p[1] for p in m["points"]]
        ax.plot(w, f, "o", ms=3, color=f"C{i}", label=rf"$\tau$ = {m['tau']:.0f}")
        wl = [0.0, max(w)]
        ax.plot(wl, [m["theory"] * x * t for x in wl], "-", color=f"C{i}", lw=0.8)
    ax.set_xlabel(r"$w_0 / t$")
    ax.set_ylabel("F [N] (whole sphere)")
    ax.set_title(f"R/t = {main_ratio}: plisse (dots), k w0 of shell theory (lines)", fontsize=9)
    ax.legend(frameon=False, fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, os.path.join(directory, "force-indentation.png"))

    fig, ax = plt.subplots(figsize=(5.5, 4))
    for i, tau in enumerate(sorted({round(m["tau"], 6) for m in results})):
        group = sorted((m for m in results if round(m["tau"], 6) == tau),
                       key=lambda m: m["thickness"] / m["radius"])
        if len(group) < 2:
            continue
        x = [m["thickness"] / m["radius"] for m in group]
        y = [100.0 * (1.0 - m["k"] / m["theory"]) for m in group]
        ax.plot(x, y, "o-", color=f"C{i}", label=rf"$\tau$ = {tau:g}")
    ax.set_xlim(0, None)
    ax.set_ylim(0, None)
    ax.set_xlabel("t / R")
    ax.set_ylabel(r"$1 - k/k_{\mathrm{theory}}$ [%]")
    ax.set_title("solid wall against shell theory, R/t = 400, 200, 100", fontsize=9)
    ax.legend(frameon=False, fontsize=8)
    ax.grid(alpha=0.3)
    save(fig, os.path.join(directory, "thickness.png"))
    return main


def bending_length(radius, thickness):
    """l_b = (B R^2 / Y)^(1/4) with nu = 1/2 (B / Y = t^2 / 9)."""
    return (radius**2 * thickness**2 / 9.0) ** 0.25


def theory_profile(rho, tau):
    """w(r) / w(0) of the point-loaded shell, rho = r / l_b: the Hankel transform of
    1 / (q^4 + 2 tau q^2 + 1) (docs/studies/shell-indentation.md, S5)."""
    from scipy import integrate, special

    def transform(x):
        f = lambda q: special.j0(q * x) * q / (q**4 + 2.0 * tau * q * q + 1.0)
        return integrate.quad(f, 0.0, 400.0, limit=2000)[0]

    centre = transform(0.0)
    return [transform(x) / centre for x in rho]


def profile_figure(directory, results):
    from plisse_study.figures import plt, save

    fig, ax = plt.subplots(figsize=(5.5, 4))
    rho = np.linspace(0.0, 6.0, 61)
    ordered = sorted(results, key=lambda m: m["tau"])
    # The lowest, a middle and the highest tau: more curves overlap.
    chosen = [ordered[i] for i in sorted({0, len(ordered) // 2, len(ordered) - 1})]
    for i, m in enumerate(chosen):
        lb = bending_length(m["radius"], m["thickness"])
        files = runs.step_files(m["run"])
        arc, w, _ = sphere.mid_surface_deflection(m["run"], m["radius"], files[-1])
        centre = w[0]
        ax.plot(arc / lb, w / centre, ".", ms=2, color=f"C{i}")
        ax.plot(rho, theory_profile(rho, m["tau"]), "-", color=f"C{i}", lw=1,
                label=rf"$\tau$ = {m['tau']:.1f}")
    ax.set_xlim(0, 6)
    ax.set_xlabel(r"$r / \ell_b$,  $\ell_b = (BR^2/Y)^{1/4}$")
    ax.set_ylabel(r"$w / w_0$")
    ax.set_title("mid-surface deflection: plisse (dots), shell theory (lines)", fontsize=9)
    ax.axhline(0.0, color="k", lw=0.5)
    ax.legend(frameon=False, fontsize=8)
    save(fig, os.path.join(directory, "profiles.png"))


def surface_figure(directory, results):
    """Top view of the dimple (outer surface about the pole), coloured by the inward normal
    displacement since the inflated state, for the lowest and the highest tau."""
    from plisse_study.figures import disc_map, mirrored_quarter, plt, save

    chosen = sorted(results, key=lambda m: m["tau"])
    chosen = [chosen[0], chosen[-1]] if len(chosen) > 1 else chosen
    fig, axes = plt.subplots(1, len(chosen), figsize=(4.6 * len(chosen), 4.2), squeeze=False)
    for ax, m in zip(axes[0], chosen):
        lb = bending_length(m["radius"], m["thickness"])
        files = runs.step_files(m["run"])
        arc, w, x = sphere.mid_surface_deflection(m["run"], m["radius"], files[-1])
        near = np.hypot(x[:, 0] / lb, x[:, 2] / lb) < 5.0
        points = mirrored_quarter(x[near, 0] / lb, x[near, 2] / lb, w[near] / w[0])
        c = disc_map(ax, points, np.linspace(-0.1, 1.0, 23), "viridis")
        ax.set_aspect("equal")
        ax.set_title(rf"$\tau$ = {m['tau']:.1f},  $w_0$ = {w[0]:.3f} mm", fontsize=9)
        ax.set_xlabel(r"$x / \ell_b$")
        ax.set_ylabel(r"$z / \ell_b$")
        fig.colorbar(c, ax=ax, label=r"$w / w_0$ (inward normal displacement)", shrink=0.85)
    save(fig, os.path.join(directory, "surface.png"))


def main():
    parser = sphere.indentation_parser(__doc__, "0,1,2,4,8", 200.0, "mesh.element_size=5")
    args = parser.parse_args()
    if args.sweep:
        sweep.sweep(args.case or CASE, args.sweep, sweep_points(args), check=True)
        return
    if not args.runs:
        parser.error("no run directories")
    results = summary(args.runs, args)
    if args.figures:
        main_runs = figures(args.figures, results, args)
        profile_figure(args.figures, main_runs)
        surface_figure(args.figures, main_runs)


if __name__ == "__main__":
    sys.exit(main())
