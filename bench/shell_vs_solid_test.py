"""Unit tests of bench/shell_vs_solid_table.py, the generated block of docs/performance.md ("The
shell against the solid"): the table from fixed measurements, the ratio taken within each pair,
and that the docs hold what the last run wrote. No timing.
Run by CTest (test bench_shell_vs_solid, label unit): /usr/bin/python3 bench/shell_vs_solid_test.py
"""
import copy
import sys
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import block_testing  # noqa: E402
import shell_vs_solid_table as table  # noqa: E402



def run(unknowns, steps, newton, wall, peak, wavelength):
    return {"unknowns": unknowns, "steps": steps, "newton": newton, "factorisations": newton,
            "peak": peak, "wall": wall, "wavelength": wavelength,
            "cerda_mahadevan": {"0.05": 4.325, "0.1": 3.637, "0.15": 3.286}}


# Two pairs to 16 % strain, the shell on 0.5 mm, the solid on 0.25 mm. Shell 30 s and 36 s
# (median 33), solid 690 s and 900 s (median 795); ratios within the pairs 23 and 25, median 24.0
# (the ratio of the medians would be 24.09). The solid had no wrinkles around 5 % in its last run:
# a dash. Largest |λ/λ_CM − 1|: the shell's 10.75 % at 5 % (9.27 and 7.79 % at 10 and 15 %), the
# solid's 10.53 % at 15 %; compared where the solid has wrinkles, the shell's 9.27 % is the
# smaller: as accurate.
MEASUREMENTS = {
    "command": "bench/shell-vs-solid --repeat 2 --strain 16", "commit": "abc1234",
    "local_changes": False, "date": "2024-01-02", "cores": 2, "repeats": 2, "end_strain": 0.16,
    "strains": [0.05, 0.10, 0.15],
    "cases": [{"h": 0.25, "shell_h": 0.5, "pairs": [
        {"shell": run(12159, 29, 40, 30.0, 372.0, {"0.05": 3.86, "0.1": 3.30, "0.15": 3.03}),
         "solid": run(153000, 29, 120, 690.0, 3100.0, {"0.05": 3.86, "0.1": 3.26, "0.15": 2.94})},
        {"shell": run(12159, 29, 40, 36.0, 380.0, {"0.05": 3.86, "0.1": 3.30, "0.15": 3.03}),
         "solid": run(153000, 29, 120, 900.0, 3000.0, {"0.1": 3.26, "0.15": 2.94})}]}]}

EXPECTED = """\
Made by `bench/shell-vs-solid --repeat 2 --strain 16` at commit abc1234 on 2024-01-02: 2 pairs \
of runs per pairing of meshes, the shell then the solid, one core each, to 16 % strain; h, each \
run's in-plane element size. Wall time and ratio: median (smallest–largest) over the pairs; peak \
memory: the largest; the wavelength λ [mm] and its ratio to λ_CM (in brackets) at each strain, \
'–' where the run had no wrinkles there, and the largest distance from λ_CM over those strains.

| element | h [mm] | unknowns | steps | Newton iterations | wall [s] | peak [MiB] \
| λ at 5 % | λ at 10 % | λ at 15 % | largest \\|λ/λ_CM − 1\\| | solid / shell |
|---|---|---|---|---|---|---|---|---|---|---|---|
| shell triangle | 0.5 | 12 159 | 29 | 40 | 33.0 (30.0–36.0) | 380 | 3.86 (0.892) \
| 3.30 (0.907) | 3.03 (0.922) | 10.8 % |  |
| Taylor–Hood, one layer | 0.25 | 153 000 | 29 | 120 | 795.0 (690.0–900.0) | 3100 | – \
| 3.26 (0.896) | 2.94 (0.895) | 10.5 % | **24.0 (23.0–25.0)** |

The shell on h = 0.5 mm is at least as accurate as the solid on h = 0.25 mm (wrinkles wherever \
the solid has them, and there a largest |λ/λ_CM − 1| no larger than the solid's), and 24.0 times \
faster (the median ratio).
"""


class ShellVsSolidTable(block_testing.BlockChecks, unittest.TestCase):
    table = table
    measurements = MEASUREMENTS
    expected = EXPECTED
    record = "shell-vs-solid"

    def test_a_record_from_before_the_shells_own_size_pairs_equal_meshes(self):
        m = copy.deepcopy(MEASUREMENTS)
        del m["cases"][0]["shell_h"]
        block = table.render_block(m)
        self.assertIn("| shell triangle | 0.25 | 12 159 |", block)
        self.assertIn("The shell on h = 0.25 mm is at least as accurate", block)

    def test_a_larger_error_or_a_missing_wrinkle_makes_the_shell_less_accurate(self):
        larger = copy.deepcopy(MEASUREMENTS)  # 2.80 / 3.286: 14.8 %, more than the solid's 10.5
        larger["cases"][0]["pairs"][-1]["shell"]["wavelength"]["0.15"] = 2.80
        missing = copy.deepcopy(MEASUREMENTS)  # no wrinkles at 10 %, where the solid has them
        del missing["cases"][0]["pairs"][-1]["shell"]["wavelength"]["0.1"]
        for m in (larger, missing):
            self.assertIn("The shell on h = 0.5 mm is less accurate than the solid on h = 0.25 mm",
                          table.render_block(m))
        # Only the last pair's wavelengths count: a deterministic run repeats them.
        first = copy.deepcopy(MEASUREMENTS)
        first["cases"][0]["pairs"][0]["shell"]["wavelength"]["0.15"] = 2.80
        self.assertIn("is at least as accurate", table.render_block(first))

    def test_two_shell_meshes_share_the_solids_runs_and_each_gets_its_verdict(self):
        # A second shell mesh, 0.6 mm (shell 20 and 24 s, ratios 34.5 and 37.5), beside the same
        # solid runs; its 3.70 mm at 15 % is 12.6 % off, more than the solid's 10.5 %.
        m = copy.deepcopy(MEASUREMENTS)
        second = copy.deepcopy(m["cases"][0])
        second["shell_h"] = 0.6
        for pair, wall in zip(second["pairs"], (20.0, 24.0)):
            pair["shell"]["wall"] = wall
            pair["shell"]["wavelength"]["0.15"] = 3.70
        m["cases"].append(second)
        block = table.render_block(m)
        self.assertIn("to 16 % strain; h, each run's in-plane element size. Pairings of one solid "
                      "mesh share its runs: each repeat ran every shell mesh, then the solid once. "
                      "Wall time", block)
        self.assertIn("| shell triangle | 0.6 | 12 159 | 29 | 40 | 22.0 (20.0–24.0) |", block)
        self.assertIn("**36.0 (34.5–37.5)** |", block)
        self.assertIn("The shell on h = 0.5 mm is at least as accurate", block)
        self.assertIn("The shell on h = 0.6 mm is less accurate than the solid on h = 0.25 mm",
                      block)
        self.assertNotIn("share its runs", table.render_block(MEASUREMENTS))


if __name__ == "__main__":
    unittest.main()
