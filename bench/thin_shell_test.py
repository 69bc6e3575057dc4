"""Unit tests of bench/thin_shell_table.py, the generated block of docs/performance.md ("The shell
triangle up to a million unknowns"): the table and the growth exponents from fixed measurements,
the markers, and that the docs hold what the last run wrote. No timing.
Run by CTest (test bench_thin_shell, label unit): /usr/bin/python3 bench/thin_shell_test.py
"""
import copy
import math
import sys
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import block_testing  # noqa: E402
import thin_shell_table  # noqa: E402

peer_table = thin_shell_table.peer_table
ROOT = HERE.parent


def run(h, triangles, unknowns, newton, assembly, factorisation, solve, entries, peak, wall,
        error):
    return {"h": h, "triangles": triangles, "unknowns": unknowns, "newton": newton,
            "factorisations": newton, "assembly": assembly, "factorisation": factorisation,
            "solve": solve, "factor_entries": entries, "peak": peak, "wall": wall,
            "stretch_error": error}


# Two meshes, the second with 8 times the unknowns. Per iteration: assembly 0.1 -> 0.8 s (a = 1),
# factorisation 0.2 -> 0.2 * 8^1.5 = 4.5255 s (a = 1.5), solve 0.01 -> 0.08 s, so a Newton
# iteration 0.31 -> 5.4055 s: a = ln(17.4371) / ln(8) = 1.375; entries 4e6 -> 4.8e7 (a = 1.195);
# peak 200 -> 1600 MiB (a = 1).
MEASUREMENTS = {
    "command": "bench/thin-shell S 0.6", "commit": "abc1234", "local_changes": False,
    "date": "2024-01-02", "cores": 2,
    "runs": [run(1.2, 6596, 10000, 10, 1.0, 2.0, 0.1, 4e6, 200.0, 5.2, 6.9e-3),
             run(0.6, 52000, 80000, 10, 8.0, 45.255, 0.8, 4.8e7, 1600.0, 60.4, -4.2e-4)]}

EXPECTED = """\
Made by `bench/thin-shell S 0.6` at commit abc1234 on 2024-01-02: one run per mesh, one core \
(OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1), full Newton.

| h [mm] | triangles | unknowns | Newton iterations | assembly [s/it] | factorisation [s/it] \
| solve [s/it] | Newton iteration [s] | factor entries [10⁶] | peak [MiB] | wall [s] \
| error of λ − 1 |
|---|---|---|---|---|---|---|---|---|---|---|---|
| 1.2 | 6 596 | 10 000 | 10 | 0.1 | 0.2 | 0.01 | 0.31 | 4 | 200 | 5 | +6.9e-03 |
| 0.6 | 52 000 | 80 000 | 10 | 0.8 | 4.53 | 0.08 | 5.41 | 48 | 1600 | 60 | -4.2e-04 |

From 10 000 to 80 000 unknowns, as unknowns^a: a Newton iteration a = 1.37 (assembly 1.00, \
factorisation 1.50), factor entries 1.19, peak memory 1.00.
"""


class ThinShellTable(unittest.TestCase):
    def test_block_from_fixed_measurements(self):
        self.assertEqual(thin_shell_table.render_block(MEASUREMENTS), EXPECTED)

    def test_exponent_is_the_slope_in_log_log(self):
        runs = MEASUREMENTS["runs"]
        self.assertAlmostEqual(thin_shell_table.exponent(runs, lambda r: r["factorisation"]),
                               1.5, places=4)
        self.assertAlmostEqual(thin_shell_table.exponent(runs, lambda r: r["factor_entries"]),
                               math.log(12) / math.log(8), places=12)

    def test_uncommitted_changes_and_load_are_said(self):
        first = block_testing.provenance_line(thin_shell_table.render_block, MEASUREMENTS)
        self.assertIn("at commit abc1234 with uncommitted changes on", first)
        self.assertIn("load average of 0.9 when the run began and 1.1 when it ended", first)

    def test_factor_entries_keep_three_digits_without_an_exponent(self):
        self.assertEqual(thin_shell_table.three_digits(71.14), "71.1")
        self.assertEqual(thin_shell_table.three_digits(282.4), "282")
        self.assertEqual(thin_shell_table.three_digits(1107.3), "1107")

    def test_one_run_has_no_exponents(self):
        m = copy.deepcopy(MEASUREMENTS)
        m["runs"] = m["runs"][:1]
        self.assertNotIn("unknowns^a", thin_shell_table.render_block(m))

    def test_update_writes_the_block_between_its_own_markers_only(self):
        block, peers, text, refused = block_testing.update_beside_the_peers(
            thin_shell_table.update_file, thin_shell_table.MARKERS, MEASUREMENTS, peer_table)
        self.assertEqual(block, EXPECTED)
        self.assertEqual(peers, "the peers' block\n")
        self.assertTrue(text.startswith("# Title\n\nProse.\n\n"))
        # Without its markers the file is refused and left alone.
        self.assertEqual(refused, "# Title\n\nno block here\n")

    def test_docs_hold_what_the_last_run_wrote(self):
        page = (ROOT / "docs" / "performance.md").read_text(encoding="utf-8")
        record = ROOT / "docs" / "performance" / "thin-shell.json"
        self.assertTrue(record.exists(), "run bench/thin-shell --update docs/performance.md")
        self.assertEqual(peer_table.read_block(page, thin_shell_table.MARKERS),
                         thin_shell_table.render_block(thin_shell_table.load(record)))


if __name__ == "__main__":
    unittest.main()
