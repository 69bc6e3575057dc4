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
import math
import os
import re
import sys

# The runs, the readers and the surface figures are plisse_study's; the study file and the report
# are this script's.
from plisse_study import figures, runs, sweep
from plisse_study.figures import plt
from matplotlib.ticker import MaxNLocator
import numpy as np
import yaml


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


def run_one(study, value, run_dir, reuse, extra=(), report_only=False):
    if reuse and sweep.finished(run_dir):
        return {"status": "reused", "seconds": None}
    if report_only:
        return {"status": "not run", "seconds": None, "message": "not run"}
    transcript = os.path.join(os.path.dirname(run_dir), os.path.basename(run_dir) + ".out")
    overrides = study["set"] + [f"{study['vary']['key']}={sweep.yaml_value(value)}"] + list(extra)
    outcome = sweep.run_case(
        study["case"], run_dir, overrides, transcript=transcript,
        echo=lambda cmd: "scripts/study: " + " ".join(shown(c) if os.path.isabs(c) else c
                                                      for c in cmd))
    if outcome.returncode == 2:
        with open(transcript) as f:
            print(f.read(), file=sys.stderr)
        fail(f"plisse refused the input for {study['vary']['key']} = {value}")
    return {"status": "ok" if outcome.returncode == 0 else "failed", "seconds": outcome.seconds,
            "message": outcome.message}


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
    best = runs.largest_ring(s)
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
    wrinkle_settings = runs.case_wrinkle_settings(study["case"])
    results = []
    for value in study["vary"]["values"]:
        run_dir = os.path.join(args.runs, name, sweep.folder_name(key, value))
        os.makedirs(os.path.dirname(run_dir), exist_ok=True)
        info = run_one(study, value, run_dir, args.reuse or args.report_only,
                       report_only=args.report_only)
        summary = runs.read_summary(run_dir)
        fine = None
        if study.get("convergence"):
            fine_dir = run_dir + "+fine"
            fine_info = run_one(study, value, fine_dir, args.reuse or args.report_only,
                                study["convergence"]["set"], args.report_only)
            fine = {"info": fine_info, "summary": runs.read_summary(fine_dir), "figure": None}
            fine_vtu = runs.last_vtu(fine_dir)
            if fine_vtu:
                figure_fine = f"{name}/surface_{sweep.folder_name(key, value).split('=', 1)[1]}_fine.png"
                if figures.surface_figure(fine_vtu, wrinkle_settings, os.path.join(args.docs, figure_fine),
                                  f"{label} = {value}, {study['convergence'].get('label', 'finer mesh')}"):
                    fine["figure"] = figure_fine
        history = runs.read_history(run_dir)
        figure = None
        vtu = runs.last_vtu(run_dir)
        if vtu:
            figure = f"{name}/surface_{sweep.folder_name(key, value).split('=', 1)[1]}.png"
            if not figures.surface_figure(vtu, wrinkle_settings, os.path.join(args.docs, figure),
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
        best = runs.largest_ring(r["summary"])
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
        ax2.plot(pos, [(runs.largest_ring(f) or {}).get("count", np.nan) for f in fine], "s:",
                 color="tab:blue", markerfacecolor="none", label="count, finer mesh")
        ax1.legend(loc="best", fontsize=8, handles=ax1.get_lines() + ax2.get_lines())
    ax2.set_ylabel("wrinkle count (ring of max amplitude)", color="tab:blue")
    ax2.yaxis.set_major_locator(MaxNLocator(integer=True))  # counts are whole numbers
    if not numeric:
        ax1.set_xticks(pos, [str(v) for v in xs], rotation=30 if len(xs) > 5 else 0)
    elif all(isinstance(v, int) for v in xs):
        ax1.set_xticks(xs)  # integer values: a tick at each, none between
    ax1.grid(alpha=0.3)
    trend = f"{name}/amplitude_count.png"
    figures.save(fig, os.path.join(args.docs, trend), dpi=110)

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
        best = runs.largest_ring(s)
        if s.get("completed"):
            outcome = "completed"
        elif s:
            outcome = f"stopped at t = {fmt(s.get('final_time'), '{:.4g}')} (below)"
            failures.append(f"- {label} = {r['value']}: {s.get('failure', '')}")
        else:
            outcome = "not run" if r["info"]["status"] == "not run" else \
                "failed: " + r["info"].get("message", "")
        stable = runs.stable_column(h)
        first_unstable = runs.first_unstable_time(h)
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
