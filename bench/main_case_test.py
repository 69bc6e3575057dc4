"""Unit tests of bench/main_case_table.py, the generated block of docs/performance.md (section
"Krylov steps with a kept factorisation"): the table, the ratio within each pair and the
comparison of the two histories from fixed measurements, the markers, and that the docs hold what
the last run wrote. No timing.
Run by CTest (test bench_main_case, label unit): /usr/bin/python3 bench/main_case_test.py
"""
import copy
import sys
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import block_testing  # noqa: E402
import main_case_table as table  # noqa: E402


def run(wall, newton, factorisations, krylov, reused, assembly, factorisation, solve, stability,
        peak, force):
    """A run of the case whose punch force ends at `force` (largest 0.02 N over the run) and whose
    volume ends at 100 (largest 110)."""
    return {"wall": wall, "newton": newton, "factorisations": factorisations,
            "krylov_steps": krylov, "reused_solves": reused, "assembly": assembly,
            "factorisation": factorisation, "solve": solve, "stability": stability, "peak": peak,
            "unknowns": 35976, "steps": 50,
            "final": {"step": 50.0, "residual_norm": 1e-9 * force, "force_y:punch": force,
                      "volume": 100.0},
            "largest": {"step": 50.0, "residual_norm": 1e-6, "force_y:punch": 0.02,
                        "volume": 110.0}}


def old(wall):
    """A run of the earlier commit: no Krylov steps or kept-factor solves in its summary."""
    return run(wall, 260, 260, None, None, 80.0, 300.0, 10.0, 65.0, 477.0, 0.012)


# Three pairs: 200/400, 210/420 and 230/400 s: ratios 0.5, 0.5 and 0.575, median 0.5 (2 times
# faster). Today's punch force ends 1e-6 N from the old one's: 5e-5 of its largest 0.02 N.
MEASUREMENTS = {
    "command": "bench/main-case --against bbce1c5", "commit": "abc1234", "local_changes": False,
    "date": "2024-01-02", "cores": 2, "against": "bbce1c5", "repeats": 3,
    "runs": [
        {"against": old(400.0), "now": run(200.0, 8, 8, 190, 1300, 70.0, 10.0, 60.0, 60.0, 528.0,
                                           0.012001)},
        {"against": old(420.0), "now": run(210.0, 8, 8, 192, 1310, 68.0, 9.0, 58.0, 62.0, 530.0,
                                           0.012001)},
        {"against": old(400.0), "now": run(230.0, 8, 8, 193, 1366, 69.0, 9.9, 56.6, 61.3, 529.0,
                                           0.012001)},
    ],
    "load_average": [0.3, 1.2]}

EXPECTED = """\
Made by `bench/main-case --against bbce1c5` at commit abc1234 on 2024-01-02: \
`examples/sphere-indentation.yaml` (35 976 unknowns, 50 steps), 3 pairs of runs, the plisse of \
commit bbce1c5 then today's, one core each (OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1). Wall time: \
median (smallest–largest); the counts: the last run's; the other times: medians; peak memory: the \
largest. The machine (2 cores) had a load average of 0.3 when the run began and 1.2 when it ended.

| | commit bbce1c5 | now (commit abc1234) |
|---|---|---|
| wall time [s] | 400.0 (400.0–420.0) | 210.0 (200.0–230.0) |
| Newton iterations | 260 | 8 |
| factorisations | 260 | 8 |
| Krylov steps | – | 193 |
| solves with a kept factorisation | – | 1366 |
| assembly [s] | 80.0 | 69.0 |
| numeric factorisation [s] | 300.0 | 9.9 |
| triangular solves [s] | 10.0 | 58.0 |
| stability checks [s] | 65.0 | 61.3 |
| peak memory [MiB] | 477 | 530 |

Today's plisse takes **0.500** (0.500–0.575) of the wall time of commit bbce1c5's: 2.00 times \
faster. The last pair's final history rows differ by at most 5.0e-05 of a column's largest value \
over the run (the largest: force_y:punch 5.0e-05, volume 0.0e+00).
"""


class MainCaseTable(block_testing.BlockChecks, unittest.TestCase):
    table, measurements, expected, record = table, MEASUREMENTS, EXPECTED, "main-case"

    def test_the_ratio_is_taken_within_each_pair(self):
        self.assertEqual([round(r, 6) for r in table.ratios(MEASUREMENTS)], [0.5, 0.5, 0.575])
        # Across pairs (the fastest today against the slowest before) it would be 200/420.

    def test_the_solvers_own_columns_are_not_compared(self):
        m = copy.deepcopy(MEASUREMENTS)
        m["runs"][-1]["now"]["final"]["residual_norm"] = 1.0  # a millionfold its largest
        self.assertEqual(table.differences(m)[0][1], "force_y:punch")

    def test_one_program_alone_gives_one_column_and_no_ratio(self):
        m = copy.deepcopy(MEASUREMENTS)
        del m["against"]
        for pair in m["runs"]:
            del pair["against"]
        block = table.render_block(m)
        self.assertIn("| | now (commit abc1234) |\n|---|---|\n", block)
        self.assertIn(", 3 runs, one core each", block)
        self.assertNotIn("faster", block)


if __name__ == "__main__":
    unittest.main()
