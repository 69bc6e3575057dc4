"""What every benchmark of bench/ that writes a generated block of the docs records beside its
measurements: the command, the commit and whether the measured sources had uncommitted changes,
the date, the machine's cores and its load average when the run began (and, appended by the
caller, when it ended); where the measurements behind a page's block are kept; and one run of
plisse timed from outside."""
import csv
import datetime
import json
import os
import resource
import shlex
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def git(*args):
    return subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True, text=True,
                          check=True).stdout.strip()


def provenance(program, sources):
    """The record's head for `program` (e.g. "bench/thin-shell") run with this process's
    arguments; `sources`: the paths whose changes change what is measured."""
    return {"command": program + " " + shlex.join(sys.argv[1:]),
            "commit": git("rev-parse", "--short", "HEAD"),
            "local_changes": bool(git("status", "--porcelain", "--", *sources)),
            "date": datetime.date.today().isoformat(), "cores": os.cpu_count(),
            "load_average": [os.getloadavg()[0]]}


def record_of(page, name):
    """Where the measurements behind the block of `page` are kept: docs/performance.md and
    "thin-shell" -> docs/performance/thin-shell.json."""
    return Path(page).with_suffix("") / f"{name}.json"


def one_core_env():
    """This process's environment with one element-loop and one BLAS thread, for a run timed on
    one core."""
    return dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1")


def children_cpu():
    """The CPU time [s] of this process's finished children so far, user and system."""
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def timed_run(command, log, cwd=None, check=True):
    """Runs `command` on one core (one_core_env), what it prints into the file `log`; returns its
    exit status, its wall time [s] and its CPU time [s]. With `check`, raises
    subprocess.CalledProcessError when it fails."""
    cpu, start = children_cpu(), time.monotonic()
    with open(log, "w", encoding="utf-8") as f:
        status = subprocess.run([str(c) for c in command], env=one_core_env(), cwd=cwd, stdout=f,
                                stderr=subprocess.STDOUT, check=check).returncode
    return status, time.monotonic() - start, children_cpu() - cpu


def run_plisse(plisse, case, options, out, log):
    """Runs `plisse run --overwrite CASE OPTIONS -o OUT` (plisse: the executable) on one core
    (timed_run); returns the wall time of the whole process [s] and its summary.json. Raises
    subprocess.CalledProcessError when the run fails."""
    _, wall, _ = timed_run([plisse, "run", "--overwrite", case, *options, "-o", out], log)
    return wall, json.loads((Path(out) / "summary.json").read_text(encoding="utf-8"))


def refuse_without_block(program, page, table):
    """Exits with status 2, before anything runs, when `page` (--update's file; None: no update)
    cannot be read or lacks the block of `table` (a bench table module: its MARKERS and
    peer_table)."""
    if page is None:
        return
    try:
        table.peer_table.block_span(Path(page).read_text(encoding="utf-8"), table.MARKERS)
    except (OSError, table.peer_table.BlockError) as error:
        print(f"{program}: --update {page}: {error}", file=sys.stderr)
        sys.exit(2)


def update_page(program, page, table, results):
    """Rewrites the block of `table` in `page` from `results` and keeps them beside it (record_of);
    `program` is the bench's name, e.g. "thin-shell"."""
    table.update_file(page, results)
    record = record_of(page, program)
    record.parent.mkdir(exist_ok=True)
    record.write_text(json.dumps(results, indent=1) + "\n")
    print(f"{program}: rewrote the block of {page}; measurements in {record}", file=sys.stderr)


def run_or_load(program, args, table, measure):
    """The end of a bench's main(): refuses --update's page (args.update) without the block of
    `table` before anything runs, takes the measurements from --from-json's file (args.from_json)
    or from measure(), then rewrites the page's block and keeps the measurements beside it
    (update_page), or prints the block. `table`: the bench's table module (MARKERS, peer_table,
    load, render_block, update_file)."""
    refuse_without_block(program, args.update, table)
    results = table.load(args.from_json) if args.from_json else measure()
    if args.update:
        update_page(program, args.update, table, results)
    else:
        print(table.render_block(results), end="")


def numeric_history(path):
    """{column: [value of each row]} of the numeric columns of a history.csv: those whose every
    row holds a number."""
    with open(path, encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    columns, text = {}, set()
    for row in rows:
        for key, value in row.items():
            try:
                columns.setdefault(key, []).append(float(value))
            except (TypeError, ValueError):
                text.add(key)
    return {k: v for k, v in columns.items() if k not in text}


def final_and_largest(path):
    """(the last row, the largest magnitude of each column) of a history.csv's numeric columns."""
    numeric = numeric_history(path)
    return ({k: v[-1] for k, v in numeric.items()},
            {k: max(abs(x) for x in v) for k, v in numeric.items()})
