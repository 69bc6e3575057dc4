"""Unit tests of bench/shell_vs_solid_table.py, the generated block of docs/performance.md ("The
shell against the solid"): the table from fixed measurements, the ratio taken within each pair,
and that the docs hold what the last run wrote. No timing.
Run by CTest (test bench_shell_vs_solid, label unit): /usr/bin/python3 bench/shell_vs_solid_test.py
"""
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


# Two pairs to 16 % strain. Shell 30 s and 36 s (median 33), solid 690 s and 900 s (median 795);
# ratios within the pairs 23 and 25, median 24.0 (the ratio of the medians would be 24.09). The
# solid had no wrinkles around 5 % in its last run: a dash.
MEASUREMENTS = {
    "command": "bench/shell-vs-solid --repeat 2 --strain 16", "commit": "abc1234",
    "local_changes": False, "date": "2024-01-02", "cores": 2, "repeats": 2, "end_strain": 0.16,
    "strains": [0.05, 0.10, 0.15],
    "cases": [{"h": 0.25, "pairs": [
        {"shell": run(12159, 29, 40, 30.0, 372.0, {"0.05": 3.86, "0.1": 3.30, "0.15": 3.03}),
         "solid": run(153000, 29, 120, 690.0, 3100.0, {"0.05": 3.86, "0.1": 3.26, "0.15": 2.94})},
        {"shell": run(12159, 29, 40, 36.0, 380.0, {"0.05": 3.86, "0.1": 3.30, "0.15": 3.03}),
         "solid": run(153000, 29, 120, 900.0, 3000.0, {"0.1": 3.26, "0.15": 2.94})}]}]}

EXPECTED = """\
Made by `bench/shell-vs-solid --repeat 2 --strain 16` at commit abc1234 on 2024-01-02: 2 pairs \
of runs per mesh, the shell then the solid, one core each, to 16 % strain. Wall time and ratio: \
median (smallest–largest) over the pairs; peak memory: the largest; the wavelength λ [mm] and its \
ratio to λ_CM (in brackets) at each strain, '–' where the run had no wrinkles there.

| h [mm] | element | unknowns | steps | Newton iterations | wall [s] | peak [MiB] \
| λ at 5 % | λ at 10 % | λ at 15 % | solid / shell |
|---|---|---|---|---|---|---|---|---|---|---|
| 0.25 | shell triangle | 12 159 | 29 | 40 | 33.0 (30.0–36.0) | 380 | 3.86 (0.892) \
| 3.30 (0.907) | 3.03 (0.922) |  |
|  | Taylor–Hood, one layer | 153 000 | 29 | 120 | 795.0 (690.0–900.0) | 3100 | – \
| 3.26 (0.896) | 2.94 (0.895) | **24.0 (23.0–25.0)** |
"""


class ShellVsSolidTable(block_testing.PairedTableChecks, unittest.TestCase):
    table = table
    measurements = MEASUREMENTS
    expected = EXPECTED
    record = "shell-vs-solid"


if __name__ == "__main__":
    unittest.main()
