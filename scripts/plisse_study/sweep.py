"""Running a case for a list of `--set` overrides: the command of one point, one run, a sweep.

A point of a sweep is a run directory name and its overrides; its run is
`build/bin/plisse run CASE -o DIR/NAME --overwrite --set KEY=VALUE ...`. A run directory that
holds a summary.json is finished (plisse writes it last, also when a run stops early), so a sweep
asked to reuse runs skips it.
"""
import json
import os
import re
import signal
import subprocess
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
PLISSE = os.path.join(ROOT, "build", "bin", "plisse")


def command(case, run_dir, overrides, plisse=None):
    """The `plisse run` command line of one point (a list of arguments)."""
    cmd = [plisse or PLISSE, "run", case, "-o", run_dir, "--overwrite"]
    for o in overrides:
        cmd += ["--set", o]
    return cmd


def finished(run_dir):
    """True when `run_dir` holds a summary.json: plisse wrote its last file there."""
    return os.path.isfile(os.path.join(run_dir, "summary.json"))


class Outcome:
    """What became of one run: `returncode` (None when it was reused), the wall time in
    `seconds`, whether the sweep `stopped` it, and the last non-empty line of its transcript
    (`message`, "" without one)."""

    def __init__(self, returncode=None, seconds=None, stopped=False, message=""):
        self.returncode = returncode
        self.seconds = seconds
        self.stopped = stopped
        self.message = message


def run_case(case, run_dir, overrides, transcript=None, stop=None, minutes=None, poll=5.0,
             check=False, echo=None, plisse=None):
    """Runs one point and waits for it; returns its Outcome.

    Prints the command first (`echo(cmd)` when given, else the arguments joined by spaces).
    `transcript`: a file that receives plisse's output and error stream (else the output is
    dropped and errors go to this process's). `stop`: a function of no arguments, asked every
    `poll` seconds while the run goes on; when it returns True, or after `minutes`, the run gets
    SIGTERM (plisse ends the step, writes its files and says `interrupted`). `check`: raise
    subprocess.CalledProcessError when plisse exits with another status than 0 and was not
    stopped."""
    cmd = command(case, run_dir, overrides, plisse)
    print(echo(cmd) if echo else " ".join(cmd), flush=True)
    start = time.monotonic()
    if transcript:
        os.makedirs(os.path.dirname(os.path.abspath(transcript)), exist_ok=True)
    out = open(transcript, "w") if transcript else subprocess.DEVNULL
    try:
        process = subprocess.Popen(cmd, stdout=out,
                                   stderr=subprocess.STDOUT if transcript else None)
        stopping = False
        if stop is None and minutes is None:
            process.wait()
        while process.poll() is None:
            time.sleep(poll)
            late = minutes is not None and time.monotonic() - start > 60.0 * minutes
            if not stopping and (late or (stop is not None and stop())):
                process.send_signal(signal.SIGTERM)
                stopping = True
    finally:
        if transcript:
            out.close()
    seconds = time.monotonic() - start
    if check and process.returncode != 0 and not stopping:
        raise subprocess.CalledProcessError(process.returncode, cmd)
    message = ""
    if transcript:
        with open(transcript) as f:
            last = [line for line in f.read().splitlines() if line.strip()]
        message = last[-1] if last else ""
    return Outcome(process.returncode, seconds, stopping, message)


def sweep(case, directory, points, reuse=False, **options):
    """Runs `case` at every point (name, overrides) into `directory`/name, one after the other;
    with `reuse` a finished run is kept ("<run>: kept"). `options` go to run_case. Returns
    [(run directory, Outcome)]."""
    os.makedirs(directory, exist_ok=True)
    done = []
    for name, overrides in points:
        run = os.path.join(directory, name)
        if reuse and finished(run):
            print(f"{run}: kept", flush=True)
            done.append((run, Outcome()))
            continue
        done.append((run, run_case(case, run, overrides, **options)))
    return done


def yaml_value(v):
    """A value as `--set` takes it: lists and maps in JSON, booleans as true/false."""
    return json.dumps(v) if isinstance(v, (list, dict)) else str(v).lower() if isinstance(v, bool) \
        else str(v)


def folder_name(key, value):
    """`<leaf>=<value>`: the last part of the key without list indices (`value` when it has
    none), and the value with the characters a file name cannot hold replaced by '_'."""
    leaf = re.sub(r"\[\d+\]", "", key).split(".")[-1] or "value"
    text = re.sub(r"[^A-Za-z0-9_.+-]", "_", yaml_value(value).replace(", ", ","))
    return f"{leaf}={text}"
