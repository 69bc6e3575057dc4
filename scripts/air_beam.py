"""Wrinkling onset and collapse of an air beam, read from runs of validation/air-beam-bending.yaml.

Usage:
  scripts/air-beam RUN [RUN ...]                 the pressure check and one row per run
  scripts/air-beam --figures DIR RUN [RUN ...]   also the study's figures, into DIR
  scripts/air-beam --c1 0.5 ...                  the neo-Hookean c1 of the runs [MPa] (default 0.5)

The model is the half z >= 0 of a tube along x, clamped at x = 0 by the cap `clamp` and pushed
along -y at x = L by the cap `tip` (docs/studies/air-beam.md). Per run:

  pressure check  at the end of the pressure ramp, in the wall slice |X - L/2| <= h/2 (the
                  tetrahedra whose centroid lies there): the current radii r_i, r_o (inner and
                  outer corner nodes), the mean axial and hoop Cauchy stress against the closed
                  tube's p r_i^2 / (r_o^2 - r_i^2) and p r_i / (r_o - r_i) (exact by equilibrium
                  for the wall averages), and the clamp's axial reaction (0: the thrusts balance)
  load            F = -force_y:tip [N], the tip displacement v = -uy:tip [mm], the clamp moment
                  M = |moment_z:clamp| [N mm]; normalised by pi p r^3 / L and pi p r^3, with r the
                  current mid radius (r_i + r_o) / 2 of the pressure check
  onset           the step at which log.txt reports a new instability (the stability check), and
                  the step before it: the onset load lies between the two
  collapse        the largest F of the run, if the curve falls after it (a limit point);
                  otherwise the last F, flagged "rising"
  wrinkles        per written step, on the outer surface, the radial displacement since the end of
                  the pressure ramp, minus its fit a + b cos(phi) + c cos(2 phi) on each section
                  x = const (the section's shift, rotation and ovalisation): what is left, w, is the
                  wrinkling. amplitude = peak-to-peak of w along the compressed generator
                  (phi = 180 deg) over x <= L/2.
"""
import argparse
import functools
import math
import os

import numpy as np

from plisse_study import runs
from plisse_study.figures import plt, save
from plisse_study.runs import read_history, written_steps


WRINKLE_THRESHOLD = 0.1  # wrinkles are visible above this fraction of the wall (the rings' default)


def instability_times(run):
    """Times of the steps where log.txt reports a new instability."""
    return [t for _, t in runs.log_instabilities(run)]


@functools.lru_cache(maxsize=None)
def geometry(run):
    """Reference points, tetrahedra and the tube's dimensions, from the run's first step file."""
    first = runs.read_state(written_steps(run)[0][1])
    X = first.points
    r = np.hypot(X[:, 1], X[:, 2])
    ri, ro, length = r.min(), r.max(), X[:, 0].max()
    cells = first.mesh.cells_dict["tetra10"]
    outer = np.flatnonzero(np.abs(r - ro) < 1e-6 * ro)
    xs = np.unique(np.round(X[outer, 0], 9))
    h = 2.0 * np.diff(xs).min()  # corner spacing: edge nodes halve it
    return X, cells, ri, ro, length, h, outer


def state(path):
    """Displacement per node and Cauchy stress per tetrahedron (3 x 3; the file's 6 components
    are xx, yy, zz, xy, yz, xz)."""
    s = runs.read_state(path)
    return s.displacement, s.stress()


def pressure_check(run, hist):
    """The closed-tube stresses at the end of the pressure ramp (see the module's docstring)."""
    X, cells, _, _, length, h, _ = geometry(run)
    p = hist["pressure:gas"]
    end = int(np.flatnonzero(p >= p.max() * (1 - 1e-12))[0])
    step = int(hist["step"][end])
    files = dict(written_steps(run))
    if step not in files:  # the first written step at full pressure
        step = min(s for s in files if s >= step)
    u, sigma = state(files[step])
    x = X + u
    corners = cells[:, :4]
    centroid = X[corners].mean(axis=1)
    in_slice = np.abs(centroid[:, 0] - length / 2) <= h / 2
    s = sigma[in_slice]
    phi = np.arctan2(centroid[in_slice, 2], centroid[in_slice, 1])
    e_phi = np.stack([np.zeros_like(phi), -np.sin(phi), np.cos(phi)], axis=1)
    hoop = np.einsum("ni,nij,nj->n", e_phi, s, e_phi).mean()
    axial = s[:, 0, 0].mean()
    r0 = np.hypot(X[:, 1], X[:, 2])
    near = np.abs(X[:, 0] - length / 2) <= 1e-9 * length
    r = np.hypot(x[:, 1], x[:, 2])
    ri = r[near & (np.abs(r0 - r0.min()) < 1e-9)].mean()
    ro = r[near & (np.abs(r0 - r0.max()) < 1e-9)].mean()
    pe = p[end]
    return {
        "step": step,
        "p": pe,
        "ri": ri,
        "ro": ro,
        "r": 0.5 * (ri + ro),
        "wall": ro - ri,
        "hoop_strain": 0.5 * (ri + ro) / (0.5 * (r0.min() + r0.max())) - 1.0,
        "axial": axial,
        "axial_closed": pe * ri**2 / (ro**2 - ri**2),
        "hoop": hoop,
        "hoop_closed": pe * ri / (ro - ri),
        "clamp_fx": hist["force_x:clamp"][end],
        "thrust": pe * math.pi * ri**2 / 2,  # on the half model
    }


def wrinkle_field(run, u, u0):
    """w on the outer surface nodes: radial displacement since u0 minus its per-section fit."""
    X, _, _, _, _, _, outer = geometry(run)
    phi = np.arctan2(X[outer, 2], X[outer, 1])
    e_r = np.stack([np.zeros_like(phi), np.cos(phi), np.sin(phi)], axis=1)
    ur = np.einsum("ni,ni->n", u[outer] - u0[outer], e_r)
    w = np.zeros_like(ur)
    xs = np.round(X[outer, 0], 9)
    for x in np.unique(xs):
        k = np.flatnonzero(xs == x)
        A = np.stack([np.ones(len(k)), np.cos(phi[k]), np.cos(2 * phi[k])], axis=1)
        coef, *_ = np.linalg.lstsq(A, ur[k], rcond=None)
        w[k] = ur[k] - A @ coef
    return outer, phi, w


def compressed_row(run, sigma):
    """Wall-averaged axial Cauchy stress of the compressed generator per slice of the mesh: the
    mean sigma_xx of the tetrahedra of the cell row next to phi = 180 deg, in slices
    [j h, (j + 1) h) along x; returns (slice centres, stresses) for x <= L/2."""
    X, cells, _, _, length, h, _ = geometry(run)
    centroid = X[cells[:, :4]].mean(axis=1)
    phi = np.arctan2(centroid[:, 2], centroid[:, 1])
    around = int(round(math.pi / np.diff(np.unique(np.round(np.arctan2(
        X[geometry(run)[6], 2], X[geometry(run)[6], 1]), 9))).min() / 2))
    row = phi > math.pi * (1 - 1.0 / around)
    j = np.floor(centroid[:, 0] / h + 1e-9).astype(int)
    slices = np.arange(int(round(length / 2 / h)))
    return (slices + 0.5) * h, np.array([sigma[row & (j == k), 0, 0].mean() for k in slices])


def bottom_amplitude(run, outer, phi, w):
    X, _, _, _, length, _, _ = geometry(run)
    line = (np.abs(phi - math.pi) < 1e-6) | (np.abs(phi + math.pi) < 1e-6)
    line &= X[outer, 0] <= length / 2
    return w[line].max() - w[line].min() if line.any() else 0.0


def measure(run, c1):
    hist = read_history(run, required=True)
    check = pressure_check(run, hist)
    _, _, ri0, ro0, length, h, _ = geometry(run)
    p, r = check["p"], check["r"]
    bending = hist["time"] > hist["time"][int(np.flatnonzero(hist["pressure:gas"] >= p)[0])]
    F = -hist["force_y:tip"]
    v = -hist["uy:tip"]
    M = np.abs(hist["moment_z:clamp"])
    unit_F = math.pi * p * r**3 / length / 2  # half model: half the force
    unit_M = math.pi * p * r**3 / 2
    onset = None
    for t in instability_times(run):
        k = int(np.argmin(np.abs(hist["time"] - t)))
        if bending[k]:
            onset = (k - 1, k)
            break
    kb = np.flatnonzero(bending)
    kmax = kb[np.argmax(M[kb])]
    limit = kmax < kb[-1] and M[kb[-1]] < M[kmax]
    kfmax = kb[np.argmax(F[kb])]
    # Wall bending: axial buckling stress of the unpressurised wall, E t / (r sqrt(3 (1 - nu^2)))
    # with E = 6 c1 and nu = 1/2, i.e. 4 c1 t / r; N_cr = 4 c1 t^2 / r.
    wall_factor = 1.0 + 2.0 * (4.0 * c1 * check["wall"] ** 2 / r) / (p * r)
    files = written_steps(run)
    u0 = state(dict(files)[check["step"]])[0]
    amplitudes, rows = [], []
    for step, path in files:
        k = int(np.flatnonzero(hist["step"] == step)[0])
        if not bending[k]:
            continue
        u, sigma = state(path)
        outer, phi, w = wrinkle_field(run, u, u0)
        amplitudes.append((k, bottom_amplitude(run, outer, phi, w)))
        rows.append((k, compressed_row(run, sigma)))
    # First slack: the smallest axial stress of the compressed row outside the clamp's first slice
    # reaches 0 (linear interpolation between written steps); M there is M_clamp - F x.
    slack = None
    previous = None
    for k, (xc, sxx) in rows:
        j = 1 + int(np.argmin(sxx[1:]))
        current = (k, sxx[j], xc[j], j)
        if previous and previous[1] > 0.0 >= current[1]:
            f = previous[1] / (previous[1] - current[1])
            ka, kb = previous[0], k
            Fs = F[ka] + f * (F[kb] - F[ka])
            Ms = M[ka] + f * (M[kb] - M[ka]) - Fs * current[2]
            slack = {"F": Fs, "M_local": Ms, "x": current[2], "slice": current[3]}
            break
        previous = current
    if slack:  # membrane theory with the prestress of that slice at the end of the pressure
        prestress = compressed_row(run, state(dict(files)[check["step"]])[1])[1][slack["slice"]]
        slack["theory"] = 0.5 * prestress / check["axial_closed"]
    compression = min(sxx[1:].min() for _, (_, sxx) in rows)
    visible = None
    for (ka, a0), (kb, a1) in zip(amplitudes, amplitudes[1:]):
        threshold = WRINKLE_THRESHOLD * (ro0 - ri0)
        if a0 < threshold <= a1:
            visible = F[ka] + (threshold - a0) / (a1 - a0) * (F[kb] - F[ka])
            break
    return {
        "run": run,
        "check": check,
        "length": length,
        "h": h,
        "t0": ro0 - ri0,
        "F": F,
        "v": v,
        "M": M,
        "bending": bending,
        "unit_F": unit_F,
        "unit_M": unit_M,
        "onset": onset,
        "kmax": kmax,
        "kfmax": kfmax,
        "limit": limit,
        "wall_factor": wall_factor,
        "amplitudes": amplitudes,
        "slack": slack,
        "compression": compression,
        "sigma_cl": 4.0 * c1 * check["wall"] / r,
        "visible": visible,
        "u0": u0,
        "files": files,
        "hist": hist,
    }


def print_run(res):
    c = res["check"]
    print(f"== {res['run']}")
    print(
        f"pressure check (step {c['step']}): p = {c['p']:.4g} MPa, r_i = {c['ri']:.4f}, "
        f"r_o = {c['ro']:.4f}, wall {c['wall']:.4f} mm, hoop strain {100 * c['hoop_strain']:.2f} %"
    )
    print(
        f"  axial stress {c['axial']:.5g} MPa, closed tube p r_i^2/(r_o^2 - r_i^2) = "
        f"{c['axial_closed']:.5g} ({100 * (c['axial'] / c['axial_closed'] - 1):+.2f} %)"
    )
    print(
        f"  hoop stress {c['hoop']:.5g} MPa, p r_i/(r_o - r_i) = {c['hoop_closed']:.5g} "
        f"({100 * (c['hoop'] / c['hoop_closed'] - 1):+.2f} %); clamp axial reaction "
        f"{c['clamp_fx']:.2e} N against the half thrust {c['thrust']:.4g} N"
    )
    uF, uM = res["unit_F"], res["unit_M"]
    print(
        f"theory (half model): F_w = {uF / 2:.4g} N, F_c = {uF:.4g} N (pi p r^3 / L = "
        f"{2 * uF:.4g} N for the whole tube); with the wall's bending stiffness the onset "
        f"x {res['wall_factor']:.3f}"
    )
    F, v, M = res["F"], res["v"], res["M"]
    if res["onset"]:
        a, b = res["onset"]
        print(
            f"onset (stability check) between v = {v[a]:.3f} and {v[b]:.3f} mm: F L/(pi p r^3) "
            f"{F[a] / uF:.3f} - {F[b] / uF:.3f}, M_clamp/(pi p r^3) {M[a] / uM:.3f} - "
            f"{M[b] / uM:.3f} (membrane 0.5, with wall stiffness {0.5 * res['wall_factor']:.3f})"
        )
    else:
        print("onset: the stability check found no instability in the bending phase")
    if res["slack"]:
        sl = res["slack"]
        print(
            f"first slack fibre (compressed row, x = {sl['x']:.2f} mm): F L/(pi p r^3) "
            f"{sl['F'] / uF:.3f}, M there/(pi p r^3) {sl['M_local'] / uM:.3f} (membrane 0.5; "
            f"with the slice's prestress {sl['theory']:.3f})"
        )
    print(
        f"largest axial compression of the compressed row (x >= h): {res['compression']:.4f} MPa"
        f" = {-res['compression'] / res['sigma_cl']:.2f} x the wall's buckling stress 4 c1 t/r ="
        f" {res['sigma_cl']:.4f} MPa"
    )
    if res["visible"]:
        print(f"wrinkles of {WRINKLE_THRESHOLD} t: F L/(pi p r^3) {res['visible'] / uF:.3f}")
    k = res["kmax"]
    print(
        f"{'collapse: largest clamp moment' if res['limit'] else 'clamp moment still rising'} at "
        f"v = {v[k]:.3f} mm: M_clamp/(pi p r^3) {M[k] / uM:.3f} (membrane 1), F L/(pi p r^3) "
        f"{F[k] / uF:.3f}; F = {2 * F[k]:.4g} N for the whole tube"
    )
    k = res["kfmax"]
    print(
        f"largest tip force at v = {v[k]:.3f} mm{' (the last step)' if k == len(F) - 1 else ''}: "
        f"F L/(pi p r^3) {F[k] / uF:.3f} (the lever arm L + u_x shortens as the tip moves)"
    )
    print("wrinkle amplitude along the compressed generator, x <= L/2 (step, v, F L/(pi p r^3), w/t):")
    for kk, a in res["amplitudes"]:
        print(f"  {int(res['hist']['step'][kk]):4d} {v[kk]:8.3f} {F[kk] / uF:7.3f} {a / res['t0']:8.4f}")


def surface_figure(res, k, ax, title):
    """The outer surface near the clamp (x <= L/2) unrolled, angle from the tension side
    (0 deg) to the compressed side (180 deg), coloured by w / t at step row k."""
    import matplotlib.tri as mtri

    run = res["run"]
    X, _, _, _, length, _, outer = geometry(run)
    u = state(dict(res["files"])[int(res["hist"]["step"][k])])[0]
    outer, phi, w = wrinkle_field(run, u, res["u0"])
    keep = X[outer, 0] <= length / 2
    tri = mtri.Triangulation(X[outer[keep], 0], np.degrees(np.abs(phi[keep])))
    values = w[keep] / res["t0"]
    lim = max(np.abs(values).max(), 1e-12)
    m = ax.tripcolor(tri, values, shading="gouraud", cmap="coolwarm", vmin=-lim, vmax=lim)
    ax.set_xlabel("x [mm] (clamp at 0)")
    ax.set_ylabel("angle from the tension side [deg]")
    ax.set_yticks([0, 45, 90, 135, 180])
    ax.set_title(title, fontsize=9)
    return m


def figures(results, folder):
    os.makedirs(folder, exist_ok=True)
    # Load against tip displacement, per pressure, with the theory's lines (whole tube).
    n = len(results)
    fig, axes = plt.subplots(2, n, figsize=(4.2 * n, 6.6), squeeze=False, sharex="col")
    for i, res in enumerate(results):
        ax = axes[1][i]
        b = res["bending"]
        ax.plot(res["v"][b], res["M"][b] / res["unit_M"], "k.-", ms=3, lw=1)
        ax.axhline(0.5, color="tab:blue", ls="--")
        ax.axhline(1.0, color="tab:red", ls="--")
        ax.axhline(0.5 * res["wall_factor"], color="tab:blue", ls=":")
        _, _, ri0, ro0, _, _, _ = geometry(res["run"])
        ax.axhline((0.5 * (ri0 + ro0) / res["check"]["r"]) ** 3, color="tab:red", ls="-.",
                   label=r"$\pi p R^3$: membrane collapse at the clamp's radius")
        ax.plot(res["v"][res["kmax"]], res["M"][res["kmax"]] / res["unit_M"], "s", mfc="none",
                color="tab:red")
        ax.set_xlabel("tip displacement [mm]")
        ax.grid(alpha=0.3)
    axes[1][0].set_ylabel(r"clamp moment $M / (\pi p r^3)$")
    axes[1][0].legend(fontsize=7, loc="lower right")
    for ax, res in zip(axes[0], results):
        c = res["check"]
        F, v, b = 2 * res["F"], res["v"], res["bending"]
        uF = 2 * res["unit_F"]
        ax.plot(v[b], F[b], "k.-", ms=3, lw=1, label="plisse")
        ax.axhline(0.5 * uF, color="tab:blue", ls="--", label="membrane onset $M_w/L$")
        ax.axhline(uF, color="tab:red", ls="--", label="membrane collapse $M_c/L$")
        ax.axhline(0.5 * uF * res["wall_factor"], color="tab:blue", ls=":",
                   label="onset with wall bending")
        if res["onset"]:
            a, k = res["onset"]
            ax.plot(v[k], F[k], "o", mfc="none", color="tab:blue", label="instability found")
        if res["slack"]:
            ax.plot(np.interp(res["slack"]["F"], res["F"][b], v[b]), 2 * res["slack"]["F"], "^",
                    mfc="none", color="tab:blue", label="first slack fibre")
        k = res["kmax"]
        ax.plot(v[k], F[k], "s", mfc="none", color="tab:red", label="largest clamp moment")
        if res["visible"]:
            ax.axvline(np.interp(res["visible"], res["F"][b], v[b]), color="0.5", lw=0.8,
                       label="wrinkles 0.1 t")
        ax.set_title(f"p = {c['p']:.3g} MPa (hoop strain {100 * c['hoop_strain']:.1f} %)",
                     fontsize=9)
        ax.grid(alpha=0.3)
    axes[0][0].set_ylabel("tip force F [N]")
    axes[0][0].legend(fontsize=7)
    save(fig, os.path.join(folder, "load.png"))
    # Normalised, all runs together.
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for res in results:
        b = res["bending"]
        ax.plot(res["v"][b] / res["length"], res["F"][b] / res["unit_F"], ".-", ms=3, lw=1,
                label=f"p = {res['check']['p']:.3g} MPa, h = {res['h']:.2g} mm")
    ax.axhline(0.5, color="tab:blue", ls="--", label="membrane onset")
    ax.axhline(1.0, color="tab:red", ls="--", label="membrane collapse")
    ax.set_xlabel("tip displacement / L")
    ax.set_ylabel(r"$F L / (\pi p r^3)$")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, os.path.join(folder, "load-normalised.png"))
    # The outer surface near the clamp where the wrinkles reach 0.1 t and at the largest clamp
    # moment, per run.
    fig, axes = plt.subplots(2, n, figsize=(4.6 * n, 6.4), squeeze=False)
    for i, res in enumerate(results):
        written = [kk for kk, _ in res["amplitudes"]]
        first = res["kmax"]
        if res["visible"]:
            first = min(written, key=lambda kk: abs(res["F"][kk] - res["visible"]))
        for row, k in enumerate((first, res["kmax"])):
            kw = min(written, key=lambda kk: abs(kk - k))
            m = surface_figure(
                res, kw, axes[row][i],
                f"p = {res['check']['p']:.3g} MPa, F L/(pi p r^3) = "
                f"{res['F'][kw] / res['unit_F']:.2f}")
            fig.colorbar(m, ax=axes[row][i], shrink=0.8, label="w / t")
    save(fig, os.path.join(folder, "surface.png"))
    # Wrinkle amplitude against load.
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for res in results:
        k = [kk for kk, _ in res["amplitudes"]]
        a = [aa / res["t0"] for _, aa in res["amplitudes"]]
        ax.semilogy(res["F"][k] / res["unit_F"], np.maximum(a, 1e-6), ".-",
                    label=f"p = {res['check']['p']:.3g} MPa, h = {res['h']:.2g} mm")
    ax.axvline(0.5, color="tab:blue", ls="--")
    ax.axvline(1.0, color="tab:red", ls="--")
    ax.set_xlabel(r"$F L / (\pi p r^3)$")
    ax.set_ylabel("deviation w along the compressed side,\npeak-to-peak / t")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    save(fig, os.path.join(folder, "amplitude.png"))


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--figures", metavar="DIR")
    parser.add_argument("--c1", type=float, default=0.5, help="neo-Hookean c1 of the runs [MPa]")
    args = parser.parse_args()
    results = [measure(run, args.c1) for run in args.runs]
    for res in results:
        print_run(res)
    if args.figures:
        figures(results, args.figures)


if __name__ == "__main__":
    main()
