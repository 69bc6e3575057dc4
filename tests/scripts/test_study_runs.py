"""Unit tests of plisse_study.runs: the readers of a run directory, on synthetic runs."""
import math
import os
import tempfile
import unittest

import numpy as np

import study_fixtures as fx
from plisse_study import runs


class HistoryTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.run = os.path.join(self.tmp.name, "run")

    def tearDown(self):
        self.tmp.cleanup()

    def test_columns_with_empty_cells_and_an_unterminated_row(self):
        # The third row was cut by a killed run: it has fewer cells and is left out.
        fx.write_history(self.run, ["step", "time", "pressure:gas", "stable"],
                         [[1, 0.5, 1e-3, 1], [2, 1.0, "", 0]], tail="3,1.5")
        h = runs.read_history(self.run)
        self.assertEqual(sorted(h), ["pressure:gas", "stable", "step", "time"])
        np.testing.assert_array_equal(h["step"], [1.0, 2.0])
        self.assertEqual(h["pressure:gas"][0], 1e-3)
        self.assertTrue(math.isnan(h["pressure:gas"][1]))

    def test_missing_or_empty_history(self):
        self.assertEqual(runs.read_history(self.run), {})
        with self.assertRaises(FileNotFoundError):
            runs.read_history(self.run, required=True)
        fx.write_history(self.run, ["step", "time"], [])
        self.assertEqual(runs.read_history(self.run), {})

    def test_stability_from_pivots_before_the_stable_column(self):
        # Row 3 has one negative pivot more than a stable state: unstable from t = 0.3 on, even
        # though the column `stable` (here deliberately contradicting it) says otherwise.
        fx.write_history(self.run, ["step", "time", "negative_pivots", "expected_negative_pivots",
                                    "stable"],
                         [[1, 0.1, 4, 4, 0], [2, 0.2, 4, 4, 1], [3, 0.3, 5, 4, 1],
                          [4, 0.4, 4, 4, 1]])
        h = runs.read_history(self.run)
        np.testing.assert_array_equal(runs.stable_column(h), [1.0, 1.0, 0.0, 1.0])
        self.assertEqual(runs.first_unstable_time(h), 0.3)

    def test_stability_from_the_stable_column_or_none(self):
        fx.write_history(self.run, ["step", "time", "stable"], [[1, 0.1, 1], [2, 0.2, 0]])
        self.assertEqual(runs.first_unstable_time(runs.read_history(self.run)), 0.2)
        fx.write_history(self.run, ["step", "time"], [[1, 0.1]])
        h = runs.read_history(self.run)
        self.assertIsNone(runs.stable_column(h))
        self.assertIsNone(runs.first_unstable_time(h))


class SummaryAndLogTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.run = os.path.join(self.tmp.name, "a-50-n15")

    def tearDown(self):
        self.tmp.cleanup()

    def test_summary_rings_instabilities_and_overrides(self):
        self.assertEqual(runs.read_summary(self.run), {})
        with self.assertRaises(FileNotFoundError):
            runs.read_summary(self.run, required=True)
        fx.write_summary(self.run, {
            "wrinkles": {"rings": [{"latitude_deg": 10, "amplitude": 0.2, "count": 8},
                                   {"latitude_deg": 20, "amplitude": 0.5, "count": 12},
                                   {"latitude_deg": 30, "count": 4}]},
            "stability": {"instabilities": [{"step": 7, "time": 0.35, "file": "step_0007.vtu"}]},
            "overrides": ["mesh.thickness=0.5", "loads[0].value=1e-3", "nonsense"]})
        s = runs.read_summary(self.run)
        self.assertEqual(runs.largest_ring(s)["count"], 12)
        self.assertIsNone(runs.largest_ring({}))
        self.assertEqual([e["step"] for e in runs.summary_instabilities(s)], [7])
        self.assertEqual(runs.summary_instabilities({"stability": None}), [])
        self.assertEqual(runs.set_values(s), {"mesh.thickness": "0.5", "loads[0].value": "1e-3"})
        self.assertEqual(runs.run_name(self.run + "/"), "a-50-n15")

    def test_log_instabilities(self):
        os.makedirs(self.run)
        self.assertEqual(runs.log_instabilities(self.run), [])
        with open(os.path.join(self.run, "log.txt"), "w") as f:
            f.write("[    1.0s] step    3  t 0.3  load 0.3\n"
                    "[   13.6s] warning:   step 8: t = 0.0744531: new instability, 573 negative "
                    "pivots (stable: 572, previous step: 572), 0 zero\n"
                    "[   20.0s] warning:   step 9: t = 0.08 failed after 3 iterations\n"
                    "[   28.7s] warning:   step 11: t = 1.5e-05: new instability, 574 negative\n")
        self.assertEqual(runs.log_instabilities(self.run), [(8, 0.0744531), (11, 1.5e-05)])

    def test_spectrum_and_case_settings(self):
        self.assertEqual(runs.read_spectrum(self.run), [])
        os.makedirs(self.run)
        with open(os.path.join(self.run, "wrinkle_spectrum.csv"), "w") as f:
            f.write("step,latitude_deg,m,amplitude,in_band\n4,10,8,0.1,1\n4,20,12,0.3,0\n")
        rows = runs.read_spectrum(self.run)
        self.assertEqual([r["m"] for r in rows], ["8", "12"])
        case = os.path.join(self.tmp.name, "case.yaml")
        with open(case, "w") as f:
            f.write("title: x\noutput:\n  wrinkles: {axis: z, rings_deg: [10, 20]}\n")
        self.assertEqual(runs.case_wrinkle_settings(case), {"axis": "z", "rings_deg": [10, 20]})
        with open(case, "w") as f:
            f.write("title: x\n")
        self.assertEqual(runs.case_wrinkle_settings(case), {})


class StepsAndStatesTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.run = os.path.join(self.tmp.name, "run")
        # One tetrahedron, unit legs; step 1 stretches it along x by 10 %.
        self.X = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
        u1 = np.zeros((4, 3))
        u1[:, 0] = 0.1 * self.X[:, 0]
        # cauchy_stress components xx, yy, zz, xy, yz, xz.
        stress = np.array([[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]])
        fx.write_steps(self.run, [
            (self.X, [[0, 1, 2, 3]], {"displacement": np.zeros((4, 3))}, {"cauchy_stress": stress}),
            (self.X, [[0, 1, 2, 3]], {"displacement": u1}, {"cauchy_stress": 2 * stress})])

    def tearDown(self):
        self.tmp.cleanup()

    def test_written_steps_from_the_collection(self):
        names = [(k, os.path.basename(p)) for k, p in runs.written_steps(self.run)]
        self.assertEqual(names, [(1, "step_0001.vtu")])
        self.assertEqual([os.path.basename(p) for p in runs.step_files(self.run)],
                         ["step_0000.vtu", "step_0001.vtu"])
        self.assertEqual(os.path.basename(runs.last_vtu(self.run)), "step_0001.vtu")
        self.assertIsNone(runs.last_vtu(os.path.join(self.tmp.name, "none")))
        self.assertEqual(runs.step_of("runs/x/step_0012.pvtu"), 12)

    def test_state_points_displacement_and_stress(self):
        s = runs.read_state(runs.last_vtu(self.run))
        np.testing.assert_array_equal(s.points, self.X)
        np.testing.assert_array_equal(s.corners, [[0, 1, 2, 3]])
        np.testing.assert_allclose(s.deformed[1], [1.1, 0.0, 0.0])
        # The symmetric tensor of (xx, yy, zz, xy, yz, xz) = 2 (1, 2, 3, 4, 5, 6).
        np.testing.assert_array_equal(s.stress()[0], [[2, 8, 12], [8, 4, 10], [12, 10, 6]])

    def test_quadratic_tetrahedra_give_their_corners(self):
        points = np.vstack([self.X, 0.5 * (self.X[[0, 1, 2, 0, 0, 1]] + self.X[[1, 2, 0, 3, 3, 3]])])
        path = os.path.join(self.tmp.name, "p2.vtu")
        fx.write_vtu(path, points, [list(range(10))], kind="tetra10")
        s = runs.read_state(path)
        self.assertEqual(s.cells.shape, (1, 10))
        np.testing.assert_array_equal(s.corners, [[0, 1, 2, 3]])



class RawVtuTest(unittest.TestCase):
    """plisse's own step files (raw appended, zlib) are read by runs.read_raw_vtu. The file in
    tests/data/vtu is the last step of examples/cube-tension-mooney-rivlin.yaml with c2 = 0.1 MPa
    (27 nodes, 48 tetrahedra, stretch 5), whose arrays Debian's meshio 1.x mixes up (the velocity
    read as the Cauchy stress: an array's new offset equals another's old one). Every element holds
    the homogeneous stress, the closed form 2 c1 (l^2 - 1/l) - 2 c2 (1/l^2 - l) = 10.912 MPa along
    z and 0 across, to 1e-9 of it (the run's Newton tolerance is 1e-10)."""

    def test_plisse_step_file(self):
        path = os.path.join(os.path.dirname(fx.SCRIPTS), "tests", "data", "vtu",
                            "cube-mooney-rivlin-step-6.vtu")
        mesh = runs.read_raw_vtu(path)
        self.assertEqual(list(mesh.cells_dict), ["tetra"])
        self.assertEqual(mesh.cells_dict["tetra"].shape, (48, 4))
        self.assertEqual(mesh.points.shape, (27, 3))
        self.assertEqual(mesh.point_data["velocity"].shape, (27, 3))
        self.assertEqual(mesh.cell_data["von_mises"][0].shape, (48, 1))
        sigma = mesh.cell_data["cauchy_stress"][0]
        l, c1, c2 = 5.0, 0.2, 0.1
        szz = 2 * c1 * (l * l - 1 / l) - 2 * c2 * (1 / l**2 - l)
        self.assertAlmostEqual(szz, 10.912, places=12)
        np.testing.assert_allclose(sigma[:, 2], szz, rtol=1e-9)
        np.testing.assert_allclose(sigma[:, [0, 1, 3, 4, 5]], 0.0, atol=1e-9 * szz)
        # The top face moved 20 mm up: u_z = 4 z at every node.
        np.testing.assert_allclose(mesh.point_data["displacement"][:, 2], 4 * mesh.points[:, 2],
                                   atol=1e-9)
        self.assertEqual(runs.read_state(path).cells.shape, (48, 4))

    def test_other_layouts_go_to_meshio(self):
        tmp = tempfile.TemporaryDirectory()
        path = os.path.join(tmp.name, "step_0001.vtu")
        points, tets, _ = fx.shell_octant(10.0, 1.0)
        fx.write_vtu(path, points, tets, {"displacement": 0.5 * points})
        self.assertIsNone(runs.read_raw_vtu(path))  # meshio writes base64
        np.testing.assert_allclose(runs.read_state(path).displacement, 0.5 * points)
        tmp.cleanup()

if __name__ == "__main__":
    unittest.main()
