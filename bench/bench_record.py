"""What every benchmark of bench/ that writes a generated block of the docs records beside its
measurements: the command, the commit and whether the measured sources had uncommitted changes,
the date, the machine's cores and its load average when the run began (and, appended by the
caller, when it ended); and where the measurements behind a page's block are kept."""
import datetime
import os
import shlex
import subprocess
import sys
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
