"""Unit tests of scripts/airbag_onset.py's reading of a run's geometry: the equatorial radius a and
the wall t of the bag, from a solid's equator (its inner and outer nodes) and from a shell's (its
nodes are the mid-surface's, and the wall is the triangles' reference thickness), on synthetic
step files."""
import os
import tempfile
import unittest

import numpy as np

import study_fixtures as fx
import airbag_onset


def equator_ring(radius, n=7):
    """Points of a quarter circle of `radius` about the y axis in the plane y = 0."""
    angles = np.linspace(0.0, 0.5 * np.pi, n)
    return [[radius * np.cos(b), 0.0, radius * np.sin(b)] for b in angles]


class GeometryTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.run = os.path.join(self.tmp.name, "run")
        os.makedirs(self.run)

    def tearDown(self):
        self.tmp.cleanup()

    def test_a_solid_wall_is_its_equators_outer_minus_inner_radius(self):
        # Inner nodes at 49.5, outer at 50.5 on the equator, and a node above it (y = 3) that is
        # not read; one tetrahedron to make the file.
        points = equator_ring(49.5) + equator_ring(50.5) + [[10.0, 3.0, 10.0]]
        fx.write_vtu(os.path.join(self.run, "step_0000.vtu"), points, [[0, 1, 7, 14]])
        a, t = airbag_onset.geometry(self.run)
        self.assertAlmostEqual(a, 50.0, places=12)
        self.assertAlmostEqual(t, 1.0, places=12)

    def test_a_shells_wall_is_its_triangles_thickness(self):
        # The mid-surface's equator at 50 and a row above it at y = 2; triangles of 1 mm.
        ring, upper = equator_ring(50.0), equator_ring(49.0)
        points = ring + [[x, 2.0, z] for x, _, z in upper]
        n = len(ring)
        triangles = [[k, k + 1, n + k] for k in range(n - 1)]
        fx.write_vtu(os.path.join(self.run, "step_0000.vtu"), points, triangles,
                     cell_data={"thickness": np.full(len(triangles), 1.0)}, kind="triangle")
        a, t = airbag_onset.geometry(self.run)
        self.assertAlmostEqual(a, 50.0, places=12)
        self.assertEqual(t, 1.0)


if __name__ == "__main__":
    unittest.main()
