"""Figures of a run directory: what `plisse plot DIR` draws (docs/output.md, "Figures").

Usage: plot.py RUN_DIR OUT_DIR PLISSE_EXECUTABLE [--x COLUMN] [--y COLUMN ...]
       plot.py RUN_DIR OUT_DIR PLISSE_EXECUTABLE --line AX,AY,AZ:BX,BY,BZ [--points N] [--step K]

Reads RUN_DIR/history.csv, summary.json and the step files, and writes PNG files into OUT_DIR:
  forces.png           each force's largest component against the time and, with probes, against
                       the largest probe displacement (load against displacement)
  moments.png          each cap's largest moment component against the time (runs with caps
                       whose turn is free or prescribed)
  pressure_volume.png  pressure against enclosed volume, for every pressure or cavity with a
                       volume column (the whole body's where the history has it)
  newton.png           Newton iterations per step and the residual reached
  wrinkles.png         the largest wrinkle amplitude and its count (runs with wrinkle rings)
  wrinkle_map.png      the last state's measured surface coloured by its normal deviation from
                       the axisymmetric mean shape, with the rings drawn (runs with rings), and
                       wrinkle_map_step_NNNN.png at every step where stability was lost
  wrinkle_unrolled.png the same surface unrolled: arc length around the axis against the axial
                       coordinate (a tube's wrinkles in one view)
  wrinkle_lines.png    each measurement line's crest height and its crests above the threshold
                       against the time (runs with output.wrinkles.lines)
With --y (one or more history columns) and --x (a column, default time) it draws only
columns.png: each --y column against the --x column. With --line it writes only line.csv and
line.png: the fields of step K (default the last written) at N points (default 200) of the
segment from A to B of the undeformed body (plisse_study.lines), against the distance from A.
Axis labels take their units from the output reference (`plisse outputs history`).
Exit status: 0 done; 2 RUN_DIR is not a run directory, its files are malformed or larger than a
run writes (history.csv at most 256 MiB, summary.json 64 MiB, a step file's arrays no larger than
its mesh: checked before they are read), a figure's path is a symbolic link, or a --x or --y
column is not in the history (the message lists those there are); 1 a figure could not be written.
"""
import os
import re
import subprocess
import sys
import tempfile

from plisse_study import figures, lines, runs
from plisse_study.figures import plt
from matplotlib.ticker import MaxNLocator
import numpy as np


MAX_HISTORY_BYTES = 256 << 20  # about ten million rows of a few columns
MAX_SUMMARY_BYTES = 64 << 20
MALFORMED = (ValueError, KeyError, TypeError, IndexError, AttributeError, UnicodeDecodeError,
             MemoryError, OverflowError)

FIGURES = ("forces.png", "moments.png", "pressure_volume.png", "newton.png", "wrinkles.png",
           "wrinkle_map.png", "wrinkle_unrolled.png", "wrinkle_lines.png", "columns.png", "line.png",
           "line.csv", "line_spectrum.csv")


def fail(message, status=2):
    print(f"plisse plot: {message}", file=sys.stderr)
    sys.exit(status)


def reference_units(plisse):
    """Column pattern -> unit, from the output reference the program writes from."""
    text = subprocess.run([plisse, "outputs", "history"], check=True, capture_output=True,
                          text=True).stdout
    units = []
    for line in text.splitlines():
        m = re.match(r"\| `([^`]+)` \| ([^|]*) \|", line)
        if m:
            pattern = "^" + re.sub(r"<[^>]*>", ".+", re.escape(m.group(1)).replace(r"\<", "<")
                                   .replace(r"\>", ">")) + "$"
            literal = len(re.sub(r"<[^>]*>", "", m.group(1)))
            units.append((pattern, literal, m.group(2).strip()))
    return units


def unit_of(units, column):
    best = None
    for pattern, literal, unit in units:
        if re.match(pattern, column) and (best is None or literal > best[0]):
            best = (literal, unit)
    return best[1] if best and best[1] not in ("–", "") else None


def label(units, column):
    unit = unit_of(units, column)
    return f"{column} [{unit}]" if unit else column


def named_groups(h, prefixes):
    """name -> [columns] of the columns `<prefix><axis>:<name>` (axis x, y, z)."""
    groups = {}
    for c in h:
        for prefix in prefixes:
            m = re.match(rf"^{prefix}[xyz]:(.+)$", c)
            if m:
                groups.setdefault(f"{prefix}:{m.group(1)}", []).append(c)
    return groups


def largest_component(h, columns):
    return max(columns, key=lambda c: float(np.nanmax(np.abs(h[c]))) if len(h[c]) else 0.0)


def save(fig, path):
    figures.save(fig, path, dpi=110)
    print(path)


def forces_figure(h, units, out):
    forces = named_groups(h, ["force_", "load_"])
    if not forces:
        return
    probes = named_groups(h, ["u"])
    probe = None
    if probes:
        moving = [largest_component(h, cols) for cols in probes.values()]
        probe = max(moving, key=lambda c: float(np.nanmax(np.abs(h[c]))))
        if float(np.nanmax(np.abs(h[probe]))) == 0.0:
            probe = None
    panels = 2 if probe else 1
    fig, axes = plt.subplots(1, panels, figsize=(6.0 * panels, 4.2), squeeze=False)
    for name, cols in sorted(forces.items()):
        c = largest_component(h, cols)
        axes[0][0].plot(h["time"], h[c], marker=".", label=c)
        if probe:
            axes[0][1].plot(h[probe], h[c], marker=".", label=c)
    axes[0][0].set_xlabel("time t [–]")
    axes[0][0].set_ylabel("force [N]")
    axes[0][0].set_title("forces (largest component of each)")
    if probe:
        axes[0][1].set_xlabel(label(units, probe))
        axes[0][1].set_ylabel("force [N]")
        axes[0][1].set_title("load against displacement")
    for ax in axes[0]:
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    save(fig, os.path.join(out, "forces.png"))


def moments_figure(h, units, out):
    moments = named_groups(h, ["moment_"])
    if not moments:
        return
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    for name, cols in sorted(moments.items()):
        c = largest_component(h, cols)
        ax.plot(h["time"], h[c], marker=".", label=c)
    ax.set_xlabel("time t [–]")
    unit = unit_of(units, next(iter(moments.values()))[0])
    ax.set_ylabel(f"moment [{unit}]" if unit else "moment")
    ax.set_title("moments on the caps (largest component of each)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, os.path.join(out, "moments.png"))


def columns_figure(h, units, out, x, ys):
    """columns.png: each of the columns `ys` against the column `x`."""
    missing = [c for c in [x, *ys] if c not in h]
    if missing:
        fail(f"history.csv has no column {', '.join(missing)}; its columns: {', '.join(h)}")
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    for y in ys:
        ax.plot(h[x], h[y], marker=".", label=y)
    ax.set_xlabel(label(units, x))
    if len(ys) == 1:
        ax.set_ylabel(label(units, ys[0]))
    else:
        ax.legend(fontsize=8)
    ax.set_title(f"{', '.join(ys)} against {x}")
    ax.grid(alpha=0.3)
    save(fig, os.path.join(out, "columns.png"))


def parse_line(text):
    """The two end points of --line AX,AY,AZ:BX,BY,BZ."""
    try:
        ends = [[float(v) for v in end.split(",")] for end in text.split(":")]
        if len(ends) != 2 or any(len(e) != 3 for e in ends) or not np.all(np.isfinite(ends)):
            raise ValueError
    except ValueError:
        fail(f"--line {text}: give the two end points as AX,AY,AZ:BX,BY,BZ (six numbers, "
             "coordinates of the undeformed body)")
    if ends[0] == ends[1]:
        fail(f"--line {text}: the two end points are the same point")
    return ends


def write_csv(path, header, rows):
    """A CSV file of `header` and `rows` (numbers, 10 digits), written to a temporary beside `path`
    and renamed over it; a `path` that is a symbolic link raises LinkRefused."""
    figures.refuse_link(path)
    fd, temporary = tempfile.mkstemp(prefix=f".{os.path.basename(path)}.tmp.",
                                     dir=os.path.dirname(path) or ".")
    with os.fdopen(fd, "w") as f:
        f.write(",".join(header) + "\n")
        for row in rows:
            f.write(",".join(f"{v:.10g}" for v in row) + "\n")
    os.replace(temporary, path)
    print(path)


def line_files(run, summary, units, out, ends, n, step):
    """line.csv and line.png: the fields of a written step along the segment `ends`."""
    steps = runs.written_steps(run, initial=True)
    if not steps:
        fail(f"{run}: no step file written (solution.pvd)")
    chosen = [path for k, path in steps if k == step] if step is not None else [steps[-1][1]]
    if not chosen:
        fail(f"--step {step}: no such step file in {os.path.join(run, 'solution.pvd')} "
             f"(written: {', '.join(str(k) for k, _ in steps[:20])}; output.every decides)")
    vtu = chosen[0]
    if not vtu.endswith(".vtu"):
        fail(f"{vtu}: a distributed run's step is written in pieces; run plisse plot --line on a "
             "step of a run on one process")
    check_step_header(vtu, summary)
    state = runs.read_state(vtu)
    blocks = state.mesh.cells_dict
    kind = next((k for k in ("tetra10", "tetra", "triangle6", "triangle") if k in blocks), None)
    if kind is None:
        fail(f"{vtu}: holds no tetrahedra or triangles")
    cell_data = {name: arrays[0] for name, arrays in state.mesh.cell_data.items()}
    # The reference positions: step 0's points (a run with output.deformed writes the current
    # ones in the later steps).
    reference = state.points
    if steps[0][0] == 0 and steps[0][1] != vtu and steps[0][1].endswith(".vtu"):
        check_step_header(steps[0][1], summary)
        initial = runs.read_state(steps[0][1]).points
        if initial.shape == reference.shape:
            reference = initial
    header, rows, outside = lines.sample(reference, blocks[kind], state.mesh.point_data,
                                         cell_data, ends[0], ends[1], n)
    if not rows:
        fail(f"--line: none of its {n} points lies in the body (the undeformed body's "
             "coordinates; a shell's points within half an element of its mid-surface)")
    write_csv(os.path.join(out, "line.csv"), header, rows)
    data = np.array(rows)
    column = {name: k for k, name in enumerate(header)}
    # The waves along the line, when every point lies in the body (equal spacing).
    measured = None
    if not outside and "displacement_x" in column:
        deformed = data[:, 1:4] + data[:, [column[f"displacement_{c}"] for c in "xyz"]]
        measured = lines.waves(data[:, 0], deformed)
    if measured:
        count, wavelength, amplitude, peak, spectrum = measured
        if peak:
            print(f"waves along the line: {count} (wavelength {wavelength:.6g} mm), amplitude "
                  f"{amplitude:.6g} mm peak to peak")
        else:
            print(f"waves along the line: none stands out of the line's smooth shape (the "
                  f"largest of 3 or more, {count}, is {amplitude:.3g} mm peak to peak)")
        write_csv(os.path.join(out, "line_spectrum.csv"), ["waves", "wavelength", "amplitude"],
                  spectrum)
    panels = [[c for c in header if c.startswith("displacement_")],
              [c for c in ("von_mises", "pressure", "thickness") if c in column]]
    panels = [p for p in panels if p]
    fig, axes = plt.subplots(len(panels), 1, figsize=(6.0, 3.0 * len(panels)), squeeze=False)
    for ax, names in zip(axes[:, 0], panels):
        for name in names:
            ax.plot(data[:, 0], data[:, column[name]], marker=".", ms=3, label=label(units, name))
        ax.set_xlabel("distance along the line s [mm]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    step_text = runs.step_of(vtu)
    axes[0, 0].set_title(f"step {step_text} along ({', '.join(f'{v:g}' for v in ends[0])}) to "
                         f"({', '.join(f'{v:g}' for v in ends[1])})"
                         + (f"; {outside} of {n} points outside the body" if outside else ""))
    save(fig, os.path.join(out, "line.png"))


def pressure_volume_figure(h, units, out):
    pairs = []
    for c in h:
        m = re.match(r"^pressure:(.+)$", c)
        if m:
            name = m.group(1)
            volume = f"full_volume:{name}" if f"full_volume:{name}" in h else f"volume:{name}"
            if volume in h:
                pairs.append((c, volume))
    if not pairs:
        return
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    for pressure, volume in pairs:
        ax.plot(h[volume], h[pressure], marker=".", label=f"{pressure} against {volume}")
    ax.set_xlabel("volume [mm³]" if len(pairs) > 1 else label(units, pairs[0][1]))
    ax.set_ylabel("pressure [MPa]" if len(pairs) > 1 else label(units, pairs[0][0]))
    ax.set_title("pressure against enclosed volume")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, os.path.join(out, "pressure_volume.png"))


def newton_figure(h, out):
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    ax.bar(h["step"], h["newton_iterations"], color="tab:blue", width=0.8)
    ax.set_xlabel("step")
    ax.set_ylabel("Newton iterations of the accepted attempt", color="tab:blue")
    ax.xaxis.set_major_locator(MaxNLocator(integer=True))
    ax.yaxis.set_major_locator(MaxNLocator(integer=True))
    twin = ax.twinx()
    twin.semilogy(h["step"], np.maximum(h["residual_norm"], 1e-300), "k.", label="|R| reached")
    twin.set_ylabel("residual norm reached")
    ax.set_title("Newton iterations per step")
    save(fig, os.path.join(out, "newton.png"))


def wrinkles_figure(h, out):
    if "wrinkle_amplitude" not in h:
        return
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    ax.plot(h["time"], h["wrinkle_amplitude"], "tab:red", marker=".")
    ax.set_xlabel("time t [–]")
    ax.set_ylabel("largest ring amplitude [mm]", color="tab:red")
    twin = ax.twinx()
    twin.step(h["time"], h["wrinkle_count"], "k", where="mid", label="above the threshold")
    if "wrinkle_peak_count" in h:
        twin.step(h["time"], h["wrinkle_peak_count"], "k:", where="mid", label="any amplitude")
        twin.legend(fontsize=8, loc="upper left")
    twin.set_ylabel("its wave count")
    twin.yaxis.set_major_locator(MaxNLocator(integer=True))
    ax.set_title("wrinkles")
    save(fig, os.path.join(out, "wrinkles.png"))


def wrinkle_lines_figure(h, out):
    """wrinkle_lines.png: each measurement line's crest height against t, and its crests counted
    above the threshold."""
    names = [c[len("wrinkle_amplitude:"):] for c in h if c.startswith("wrinkle_amplitude:")]
    if not names:
        return
    fig, ax = plt.subplots(figsize=(6.0, 4.2))
    twin = ax.twinx()
    for k, name in enumerate(names):
        color = f"C{k % 10}"
        ax.plot(h["time"], h["wrinkle_amplitude:" + name], color=color, marker=".", label=name)
        twin.step(h["time"], h["wrinkle_crests:" + name], color=color, linestyle=":",
                  where="mid")
    ax.set_xlabel("time t [–]")
    ax.set_ylabel("crest height along the line [mm] (solid)")
    twin.set_ylabel("crests above the threshold (dotted)")
    twin.yaxis.set_major_locator(MaxNLocator(integer=True))
    ax.legend(fontsize=8, loc="upper left", title="line")
    ax.set_title("wrinkles along the measurement lines")
    save(fig, os.path.join(out, "wrinkle_lines.png"))


def case_wrinkle_settings(summary):
    path = summary.get("case_path")
    settings = {}
    if path and os.path.isfile(path):
        try:
            settings = runs.case_wrinkle_settings(path)
        except Exception:  # noqa: BLE001  the case may have changed since: use the summary
            settings = {}
    table = summary.get("wrinkles") or {}
    settings = dict(settings)
    settings.setdefault("axis", table.get("axis", "y"))
    settings.setdefault("rings_deg", [r.get("latitude_deg") for r in table.get("rings", [])])
    return settings


def wrinkle_maps(run, summary, out):
    settings = case_wrinkle_settings(summary)
    if not settings.get("rings_deg"):
        return
    files = []
    last = runs.last_vtu(run)
    if last and last.endswith(".vtu"):
        files.append((last, os.path.join(out, "wrinkle_map.png"),
                      f"t = {summary.get('final_time', '?')}: normal deviation, rings"))
    for event in runs.summary_instabilities(summary):
        vtu = os.path.join(run, event.get("file", ""))
        if vtu.endswith(".vtu") and os.path.isfile(vtu):
            files.append((vtu, os.path.join(out, f"wrinkle_map_step_{event['step']:04d}.png"),
                          f"step {event['step']} (stability lost): normal deviation, rings"))
    for vtu, path, title in files:
        check_step_header(vtu, summary)
        if figures.surface_figure(vtu, settings, path, title):
            print(path)
    if files and files[0][1].endswith("wrinkle_map.png"):
        unrolled = os.path.join(out, "wrinkle_unrolled.png")
        figures.refuse_link(unrolled)
        if figures.unrolled_figure(files[0][0], settings, unrolled,
                                   f"t = {summary.get('final_time', '?')}: normal deviation, "
                                   "unrolled"):
            print(unrolled)


def check_size(path, limit):
    if os.path.isfile(path) and os.path.getsize(path) > limit:
        fail(f"{path}: {os.path.getsize(path)} bytes, more than the {limit} a run writes; "
             "not read")


def check_step_header(vtu, summary):
    """Refuses a step file whose header declares more than the run's mesh: a compressed array
    that would inflate to gigabytes is not read. plisse writes at most 9 components per array."""
    with open(vtu, "rb") as f:
        head = f.read(1 << 20).split(b"<AppendedData")[0].decode("utf-8", "replace")
    points = re.search(r'NumberOfPoints="(\d+)"', head)
    cells = re.search(r'NumberOfCells="(\d+)"', head)
    components = [int(n) for n in re.findall(r'NumberOfComponents="(\d+)"', head)]
    nodes = summary.get("nodes")
    if (not points or not cells or (isinstance(nodes, int) and int(points.group(1)) != nodes)
            or any(n > 9 for n in components)):
        raise ValueError(f"{vtu}: its header does not fit the run's mesh ({nodes} nodes); "
                         "not read")


def main():
    usage = "usage: plot.py RUN_DIR OUT_DIR PLISSE_EXECUTABLE [--x COLUMN] [--y COLUMN ...]"
    if len(sys.argv) < 4:
        fail(usage)
    run, out, plisse = sys.argv[1:4]
    x, ys, line, n, step, rest = None, [], None, 200, None, sys.argv[4:]
    while rest:
        if len(rest) < 2 or rest[0] not in ("--x", "--y", "--line", "--points", "--step"):
            fail(usage)
        if rest[0] == "--x":
            x = rest[1]
        elif rest[0] == "--y":
            ys.append(rest[1])
        elif rest[0] == "--line":
            line = parse_line(rest[1])
        elif rest[0] == "--points":
            n = int(rest[1]) if rest[1].isdigit() else 0
            if not 2 <= n <= 100000:
                fail(f"--points {rest[1]}: give a whole number from 2 to 100000")
        else:
            step = int(rest[1]) if rest[1].isdigit() else fail(f"--step {rest[1]}: not a step number")
        rest = rest[2:]
    if x is not None and not ys:
        fail("--x needs at least one --y column to draw against it")
    if line is not None and (ys or x is not None):
        fail("--line and --x/--y draw different figures: give one or the other")
    if not os.path.isfile(os.path.join(run, "history.csv")):
        fail(f"{run}: not a run directory (no history.csv)")
    check_size(os.path.join(run, "history.csv"), MAX_HISTORY_BYTES)
    check_size(os.path.join(run, "summary.json"), MAX_SUMMARY_BYTES)
    try:
        h = runs.read_history(run)
    except MALFORMED as e:
        fail(f"{os.path.join(run, 'history.csv')}: not a history plisse writes: {e}")
    if not h:
        fail(f"{os.path.join(run, 'history.csv')}: no converged step to plot")
    try:
        summary = runs.read_summary(run)
        if not isinstance(summary, dict):
            raise ValueError("not a JSON object")
    except MALFORMED as e:
        fail(f"{os.path.join(run, 'summary.json')}: not a summary plisse writes: {e}")
    try:
        figures.refuse_link(out)
        os.makedirs(out, exist_ok=True)
        for name in sorted(os.listdir(out)):
            if name.endswith(".png") and (name in FIGURES or name.startswith("wrinkle_map_step_")):
                figures.refuse_link(os.path.join(out, name))
    except figures.LinkRefused as e:
        fail(str(e))
    units = reference_units(plisse)
    try:
        if ys:
            columns_figure(h, units, out, x or "time", ys)
            return
        if line is not None:
            line_files(run, summary, units, out, line, n, step)
            return
        forces_figure(h, units, out)
        moments_figure(h, units, out)
        pressure_volume_figure(h, units, out)
        newton_figure(h, out)
        wrinkles_figure(h, out)
        wrinkle_lines_figure(h, out)
        wrinkle_maps(run, summary, out)
    except figures.LinkRefused as e:
        fail(str(e))
    except MALFORMED as e:
        fail(f"{run}: its files are malformed: {type(e).__name__}: {e}")


if __name__ == "__main__":
    main()
