"""Unit tests of bench/variants_table.py, the generated blocks of docs/performance.md that
bench/variants writes (one per set of variants): the table from fixed measurements, a run that did
not finish, the final states' differences, the markers, and that the docs hold what the last run
of each set wrote. No timing.
Run by CTest (test bench_variants, label unit): /usr/bin/python3 bench/variants_test.py
"""
import copy
import sys
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import block_testing  # noqa: E402
import variants_table as table  # noqa: E402


def run(wall, cpu, newton, factorisations, factorisation, final, status=0, cutbacks=0):
    return {"status": status, "wall": wall, "cpu": cpu, "unknowns": 35000, "steps": 5,
            "newton": newton, "factorisations": factorisations, "cutbacks": cutbacks,
            "factorisation": factorisation, "peak": 300.0,
            "final": {"step": 5.0, "newton_iterations": newton, "residual_norm": 1e-10,
                      "force": final[0], "volume": final[1]},
            "largest": {"step": 5.0, "newton_iterations": 9.0, "residual_norm": 1.0,
                        "force": 10.0, "volume": 200.0}}


# Two rounds of the set "blr" (one group, three variants); the command as bench/variants records
# it (the set's name among its arguments). Full rank: 10 and 12 s (median 11),
# 12 factorisations in 6 s (0.500 s each). ε = 1e-8: 13.2 and 14.3 s, relative to 11 s 1.20 and
# 1.30 (median 1.25); 12 factorisations in 9 s (0.750 each); its final force 10.02 against 10.0,
# 0.02 / 10 = 2.0e-3 of the force's largest value, and its volume 200.1 against 200, 0.1 / 200 =
# 5.0e-4: the force's first, then the volume's. ε = 1e-5: the second round did not finish (exit
# status 1).
def measurements():
    ref = [run(10.0, 9.5, 12, 12, 6.0, (10.0, 200.0)),
           run(12.0, 11.5, 12, 12, 6.0, (10.0, 200.0))]
    blr8 = [run(13.2, 13.0, 12, 12, 9.0, (10.02, 200.1)),
            run(14.3, 14.0, 12, 12, 9.0, (10.02, 200.1))]
    blr5 = [run(15.0, 15.0, 13, 13, 9.1, (10.0, 200.0)), {"status": 1, "wall": 3.0, "cpu": 2.9}]
    return {"command": "bench/variants blr --repeat 2", "commit": "abc1234",
            "local_changes": False, "date": "2024-01-02", "cores": 2, "name": "blr",
            "repeats": 2,
            "groups": [{"label": "shell M", "case": "bench/cases/shell-pressure.yaml",
                        "variants": [{"label": "full rank", "runs": ref},
                                     {"label": "ε = 1e-8", "runs": blr8},
                                     {"label": "ε = 1e-5", "runs": blr5}]}],
            "load_average": [0.2, 0.4]}


EXPECTED = f"""\
Made by `bench/variants blr --repeat 2` at commit abc1234 on 2024-01-02: \
{table.SETS['blr']['what']}. Each variant a whole `plisse run`, one core per rank \
(`OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1`), 2 rounds of every run in turn; wall and CPU time \
(user + system of the run's processes) as median (smallest–largest), the wall time also relative \
to the group's first variant's median; the counts and the factorisation's time are the first \
round's. The last column: the two largest differences of the final history row from the first \
variant's, each column's relative to its largest magnitude over the first variant's run (the \
solver's columns and the contacts' penetrations left out). The machine (2 cores) had a load \
average of 0.2 when the run began and 0.4 when it ended.

| case | variant | unknowns | steps | Newton iterations | factorisations | cut-backs \
| per factorisation [s] | wall [s] | wall / first | CPU [s] | final state against the first |
|---|---|---|---|---|---|---|---|---|---|---|---|
| shell M: `bench/cases/shell-pressure.yaml` | full rank | 35 000 | 5 | 12 | 12 | 0 | 0.500 \
| 11.0 (10.0–12.0) | 1 | 10.5 (9.5–11.5) | reference |
|  | ε = 1e-8 | 35 000 | 5 | 12 | 12 | 0 | 0.750 | 13.8 (13.2–14.3) | 1.25 (1.20–1.30) \
| 13.5 (13.0–14.0) | 2.0e-03 (force), then 5.0e-04 (volume) |
|  | ε = 1e-5 | – | – | – | – | – | – | – | – | – | did not finish (exit status 0, 1) |
"""


class VariantsTable(unittest.TestCase):
    def test_block_from_fixed_measurements(self):
        self.assertEqual(table.render_block(measurements()), EXPECTED)

    def test_the_differences_leave_the_solver_and_penetration_columns_out_largest_first(self):
        m = measurements()
        first, blr8 = (v["runs"][0] for v in m["groups"][0]["variants"][:2])
        blr8["final"]["residual_norm"] = 1.0  # the solver's: not compared
        blr8["final"]["penetration:punch"] = 1.0  # set by the contact's tolerance: not compared
        first["final"]["penetration:punch"] = 0.5
        first["largest"]["penetration:punch"] = 0.5
        (force, first_column), (volume, second_column) = table.final_differences(blr8, first)
        self.assertEqual((first_column, second_column), ("force", "volume"))
        self.assertAlmostEqual(force, 2.0e-3, places=12)
        self.assertAlmostEqual(volume, 5.0e-4, places=12)
        self.assertEqual(table.final_differences({"final": {"other": 1.0}}, first), [])

    def test_uncommitted_changes_and_load_are_said(self):
        first = block_testing.provenance_line(table.render_block, measurements())
        self.assertIn("at commit abc1234 with uncommitted changes on", first)
        self.assertIn("load average of 0.9 when the run began and 1.1 when it ended", first)

    def test_update_leaves_the_other_blocks_alone(self):
        page = table.Page("blr")
        block, peers, _, refused = block_testing.update_beside_the_peers(
            page.update_file, page.MARKERS, measurements(), table.peer_table)
        self.assertEqual(block, EXPECTED)
        self.assertEqual(peers, "the peers' block\n")
        self.assertEqual(refused, "# Title\n\nno block here\n")

    def test_a_failed_reference_gives_no_ratio(self):
        m = copy.deepcopy(measurements())
        m["groups"][0]["variants"][0]["runs"][1] = {"status": 2, "wall": 1.0, "cpu": 1.0}
        rows = table.render_block(m).splitlines()
        self.assertIn("did not finish (exit status 0, 2)", rows[-3])
        self.assertIn("| 13.8 (13.2–14.3) | – |", rows[-2])

    def test_a_reference_without_history_is_said(self):
        m = copy.deepcopy(measurements())
        m["groups"][0]["variants"][0]["runs"][0] = {"status": 0, "wall": 1.0, "cpu": 1.0,
                                                    "unknowns": 1, "steps": 0, "newton": 0,
                                                    "factorisations": 0, "cutbacks": 0,
                                                    "factorisation": 0.0, "peak": 1.0}
        rows = table.render_block(m).splitlines()
        self.assertIn("| no reference: the first variant wrote no history |", rows[-2])

    def test_docs_hold_what_the_last_run_of_each_set_wrote(self):
        text = (ROOT / "docs" / "performance.md").read_text(encoding="utf-8")
        for name in table.SETS:
            with self.subTest(set=name):
                record = ROOT / "docs" / "performance" / f"variants-{name}.json"
                self.assertTrue(record.exists(),
                                f"run bench/variants {name} --update docs/performance.md")
                self.assertEqual(table.peer_table.read_block(text, table.markers(name)),
                                 table.render_block(table.load(record)))


if __name__ == "__main__":
    unittest.main()
