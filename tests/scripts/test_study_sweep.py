"""Unit tests of plisse_study.sweep: the command of a point, run naming, running with a transcript,
failures, the stop rule, and the reuse of finished runs, with a fake plisse that writes a run
directory."""
import contextlib
import io
import os
import stat
import subprocess
import tempfile
import unittest

import study_fixtures  # noqa: F401  (scripts/ on the import path)
from plisse_study import sweep

# The fake plisse: appends its arguments to calls.txt beside it, makes the -o directory with a
# summary.json, prints two lines, and exits with $FAKE_STATUS. With $FAKE_WAIT it keeps running
# until SIGTERM, then exits 143 as plisse does when interrupted; its handler is in place before it
# prints its first line.
FAKE = """#!/bin/sh
[ -n "$FAKE_WAIT" ] && trap 'echo "interrupted"; exit 143' TERM
echo "$@" >> "$(dirname "$0")/calls.txt"
out=""; prev=""
for a in "$@"; do [ "$prev" = "-o" ] && out="$a"; prev="$a"; done
mkdir -p "$out"
echo "plisse: starting"
echo ""
if [ -n "$FAKE_WAIT" ]; then
  while :; do sleep 0.02; done
fi
echo '{"completed": true}' > "$out/summary.json"
echo "done: 3 steps"
exit ${FAKE_STATUS:-0}
"""


class SweepTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.plisse = os.path.join(self.tmp.name, "plisse")
        with open(self.plisse, "w") as f:
            f.write(FAKE)
        os.chmod(self.plisse, os.stat(self.plisse).st_mode | stat.S_IXUSR)
        self.calls = os.path.join(self.tmp.name, "calls.txt")
        self.case = os.path.join(self.tmp.name, "case.yaml")
        os.environ.pop("FAKE_STATUS", None)
        os.environ.pop("FAKE_WAIT", None)

    def tearDown(self):
        os.environ.pop("FAKE_STATUS", None)
        os.environ.pop("FAKE_WAIT", None)
        self.tmp.cleanup()

    def read_calls(self):
        if not os.path.isfile(self.calls):
            return []
        with open(self.calls) as f:
            return f.read().splitlines()

    def quiet(self, function, *args, **kwargs):
        """Runs function, returning (its result, what it printed)."""
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            result = function(*args, **kwargs)
        return result, out.getvalue()

    def test_command(self):
        self.assertEqual(sweep.command("c.yaml", "runs/x", ["a=1", "b.c=[0,1]"], plisse="p"),
                         ["p", "run", "c.yaml", "-o", "runs/x", "--overwrite",
                          "--set", "a=1", "--set", "b.c=[0,1]"])
        self.assertTrue(sweep.command("c.yaml", "r", [])[0].endswith(
            os.path.join("build", "bin", "plisse")))

    def test_folder_names(self):
        self.assertEqual(sweep.folder_name("mesh.layers", 3), "layers=3")
        self.assertEqual(sweep.folder_name("loads[0].value", 0.001), "value=0.001")
        self.assertEqual(sweep.folder_name("solver.stability.check", True), "check=true")
        # A list in JSON without spaces, then the characters a file name cannot hold replaced.
        self.assertEqual(sweep.yaml_value([0, 1.5, 0]), "[0, 1.5, 0]")
        self.assertEqual(sweep.folder_name("dies[0].point", [0, 1.5, 0]), "point=_0_1.5_0_")
        self.assertEqual(sweep.folder_name("element", "taylor-hood"), "element=taylor-hood")
        # List indices leave the leaf.
        self.assertEqual(sweep.folder_name("caps[1].displacement[1]", -15), "displacement=-15")
        self.assertEqual(sweep.folder_name("x", "a b/c"), "x=a_b_c")

    def test_run_with_transcript(self):
        run = os.path.join(self.tmp.name, "runs", "layers=2")
        transcript = run + ".out"
        outcome, printed = self.quiet(sweep.run_case, self.case, run, ["mesh.layers=2"],
                                      transcript=transcript, plisse=self.plisse,
                                      echo=lambda cmd: "study: " + " ".join(cmd[1:3]))
        self.assertEqual(printed, "study: run " + self.case + "\n")
        self.assertEqual(outcome.returncode, 0)
        self.assertFalse(outcome.stopped)
        self.assertEqual(outcome.message, "done: 3 steps")
        self.assertGreaterEqual(outcome.seconds, 0.0)
        self.assertTrue(sweep.finished(run))
        with open(transcript) as f:
            self.assertEqual(f.read(), "plisse: starting\n\ndone: 3 steps\n")
        self.assertEqual(self.read_calls(),
                         [f"run {self.case} -o {run} --overwrite --set mesh.layers=2"])

    def test_failed_run(self):
        run = os.path.join(self.tmp.name, "failed")
        os.environ["FAKE_STATUS"] = "1"
        outcome, printed = self.quiet(sweep.run_case, self.case, run, [], plisse=self.plisse)
        self.assertEqual(outcome.returncode, 1)
        self.assertEqual(outcome.message, "")  # no transcript: the output is dropped
        self.assertEqual(printed, f"{self.plisse} run {self.case} -o {run} --overwrite\n")
        with self.assertRaises(subprocess.CalledProcessError):
            self.quiet(sweep.run_case, self.case, run, [], plisse=self.plisse, check=True)

    def test_stop_rule_and_time_limit(self):
        os.environ["FAKE_WAIT"] = "1"
        asked = []
        run = os.path.join(self.tmp.name, "stopped")

        def stop():
            # Not before the fake has printed, and so set its handler: on a loaded machine the
            # second poll can come before the shell has read its first line.
            asked.append(1)
            try:
                with open(run + ".out") as f:
                    started = "plisse: starting" in f.read()
            except FileNotFoundError:
                started = False
            return len(asked) >= 2 and started

        outcome, _ = self.quiet(sweep.run_case, self.case, run, [], plisse=self.plisse,
                                transcript=run + ".out", stop=stop, poll=0.05, check=True)
        self.assertTrue(outcome.stopped)
        self.assertEqual(outcome.returncode, 143)
        self.assertEqual(outcome.message, "interrupted")
        self.assertGreaterEqual(len(asked), 2)
        self.assertFalse(sweep.finished(run))
        outcome, _ = self.quiet(sweep.run_case, self.case, run, [], plisse=self.plisse,
                                minutes=0.1 / 60.0, poll=0.05)
        self.assertTrue(outcome.stopped)

    def test_sweep_reuses_finished_runs(self):
        directory = os.path.join(self.tmp.name, "sweep")
        points = [("tau-1", ["loads[0].value=1e-3"]), ("tau-2", ["loads[0].value=2e-3"])]
        done, _ = self.quiet(sweep.sweep, self.case, directory, points, plisse=self.plisse)
        self.assertEqual([os.path.basename(run) for run, _ in done], ["tau-1", "tau-2"])
        self.assertEqual(len(self.read_calls()), 2)
        # tau-2 lost its summary (a run killed before its end): only it runs again.
        os.remove(os.path.join(directory, "tau-2", "summary.json"))
        done, printed = self.quiet(sweep.sweep, self.case, directory, points, reuse=True,
                                   plisse=self.plisse)
        calls = self.read_calls()
        self.assertEqual(len(calls), 3)
        self.assertIn("tau-2 --overwrite --set loads[0].value=2e-3", calls[-1])
        self.assertIn(os.path.join(directory, "tau-1") + ": kept\n", printed)
        self.assertIsNone(done[0][1].returncode)
        self.assertEqual(done[1][1].returncode, 0)
        # Without reuse every point runs again.
        self.quiet(sweep.sweep, self.case, directory, points, plisse=self.plisse)
        self.assertEqual(len(self.read_calls()), 5)


if __name__ == "__main__":
    unittest.main()
