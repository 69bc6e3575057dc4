"""Unit tests of bench/kernels_table.py, the generated block of docs/performance.md (section "The
element kernels"): the reading of plisse-bench's JSON report, the table and its ratios from fixed
measurements, the markers, and that the docs hold what the last run wrote. No timing.
Run by CTest (test bench_kernels, label unit): /usr/bin/python3 bench/kernels_test.py
"""
import sys
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import block_testing  # noqa: E402
import kernels_table as table  # noqa: E402


def row(name, cpu, unit="ns", run_type="iteration", **counters):
    return {"name": name, "run_name": name.split("_median")[0], "run_type": run_type,
            "cpu_time": cpu, "real_time": cpu, "time_unit": unit, **counters}


# A report as Google Benchmark writes it with --benchmark_repetitions=3: each benchmark's three
# repetitions, then its aggregates (which the reader leaves out). MINI's tangent 1.4, 1.5 and
# 1.6 µs (median 1.5); its residual 1.0 µs each time; its Newton update 3.0, 3.3 and 3.6 µs with
# 2.4, 2.5 and 2.5 bubble evaluations (median 2.5); the Taylor-Hood tangent 12 000, 13 500 and
# 15 000 ns (median 13.5 µs, one decimal from 10 µs up) and residual given in µs, 3.0 each time.
# Ratios: 13.5 / 1.5 = 9.0, 3.0 / 1.0 = 3.0, 3.3 / 1.5 = 2.2.
REPORT = {"context": {}, "benchmarks": [
    row("MiniTangent/neo_hookean", 1400.0), row("MiniTangent/neo_hookean", 1500.0),
    row("MiniTangent/neo_hookean", 1600.0),
    row("MiniTangent/neo_hookean_median", 1500.0, run_type="aggregate"),
    row("MiniResidual/neo_hookean", 1000.0), row("MiniResidual/neo_hookean", 1000.0),
    row("MiniResidual/neo_hookean", 1000.0),
    row("MiniNewtonUpdate/neo_hookean", 3000.0, bubble_iterations=2.4),
    row("MiniNewtonUpdate/neo_hookean", 3300.0, bubble_iterations=2.5),
    row("MiniNewtonUpdate/neo_hookean", 3600.0, bubble_iterations=2.5),
    row("TaylorHoodTangent/neo_hookean", 12000.0), row("TaylorHoodTangent/neo_hookean", 13500.0),
    row("TaylorHoodTangent/neo_hookean", 15000.0),
    row("TaylorHoodResidual/neo_hookean", 3.0, unit="us"),
    row("TaylorHoodResidual/neo_hookean", 3.0, unit="us"),
    row("TaylorHoodResidual/neo_hookean", 3.0, unit="us"),
]}

MEASUREMENTS = {"command": "bench/kernels --repeat 3", "commit": "abc1234", "local_changes": False,
                "date": "2024-01-02", "cores": 2, "min_time": 0.5,
                "kernels": table.read_benchmarks(REPORT), "load_average": [0.2, 0.4]}

EXPECTED = """\
Made by `bench/kernels --repeat 3` at commit abc1234 on 2024-01-02: `plisse-bench` (Google \
Benchmark; `bench/mini_bench.cpp`, `bench/taylor_hood_bench.cpp`), one core, 3 repetitions of at \
least 0.5 s each. CPU time per call: median (smallest–largest) over the repetitions. The machine \
(2 cores) had a load average of 0.2 when the run began and 0.4 when it ended.

| benchmark | what one call does | material | CPU time per call [µs] |
|---|---|---|---|
| `MiniTangent/neo_hookean` | MINI: residual and condensed tangent, bubble at its converged \
value | neo-Hookean | 1.50 (1.40–1.60) |
| `MiniResidual/neo_hookean` | MINI: residual only, bubble at its converged value | neo-Hookean \
| 1.00 (1.00–1.00) |
| `MiniNewtonUpdate/neo_hookean` | MINI: residual and tangent after the nodes moved (the \
bubble's local Newton iterates), 2.50 bubble evaluations per call | neo-Hookean | 3.30 \
(3.00–3.60) |
| `TaylorHoodTangent/neo_hookean` | Taylor–Hood: residual and tangent | neo-Hookean | 13.5 \
(12.0–15.0) |
| `TaylorHoodResidual/neo_hookean` | Taylor–Hood: residual only | neo-Hookean | 3.00 \
(3.00–3.00) |

Ratios of the medians:
- a Taylor–Hood tangent against a MINI one: 9.0 times the time.
- a Taylor–Hood residual against a MINI one: 3.0 times the time.
- a MINI tangent whose bubble iterates against one at its converged bubble: 2.2 times the time.
"""


class KernelsTable(block_testing.BlockChecks, unittest.TestCase):
    table, measurements, expected, record = table, MEASUREMENTS, EXPECTED, "kernels"

    def test_the_report_is_read_in_microseconds_without_its_aggregates(self):
        kernels = table.read_benchmarks(REPORT)
        self.assertEqual(list(kernels)[:2], ["MiniTangent/neo_hookean", "MiniResidual/neo_hookean"])
        self.assertEqual(kernels["MiniTangent/neo_hookean"], {"cpu": [1.4, 1.5, 1.6]})
        self.assertEqual(kernels["TaylorHoodResidual/neo_hookean"]["cpu"], [3.0, 3.0, 3.0])
        self.assertEqual(kernels["MiniNewtonUpdate/neo_hookean"]["bubble_iterations"],
                         [2.4, 2.5, 2.5])

    def test_a_ratio_without_both_benchmarks_is_left_out(self):
        m = dict(MEASUREMENTS, kernels={k: v for k, v in MEASUREMENTS["kernels"].items()
                                        if not k.startswith("TaylorHood")})
        block = table.render_block(m)
        self.assertNotIn("Taylor–Hood tangent against", block)
        self.assertIn("- a MINI tangent whose bubble iterates against one at its converged bubble: "
                      "2.2 times the time.", block)

    def test_an_empty_report_or_an_unknown_unit_is_refused(self):
        with self.assertRaisesRegex(table.ReadError, "no benchmark runs"):
            table.read_benchmarks({"benchmarks": []})
        with self.assertRaisesRegex(table.ReadError, "unknown time unit 'fs'"):
            table.read_benchmarks({"benchmarks": [row("MiniTangent/neo_hookean", 1.0, unit="fs")]})


if __name__ == "__main__":
    unittest.main()
