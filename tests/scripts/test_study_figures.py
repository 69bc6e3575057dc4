"""Unit tests of plisse_study.figures: the outer surface, the normal deviation from the
axisymmetric mean shape (by hand), the mirrored quarter disc, and the figures written."""
import os
import tempfile
import unittest

import numpy as np

import study_fixtures as fx
from plisse_study import figures


def sphere_points(latitudes_deg, azimuths_deg, radius=1.0):
    """Points of a sphere about the y axis at the given latitudes and azimuths."""
    out = []
    for lat in np.radians(latitudes_deg):
        for lon in np.radians(azimuths_deg):
            out.append([radius * np.cos(lat) * np.cos(lon), radius * np.sin(lat),
                        radius * np.cos(lat) * np.sin(lon)])
    return np.array(out)


class NormalDeviationTest(unittest.TestCase):
    latitudes = [10.0, 20.0, 30.0, 40.0, 50.0]
    azimuths = list(range(0, 90, 10))  # 9 per latitude

    def test_uniform_inflation_has_no_deviation(self):
        X = sphere_points(self.latitudes, self.azimuths)
        dev = figures.normal_deviation(X, 1.1 * X, 1, np.zeros(3))
        np.testing.assert_allclose(dev, 0.0, atol=1e-12)

    def test_one_node_pushed_out(self):
        # One node of latitude 30 deg moved out by d = 0.09 along the radius: the mean of its
        # latitude moves out by d/9, the neighbouring latitudes set the normal there (central
        # differences), which is the radius; so the node deviates by d - d/9 = 0.08 and the other
        # eight of its latitude by -d/9 = -0.01. The other latitudes do not deviate.
        X = sphere_points(self.latitudes, self.azimuths)
        x = X.copy()
        k = 2 * 9 + 4
        x[k] *= 1.09
        dev = figures.normal_deviation(X, x, 1, np.zeros(3))
        self.assertAlmostEqual(dev[k], 0.08, places=12)
        same = [i for i in range(18, 27) if i != k]
        np.testing.assert_allclose(dev[same], -0.01, atol=1e-12)
        np.testing.assert_allclose(np.delete(dev, range(18, 27)), 0.0, atol=1e-12)


class SurfaceTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.tmp.cleanup()

    def test_outer_surface_of_a_shell(self):
        # An 8 x 8 grid of nodes per sphere: 7 x 7 cells of two triangles on the outer sphere.
        points, tets, _ = fx.shell_octant(10.0, 1.0)
        faces = figures.outer_surface(points, tets, np.zeros(3))
        self.assertEqual(len(faces), 2 * 7 * 7)
        np.testing.assert_allclose(np.linalg.norm(points[faces.ravel()], axis=1), 10.5,
                                   rtol=1e-12)

    def test_surface_figure_written(self):
        points, tets, _ = fx.shell_octant(10.0, 1.0)
        u = 0.1 * points + 0.01 * np.sin(8 * np.arctan2(points[:, 2], points[:, 0]))[:, None]
        vtu = os.path.join(self.tmp.name, "step_0001.vtu")
        fx.write_vtu(vtu, points, tets, {"displacement": u})
        png = os.path.join(self.tmp.name, "map.png")
        self.assertTrue(figures.surface_figure(vtu, {"axis": "y", "rings_deg": [30]}, png, "t"))
        with open(png, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertEqual(figures.plt.get_fignums(), [])  # closed
        bare = os.path.join(self.tmp.name, "bare.vtu")
        fx.write_vtu(bare, points, tets)
        self.assertFalse(figures.surface_figure(bare, {}, os.path.join(self.tmp.name, "no.png"),
                                                "t"))
        self.assertFalse(os.path.exists(os.path.join(self.tmp.name, "no.png")))


def shell_tube(radius=10.0, length=20.0, around=48, along=11):
    """A closed shell tube about the y axis from y = 0 to `length`: points and triangles (two per
    cell, the cells across the azimuth's seam included)."""
    phi = np.linspace(0.0, 2.0 * np.pi, around, endpoint=False)
    y = np.linspace(0.0, length, along)
    points = np.array([[radius * np.cos(p), h, radius * np.sin(p)] for h in y for p in phi])
    triangles = []
    for j in range(along - 1):
        for i in range(around):
            a, b = j * around + i, j * around + (i + 1) % around
            c, d = a + around, b + around
            triangles += [[a, b, d], [a, d, c]]
    return points, np.array(triangles)


class UnrolledTest(unittest.TestCase):
    """The unrolled map of a shell tube moved radially by a cos(6 phi): arc length from -pi R to
    pi R, the seam's triangles left out, and each triangle's deviation the mean of a cos(6 phi) at
    its nodes (the mean shape of each ring is the circle of radius R)."""

    def test_radial_waves_unrolled(self):
        points, triangles = shell_tube()
        phi = np.arctan2(points[:, 2], points[:, 0])
        a = 0.1
        u = a * np.cos(6 * phi)[:, None] * np.column_stack([np.cos(phi), 0 * phi, np.sin(phi)])
        center = np.array([0.0, 10.0, 0.0])
        s, h, kept, dev = figures.unrolled_map(points, points + u, triangles, 1, center)
        self.assertEqual(len(kept), len(triangles) - 2 * 10)
        np.testing.assert_allclose([s.min(), s.max()], [-np.pi * 10.0, np.pi * 10.0 * 46 / 48],
                                   rtol=1e-12)
        np.testing.assert_allclose(h, points[:, 1] - 10.0, atol=1e-12)
        np.testing.assert_allclose(dev, (a * np.cos(6 * phi))[kept].mean(axis=1), atol=1e-12)

    def test_unrolled_figure_written(self):
        tmp = tempfile.TemporaryDirectory()
        points, triangles = shell_tube()
        phi = np.arctan2(points[:, 2], points[:, 0])
        u = 0.1 * np.cos(6 * phi)[:, None] * np.column_stack([np.cos(phi), 0 * phi, np.sin(phi)])
        vtu = os.path.join(tmp.name, "step_0001.vtu")
        fx.write_vtu(vtu, points, triangles, {"displacement": u}, kind="triangle")
        png = os.path.join(tmp.name, "unrolled.png")
        self.assertTrue(figures.unrolled_figure(vtu, {"axis": "y", "center": [0, 10, 0]}, png,
                                                "t"))
        with open(png, "rb") as f:
            self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        self.assertEqual(figures.plt.get_fignums(), [])
        tmp.cleanup()


class DiscTest(unittest.TestCase):
    def test_mirrored_quarter(self):
        # (0, 0) lies on both mirrors, (1, 0) and (0, 1) on one: 1 + 2 + 2 + 4 = 9 points.
        x = np.array([0.0, 1.0, 0.0, 1.0])
        z = np.array([0.0, 0.0, 1.0, 1.0])
        points = figures.mirrored_quarter(x, z, np.array([1.0, 2.0, 3.0, 4.0]))
        self.assertEqual(len(points), 9)
        as_map = {(p[0], p[1]): p[2] for p in points}
        self.assertEqual(as_map[(0.0, 0.0)], 1.0)
        self.assertEqual(as_map[(-1.0, 0.0)], 2.0)
        self.assertEqual(as_map[(0.0, -1.0)], 3.0)
        self.assertEqual(as_map[(-1.0, -1.0)], 4.0)
        # A node a rounding error off the mirror is on it: its images are one point.
        points = figures.mirrored_quarter(np.array([1e-12]), np.array([1.0]), np.array([5.0]))
        np.testing.assert_array_equal(points, [[0.0, -1.0, 5.0], [0.0, 1.0, 5.0]])

    def test_disc_map_and_save(self):
        tmp = tempfile.TemporaryDirectory()
        r, phi = np.meshgrid(np.linspace(0.0, 1.0, 6), np.linspace(0.0, np.pi / 2, 6))
        x, z = (r * np.cos(phi)).ravel(), (r * np.sin(phi)).ravel()
        points = figures.mirrored_quarter(x, z, 1.0 - (x * x + z * z))
        fig, ax = figures.plt.subplots()
        contours = figures.disc_map(ax, points, np.linspace(-0.1, 1.0, 12), "viridis")
        self.assertEqual(list(contours.levels), list(np.linspace(-0.1, 1.0, 12)))
        path = os.path.join(tmp.name, "disc.png")
        figures.save(fig, path)
        self.assertTrue(os.path.getsize(path) > 0)
        self.assertEqual(figures.plt.get_fignums(), [])
        tmp.cleanup()


if __name__ == "__main__":
    unittest.main()
