"""Unit tests of bench/e2e_shell_table.py, the generated block of docs/performance.md ("End-to-end:
the shell benchmark on one and two ranks"): the rows, the speed-ups within each repeat, the growth
exponents, the scaling verdict and the comparison of the results from fixed measurements, the
markers, and that the docs hold what the last run wrote. No timing.
Run by CTest (test bench_e2e_shell, label unit): /usr/bin/python3 bench/e2e_shell_test.py
"""
import copy
import sys
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import block_testing  # noqa: E402
import e2e_shell_table as table  # noqa: E402


def run(size, h, linear, ranks, repeat, unknowns, assembly, factorisation, solve, wall, peak,
        peak_rank, nonzeros=0, entries=0, gmres=(), linear_solve=None, final=None):
    """One run of 10 Newton iterations; its linear solves are its factorisations and solves
    unless `linear_solve` says otherwise."""
    return {"size": size, "h": h, "linear": linear, "ranks": ranks, "repeat": repeat,
            "unknowns": unknowns, "newton": 10, "factorisations": 10 if linear == "direct" else 0,
            "assembly": assembly,
            "linear_solve": factorisation + solve if linear_solve is None else linear_solve,
            "factorisation": factorisation, "solve": solve, "wall": wall, "peak": peak,
            "peak_rank": peak_rank, "tangent_nonzeros": nonzeros, "factor_entries": entries,
            "gmres": list(gmres), "final": final or {"step": 3.0, "residual_norm": 1e-12,
                                                     "volume": 100.0}}


# S twice on 1 and 2 ranks: Newton iterations of 0.4 and 0.2 s (repeat 0), 0.48 and 0.3 s
# (repeat 1): speed-ups per iteration 2.0 and 1.6, median 1.8; per run 5/3 and 6/4, median 1.58.
# Per iteration on 1 rank (medians): assembly 0.11, factorisation 0.275, solve 0.055 s; peak
# memory 205 MiB (the median; 210 the largest).
# M, 8 times the unknowns, once: assembly 0.88 s an iteration (a = 1), factorisation
# 0.275 * 8^1.5 = 6.2225 s (a = 1.5), solve 0.44 s, so an iteration 7.5425 s against S's 0.44
# (a = ln(17.142) / ln 8 = 1.366), 1.13 times its factorisation and solve; factor entries 12 times
# S's (a = 1.195), peak 8 times (a = 1). On 2 ranks an iteration of 5.0284 s, 1.5 times faster:
# the target is missed. The 2-rank S run of repeat 0 ends 1e-12 (relative) from the 1-rank one,
# M's iterative run 3e-9, both with another residual; M's iterative run takes 1.5 times the direct
# run's wall time and 0.75 times its memory, its Newton iteration 4.88 s.
MEASUREMENTS = {
    "command": "bench/e2e-shell --linear direct,iterative S:2 M:1", "commit": "abc1234",
    "local_changes": False, "date": "2024-01-02", "cores": 2,
    "runs": [
        run("S", 1.5, "direct", 1, 0, 10000, 1.0, 2.5, 0.5, 5.0, 200.0, 200.0, 1e6, 7e6),
        run("S", 1.5, "direct", 2, 0, 10000, 0.5, 1.25, 0.25, 3.0, 300.0, 160.0, 1e6, 7e6,
            final={"step": 3.0, "residual_norm": 5e-12, "volume": 100.0 * (1 + 1e-12)}),
        run("M", 0.75, "direct", 1, 0, 80000, 8.8, 62.225397, 4.4, 80.0, 1640.0, 1640.0, 8e6,
            8.4e7),
        run("M", 0.75, "direct", 2, 0, 80000, 5.866667, 41.483598, 2.933333, 56.0, 2400.0,
            1250.0, 8e6, 8.4e7),
        run("M", 0.75, "iterative", 1, 0, 80000, 8.8, 0.0, 0.0, 120.0, 1230.0, 1230.0,
            gmres=(100, 80, 70, 60, 60, 50, 50, 50, 40, 40), linear_solve=40.0,
            final={"step": 3.0, "residual_norm": 1e-11, "volume": 100.0 * (1 + 3e-9)}),
        run("S", 1.5, "direct", 1, 1, 10000, 1.2, 3.0, 0.6, 6.0, 210.0, 210.0, 1e6, 7e6),
        run("S", 1.5, "direct", 2, 1, 10000, 0.6, 2.0, 0.4, 4.0, 310.0, 170.0, 1e6, 7e6),
    ],
    "load_average": [0.5, 1.5]}

EXPECTED = """\
Made by `bench/e2e-shell --linear direct,iterative S:2 M:1` at commit abc1234 on 2024-01-02: 1 \
or 2 repeats per row, the rank counts of a size in turn within each; one assembly and one BLAS \
thread a rank, full Newton. Per-iteration times and ratios: medians over the repeats; wall time \
and speed-ups: median (smallest–largest); peak memory: the largest (job / largest rank). The \
machine (2 cores) had a load average of 0.5 when the run began and 1.5 when it ended.

| size | h [mm] | unknowns | linear solver | ranks | Newton iterations | GMRES a Newton \
iteration | assembly [s/it] | factorisation [s/it] | solve [s/it] | Newton iteration [s] | \
assembly [%] | iteration / (factorisation + solve) | tangent nonzeros [10⁶] | factor entries \
[10⁶] | fill | wall [s] | peak [MiB] | speed-up: iteration / run |
|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|
| S | 1.5 | 10 000 | direct | 1 | 10 | – | 0.11 | 0.275 | 0.055 | 0.44 | 25 | 1.33 | 1 | 7 | \
7.0 | 5.5 (5.0–6.0) | 210 |  |
| S | 1.5 | 10 000 | direct | 2 | 10 | – | 0.055 | 0.163 | 0.0325 | 0.25 | 22 | 1.29 | 1 | 7 | \
7.0 | 3.5 (3.0–4.0) | 310 / 170 | 1.80 (1.60–2.00) / 1.58 (1.50–1.67) |
| M | 0.75 | 80 000 | direct | 1 | 10 | – | 0.88 | 6.22 | 0.44 | 7.54 | 12 | 1.13 | 8 | 84 | \
10.5 | 80.0 | 1640 |  |
| M | 0.75 | 80 000 | direct | 2 | 10 | – | 0.587 | 4.15 | 0.293 | 5.03 | 12 | 1.13 | 8 | 84 | \
10.5 | 56.0 | 2400 / 1250 | 1.50 / 1.43 |
| M | 0.75 | 80 000 | iterative | 1 | 10 | 60 (100 → 40) | 0.88 | – | – | 4.88 | 18 | – | – | – \
| – | 120.0 | 1230 |  |

From 10 000 to 80 000 unknowns on 1 rank, direct solver, as unknowns^a: a Newton iteration a = \
1.37 (assembly 1.00, factorisation 1.50), factor entries 1.19, peak memory 1.00.
Target: on M, 2 ranks at least 1.6 times faster per Newton iteration than 1 (direct solver): \
1.50, **not met**.
The iterative solver against the direct one: M on 1 rank: wall 1.50 times the direct solver's, \
peak memory 0.75 times.
Every other run's last history row lies within 3.0e-09 (relative, the largest over its columns) \
of the 1-rank direct run of its size and repeat.
"""


class E2eShellTable(block_testing.BlockChecks, unittest.TestCase):
    table, measurements, expected, record = table, MEASUREMENTS, EXPECTED, "e2e-shell"

    def test_speed_ups_are_taken_within_each_repeat(self):
        ups = table.speed_ups(MEASUREMENTS, ("S", "direct", 2), table.iteration_time)
        self.assertEqual(len(ups), 2)
        self.assertAlmostEqual(ups[0], 2.0)
        self.assertAlmostEqual(ups[1], 1.6)
        # Paired across repeats instead (0.4 against 0.3, 0.48 against 0.2), they would be 1.33
        # and 2.4.

    def test_the_target_is_met_at_its_threshold_and_not_below(self):
        m = copy.deepcopy(MEASUREMENTS)
        two = next(r for r in m["runs"] if (r["size"], r["ranks"]) == ("M", 2))
        one = next(r for r in m["runs"] if (r["size"], r["ranks"]) == ("M", 1))
        for key in ("assembly", "linear_solve"):
            two[key] = one[key] / 1.6
        self.assertIn("1.60, met.", table.scaling_verdict(m))
        for key in ("assembly", "linear_solve"):
            two[key] = one[key] / 1.59
        self.assertIn("1.59, **not met**.", table.scaling_verdict(m))

    def test_no_verdict_without_the_targets_rows(self):
        m = copy.deepcopy(MEASUREMENTS)
        m["runs"] = [r for r in m["runs"] if r["size"] == "S"]
        self.assertEqual(table.scaling_verdict(m), "")
        self.assertNotIn("Target", table.render_block(m))

    def test_the_solvers_own_columns_are_not_compared(self):
        reference = {"step": 3.0, "residual_norm": 1e-12, "newton_iterations": 2.0,
                     "volume": 100.0, "zero": 0.0}
        other = {"final": {"step": 3.0, "residual_norm": 9e-12, "newton_iterations": 4.0,
                           "volume": 100.0 * (1 - 2e-7), "zero": 0.0}}
        self.assertAlmostEqual(table.largest_difference(other, reference), 2e-7, delta=1e-15)


if __name__ == "__main__":
    unittest.main()
