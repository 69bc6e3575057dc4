"""Parameter studies: run one case for several values of a key and write a Markdown report.

Usage: scripts/study STUDY.yaml [--runs DIR] [--docs DIR] [--reuse | --report-only]

A study file names a case, the key to vary and its values (docs/studies/README.md):

    name: layers                      # report layers.md, figures layers/, beside the study file
    title: Tetrahedra through the wall
    case: ../examples/sphere-indentation.yaml   # relative to the study file
    report: ../docs/studies           # where the report goes (optional; default: the study
                                      # file's folder); --docs overrides it
    set: [solver.stability.check=true]          # overrides for every run (optional)
    vary: {key: mesh.layers, values: [1, 2, 3, 4], label: tetrahedra through the wall}
    convergence: {label: "elements of 0.5 mm", set: [mesh.element_size=0.5]}   # optional
    discussion: |
      Markdown written under the table.

Each run is `build/bin/plisse run CASE -o RUNS/<name>/<leaf>=<value> --set key=value ...`, with
RUNS the folder `runs` beside the study file unless --runs says otherwise, and <leaf> the last
part of the key (`layers` for mesh.layers, `value` for loads[0].value); with `convergence`, each
value runs a second time with its overrides added (a finer mesh), into
`RUNS/<name>/<leaf>=<value>+fine`, and the table gets that run's wrinkle count and amplitude. The
report reads each run's summary.json (wrinkle table, steps, times), history.csv and last VTU
(deformed outer surface coloured by its normal deviation from the axisymmetric mean shape).
A run that fails (exit status 1) is reported as such with its message; bad input (2) stops.
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
import time
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
AXES = {"x": 0, "y": 1, "z": 2}


def fail(message):
    print(f"scripts/study: {message}", file=sys.stderr)
    sys.exit(2)


def load_study(path):
    try:
        with open(path) as f:
            s = yaml.safe_load(f)
    except (OSError, yaml.YAMLError) as e:
        fail(f"{path}: {e}")
    if not isinstance(s, dict):
        fail(f"{path}: expected a map (name, title, case, vary, ...)")
    allowed = {"name", "title", "case", "set", "vary", "convergence", "discussion", "intro",
               "report"}
    for key in s:
        if key not in allowed:
            fail(f"{path}: key '{key}': unknown key; allowed: {', '.join(sorted(allowed))}")
    for key in ("name", "case", "vary"):
        if key not in s:
            fail(f"{path}: key '{key}' is required")
    vary = s["vary"]
    if not isinstance(vary, dict) or "key" not in vary or not isinstance(vary.get("values"), list) \
            or not vary["values"]:
        fail(f"{path}: key 'vary': needs 'key' and a non-empty list 'values'")
    conv = s.get("convergence")
    if conv is not None and (not isinstance(conv, dict) or not isinstance(conv.get("set"), list)
                             or not conv["set"] or set(conv) - {"label", "set"}):
        fail(f"{path}: key 'convergence': needs a non-empty list 'set' (and optionally 'label')")
    here = os.path.dirname(os.path.abspath(path))
    s["case"] = os.path.normpath(os.path.join(here, s["case"]))
    s["report"] = os.path.normpath(os.path.join(here, str(s.get("report", "."))))
    s["runs"] = os.path.join(here, "runs")
    if not re.fullmatch(r"[A-Za-z0-9_.-]+", str(s["name"])):
        fail(f"{path}: key 'name': letters, digits, '_', '.', '-' only (it names files)")
    if not os.path.isfile(s["case"]):
        fail(f"{path}: key 'case': no such file {s['case']}")
    s.setdefault("set", [])
    s.setdefault("title", s["name"])
    return s


def shown(path):
    """`path` relative to the working directory when it lies below it, else absolute."""
    path = os.path.abspath(path)
    rel = os.path.relpath(path)
    return path if rel.startswith("..") else rel


def folder_name(key, value):
    """`<leaf>=<value>`: the last part of the key without list indices, and the value with the
    characters a file name cannot hold replaced."""
    leaf = re.sub(r"\[\d+\]", "", key).split(".")[-1] or "value"
    text = re.sub(r"[^A-Za-z0-9_.+-]", "_", yaml_value(value).replace(", ", ","))
    return f"{leaf}={text}"


def yaml_value(v):
    return json.dumps(v) if isinstance(v, (list, dict)) else str(v).lower() if isinstance(v, bool) \
        else str(v)


def run_one(study, value, run_dir, reuse, extra=(), report_only=False):
    summary = os.path.join(run_dir, "summary.json")
    if reuse and os.path.isfile(summary):
        return {"status": "reused", "seconds": None}
    if report_only:
        return {"status": "not run", "seconds": None, "message": "not run"}
    cmd = [os.path.join(ROOT, "build", "bin", "plisse"), "run", study["case"], "-o", run_dir,
           "--overwrite"]
    for o in study["set"] + [f"{study['vary']['key']}={yaml_value(value)}"] + list(extra):
        cmd += ["--set", o]
    print("scripts/study: " + " ".join(shown(c) if os.path.isabs(c) else c for c in cmd),
          flush=True)
    t0 = time.time()
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    seconds = time.time() - t0
    with open(os.path.join(os.path.dirname(run_dir), os.path.basename(run_dir) + ".out"), "w") as f:
        f.write(proc.stdout)
    if proc.returncode == 2:
        print(proc.stdout, file=sys.stderr)
        fail(f"plisse refused the input for {study['vary']['key']} = {value}")
    last = [l for l in proc.stdout.splitlines() if l.strip()]
    return {"status": "ok" if proc.returncode == 0 else "failed", "seconds": seconds,
            "message": last[-1] if last else ""}


def read_summary(run_dir):
    path = os.path.join(run_dir, "summary.json")
    if not os.path.isfile(path):
        return {}
    with open(path) as f:
        return json.load(f)


def largest_ring(summary):
    """The ring of largest amplitude in a run's summary, or None."""
    rings = (summary.get("wrinkles") or {}).get("rings", [])
    return max(rings, key=lambda g: g.get("amplitude", 0.0), default=None)


def read_history(run_dir):
    """Column name -> values of a run's history.csv, or {} when it has no complete row."""
    path = os.path.join(run_dir, "history.csv")
    if not os.path.isfile(path):
        return {}
    with open(path) as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        return {}
    cols = rows[0]
    # A row of another length is one a killed run left unterminated (a run still going may be
    # writing it): it is left out.
    data = np.array([[float(x) if x not in ("", "nan") else np.nan for x in r]
                     for r in rows[1:] if len(r) == len(cols)])
    if len(data) == 0:
        return {}
    return {c: data[:, i] for i, c in enumerate(cols)}


def last_vtu(run_dir):
    pvd = os.path.join(run_dir, "solution.pvd")
    if not os.path.isfile(pvd):
        return None
    files = [d.get("file") for d in ET.parse(pvd).getroot().iter("DataSet")]
    return os.path.join(run_dir, files[-1]) if files else None


def outer_surface(points, tets, center):
    """Boundary faces of the tetrahedra whose outward normal points away from `center`."""
    faces = np.concatenate([tets[:, [0, 2, 1]], tets[:, [0, 1, 3]], tets[:, [1, 2, 3]],
                            tets[:, [0, 3, 2]]])
    key = np.sort(faces, axis=1)
    _, inverse, counts = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    boundary = faces[counts[inverse.ravel()] == 1]
    p = points[boundary]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    r = p.mean(axis=1) - center
    cosine = np.einsum("ij,ij->i", n, r) / (np.linalg.norm(n, axis=1) * np.linalg.norm(r, axis=1)
                                            + 1e-300)
    return boundary[cosine > 0.3]


def normal_deviation(X, x, axis, center):
    """Deviation of the deformed points x from the mean deformed shape of their reference latitude,
    along the mean shape's normal (bins of 0.5 degree of reference latitude)."""
    a = np.zeros(3)
    a[axis] = 1.0

    def cyl(p):
        r = p - center
        h = r @ a
        rho = np.linalg.norm(r - np.outer(h, a), axis=1)
        return rho, h

    rho0, h0 = cyl(X)
    lat = np.degrees(np.arctan2(h0, rho0))
    rho, h = cyl(x)
    bins = np.round(lat / 0.5).astype(int)
    uniq, inv = np.unique(bins, return_inverse=True)
    inv = inv.ravel()
    mean_rho = np.bincount(inv, rho) / np.bincount(inv)
    mean_h = np.bincount(inv, h) / np.bincount(inv)
    # Meridian tangent of the mean curve by differences over latitude; the normal is its rotation.
    t_rho = np.gradient(mean_rho) if len(uniq) > 1 else np.zeros_like(mean_rho)
    t_h = np.gradient(mean_h) if len(uniq) > 1 else np.ones_like(mean_h)
    norm = np.hypot(t_rho, t_h) + 1e-300
    n_rho, n_h = t_h / norm, -t_rho / norm
    return (rho - mean_rho[inv]) * n_rho[inv] + (h - mean_h[inv]) * n_h[inv]


def surface_figure(vtu, settings, path, title):
    """The deformed measured surface of `vtu` coloured by its normal deviation from the mean
    (axisymmetric) shape at the same reference latitude, with the rings of settings["rings_deg"]
    drawn on the mean shape. `settings`: the case's output.wrinkles (axis, center, rings_deg).
    False when the file has no tetrahedra or displacement."""
    mesh = meshio.read(vtu)
    X = mesh.points
    tets = mesh.cells_dict.get("tetra")
    if tets is None and "tetra10" in mesh.cells_dict:
        tets = mesh.cells_dict["tetra10"][:, :4]
    if tets is None or "displacement" not in mesh.point_data:
        return False
    x = X + mesh.point_data["displacement"]
    axis = AXES.get(settings.get("axis", "y"), 1)
    center = np.array(settings.get("center", [0.0, 0.0, 0.0]), dtype=float)
    tris = outer_surface(X, tets, center)
    if len(tris) == 0:
        return False
    used = np.unique(tris)
    dev = np.zeros(len(X))
    dev[used] = normal_deviation(X[used], x[used], axis, center)
    face_dev = dev[tris].mean(axis=1)
    limit = max(np.percentile(np.abs(face_dev), 99), 1e-9)
    fig = plt.figure(figsize=(6.4, 5.2))
    ax = fig.add_subplot(projection="3d")
    ax.computed_zorder = False  # the rings are drawn over the surface
    order = [(axis + 1) % 3, (axis + 2) % 3, axis]  # the rings' axis vertical
    surf = ax.plot_trisurf(x[:, order[0]], x[:, order[1]], x[:, order[2]], triangles=tris,
                           cmap="coolwarm", linewidth=0, antialiased=False, shade=False)
    surf.set_array(face_dev)
    surf.set_clim(-limit, limit)
    fig.colorbar(surf, ax=ax, shrink=0.7, label="normal deviation [mm]")
    # The rings, on the deformed mean shape: the mean distance from the axis and height of the
    # surface nodes near each ring's reference latitude (within a node spacing), drawn over the
    # modelled sector's azimuths.
    a = np.zeros(3)
    a[axis] = 1.0
    r0 = X[used] - center
    h0 = r0 @ a
    rho0 = np.linalg.norm(r0 - np.outer(h0, a), axis=1)
    latitude = np.degrees(np.arctan2(h0, rho0))
    e_u, e_v = np.eye(3)[order[0]], np.eye(3)[order[1]]
    azimuth = np.arctan2(r0 @ e_v, r0 @ e_u)
    edges = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]]])
    spacing = np.degrees(np.median(np.linalg.norm(X[edges[:, 0]] - X[edges[:, 1]], axis=1))
                         / max(np.median(np.linalg.norm(r0, axis=1)), 1e-12))
    xc = x[used] - center
    hc = xc @ a
    rhoc = np.linalg.norm(xc - np.outer(hc, a), axis=1)
    for ring in settings.get("rings_deg") or []:
        near = np.abs(latitude - float(ring)) < max(0.5, spacing)
        if not near.any():
            continue
        phi = np.linspace(azimuth[near].min(), azimuth[near].max(), 200)
        rho, h = rhoc[near].mean(), hc[near].mean()
        p = center + rho * (np.outer(np.cos(phi), e_u) + np.outer(np.sin(phi), e_v)) + h * a
        ax.plot(p[:, order[0]], p[:, order[1]], p[:, order[2]], "k-", linewidth=1.2, zorder=10)
    ax.set_box_aspect(np.ptp(x[used][:, order], axis=0) + 1e-9)
    ax.view_init(elev=35, azim=-55)
    ax.set_axis_off()
    ax.set_title(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return True


def case_wrinkle_settings(case_path):
    with open(case_path) as f:
        c = yaml.safe_load(f)
    return ((c or {}).get("output") or {}).get("wrinkles") or {}


def fmt(v, spec="{:.3g}"):
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "–"
    if isinstance(v, bool):
        return "yes" if v else "no"
    if isinstance(v, int):
        return str(v)
    return spec.format(v) if isinstance(v, float) else str(v)


def fine_columns(result, label):
    """The finer-mesh columns of a table row: largest amplitude and its count (with the time the
    finer run stopped at, when it stopped early); none without a convergence run."""
    fine = result.get("fine")
    if fine is None:
        return []
    s = fine["summary"]
    if not s:
        return [fine["info"].get("message") or "failed", "–"]
    best = largest_ring(s)
    amplitude = fmt((s.get("wrinkles") or {}).get("max_amplitude"))
    if not s.get("completed"):
        amplitude += f" (stopped at t = {fmt(s.get('final_time'), '{:.4g}')})"
    return [amplitude, fmt(best.get("count") if best else None)]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("study")
    ap.add_argument("--runs", help="folder for the runs (default: runs/ beside the study file)")
    ap.add_argument("--docs", help="folder for the report and its figures (default: the study "
                                   "file's `report`, else its folder)")
    ap.add_argument("--reuse", action="store_true", help="keep runs that already have summary.json")
    ap.add_argument("--report-only", action="store_true",
                    help="run nothing: write the report from the runs already there (a run "
                         "without summary.json is reported as not run)")
    args = ap.parse_args()
    study = load_study(args.study)
    args.runs = os.path.abspath(args.runs) if args.runs else study["runs"]
    args.docs = os.path.abspath(args.docs) if args.docs else study["report"]
    name, key = study["name"], study["vary"]["key"]
    label = study["vary"].get("label", key)
    fig_dir = os.path.join(args.docs, name)
    os.makedirs(fig_dir, exist_ok=True)
    wrinkle_settings = case_wrinkle_settings(study["case"])
    results = []
    for value in study["vary"]["values"]:
        run_dir = os.path.join(args.runs, name, folder_name(key, value))
        os.makedirs(os.path.dirname(run_dir), exist_ok=True)
        info = run_one(study, value, run_dir, args.reuse or args.report_only,
                       report_only=args.report_only)
        summary = read_summary(run_dir)
        fine = None
        if study.get("convergence"):
            fine_dir = run_dir + "+fine"
            fine_info = run_one(study, value, fine_dir, args.reuse or args.report_only,
                                study["convergence"]["set"], args.report_only)
            fine = {"info": fine_info, "summary": read_summary(fine_dir), "figure": None}
            fine_vtu = last_vtu(fine_dir)
            if fine_vtu:
                figure_fine = f"{name}/surface_{folder_name(key, value).split('=', 1)[1]}_fine.png"
                if surface_figure(fine_vtu, wrinkle_settings, os.path.join(args.docs, figure_fine),
                                  f"{label} = {value}, {study['convergence'].get('label', 'finer mesh')}"):
                    fine["figure"] = figure_fine
        history = read_history(run_dir)
        figure = None
        vtu = last_vtu(run_dir)
        if vtu:
            figure = f"{name}/surface_{folder_name(key, value).split('=', 1)[1]}.png"
            if not surface_figure(vtu, wrinkle_settings, os.path.join(args.docs, figure),
                                  f"{label} = {value}"):
                figure = None
        results.append({"value": value, "info": info, "summary": summary, "history": history,
                        "figure": figure, "run_dir": run_dir, "fine": fine})

    # Amplitude and count against the parameter.
    xs = [r["value"] for r in results]
    numeric = all(isinstance(v, (int, float)) for v in xs)
    amp = [((r["summary"].get("wrinkles") or {}).get("max_amplitude", np.nan)) for r in results]
    count = []
    for r in results:
        best = largest_ring(r["summary"])
        count.append(best["count"] if best else np.nan)
    fig, ax1 = plt.subplots(figsize=(6, 3.6))
    pos = xs if numeric else list(range(len(xs)))
    ax1.plot(pos, amp, "o-", color="tab:red", label="max amplitude")
    ax1.set_xlabel(label)
    ax1.set_ylabel("max peak-to-peak amplitude [mm]", color="tab:red")
    if numeric and min(xs) > 0 and max(xs) / min(xs) > 50:
        ax1.set_xscale("log")
    ax2 = ax1.twinx()
    ax2.plot(pos, count, "s--", color="tab:blue", label="count")
    if study.get("convergence"):
        fine = [(r["fine"] or {}).get("summary") or {} for r in results]
        ax1.plot(pos, [(f.get("wrinkles") or {}).get("max_amplitude", np.nan) for f in fine], "o:",
                 color="tab:red", markerfacecolor="none", label="max amplitude, finer mesh")
        ax2.plot(pos, [(largest_ring(f) or {}).get("count", np.nan) for f in fine], "s:",
                 color="tab:blue", markerfacecolor="none", label="count, finer mesh")
        ax1.legend(loc="best", fontsize=8, handles=ax1.get_lines() + ax2.get_lines())
    ax2.set_ylabel("wrinkle count (ring of max amplitude)", color="tab:blue")
    ax2.yaxis.set_major_locator(MaxNLocator(integer=True))  # counts are whole numbers
    if not numeric:
        ax1.set_xticks(pos, [str(v) for v in xs], rotation=30 if len(xs) > 5 else 0)
    elif all(isinstance(v, int) for v in xs):
        ax1.set_xticks(xs)  # integer values: a tick at each, none between
    ax1.grid(alpha=0.3)
    fig.tight_layout()
    trend = f"{name}/amplitude_count.png"
    fig.savefig(os.path.join(args.docs, trend), dpi=110)
    plt.close(fig)

    lines = [f"# Study: {study['title']}", "",
             "Generated by `scripts/study " + shown(args.study) +
             "` (do not edit by hand). Units: those of the case (the examples' mm, N, MPa, s).",
             "",
             f"Case: `{os.path.relpath(study['case'], args.docs)}`, varying `{key}` ({label})" +
             (", with " + ", ".join(f"`--set {o}`" for o in study["set"]) if study["set"] else "") +
             ".", ""]
    if study.get("intro"):
        lines += [study["intro"].strip(), ""]
    conv = study.get("convergence")
    conv_label = (conv.get("label") or ", ".join(conv["set"])) if conv else None
    if conv:
        lines += [f"The last two columns repeat each run on the finer mesh ({conv_label}: " +
                  ", ".join(f"`--set {o}`" for o in conv["set"]) +
                  "): the largest ring amplitude and its wave count there.", ""]
    lines += [f"| {label} | outcome | steps | Newton its | unknowns | wall time [s] | stable at every step |"
              " instability at t | wrinkled | max amplitude [mm] | count | wavelength [mm] |"
              " tension field: taut / wrinkled / slack elements |" +
              (" max amplitude, finer mesh [mm] | count, finer mesh |" if conv else ""),
              "|---|---|---|---|---|---|---|---|---|---|---|---|---|" + ("---|---|" if conv else "")]
    failures = []
    for r, a, m in zip(results, amp, count):
        s, h = r["summary"], r["history"]
        w = s.get("wrinkles") or {}
        best = largest_ring(s)
        if s.get("completed"):
            outcome = "completed"
        elif s:
            outcome = f"stopped at t = {fmt(s.get('final_time'), '{:.4g}')} (below)"
            failures.append(f"- {label} = {r['value']}: {s.get('failure', '')}")
        else:
            outcome = "not run" if r["info"]["status"] == "not run" else \
                "failed: " + r["info"].get("message", "")
        # Unstable: more negative pivots than a stable state has (a state with the expected count
        # and a null pivot is singular, not unstable; the log says SINGULAR).
        stable = h.get("stable")
        first_unstable = None
        if "negative_pivots" in h and "expected_negative_pivots" in h and len(h["time"]):
            stable = (h["negative_pivots"] <= h["expected_negative_pivots"]).astype(float)
        if stable is not None and len(stable):
            bad = np.where(stable < 0.5)[0]
            first_unstable = h["time"][bad[0]] if len(bad) else None
        lines.append("| " + " | ".join([
            str(r["value"]), outcome.replace("|", "/"), fmt(s.get("steps")),
            fmt(s.get("newton_iterations")), fmt(s.get("free_dofs")),
            fmt((s.get("wall_time") or {}).get("total"), "{:.0f}"),
            "–" if stable is None else ("yes" if first_unstable is None else "no"),
            fmt(first_unstable), fmt(w.get("wrinkled")), fmt(a),
            fmt(int(m) if isinstance(m, (int, float)) and not math.isnan(m) else None),
            fmt(best.get("wavelength") if best else None),
            " / ".join(str((w.get("tension_field") or {}).get(k, "–"))
                       for k in ("taut", "wrinkled", "slack"))] + fine_columns(r, label)) + " |")
    for r in results:
        fs = (r["fine"] or {}).get("summary")
        if r["fine"] is not None and r["fine"]["info"]["status"] != "not run" \
                and not fs.get("completed"):
            failures.append(f"- {label} = {r['value']}, finer mesh: " +
                            (fs.get("failure", "") if fs else r["fine"]["info"].get("message", "")))
    if failures:
        lines += ["", "Runs that stopped:", ""] + failures
    lines += ["", f"![amplitude and count against {label}]({trend})", ""]
    lines += ["## Rings of each run", ""]
    for r in results:
        rings = (r["summary"].get("wrinkles") or {}).get("rings", [])
        if not rings:
            continue
        lines += [f"{label} = {r['value']}:", "", "| latitude [deg] | count | amplitude [mm] | wavelength [mm] |",
                  "|---|---|---|---|"]
        for g in rings:
            lines.append(f"| {fmt(g.get('latitude_deg'))} | {fmt(g.get('count'))} | "
                         f"{fmt(g.get('amplitude'))} | {fmt(g.get('wavelength'))} |")
        lines.append("")
    lines += ["## Deformed outer surfaces", "",
              "Coloured by the normal deviation from the mean (axisymmetric) deformed shape at the "
              "same reference latitude; last converged step of each run.", ""]
    for r in results:
        if r["figure"]:
            lines += [f"![{label} = {r['value']}]({r['figure']})", ""]
        if r["fine"] and r["fine"]["figure"]:
            lines += [f"![{label} = {r['value']}, finer mesh]({r['fine']['figure']})", ""]
    if study.get("discussion"):
        lines += ["## Discussion", "", study["discussion"].strip(), ""]
    report = os.path.join(args.docs, f"{name}.md")
    with open(report, "w") as f:
        f.write("\n".join(lines))
    print(f"scripts/study: wrote {shown(report)}")


if __name__ == "__main__":
    main()
