"""Unit tests of bench/threads_table.py, the generated block of docs/performance.md (section
"Threads"): the table and its verdict from fixed measurements, the markers, and that the docs hold
what the last run wrote. No timing.
Run by CTest (test bench_threads, label unit): /usr/bin/python3 bench/threads_test.py
"""
import copy
import sys
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import block_testing  # noqa: E402
import threads_table as table  # noqa: E402


def run(setting, wall, cpu):
    return {"setting": setting, "wall": wall, "cpu": cpu,
            "threads": [2, 1] if setting is None else setting}


# Three rounds. The default: 20, 22 and 25 s of wall time, 30, 33 and 36 s of CPU. 1/1 takes
# 1.25, 1.2 and 1.2 times the wall time (median 1.2) and 0.8 times the CPU; 2/2 takes 0.9, 1.1
# and 1.0 times the wall time (median 1.0: not faster) and 1.25 times the CPU.
MEASUREMENTS = {
    "command": "bench/threads --settings 1/1,2/2", "commit": "abc1234", "local_changes": False,
    "date": "2024-01-02", "cores": 2,
    "rounds": [[run(None, 20.0, 30.0), run([1, 1], 25.0, 24.0), run([2, 2], 18.0, 37.5)],
               [run(None, 22.0, 33.0), run([1, 1], 26.4, 26.4), run([2, 2], 24.2, 41.25)],
               [run(None, 25.0, 36.0), run([1, 1], 30.0, 28.8), run([2, 2], 25.0, 45.0)]],
    "load_average": [0.2, 0.4]}

EXPECTED = """\
Made by `bench/threads --settings 1/1,2/2` at commit abc1234 on 2024-01-02: the main case at 2 mm \
elements (`examples/sphere-indentation.yaml --set mesh.element_size=2`), 3 rounds of whole runs, \
the settings in turn within each, plisse's own choice first. Wall and CPU time (user + system) \
relative to plisse's own choice in the same round: median (smallest–largest); that choice's own \
times: median. The machine (2 cores) had a load average of 0.2 when the run began and 0.4 when it \
ended.

| element-loop threads | BLAS threads | wall time | CPU time |
|---|---|---|---|
| 2 (plisse's own choice) | 1 (plisse's own choice) | 1 (22.0 s) | 1 (33.0 s) |
| 1 (OMP_NUM_THREADS) | 1 (OPENBLAS_NUM_THREADS) | 1.20 (1.20–1.25) | 0.80 (0.80–0.80) |
| 2 (OMP_NUM_THREADS) | 2 (OPENBLAS_NUM_THREADS) | 1.00 (0.90–1.10) | 1.25 (1.25–1.25) |

No setting is faster than plisse's own choice (every median wall time is 1 or more).
"""


class ThreadsTable(block_testing.BlockChecks, unittest.TestCase):
    table, measurements, expected, record = table, MEASUREMENTS, EXPECTED, "threads"

    def test_the_ratios_are_taken_within_each_round(self):
        self.assertEqual([round(r, 6) for r in table.ratios(MEASUREMENTS, 1, "wall")],
                         [1.25, 1.2, 1.2])

    def test_a_faster_setting_is_named(self):
        m = copy.deepcopy(MEASUREMENTS)
        m["rounds"][2][2]["wall"] = 20.0  # 2/2: 0.9, 1.1, 0.8 -> median 0.9
        self.assertIn("Faster than plisse's own choice (median wall time below 1): 2/2.",
                      table.render_block(m))


if __name__ == "__main__":
    unittest.main()
