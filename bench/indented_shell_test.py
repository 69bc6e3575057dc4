"""Unit tests of bench/indented_shell_table.py, the generated block of docs/performance.md ("The
indented shell against the solid"): the table from fixed measurements, the ratio taken within
each pair, and that the docs hold what the last run wrote. No timing.
Run by CTest (test bench_indented_shell, label unit): /usr/bin/python3 bench/indented_shell_test.py
"""
import copy
import sys
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import block_testing  # noqa: E402
import indented_shell_table as table  # noqa: E402



def run(unknowns, newton, wall, peak, compression, onset, count):
    return {"unknowns": unknowns, "steps": 51, "newton": newton, "factorisations": newton,
            "peak": peak, "wall": wall, "tau": 8.0, "compression": compression, "onset": onset,
            "count": count}


# Two pairs at tau = 8, the shell with 9 mm about the pole, the solid with 6 mm. Shell 40 s and
# 50 s (median 45), solid 400 s and 460 s (median 430); ratios within the pairs 10 and 9.2, median
# 9.6 (the ratio of the medians would be 9.56). The solid's last run found no wrinkles: dashes,
# and no onset for the shell's to overlap.
MEASUREMENTS = {
    "command": "bench/indented-shell --repeat 2", "commit": "abc1234", "local_changes": False,
    "date": "2024-01-02", "cores": 2, "repeats": 2,
    "cases": [{"tau": 8.0, "pole_h": 6.0, "shell_pole_h": 9.0, "pairs": [
        {"shell": run(8110, 42, 40.0, 261.0, [1.234, 1.357], [4.291, 4.412], 12),
         "solid": run(62990, 24, 400.0, 1200.0, [1.2, 1.3], [4.27, 4.4], 12)},
        {"shell": run(8110, 42, 50.0, 262.0, [1.234, 1.357], [4.291, 4.412], 12),
         "solid": run(62990, 24, 460.0, 1250.0, [1.2, 1.3], None, 0)}]}]}

EXPECTED = """\
Made by `bench/indented-shell --repeat 2` at commit abc1234 on 2024-01-02: 2 pairs of runs per \
tau, the shell then the solid, one core each, each on its own mesh (h, the edges' length within \
2 ℓ_p of the pole). Wall time and ratio: median (smallest–largest) over the pairs; peak memory: the largest; the onsets: the pole's inward travel w0 / (p R² / Y) at the \
last step before and the first step with hoop compression, and with wrinkles (the first \
instability or wrinkled ring), and the full-circle wrinkle count there ('–': none).

| τ | element | h at the pole [mm] | unknowns | steps | Newton iterations | wall [s] | peak [MiB] \
| compression onset | wrinkling onset | count | solid / shell |
|---|---|---|---|---|---|---|---|---|---|---|---|
| 8 | shell triangle | 9 | 8 110 | 51 | 42 | 45.0 (40.0–50.0) | 262 | 1.23 – 1.36 \
| 4.29 – 4.41 | 12 |  |
|  | Taylor–Hood, one layer | 6 | 62 990 | 51 | 24 | 430.0 (400.0–460.0) | 1250 | 1.20 – 1.30 \
| – | – | **9.6 (9.2–10.0)** |

τ = 8: the shell with 9 mm about the pole does not bracket the wrinkles' onset where the solid \
does with 6 mm, and is 9.6 times faster (the median ratio).
"""


class IndentedShellTable(block_testing.BlockChecks, unittest.TestCase):
    table = table
    measurements = MEASUREMENTS
    expected = EXPECTED
    record = "indented-shell"

    def test_the_onsets_overlap_only_where_the_brackets_share_a_step(self):
        def said(shell_onset, solid_onset):
            m = copy.deepcopy(MEASUREMENTS)
            last = m["cases"][0]["pairs"][-1]
            last["shell"]["onset"], last["solid"]["onset"] = shell_onset, solid_onset
            return table.render_block(m).splitlines()[-1]
        self.assertIn("the shell with 9 mm about the pole brackets the wrinkles' onset between "
                      "steps that overlap the solid's with 6 mm",
                      said([4.291, 4.412], [4.27, 4.4]))
        self.assertIn("does not bracket", said([4.412, 4.53], [4.27, 4.4]))  # a step later
        self.assertIn("does not bracket", said(None, [4.27, 4.4]))  # the shell found none

    def test_a_record_from_before_the_shells_own_mesh_pairs_the_cases_six_millimetres(self):
        m = copy.deepcopy(MEASUREMENTS)
        del m["cases"][0]["pole_h"], m["cases"][0]["shell_pole_h"]
        block = table.render_block(m)
        self.assertIn("| 8 | shell triangle | 6 | 8 110 |", block)
        self.assertIn("|  | Taylor–Hood, one layer | 6 | 62 990 |", block)


if __name__ == "__main__":
    unittest.main()
