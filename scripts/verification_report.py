"""Measures the verification runs into a record and writes docs/verification.md from that record.

Usage: /usr/bin/python3 scripts/verification_report.py [--run-time SECONDS] RUNS_DIR [DOCS_DIR]
           measure: every number of the page's tables from the runs, with the commit, the date
           and the run time of the runs (SECONDS, as scripts/verification-report passes it; "not
           measured" without it), into DOCS_DIR/verification/record.json, and the figures, which
           need the curves, into DOCS_DIR/figures; then render the page from the record
       /usr/bin/python3 scripts/verification_report.py --render [DOCS_DIR]
           rewrite DOCS_DIR/verification.md from DOCS_DIR/verification/record.json, without runs
       /usr/bin/python3 scripts/verification_report.py --check [DOCS_DIR]
           exit 1 when DOCS_DIR/verification.md is not what its record renders (a unit test)
DOCS_DIR defaults to the repository's docs/. The record is the one source of the page's numbers:
the measure step keeps them at full precision and the render step alone formats them, so the same
record always gives the same page. Measuring refuses a cube whose error is not below the
tolerance its test asserts, before anything is written.
Needs Debian's python3-matplotlib, python3-numpy and python3-yaml to measure (hence
/usr/bin/python3); rendering and checking need Python alone.
"""
import argparse
import datetime
import difflib
import json
import math
import sys
from pathlib import Path

from plisse_study.provenance import tree_commit

ROOT = Path(__file__).resolve().parent.parent
COMMAND = "scripts/verification-report"

# The tolerances the tests assert on what the tables below print (tests/verification): a report
# whose number exceeds them is refused, so the page never prints what the test would fail.
CUBE_TOLERANCE = 1e-10  # cube_tension_test.cpp, kTolerance
INELASTIC_TOLERANCE = 1e-11  # inelastic/inelastic_run_test.cpp, kTolerance

CUBES = ["cube-tension-neo-hookean", "cube-tension-mooney-rivlin", "cube-tension-fung",
         "cube-tension-ogden"]
ELEMENTS = [("", "mini"), ("-th", "taylor-hood")]  # run-name suffix, element


def fail(message, status=2):
    print(f"verification-report: {message}", file=sys.stderr)
    sys.exit(status)


def claim_holds(run, error, tolerance):
    if not error < tolerance:
        sys.exit(f"verification-report: {run}: error {error:.3e} is above the {tolerance:g} "
                 "its test asserts")


def record_path(docs):
    return docs / "verification" / "record.json"


# Measure: runs -> numbers (and figures).

def read_history(path):
    """The columns of a history.csv file; stops at a missing file."""
    from plisse_study.runs import history_columns
    return history_columns(path, required=True)


def read_summary(run_dir):
    return json.loads((run_dir / "summary.json").read_text())


def material(case_yaml):
    """The `material:` map of an example."""
    import yaml
    return yaml.safe_load(Path(case_yaml).read_text())["material"]


def sigma_zz(mat, lam):
    if mat["model"] == "neo-hookean":
        return 2 * mat["c1"] * (lam**2 - 1 / lam)
    if mat["model"] == "mooney-rivlin":
        return 2 * mat["c1"] * (lam**2 - 1 / lam) - 2 * mat["c2"] * (1 / lam**2 - lam)
    if mat["model"] == "fung":
        i1 = lam**2 + 2 / lam
        return mat["mu"] * math.exp(mat["gamma"] * (i1 - 3)) * (lam**2 - 1 / lam)
    if mat["model"] == "ogden":  # Ogden (1972), eq. 4.4 with the lateral stresses zero
        return sum(mat.get(f"mu{p}", 0.0) * (lam ** mat.get(f"alpha{p}", 0.0) - lam ** (-mat.get(f"alpha{p}", 0.0) / 2))
                   for p in (1, 2, 3))
    raise ValueError(mat["model"])


def ogden_pressure(dW, lambda_a, A=10.0, B=15.0, n=600):
    """P(λa) = ∫_{λb}^{λa} Ŵ'(λ)/(λ³ − 1) dλ by composite Simpson (Ogden, section 5.3.1)."""
    lambda_b = (1.0 + (A / B) ** 3 * (lambda_a**3 - 1.0)) ** (1.0 / 3.0)
    h = (lambda_a - lambda_b) / n
    f = lambda l: dW(l) / (l**3 - 1.0)
    total = f(lambda_b) + f(lambda_a) + sum((4 if i % 2 else 2) * f(lambda_b + i * h) for i in range(1, n))
    return total * h / 3.0


def measure_cube_tension(runs, figures):
    """The sliding-ends cubes, both elements: each error against the closed form of σzz."""
    from plisse_study.figures import plt
    rows = []
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for name in CUBES:
        mat = material(ROOT / "examples" / f"{name}.yaml")
        for suffix, element in ELEMENTS:
            h = read_history(runs / f"{name}{suffix}" / "history.csv")
            lam = h["stretch"]
            exact = [sigma_zz(mat, l) for l in lam]
            err = max(abs(a - b) / abs(b) for a, b in zip(h["cauchy_zz"], exact))
            claim_holds(f"{name}{suffix}", err, CUBE_TOLERANCE)
            rows.append({"run": f"{name}{suffix}", "case": name, "element": element,
                         "material": mat, "steps": len(lam),
                         "newton_iterations": int(sum(h["newton_iterations"])),
                         "max_relative_error_sigma_zz": err})
        h = read_history(runs / name / "history.csv")
        lam = h["stretch"]
        fine = [1 + 4 * i / 200 for i in range(1, 201)]
        line, = ax.plot(fine, [sigma_zz(mat, l) for l in fine], lw=1)
        ax.plot(lam, h["cauchy_zz"], "o", ms=4, color=line.get_color(), label=f"{mat['model']}: plisse")
    ax.set_xlabel("stretch λ")
    ax.set_ylabel("Cauchy stress σzz [MPa]")
    ax.set_yscale("log")
    ax.set_title("Cube tension: plisse (markers) and closed form (lines)")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figures / "cube-tension.png", dpi=120)
    return {"tolerance": CUBE_TOLERANCE, "rows": rows}


def measure_cube_sticking(runs, figures):
    """The stuck cube on three meshes: die force at stretch 5, order, extrapolation."""
    from plisse_study.figures import plt
    name = "cube-tension-sticking"
    mat = material(ROOT / "examples" / f"{name}.yaml")
    a0 = 25.0
    fig, ax = plt.subplots(figsize=(6, 4.2))
    meshes = []
    for run, divisions in [(f"{name}-3", 3), (name, 6), (f"{name}-12", 12)]:
        h = read_history(runs / run / "history.csv")
        summary = read_summary(runs / run)
        # The die travels 20 mm on a linear ramp over the whole run.
        lam = [1 + 20.0 * lf / 5.0 for lf in h["load_factor"]]
        ax.plot(lam, h["force_z:die"], "o-", ms=2.5, label=f"plisse, {divisions} divisions per edge")
        meshes.append((run, divisions, summary, h["force_z:die"][-1]))
    homogeneous = [sigma_zz(mat, l) * a0 / l for l in lam]
    ax.plot(lam, homogeneous, "k--", label="homogeneous closed form σzz(λ) A0/λ")
    ax.set_xlabel("nominal stretch λ = 1 + die travel / 5 mm")
    ax.set_ylabel("die force [N]")
    ax.set_title("Cube tension with bilateral sticking (Mooney-Rivlin)")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figures / "cube-tension-sticking.png", dpi=120)
    rows = [{"run": run, "divisions": divisions, "tetrahedra": summary["elements"],
             "unknowns": summary["free_dofs"], "steps": summary["steps"],
             "newton_iterations": summary["newton_iterations"], "die_force": force,
             "ratio_to_homogeneous": force / homogeneous[-1]}
            for run, divisions, summary, force in meshes]
    f1, f2, f3 = (m[3] for m in meshes)
    order = math.log((f1 - f2) / (f2 - f3)) / math.log(2.0)
    extrapolated = f3 - (f2 - f3) / (2.0**order - 1.0)
    return {"rows": rows, "homogeneous_force": homogeneous[-1], "observed_order": order,
            "extrapolated_force": extrapolated,
            "extrapolated_ratio_to_homogeneous": extrapolated / homogeneous[-1]}


def measure_inelastic_cubes(runs, figures):
    """The viscoelastic and Mullins cubes (docs/theory/materials.md, V7 and MR2-MR3)."""
    from plisse_study.figures import plt
    c1, area = 0.25, 25.0
    rows = []
    beta, tau = (0.8, 0.3), (0.5, 4.0)

    def s_axial_lateral(lam):
        i1 = lam**2 + 2 / lam
        return 2 * c1 * (1 - i1 / (3 * lam**2)), 2 * c1 * (1 - i1 * lam / 3)

    def relaxation(h):
        times, lams, out = [0.0], [1.0], []
        for t, lam in zip(h["time"], h["stretch_z"]):
            times.append(t)
            lams.append(lam)
            sa, sl = s_axial_lateral(lam)
            for k in range(1, len(times)):
                for b_i, t_i in zip(beta, tau):
                    d = b_i * math.exp(-(t - 0.5 * (times[k - 1] + times[k])) / t_i)
                    a1, l1 = s_axial_lateral(lams[k])
                    a0, l0 = s_axial_lateral(lams[k - 1])
                    sa += d * (a1 - a0)
                    sl += d * (l1 - l0)
            out.append(lam * sa - sl / lam**2)
        return out

    def mullins(h, r=2.0, m=0.05, b=0.1):
        wmax, out = 0.0, []
        for lam in h["stretch_z"]:
            w = c1 * (lam**2 + 2 / lam - 3)
            wmax = max(wmax, w)
            eta = 1 - math.erf((wmax - w) / (m + b * wmax)) / r
            out.append(eta * 2 * c1 * (lam - 1 / lam**2))
        return out

    scale = 2 * c1 * (2.0 - 0.25)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.2))
    for name, exact, ax in [("cube-relaxation-viscoelastic", relaxation, ax1),
                            ("cube-cycles-mullins", mullins, ax2)]:
        for suffix, element in ELEMENTS:
            h = read_history(runs / f"{name}{suffix}" / "history.csv")
            p = [f / area for f in h["force_z:top"]]
            e = exact(h)
            err = max(abs(a - b) for a, b in zip(p, e)) / scale
            claim_holds(f"{name}{suffix}", err, INELASTIC_TOLERANCE)
            rows.append({"run": f"{name}{suffix}", "case": name, "element": element,
                         "steps": len(p), "newton_iterations": int(sum(h["newton_iterations"])),
                         "max_error_over_p_inf": err})
            if suffix == "":
                x = h["time"] if name.startswith("cube-relaxation") else h["stretch_z"]
                ax.plot(x, p, "o", ms=3, label="plisse (MINI)", zorder=3)
    # The closed forms on fine grids: the relaxation after a jump at 0.01 s, the cycles' load curve.
    t = [0.02 * 1000 ** (k / 400) for k in range(401)]
    ax1.plot(t, [scale * (1 + sum(b_i * math.exp(-(x - 0.01) / t_i) for b_i, t_i in zip(beta, tau)))
                 for x in t], "k-", lw=1, label="closed form")
    corners = [(0, 0), (1, 1), (2, 0), (3, 1), (4, 0), (5, 1.5), (6, 0)]
    path = []
    for (t0, f0), (t1, f1) in zip(corners, corners[1:]):
        path += [1 + (f0 + (f1 - f0) * k / 200) for k in range(200)]
    ax2.plot(path, mullins({"stretch_z": path}), "k-", lw=1, label="closed form")
    ax1.axhline(scale, color="gray", ls=":", label="equilibrium P∞")
    ax1.set_xscale("log")
    ax1.set_xlabel("time [s]")
    ax1.set_ylabel("nominal stress P [MPa]")
    ax1.set_title("Relaxation at stretch 2")
    ax2.set_xlabel("stretch λ")
    ax2.set_ylabel("nominal stress P [MPa]")
    ax2.set_title("Mullins cycles to 2, 2, 2.5")
    for ax in (ax1, ax2):
        ax.legend()
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figures / "cube-inelastic.png", dpi=120)
    return {"tolerance": INELASTIC_TOLERANCE, "rows": rows}


def sphere_neo_hookean_dW(stretch):
    """Ŵ'(λ) of the thick sphere's neo-Hookean material (c1 = 0.5 MPa) in Ogden's closed form."""
    return 4 * 0.5 * (stretch - stretch**-5)


def sphere_pressure_error(h, dW):
    """The largest relative error of the thick sphere's pressure against Ogden's closed form over
    the steps of the history columns `h` (inner radius 10 mm, probe `inner`)."""
    lam = [1 + u / 10.0 for u in h["ux:inner"]]
    return max(abs(p - ogden_pressure(dW, l)) / p for p, l in zip(h["pressure:gas"], lam))


def measure_sphere_inflation(runs, figures):
    """The thick sphere on three meshes and both elements against Ogden's closed form."""
    from plisse_study.figures import plt
    nh = sphere_neo_hookean_dW
    mr = lambda l: 4 * 0.4 * (l - l**-5) + 4 * 0.1 * (l**3 - l**-3)
    rows = []
    fig, ax = plt.subplots(figsize=(6, 4.2))
    for run, label, dW, size, layers in [("sphere-inflation-3", "neo-Hookean", nh, 1.4, 3),
                                         ("sphere-inflation-4", "neo-Hookean", nh, 1.0, 4),
                                         ("sphere-inflation-6", "neo-Hookean", nh, 0.7, 6),
                                         ("sphere-inflation-mr", "Mooney-Rivlin", mr, 0.7, 6),
                                         ("sphere-inflation-th-2.0-1", "neo-Hookean", nh, 2.0, 1),
                                         ("sphere-inflation-th-1.5-2", "neo-Hookean", nh, 1.5, 2),
                                         ("sphere-inflation-th-1.0-2", "neo-Hookean", nh, 1.0, 2),
                                         ("sphere-inflation-th-0.7-3", "neo-Hookean", nh, 0.7, 3)]:
        h = read_history(runs / run / "history.csv")
        summary = read_summary(runs / run)
        lam = [1 + u / 10.0 for u in h["ux:inner"]]
        err = sphere_pressure_error(h, dW)
        rows.append({"run": run, "material": label, "element": summary.get("element", "mini"),
                     "element_size": size, "layers": layers, "tetrahedra": summary["elements"],
                     "unknowns": summary["free_dofs"], "max_relative_error_p": err})
        if layers == 6:
            fine = [1 + 0.6 * i / 100 for i in range(1, 101)]
            line, = ax.plot(fine, [ogden_pressure(dW, l) for l in fine], lw=1, label=f"{label}: closed form")
            ax.plot(lam, h["pressure:gas"], "o", ms=4, color=line.get_color(), label=f"{label}: plisse")
    ax.set_xlabel("inner stretch λa")
    ax.set_ylabel("pressure [MPa]")
    ax.set_title("Thick sphere (B/A = 1.5) under internal pressure")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figures / "sphere-inflation.png", dpi=120)
    return {"rows": rows}


def measure_balloon(runs, figures):
    """The thin balloon through its pressure maximum (examples/balloon-limit-point.yaml)."""
    import numpy
    from plisse_study.figures import plt
    c1, A, B = 0.1, 20.0, 21.0
    dW = lambda l: 4 * c1 * (l - l**-5)
    h = read_history(runs / "balloon-limit-point" / "history.csv")
    lam = [1 + u / A for u in h["ux:inner"]]
    p = h["pressure:balloon"]
    i = max(range(1, len(p) - 1), key=lambda k: p[k])
    # Vertex of the parabola through the three points around the largest pressure.
    a, b, c = numpy.polyfit(lam[i - 1:i + 2], p[i - 1:i + 2], 2)
    lam_max = -b / (2 * a)
    p_max = numpy.polyval([a, b, c], lam_max)
    fine = [1 + 0.7 * k / 300 for k in range(1, 301)]
    exact = [ogden_pressure(dW, l, A, B) for l in fine]
    k = max(range(len(exact)), key=lambda j: exact[j])
    near = [fine[k] - 0.004 + 0.008 * j / 400 for j in range(401)]
    exact_max, lam_exact = max((ogden_pressure(dW, l, A, B), l) for l in near)
    thin = [4 * c1 * (B - A) / A * (1 / l - l**-7) for l in fine]
    fig, ax = plt.subplots(figsize=(6, 4.2))
    ax.plot(fine, exact, "k-", lw=1, label="closed form, thick wall (Ogden)")
    ax.plot(fine, thin, "k:", lw=1, label="thin-membrane limit")
    ax.plot(lam, p, "o", ms=3, label="plisse, volume control")
    ax.set_xlabel("inner stretch λa")
    ax.set_ylabel("cavity pressure [MPa]")
    ax.set_title("Balloon through its pressure maximum")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figures / "balloon-limit-point.png", dpi=120)
    summary = read_summary(runs / "balloon-limit-point")
    return {"run": "balloon-limit-point", "tetrahedra": summary["elements"],
            "steps": summary["steps"], "newton_iterations": summary["newton_iterations"],
            "plisse": {"stretch": float(lam_max), "pressure": float(p_max)},
            "closed_form": {"stretch": lam_exact, "pressure": exact_max},
            "thin_membrane_stretch": 7 ** (1 / 6)}


def measure_ogden_balloon(runs, figures):
    """The Ogden rubber balloon through its pressure maximum and minimum (examples/balloon-ogden.yaml)."""
    from plisse_study.figures import plt
    mu, alpha, A, B = (0.618, 0.00118, -0.00981), (1.3, 5.0, -2.0), 20.0, 21.0
    dW = lambda l: sum(2 * m * (l ** (a - 1) - l ** (-2 * a - 1)) for m, a in zip(mu, alpha))
    rows = []
    fig, ax = plt.subplots(figsize=(6, 4.2))
    fine = [1 + 4.1 * k / 400 for k in range(1, 401)]
    ax.plot(fine, [ogden_pressure(dW, l, A, B) for l in fine], "k-", lw=1, label="closed form, thick wall (Ogden)")
    for run, label in [("balloon-ogden", "MINI, 2 layers of 2 mm"),
                       ("balloon-ogden-1.4", "MINI, 3 layers of 1.4 mm"),
                       ("balloon-ogden-th", "Taylor-Hood, 1 layer of 3 mm")]:
        h = read_history(runs / run / "history.csv")
        lam = [1 + u / A for u in h["ux:inner"]]
        p = h["pressure:balloon"]
        err = max(abs(q - ogden_pressure(dW, l, A, B)) / ogden_pressure(dW, l, A, B) for l, q in zip(lam, p))
        summary = read_summary(runs / run)
        rows.append({"run": run, "element_and_mesh": label, "tetrahedra": summary["elements"],
                     "steps": summary["steps"], "newton_iterations": summary["newton_iterations"],
                     "max_relative_error_p": err})
        ax.plot(lam, p, "o", ms=3, label=f"plisse, {label}")
    ax.set_xlabel("inner stretch λa")
    ax.set_ylabel("cavity pressure [MPa]")
    ax.set_title("Ogden rubber balloon (Treloar fit), volume control")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(figures / "balloon-ogden.png", dpi=120)
    return {"rows": rows}


def measure(runs, figures, run_time=None):
    """The record of the runs in `runs`: every number the page's tables print, per table and row,
    at full precision, with the commit, the date and `run_time` (seconds the runs took, or None
    when not measured). Draws the figures into `figures` on the way; exits when a claim fails."""
    figures.mkdir(parents=True, exist_ok=True)
    tables = {
        "cube_tension": measure_cube_tension(runs, figures),
        "cube_sticking": measure_cube_sticking(runs, figures),
        "inelastic_cubes": measure_inelastic_cubes(runs, figures),
        "sphere_inflation": measure_sphere_inflation(runs, figures),
        "balloon_limit_point": measure_balloon(runs, figures),
        "balloon_ogden": measure_ogden_balloon(runs, figures),
    }
    return {"command": COMMAND, "commit": tree_commit(ROOT), "date": datetime.date.today().isoformat(),
            "run_time_seconds": run_time, "tables": tables}


# Render: record -> the markdown of docs/verification.md. Formats numbers, computes none.

def run_time_text(seconds):
    if seconds is None:
        return "not measured"
    if seconds < 120:
        return f"{seconds:.0f} s"
    return f"{seconds / 60:.0f} min"


def material_text(mat):
    params = ", ".join(f"{k} = {v:g}{'' if k == 'gamma' or k.startswith('alpha') else ' MPa'}"
                       for k, v in mat.items() if k != "model")
    return f"{mat['model']} ({params})"


def render_cube_tension(t):
    return [
        "## Cube in uniaxial tension, sliding ends (paper section 4.1)",
        "",
        "A 5 mm cube, symmetry conditions on x = 0, y = 0, z = 0 and the top face moved 20 mm up",
        "(stretch 5). The deformation is homogeneous, so the volume-averaged Cauchy stress must equal",
        "the closed form at every step: neo-Hookean 2c1(λ² − 1/λ); Mooney-Rivlin",
        "2c1(λ² − 1/λ) − 2c2(1/λ² − λ) (paper eq. 7); Fung μ exp(γ(I1 − 3))(λ² − 1/λ), I1 = λ² + 2/λ;",
        "Ogden Σ μp (λ^αp − λ^(−αp/2)) (Ogden 1972, eq. 4.4; his fit to Treloar's rubber).",
        f"tests/verification/cube_tension_test.cpp asserts every error below {t['tolerance']:g},",
        "on the same constant steps, and, as a regression guard, each row's steps and Newton",
        "iterations (those of the converged steps, in total).",
        "",
        "| case | element | material | steps | Newton iterations | max relative error of σzz |",
        "|---|---|---|---|---|---|",
        *(f"| `{r['case']}` | {r['element']} | {material_text(r['material'])} | {r['steps']} | "
          f"{r['newton_iterations']} | {r['max_relative_error_sigma_zz']:.2e} |" for r in t["rows"]),
        "",
        "![cube tension](figures/cube-tension.png)",
        "",
    ]


def render_cube_sticking(t):
    return [
        "## Cube in uniaxial tension, both ends stuck to the dies",
        "",
        "The paper's boundary condition (\"bilateral sticking contact\" with the upper and lower dies):",
        "the end faces cannot contract, so the cube necks between the dies and carries more force",
        "than the homogeneous solution, shown for reference. The die force at stretch 5 on three",
        "meshes shows how far the answer is from mesh convergence.",
        "",
        "| divisions per edge | tetrahedra | unknowns | steps | Newton iterations | die force at λ = 5 [N] | / homogeneous |",
        "|---|---|---|---|---|---|---|",
        *(f"| {r['divisions']} | {r['tetrahedra']} | {r['unknowns']} | {r['steps']} | "
          f"{r['newton_iterations']} | {r['die_force']:.4f} | {r['ratio_to_homogeneous']:.4f} |"
          for r in t["rows"]),
        "",
        f"Homogeneous closed form at λ = 5: {t['homogeneous_force']:.4f} N. Observed order of convergence of the",
        f"die force under halving of h: {t['observed_order']:.2f}; Richardson extrapolation from the two finest",
        f"meshes: {t['extrapolated_force']:.2f} N ({t['extrapolated_ratio_to_homogeneous']:.3f} times the homogeneous value).",
        "The stuck edges are stress singularities, and a coarse mesh overestimates the force markedly.",
        "tests/verification/cube_tension_test.cpp asserts every force above the homogeneous one and",
        "falling with refinement, and, as regression guards (no closed form gives the converged",
        "force), the three forces to 1e-5, the order and the extrapolation to the digits shown, and",
        "each run's steps and Newton iterations (in total).",
        "",
        "![cube tension, sticking](figures/cube-tension-sticking.png)",
        "",
    ]


def render_inelastic_cubes(t):
    return [
        "## Cube with viscoelasticity and with Mullins softening",
        "",
        "The sliding-ends cube (neo-Hookean c1 = 0.25 MPa) deforms homogeneously, so the nominal",
        "stress (the top's reaction over its 25 mm² reference area) has a closed form at every step.",
        "`cube-relaxation-viscoelastic`: stretched to 2 in the first step (0.02 s) and held 20 s, with",
        "two Maxwell elements (β = 0.8, τ = 0.5 s; β = 0.3, τ = 4 s): P(t) = P∞ (1 + Σ β_i",
        "exp(−(t − t_jump)/τ_i)) (Simo 1987; Holzapfel 2000, section 6.10), or the same sum over the",
        "steps that share the stretch when the first one is cut back (Taylor-Hood's). `cube-cycles-mullins`:",
        "cycles to stretch 2, 2 and 2.5 with Ogden & Roxburgh's softening (r = 2, m = 0.05 MPa, β = 0.1):",
        "P = η P0, η = 1 − erf((Wmax − W)/(m + β Wmax))/r (Ogden & Roxburgh 1999).",
        f"tests/verification/inelastic asserts every error below {t['tolerance']:g} P∞(λ = 2), and, as a",
        "regression guard, each row's steps and Newton iterations (those of the converged steps, in total).",
        "",
        "| case | element | steps | Newton iterations | max error of P / P∞(λ = 2) |",
        "|---|---|---|---|---|",
        *(f"| `{r['case']}` | {r['element']} | {r['steps']} | {r['newton_iterations']} | "
          f"{r['max_error_over_p_inf']:.2e} |" for r in t["rows"]),
        "",
        "![viscoelastic and Mullins cubes](figures/cube-inelastic.png)",
        "",
    ]


def render_sphere_inflation(t):
    return [
        "## Thick sphere under internal pressure",
        "",
        "`examples/sphere-inflation.yaml`: inner radius A = 10 mm, outer B = 15 mm, octant with three",
        "symmetry planes, follower pressure on the inner surface up to 0.4 MPa. Closed form (Ogden,",
        "*Non-linear Elastic Deformations*, 5.3.1): P(λa) = ∫ Ŵ'(λ)/(λ³ − 1) dλ from λb to λa, with",
        "Ŵ(λ) = W(λ, λ, λ⁻²) and λb³ = 1 + (A/B)³(λa³ − 1); λa = 1 + u_x/A at the probe (10, 0, 0).",
        "",
        "| material | element | element size [mm] | layers | tetrahedra | unknowns | max relative error of p |",
        "|---|---|---|---|---|---|---|",
        *(f"| {r['material']} | {r['element']} | {r['element_size']} | {r['layers']} | "
          f"{r['tetrahedra']} | {r['unknowns']} | {r['max_relative_error_p']:.4f} |"
          for r in t["rows"]),
        "",
        "The largest error is at the first, smallest load step, where it is the small-strain",
        "stiffness error of the mesh (both materials have shear modulus 1 MPa there). On the two",
        "coarse meshes it depends on how the prisms of the layered wall are cut into tetrahedra (the",
        "cut follows the node numbering): the same surface meshes numbered in Gmsh's own order gave",
        "0.0132 and 0.0081, and 0.0050 on the fine one. The error falls with refinement either way.",
        "The Taylor–Hood rows (10-node tetrahedra with their edge nodes on the spheres,",
        "[theory/taylor_hood.md](theory/taylor_hood.md)) reach a given error with fewer unknowns and",
        "with one to three layers through the wall instead of six.",
        "",
        "![sphere inflation](figures/sphere-inflation.png)",
        "",
    ]


def render_balloon(t):
    return [
        "## Thin balloon through its pressure maximum",
        "",
        "`examples/balloon-limit-point.yaml`: neo-Hookean (c1 = 0.1 MPa), A = 20 mm, wall 1 mm,",
        f"2 layers, octant ({t['tetrahedra']} tetrahedra); the cavity volume is prescribed (4 times",
        "the initial one), so the pressure is an unknown that passes its maximum.",
        "",
        "| | stretch at the maximum | pressure at the maximum [MPa] |",
        "|---|---|---|",
        f"| plisse (parabola through the 3 points around the maximum) | {t['plisse']['stretch']:.5f} | "
        f"{t['plisse']['pressure']:.6f} |",
        f"| closed form, thick wall | {t['closed_form']['stretch']:.5f} | {t['closed_form']['pressure']:.6f} |",
        f"| thin-membrane limit 7^(1/6) | {t['thin_membrane_stretch']:.5f} | |",
        "",
        f"{t['steps']} steps, {t['newton_iterations']} Newton iterations in total. The thin-membrane",
        "stretch refers to the mid-surface; the inner surface of a 1 mm wall peaks later, as the",
        "thick-wall solution shows. tests/verification/cavity asserts the maximum within 1e-4 of the",
        "thick wall's stretch and 3e-3 of its pressure, and, as a regression guard, the steps and",
        "Newton iterations.",
        "",
        "![balloon limit point](figures/balloon-limit-point.png)",
        "",
    ]


def render_ogden_balloon(t):
    return [
        "## Rubber balloon with Ogden's Treloar fit: pressure maximum and minimum",
        "",
        "`examples/balloon-ogden.yaml`: Ogden's three-term fit to Treloar's rubber (Ogden 1972,",
        "section 4: μ = 0.618, 0.00118, −0.00981 MPa, α = 1.3, 5, −2), A = 20 mm, wall 1 mm, octant;",
        "the cavity volume is prescribed up to 125 times the initial one (λa = 5), past the pressure",
        "maximum (λa = 1.395) and the minimum (λa = 4.42) of the exact thick-wall solution. Largest",
        "relative difference from it over the steps:",
        "",
        "| element and mesh | tetrahedra | steps | Newton iterations | max relative error of P(λa) |",
        "|---|---|---|---|---|",
        *(f"| {r['element_and_mesh']} | {r['tetrahedra']} | {r['steps']} | {r['newton_iterations']} | "
          f"{r['max_relative_error_p']:.2e} |" for r in t["rows"]),
        "",
        "tests/verification/cavity asserts 0.3 % for the first, 0.14 % for the second and 1e-5 for the",
        "Taylor-Hood run, and, as a regression guard, each run's steps and Newton iterations (every",
        "iteration, those of steps cut back included).",
        "",
        "![Ogden balloon](figures/balloon-ogden.png)",
        "",
    ]


def render(record):
    """The markdown of docs/verification.md from a record as `measure` returns it."""
    t = record["tables"]
    return "\n".join([
        "# Verification",
        "",
        "Generated by `scripts/verification-report` from runs of the examples; do not edit by hand.",
        f"Last run: commit {record['commit']}, {record['date']}, run time "
        f"{run_time_text(record['run_time_seconds'])}; its numbers are kept in "
        "[verification/record.json](verification/record.json), against which a unit test checks this page.",
        "The same comparisons are asserted by the test suite (`tests/verification`).",
        "\"Newton iterations\" counts the tangents factorised (summary.json and history.csv",
        "`newton_iterations`); the iterations that reuse a factorisation (chord and Krylov steps,",
        "summary.json `reused_factor_solves`) are not counted, so a smooth run can take fewer than",
        "one a step.",
        "Units: mm, N, MPa, s (the consistent units the examples are written in).",
        "",
        *render_cube_tension(t["cube_tension"]),
        *render_cube_sticking(t["cube_sticking"]),
        *render_inelastic_cubes(t["inelastic_cubes"]),
        *render_sphere_inflation(t["sphere_inflation"]),
        *render_balloon(t["balloon_limit_point"]),
        *render_ogden_balloon(t["balloon_ogden"]),
    ])


def read_record(docs):
    path = record_path(docs)
    if not path.is_file():
        fail(f"no record at {path} (scripts/verification-report writes it)")
    return json.loads(path.read_text())


def write_record(docs, record):
    path = record_path(docs)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(record, indent=1, ensure_ascii=False) + "\n")


def check(docs):
    """0 when docs/verification.md is what its record renders; else prints the difference, 1."""
    page = docs / "verification.md"
    expected = render(read_record(docs))
    actual = page.read_text() if page.is_file() else ""
    if actual == expected:
        return 0
    diff = list(difflib.unified_diff(expected.splitlines(), actual.splitlines(),
                                     "rendered from verification/record.json", "verification.md",
                                     lineterm="", n=0))
    print(f"verification-report: {page} is not what {record_path(docs)} renders "
          "(scripts/verification_report.py --render rewrites it from the record, "
          "scripts/verification-report reruns the cases):", file=sys.stderr)
    for line in diff[:40]:
        print(line, file=sys.stderr)
    if len(diff) > 40:
        print(f"... {len(diff) - 40} more lines", file=sys.stderr)
    return 1


def main(argv):
    parser = argparse.ArgumentParser(
        description="Measures the verification runs into docs/verification/record.json and "
                    "renders docs/verification.md from it.")
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true",
                      help="compare the page with what its record renders; exit 1 on a difference")
    mode.add_argument("--render", action="store_true",
                      help="rewrite the page from its record, without runs")
    parser.add_argument("--run-time", type=float, metavar="SECONDS",
                        help="the wall time the runs took, for the record and the page")
    parser.add_argument("dirs", nargs="*", metavar="DIR",
                        help="RUNS_DIR [DOCS_DIR] to measure; DOCS_DIR alone with --check/--render")
    args = parser.parse_args(argv)
    if args.check or args.render:
        if len(args.dirs) > 1 or args.run_time is not None:
            parser.error("--check and --render take DOCS_DIR alone")
        docs = Path(args.dirs[0]) if args.dirs else ROOT / "docs"
        if args.check:
            return check(docs)
        (docs / "verification.md").write_text(render(read_record(docs)))
        return 0
    if not 1 <= len(args.dirs) <= 2:
        parser.error("give RUNS_DIR [DOCS_DIR], or --check / --render")
    runs = Path(args.dirs[0])
    docs = Path(args.dirs[1]) if len(args.dirs) == 2 else ROOT / "docs"
    record = measure(runs, docs / "figures", args.run_time)
    write_record(docs, record)
    (docs / "verification.md").write_text(render(record))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
