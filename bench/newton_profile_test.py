"""Unit tests of bench/newton_profile_table.py, the generated block of docs/performance.md (section
"Where the time of one Newton iteration goes"): the reading of plisse-newton-profile's printout,
the table from fixed measurements, the markers, and that the docs hold what the last run wrote.
No timing.
Run by CTest (test bench_newton_profile, label unit): /usr/bin/python3 bench/newton_profile_test.py
"""
import copy
import sys
import unittest
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
sys.path.insert(0, str(HERE))
import block_testing  # noqa: E402
import newton_profile_table as table  # noqa: E402

# A printout in the form bench/newton_profile.cpp prints, with round numbers.
PRINTOUT = """\
examples/sphere-indentation.yaml: 1000 nodes, 4000 tetrahedra, 3500 unknowns; 1 assembly threads
  step 1 t = 0.02: 3 Newton iterations, |R| = 1.000e-10 
after the steps: 1 assembly threads
pieces of one Newton iteration at t = 0.06 + dt: ...; 3 calls each:
  sparsity (create_matrix)               wall best   0.0300 s  mean   0.0300 s   cpu best   0.0290 s
  element kernel, residual only          wall best   0.0800 s  mean   0.0810 s   cpu best   0.0790 s
  element kernel, with tangent           wall best   0.1000 s  mean   0.1010 s   cpu best   0.0900 s
  (2.05 bubble evaluations per element)
  assemble_residual                      wall best   0.0800 s  mean   0.0800 s   cpu best   0.0780 s
  assemble_tangent                       wall best   0.1200 s  mean   0.1200 s   cpu best   0.1100 s
    of which MatZeroEntries              wall best   0.0001 s  mean   0.0001 s   cpu best   0.0001 s
  restore + predictor (included above)   wall best   0.0020 s  mean   0.0020 s   cpu best   0.0020 s
  terms, residual only                   wall best   0.0001 s  mean   0.0001 s   cpu best   0.0001 s
  terms, with tangent (no-op sink)       wall best   0.0002 s  mean   0.0002 s   cpu best   0.0002 s
  matrix: 180000 nonzeros (51.4 per row)
  factorisation, symbolic + numeric      wall best   0.5000 s  mean   0.5000 s   cpu best   0.4900 s
  MUMPS factor entries INFOG(29) = 1260000 (fill 7.0 x the matrix)
  factorisation, numeric only            wall best   0.3500 s  mean   0.3600 s   cpu best   0.3400 s
  solve (forward/backward)               wall best   0.0200 s  mean   0.0210 s   cpu best   0.0200 s
one load step through SNES: 2 iterations, 0.900 s (0.4500 s per iteration), cpu 0.890 s
  3 residual and 2 tangent assemblies
  assembly      0.1800 s per iteration (40 %)
  factorisation 0.2000 s per iteration
  triangular    0.0250 s per iteration
  symbolic factorisations 0, numeric 2 in this step (whole run: 2 / 12)
"""


def measurements():
    """Three processes: the printout, then its pieces' CPU times x 1.1 and x 0.9 (the tangent's
    0.110, 0.121 and 0.099 s: median 0.110, range 0.099-0.121), the SNES step 0.9, 1.0 and 0.8 s
    (per iteration 0.45, 0.5, 0.4) with the same phase times."""
    first = table.parse(PRINTOUT)
    processes = [first]
    for factor, wall in ((1.1, 1.0), (0.9, 0.8)):
        p = copy.deepcopy(first)
        for piece in p["pieces"].values():
            piece["cpu_best"] *= factor
        p["step"]["wall"] = wall
        processes.append(p)
    return {"command": "bench/newton-profile --repeat 3", "commit": "abc1234",
            "local_changes": False, "date": "2024-01-02", "cores": 2,
            "profile": "examples/sphere-indentation.yaml --time 0.06 --steps 3 --repeat 3",
            "processes": processes, "load_average": [0.2, 0.4]}


# Per process, the kernel with tangent is 0.090 x (1, 1.1, 0.9) and the tangent 0.110 x the same:
# all but the kernel 0.020 x (1, 1.1, 0.9): median 0.0200 (0.0180-0.0220). The SNES step: assembly
# 0.18 s/it, factorisation + solve 0.2 + 0.025 = 0.225 s/it; iterations 0.45, 0.5, 0.4 s (median
# 0.45); assembly shares 0.40, 0.36, 0.45 (median 40 %); iteration / (f + s) 2.0, 2.22, 1.78
# (median 2.00).
EXPECTED = """\
Made by `bench/newton-profile --repeat 3` at commit abc1234 on 2024-01-02: `plisse-newton-profile \
examples/sphere-indentation.yaml --time 0.06 --steps 3 --repeat 3`, 3 processes in turn, one core \
each (`OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1`). A piece's time is its best CPU time of the \
calls within a process; the table gives the median (smallest–largest) over the processes. The \
machine (2 cores) had a load average of 0.2 when the run began and 0.4 when it ended.

The case: 1 000 nodes, 4 000 tetrahedra, 3 500 unknowns, 180 000 tangent nonzeros; the MUMPS \
factor has 1 260 000 entries (fill 7.0); the bubbles need 2.05 local Newton evaluations per \
element.

| piece | CPU time [s] |
|---|---|
| element kernel, residual only (all elements, no scatter) | 0.0790 (0.0711–0.0869) |
| element kernel, residual and tangent | 0.0900 (0.0810–0.0990) |
| `assemble_residual` (kernel + scatter + terms) | 0.0780 (0.0702–0.0858) |
| `assemble_tangent` (kernel + zeroing + scatter + terms + `MatAssembly`) | 0.1100 (0.0990–0.1210) |
| of both: restoring the state and its predictor, per call | 0.0020 (0.0018–0.0022) |
| `MatZeroEntries` | 0.0001 (0.0001–0.0001) |
| terms, residual only | 0.0001 (0.0001–0.0001) |
| terms, with tangent | 0.0002 (0.0002–0.0002) |
| sparsity (`create_matrix`, once per run) | 0.0290 (0.0261–0.0319) |
| MUMPS symbolic + numeric factorisation (once per run) | 0.4900 (0.4410–0.5390) |
| MUMPS numeric factorisation | 0.3400 (0.3060–0.3740) |
| forward/backward solve | 0.0200 (0.0180–0.0220) |
| of `assemble_tangent`, all but the kernel (tangent − kernel) | 0.0200 (0.0180–0.0220) |

One more load step through SNES, as a run makes it (wall time per Newton iteration, plisse's own \
phase clocks):

| Newton iterations | residual / tangent assemblies | symbolic / numeric factorisations \
| assembly [s/it] | factorisation + solve [s/it] | iteration [s] | assembly share \
| iteration / (factorisation + solve) |
|---|---|---|---|---|---|---|---|
| 2 | 3 / 2 | 0 / 2 | 0.1800 (0.1800–0.1800) | 0.2250 (0.2250–0.2250) \
| 0.4500 (0.4000–0.5000) | 40 % | 2.00 |
"""


class NewtonProfileTable(block_testing.BlockChecks, unittest.TestCase):
    table, measurements, expected, record = table, measurements(), EXPECTED, "newton-profile"

    def test_the_printout_is_read(self):
        p = table.parse(PRINTOUT)
        self.assertEqual((p["nodes"], p["tetrahedra"], p["unknowns"], p["threads"]),
                         (1000, 4000, 3500, 1))
        self.assertEqual((p["nonzeros"], p["factor_entries"], p["fill"], p["bubbles"]),
                         (180000, 1260000, 7.0, 2.05))
        self.assertEqual(p["pieces"]["of which MatZeroEntries"],
                         {"wall_best": 0.0001, "wall_mean": 0.0001, "cpu_best": 0.0001})
        self.assertEqual(p["step"], {"iterations": 2, "wall": 0.9, "cpu": 0.89, "residuals": 3,
                                     "tangents": 2, "assembly": 0.18, "factorisation": 0.2,
                                     "triangular": 0.025, "symbolic": 0, "numeric": 2})

    def test_a_case_not_of_mini_has_no_kernel_rows(self):
        text = "\n".join(line for line in PRINTOUT.splitlines()
                         if "element kernel" not in line and "bubble" not in line)
        m = measurements()
        m["processes"] = [table.parse(text)]
        block = table.render_block(m)
        self.assertNotIn("element kernel", block)
        self.assertNotIn("tangent − kernel", block)
        self.assertIn("(fill 7.0).\n", block)
        self.assertIn("| `assemble_tangent` (kernel + zeroing + scatter + terms + `MatAssembly`) "
                      "| 0.1100 |", block)

    def test_a_printout_without_the_snes_step_is_refused(self):
        text = PRINTOUT.split("one load step")[0]
        with self.assertRaisesRegex(table.ParseError, "load step through SNES"):
            table.parse(text)

    def test_a_printout_without_a_piece_is_refused(self):
        text = "\n".join(line for line in PRINTOUT.splitlines() if "assemble_tangent " not in line)
        with self.assertRaisesRegex(table.ParseError, "assemble_tangent"):
            table.parse(text)


if __name__ == "__main__":
    unittest.main()
