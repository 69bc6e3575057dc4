"""Unit tests of bench/element_families_table.py, the generated block of docs/performance.md
(section "Element families: what each needs for a given accuracy"): the tables and what they show
from fixed measurements, the markers, and that the docs hold what the last run wrote. No timing.
Run by CTest (test bench_element_families, label unit):
/usr/bin/python3 bench/element_families_test.py
"""
import copy
import sys
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import block_testing  # noqa: E402
import element_families_table as table  # noqa: E402


def strip(element, layers, size, unknowns, ratio, wall, memory):
    return {"element": element, "layers": layers, "size": size, "unknowns": unknowns,
            "ratio": ratio, "wall": wall, "memory": memory}


def sphere(element, size, layers, unknowns, error, wall, memory):
    return {"element": element, "size": size, "layers": layers, "unknowns": unknowns,
            "error": error, "wall": wall, "memory": memory}


# Two rounds. The strip: MINI's ratio is 1.013 + 2 h^2 exactly (h = 0.5 and 0.25 t: 1.513 and
# 1.138), so the fit gives c = 2.00 with no misfit, and 2 % of 1.013 is reached where 2 h^2 =
# 0.02026, at 1/h = sqrt(2 / 0.02026) = 9.94: "about 10 layers". Taylor-Hood: 1.050 (3.65 % above
# 1.013, not within 2 %) and 1.030 (1.68 %: within), so the cheapest within 2 % is the second.
# MINI's most accurate is the 4-layer mesh (12.3 % above); both Taylor-Hood meshes are closer, the
# cheapest has 500 unknowns: 8000 / 500 = 16 times fewer, wall medians 42 / 1 = 42, memory medians
# 410 / 50 = 8.2 (one decimal below 10).
# The sphere: MINI's most accurate mesh has the error 5.0e-3 (30 000 unknowns, wall 11 s, 320 MiB);
# the Taylor-Hood meshes have 1.0e-2 (less accurate) and 1.5e-3 (6 000 unknowns, 1.5 s, 150 MiB):
# 5.0 times fewer unknowns, 7.3 times less time, 2.1 times less memory.
ROUND_1 = {
    "strip": [strip("mini", 2, 0.5, 1000, 1.513, 2.0, 100.0),
              strip("mini", 4, 0.25, 8000, 1.138, 40.0, 400.0),
              strip("taylor-hood", 1, 1.0, 500, 1.05, 1.0, 50.0),
              strip("taylor-hood", 2, 0.5, 2000, 1.03, 2.0, 80.0)],
    "sphere": [sphere("mini", 1.0, 4, 4000, 2.0e-2, 1.0, 100.0),
               sphere("mini", 0.5, 8, 30000, 5.0e-3, 10.0, 300.0),
               sphere("taylor-hood", 2.0, 1, 3000, 1.0e-2, 1.0, 100.0),
               sphere("taylor-hood", 1.5, 2, 6000, 1.5e-3, 1.5, 150.0)]}
ROUND_2 = copy.deepcopy(ROUND_1)
for row, wall, memory in zip(ROUND_2["strip"], [4.0, 44.0, 1.0, 2.4], [120.0, 420.0, 50.0, 80.0]):
    row.update(wall=wall, memory=memory)
for row, wall, memory in zip(ROUND_2["sphere"], [1.2, 12.0, 1.0, 1.5],
                             [100.0, 340.0, 100.0, 150.0]):
    row.update(wall=wall, memory=memory)

MEASUREMENTS = {
    "command": "bench/element-families --repeat 2", "commit": "abc1234", "local_changes": False,
    "date": "2024-01-02", "cores": 2, "rounds": [ROUND_1, ROUND_2], "load_average": [0.2, 0.4]}

EXPECTED = """\
Made by `bench/element-families --repeat 2` at commit abc1234 on 2024-01-02: 2 rounds of every \
configuration, one process each, one core (`OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1`). Wall time: \
median (smallest–largest) over the rounds; peak memory: median. The machine (2 cores) had a load \
average of 0.2 when the run began and 0.4 when it ended.

**Clamped strip** (`build/bin/plisse-strip-buckling ELEMENT LAYERS [SIZE]`):

| element | layers | in-plane cell [t] | unknowns | ε_cr / beam theory | wall time [s] | peak memory [MiB] |
|---|---|---|---|---|---|---|
| MINI | 2 | 0.5 | 1 000 | 1.513 | 3.0 (2.0–4.0) | 110 |
| MINI | 4 | 0.25 | 8 000 | 1.138 | 42.0 (40.0–44.0) | 410 |
| Taylor–Hood | 1 | 1 | 500 | 1.050 | 1.0 (1.0–1.0) | 50 |
| Taylor–Hood | 2 | 0.5 | 2 000 | 1.030 | 2.2 (2.0–2.4) | 80 |

MINI's excess over the converged value (1.013) fits c h² with c = 2.00 (h in t) to 0 % over its \
rows: it comes within 2 % at about 10 layers.
The cheapest Taylor–Hood mesh within 2 % has 2 000 unknowns (2 layers of cells 0.5 t).
Against MINI's most accurate mesh (8 000 unknowns, ε_cr 1.138 of beam theory), the cheapest \
Taylor–Hood mesh at least as accurate has 500 unknowns (ε_cr 1.050 of beam theory): **16 times \
fewer, 42 times less time and 8.2 times less memory**.

**Thick sphere** (`plisse run examples/sphere-inflation.yaml --set element=ELEMENT --set \
mesh.element_size=SIZE --set mesh.layers=LAYERS`):

| element | element size [mm] | layers | unknowns | max relative error of p | wall time [s] | peak memory [MiB] |
|---|---|---|---|---|---|---|
| MINI | 1 | 4 | 4 000 | 2.0e-02 | 1.1 (1.0–1.2) | 100 |
| MINI | 0.5 | 8 | 30 000 | 5.0e-03 | 11.0 (10.0–12.0) | 320 |
| Taylor–Hood | 2 | 1 | 3 000 | 1.0e-02 | 1.0 (1.0–1.0) | 100 |
| Taylor–Hood | 1.5 | 2 | 6 000 | 1.5e-03 | 1.5 (1.5–1.5) | 150 |

Against MINI's most accurate mesh (30 000 unknowns, error 5.0e-03), the cheapest Taylor–Hood mesh \
at least as accurate has 6 000 unknowns (error 1.5e-03): **5.0 times fewer, 7.3 times less time and \
2.1 times less memory**.
"""


class ElementFamiliesTable(block_testing.BlockChecks, unittest.TestCase):
    table, measurements, expected, record = table, MEASUREMENTS, EXPECTED, "element-families"

    def test_the_h2_fit_says_how_far_it_misses(self):
        m = copy.deepcopy(MEASUREMENTS)
        m["rounds"][0]["strip"][0]["ratio"] = 1.013 + 2.2 * 0.25  # 10 % above the 2.0 h^2 line
        c, misfit = table.mini_h2_fit(table.rows(m, "strip"))
        # Least squares of e = c h^2 over (h^2, e) = (0.25, 0.55) and (0.0625, 0.125).
        self.assertAlmostEqual(c, (0.55 * 0.25 + 0.125 * 0.0625) / (0.25**2 + 0.0625**2), 12)
        self.assertAlmostEqual(misfit, max(abs(c * 0.25 / 0.55 - 1), abs(c * 0.0625 / 0.125 - 1)),
                               12)

    def test_no_taylor_hood_mesh_as_accurate_is_said(self):
        m = copy.deepcopy(MEASUREMENTS)
        for r in m["rounds"]:
            r["sphere"][3]["error"] = 6.0e-3
        self.assertIn("Against MINI's most accurate mesh (30 000 unknowns, error 5.0e-03), no "
                      "Taylor–Hood mesh measured is as accurate.", table.render_block(m))

    def test_none_within_two_percent_names_no_cheapest(self):
        m = copy.deepcopy(MEASUREMENTS)
        for r in m["rounds"]:
            r["strip"][3]["ratio"] = 1.034  # 2.07 % above 1.013
        self.assertNotIn("The cheapest Taylor–Hood mesh within 2 %", table.render_block(m))


if __name__ == "__main__":
    unittest.main()
