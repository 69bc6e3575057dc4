"""Unit tests of bench/bench_record.py's helpers that every bench shares: a command run on one core
and timed from outside (exit status, log, wall and CPU time, working directory, the failure's
exception), and the last row and largest magnitudes of a history.csv. No timing figure is
asserted beyond what the command itself guarantees (a child that spins until its own CPU clock
reaches 0.3 s has used at least that much).
Run by CTest (test bench_bench_record, label unit): /usr/bin/python3 bench/bench_record_test.py
"""
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import bench_record  # noqa: E402

SPIN = "import time\nwhile time.process_time() < 0.3:\n    pass\n"


class TimedRun(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.work = Path(self.dir.name)

    def tearDown(self):
        self.dir.cleanup()

    def test_status_and_both_streams_in_the_log(self):
        log = self.work / "run.log"
        status, wall, cpu = bench_record.timed_run(
            ["sh", "-c", "echo to-stdout; echo to-stderr >&2; exit 3"], log, check=False)
        self.assertEqual(status, 3)
        self.assertEqual(log.read_text().split(), ["to-stdout", "to-stderr"])
        self.assertGreaterEqual(wall, 0.0)
        self.assertGreaterEqual(cpu, 0.0)

    def test_a_failure_raises_when_checked(self):
        with self.assertRaises(subprocess.CalledProcessError):
            bench_record.timed_run(["sh", "-c", "exit 1"], self.work / "run.log")

    def test_one_core_and_the_working_directory(self):
        log = self.work / "run.log"
        status, _, _ = bench_record.timed_run(
            ["sh", "-c", "pwd; echo $OMP_NUM_THREADS $OPENBLAS_NUM_THREADS"], log, cwd=self.work)
        self.assertEqual(status, 0)
        self.assertEqual(log.read_text().splitlines(), [str(self.work.resolve()), "1 1"])

    def test_cpu_time_is_the_childs_own(self):
        status, wall, cpu = bench_record.timed_run([sys.executable, "-c", SPIN],
                                                   self.work / "run.log")
        self.assertEqual(status, 0)
        self.assertGreaterEqual(cpu, 0.3)
        self.assertGreaterEqual(wall + 0.05, cpu)  # one core: no more CPU than wall time


class History(unittest.TestCase):
    def test_last_row_and_largest_magnitudes_of_the_numeric_columns(self):
        with tempfile.TemporaryDirectory() as d:
            path = Path(d) / "history.csv"
            # A text column, and one numeric in one row only: neither is a numeric column.
            path.write_text("step,time,force,status,note\n1,0.5,-3.0,ok,1\n2,1.0,2.0,ok,x\n")
            final, largest = bench_record.final_and_largest(path)
        self.assertEqual(final, {"step": 2.0, "time": 1.0, "force": 2.0})
        self.assertEqual(largest, {"step": 2.0, "time": 1.0, "force": 3.0})


if __name__ == "__main__":
    unittest.main()
