"""Unit tests of plisse_study.sphere: the thin inflated sphere against its pressure law, Vella et
al.'s dimensionless pressure by hand, and the indented shell's readers on a synthetic shell."""
import argparse
import os
import tempfile
import unittest

import numpy as np

import study_fixtures as fx
from plisse_study import sphere


def thin_sphere_pressure(stretch, c1, radius, thickness):
    """p = (4 c1 t / R)(1/lambda - 1/lambda^7): the thin neo-Hookean sphere."""
    return 4.0 * c1 * thickness / radius * (1.0 / stretch - stretch**-7)


class InflatedSphereTest(unittest.TestCase):
    def test_stretch_by_hand(self):
        # c1 = 1, t = 1, R = 100, lambda = 1.1: 1.1^7 = 1.9487171, so
        # p = 0.04 (0.9090909 - 0.5131581) = 0.04 x 0.3959328 = 0.01583731 MPa.
        self.assertAlmostEqual(sphere.inflated_stretch(0.01583731, 1.0, 100.0, 1.0), 1.1,
                               delta=1e-7)

    def test_stretch_inverts_the_pressure_law(self):
        for stretch in (1.0001, 1.05, 1.2, 1.3):
            for c1, radius, thickness in ((1.0, 100.0, 1.0), (0.0033, 25.0, 0.5)):
                p = thin_sphere_pressure(stretch, c1, radius, thickness)
                self.assertAlmostEqual(sphere.inflated_stretch(p, c1, radius, thickness), stretch,
                                       delta=1e-12)
        self.assertEqual(sphere.inflated_stretch(0.0, 1.0, 100.0, 1.0), 1.0)

    def test_limit_point(self):
        # The largest pressure is at lambda = 7^(1/6): p_max = (4 c1 t / R)(6/7) 7^(-1/6) =
        # 2.47892 c1 t / R (7^(1/6) = 1.38309); above it there is no inflated state.
        self.assertLess(sphere.inflated_stretch(2.4789, 1.0, 1.0, 1.0), 7.0 ** (1.0 / 6.0))
        with self.assertRaises(SystemExit):
            sphere.inflated_stretch(2.4790, 1.0, 1.0, 1.0)

    def test_outer_pole(self):
        # 1.1 x 100 + 0.5 x 1 / 1.21.
        self.assertAlmostEqual(sphere.outer_pole(1.1, 100.0, 1.0), 110.41322314049587, places=12)

    def test_dimensionless_pressure(self):
        # tau = p R^2 / (8 c1 t^2) = 1e-3 x 200^2 / 8 = 5.
        self.assertAlmostEqual(sphere.tau_of(1e-3, 1.0, 200.0, 1.0), 5.0, places=12)
        self.assertAlmostEqual(sphere.pressure_of(5.0, 1.0, 200.0, 1.0), 1e-3, places=15)
        self.assertAlmostEqual(sphere.tau_of(sphere.pressure_of(2.5, 0.5, 80.0, 0.4), 0.5, 80.0,
                                             0.4), 2.5, places=12)


class IndentedShellTest(unittest.TestCase):
    radius, thickness = 50.0, 2.0

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.run = os.path.join(self.tmp.name, "tau-4")
        self.points, self.tets, self.mid = fx.shell_octant(self.radius, self.thickness)
        n = self.points / np.linalg.norm(self.points, axis=1)[:, None]
        # Step 0: the shell; step 1: inflated by 0.5 mm outward, the indenter not touching;
        # step 2: pushed 0.2 mm back in everywhere, touching.
        self.states = [(self.points, self.tets, {"displacement": 0.0 * n}, None),
                       (self.points, self.tets, {"displacement": 0.5 * n}, None),
                       (self.points, self.tets, {"displacement": 0.3 * n}, None)]
        fx.write_steps(self.run, self.states)
        fx.write_history(self.run, ["step", "time", "contact_nodes:indenter", "uy:mid"],
                         [[1, 0.5, 0, 0.5], [2, 1.0, 3, 0.3]])

    def tearDown(self):
        self.tmp.cleanup()

    def test_mid_surface(self):
        radius, thickness = sphere.mid_surface(os.path.join(self.run, "step_0000.vtu"))
        self.assertAlmostEqual(radius, self.radius, places=12)
        self.assertAlmostEqual(thickness, self.thickness, places=12)
        self.assertEqual(sphere.shell_geometry(self.run), (radius, thickness))
        with self.assertRaises(SystemExit):
            sphere.shell_geometry(os.path.join(self.tmp.name, "empty"))

    def test_before_contact_and_inflated_pole(self):
        h = {"contact_nodes:indenter": np.array([0.0, 0.0, 3.0, 0.0, 2.0]),
             "uy:mid": np.array([0.0, 0.1, 0.2, 0.3, 0.4])}
        self.assertEqual(sphere.before_contact(h, "contact_nodes:indenter"), 3)
        self.assertEqual(sphere.inflated_pole("r", h), 0.3)
        for contact in ([1.0, 2.0], [0.0, 0.0]):  # touching from the start; never touching
            h = {"contact_nodes:indenter": np.array(contact), "uy:mid": np.array([0.0, 0.1])}
            with self.assertRaises(SystemExit):
                sphere.inflated_pole("r", h)
        self.assertIsNone(sphere.before_contact({"c": np.array([1.0])}, "c"))

    def test_indented_history(self):
        self.assertEqual(list(sphere.indented_history(self.run)["uy:mid"]), [0.5, 0.3])
        with self.assertRaises(FileNotFoundError):
            sphere.indented_history(os.path.join(self.tmp.name, "none"))
        empty = os.path.join(self.tmp.name, "empty")
        fx.write_history(empty, ["step"], [])
        with self.assertRaises(SystemExit):
            sphere.indented_history(empty)

    def test_mid_surface_deflection_since_the_inflated_state(self):
        arc, w, x = sphere.mid_surface_deflection(self.run, self.radius,
                                                  os.path.join(self.run, "step_0002.vtu"))
        self.assertEqual(len(w), len(self.mid))
        np.testing.assert_allclose(w, 0.2, atol=1e-12)  # 0.5 - 0.3 inward, on every mid node
        np.testing.assert_allclose(np.linalg.norm(x, axis=1), self.radius, rtol=1e-12)
        # From the highest latitude (72 deg: 18 deg from the pole) down to the equator.
        self.assertTrue(np.all(np.diff(arc) >= 0))
        self.assertAlmostEqual(arc[0], self.radius * np.radians(18.0), places=9)
        self.assertAlmostEqual(arc[-1], self.radius * np.radians(90.0), places=9)

    def test_options_of_the_indented_shell_scripts(self):
        parser = sphere.indentation_parser("Title line.\nMore.", "4,8", 1000.0, "x=1")
        self.assertIsInstance(parser, argparse.ArgumentParser)
        args = parser.parse_args(["--sweep", "d", "--set", "a=1", "--set", "b=2"])
        self.assertEqual((args.sweep, args.taus, args.radius, args.thickness, args.c1, args.set),
                         ("d", "4,8", 1000.0, 1.0, 1.0, ["a=1", "b=2"]))
        self.assertEqual(parser.description, "Title line.")


if __name__ == "__main__":
    unittest.main()
