"""Unit tests of the plain-Python parts of bench/peers: peer_table.py, the generated block of
docs/performance.md ("Against DOLFINx"): the table from fixed measurements, the markers, and that
the docs hold what the last run wrote; thick_sphere.py, the closed form both programs are
measured against, and the case's load derived from it. Need neither DOLFINx nor timing.
Run by CTest (test bench_peers, label unit): /usr/bin/python3 bench/peers/peers_test.py
"""
import copy
import os
import sys
import tempfile
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import peer_table  # noqa: E402
import thick_sphere  # noqa: E402
import yaml  # noqa: E402

ROOT = HERE.parent.parent


def run(unknowns, newton, factorisations, reused_solves, wall, peak, error):
    return {"unknowns": unknowns, "newton": newton, "factorisations": factorisations,
            "reused_solves": reused_solves, "wall": wall, "peak": peak, "error": error}


# Three pairs on one mesh. Wall times [s]: plisse 4.0, 5.0, 4.4 (median 4.4); DOLFINx 22.0, 27.5,
# 26.4 (median 26.4). Ratios within the pairs: 5.5, 5.5, 6.0, so the median ratio is 5.50, not
# the ratio of the medians (26.4 / 4.4 = 6.0). Peaks: the largest, 155.4 -> 155 and 251.
MEASUREMENTS = {
    "command": "bench/peer-shell --repeat 3 --elements mini 0.5", "commit": "abc1234",
    "local_changes": False, "date": "2024-01-02", "repeats": 3,
    "cases": [{"h": 0.5, "tetrahedra": 8379, "element": "mini", "pairs": [
        {"plisse": run(9329, 1, 1, 59, 4.0, 150.0, 2.81e-3),
         "DOLFINx": run(34841, 37, 37, 0, 22.0, 250.0, 2.843e-3)},
        {"plisse": run(9329, 1, 1, 59, 5.0, 155.4, 2.81e-3),
         "DOLFINx": run(34841, 37, 37, 0, 27.5, 251.0, 2.843e-3)},
        {"plisse": run(9329, 1, 1, 59, 4.4, 152.0, 2.81e-3),
         "DOLFINx": run(34841, 37, 37, 0, 26.4, 249.6, 2.843e-3)}]}]}

EXPECTED = """\
Made by `bench/peer-shell --repeat 3 --elements mini 0.5` at commit abc1234 on 2024-01-02: 3 \
pairs of runs per row, plisse then DOLFINx, one core each. Wall time and ratio: median \
(smallest–largest) over the pairs; peak memory: the largest.

| h [mm] | tetrahedra | element | program | unknowns | factorisations | reused-factor solves \
| wall [s] | peak [MiB] | error of p | DOLFINx / plisse |
|---|---|---|---|---|---|---|---|---|---|---|
| 0.5 | 8 379 | MINI | plisse | 9 329 | 1 | 59 | 4.40 (4.00–5.00) | 155 | +2.81e-03 |  |
|  |  |  | DOLFINx | 34 841 | 37 | 0 | 26.40 (22.00–27.50) | 251 | +2.84e-03 \
| **5.50 (5.50–6.00)** |
"""

PAGE = f"""# Title

Prose before, which the block leaves alone.

{peer_table.BEGIN}
an old table
{peer_table.END}

Prose after.
"""


class PeerTable(unittest.TestCase):
    def test_block_from_fixed_measurements(self):
        self.assertEqual(peer_table.render_block(MEASUREMENTS), EXPECTED)

    def test_uncommitted_changes_are_said(self):
        dirty = copy.deepcopy(MEASUREMENTS)
        dirty["local_changes"] = True
        self.assertIn("at commit abc1234 with uncommitted changes on",
                      peer_table.render_block(dirty))

    def test_load_of_the_machine_is_said_when_recorded(self):
        loaded = copy.deepcopy(MEASUREMENTS)
        loaded.update(cores=2, load_average=[3.04, 4.96])
        self.assertIn("largest. The machine (2 cores) had a load average of 3.0 when the run began "
                      "and 5.0 when it ended.\n", peer_table.render_block(loaded))

    def test_rewriting_keeps_the_prose_and_is_repeatable(self):
        once = peer_table.replace_block(PAGE, EXPECTED)
        self.assertEqual(once, PAGE.replace("an old table\n", EXPECTED))
        self.assertEqual(peer_table.read_block(once), EXPECTED)
        self.assertEqual(peer_table.replace_block(once, EXPECTED), once)

    def test_update_file_writes_the_block(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "page.md")
            Path(path).write_text(PAGE, encoding="utf-8")
            peer_table.update_file(path, MEASUREMENTS)
            self.assertEqual(Path(path).read_text(encoding="utf-8"),
                             PAGE.replace("an old table\n", EXPECTED))

    def test_wrong_markers_are_errors_and_leave_the_file_alone(self):
        BEGIN, END = peer_table.BEGIN, peer_table.END
        broken = {
            "no begin": PAGE.replace(peer_table.BEGIN + "\n", ""),
            "no end": PAGE.replace(peer_table.END + "\n", ""),
            "two begins": PAGE.replace(BEGIN, BEGIN + "\n" + BEGIN),
            "end first": PAGE.replace(BEGIN, "@").replace(END, BEGIN).replace("@", END),
        }
        for what, text in broken.items():
            with self.subTest(what), tempfile.TemporaryDirectory() as folder:
                with self.assertRaises(peer_table.BlockError):
                    peer_table.read_block(text)
                path = os.path.join(folder, "page.md")
                Path(path).write_text(text, encoding="utf-8")
                with self.assertRaises(peer_table.BlockError):
                    peer_table.update_file(path, MEASUREMENTS)
                self.assertEqual(Path(path).read_text(encoding="utf-8"), text)

    def test_docs_hold_what_the_last_run_wrote(self):
        """docs/performance.md's block is the one made from docs/performance/peer-shell.json: a
        hand edit of the table, or measurements committed without their table, fail here."""
        page = (ROOT / "docs" / "performance.md").read_text(encoding="utf-8")
        results = peer_table.load(ROOT / "docs" / "performance" / "peer-shell.json")
        self.assertEqual(peer_table.read_block(page), peer_table.render_block(results))


class ThickSphere(unittest.TestCase):
    def test_undeformed_sphere_carries_no_pressure(self):
        # 0 up to the rounding of b = (a^3 + RO^3 - RI^3)^(1/3): 1e-14 of p_max
        self.assertAlmostEqual(thick_sphere.pressure(thick_sphere.RI, 0.0033), 0.0, delta=1e-17)

    def test_limit_pressure_is_the_maximum(self):
        """p_max = 7.789e-4 MPa at a = 14.26 mm (thick_sphere.py); p is lower on either side."""
        p_max, a = thick_sphere.limit_pressure(0.0033)
        self.assertAlmostEqual(p_max, 7.789e-4, delta=0.0005e-4)
        self.assertAlmostEqual(a, 14.26, delta=0.005)
        for da in (-1e-3, 1e-3):
            self.assertLess(thick_sphere.pressure(a + da, 0.0033), p_max)

    def test_case_load_is_095_of_the_limit(self):
        """bench/cases/peer-shell.yaml writes 0.95 p_max to 5 digits, for c1 of its material."""
        case = yaml.safe_load((ROOT / "bench" / "cases" / "peer-shell.yaml").read_text())
        load = next(load["value"] for load in case["loads"] if load["name"] == "gas")
        p_max, _ = thick_sphere.limit_pressure(case["material"]["c1"])
        self.assertEqual(float(f"{0.95 * p_max:.4e}"), load)


if __name__ == "__main__":
    unittest.main()
