"""Unit tests of scripts/plot.py (`plisse plot`): the figure of chosen columns (--x, --y) draws
exactly those columns, with their units; moments.png draws each cap's largest moment component;
a column the history lacks, or --x without --y, is refused with exit status 2; the fields along a
line (plisse_study.lines, --line) are sampled exactly where the element's shape functions hold
the field, and written to line.csv; wrinkle_lines.png draws each measurement line's crest height
and crests."""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import study_fixtures as fx
import plot
from plisse_study import lines, runs

UNITS_TABLE = """| column | unit | what |
|---|---|---|
| `time` | – | t |
| `force_<axis>:<cap>` | N | force |
| `moment_<axis>:<cap>` | N mm | moment |
| `u<axis>:<cap>` | mm | displacement |
"""

HEADER = ["step", "time", "newton_iterations", "residual_norm", "force_x:tip", "force_y:tip",
          "force_z:tip", "moment_x:tip", "moment_y:tip", "moment_z:tip", "ux:tip", "uy:tip",
          "uz:tip"]
ROWS = [[k, 0.25 * k, 2, 1e-12, 0.0, 0.0, -0.5 * k, 0.0, 3.0 * k, -0.1 * k, 0.0, 0.0, -0.7 * k]
        for k in range(1, 5)]


class Captured:
    """plot.save replaced: keeps the figures instead of writing them."""

    def __init__(self):
        self.figures = {}

    def __call__(self, fig, path):
        self.figures[os.path.basename(path)] = fig


class FiguresTest(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.run = os.path.join(self.dir.name, "run")
        fx.write_history(self.run, HEADER, ROWS)
        self.h = runs.read_history(self.run)
        self.units = [("^time$", 4, "–"), ("^force_.+:.+$", 7, "N"), ("^moment_.+:.+$", 8, "N mm"),
                      ("^u.+:.+$", 2, "mm")]
        self.saved = plot.save
        self.captured = Captured()
        plot.save = self.captured

    def tearDown(self):
        plot.save = self.saved
        self.dir.cleanup()

    def test_chosen_columns_against_the_chosen_abscissa(self):
        plot.columns_figure(self.h, self.units, self.dir.name, "uz:tip", ["force_z:tip"])
        ax = self.captured.figures["columns.png"].axes[0]
        self.assertEqual(len(ax.lines), 1)
        np.testing.assert_array_equal(ax.lines[0].get_xdata(), [-0.7 * k for k in range(1, 5)])
        np.testing.assert_array_equal(ax.lines[0].get_ydata(), [-0.5 * k for k in range(1, 5)])
        self.assertEqual(ax.get_xlabel(), "uz:tip [mm]")
        self.assertEqual(ax.get_ylabel(), "force_z:tip [N]")

    def test_several_columns_against_the_time(self):
        plot.columns_figure(self.h, self.units, self.dir.name, "time", ["moment_y:tip", "uz:tip"])
        ax = self.captured.figures["columns.png"].axes[0]
        self.assertEqual([line.get_label() for line in ax.lines], ["moment_y:tip", "uz:tip"])
        np.testing.assert_array_equal(ax.lines[0].get_xdata(), [0.25, 0.5, 0.75, 1.0])
        np.testing.assert_array_equal(ax.lines[0].get_ydata(), [3.0, 6.0, 9.0, 12.0])

    def test_moments_draw_each_caps_largest_component(self):
        plot.moments_figure(self.h, self.units, self.dir.name)
        ax = self.captured.figures["moments.png"].axes[0]
        self.assertEqual([line.get_label() for line in ax.lines], ["moment_y:tip"])
        self.assertEqual(ax.get_ylabel(), "moment [N mm]")

    def test_wrinkle_lines_draw_each_lines_height_and_crests(self):
        header = ["step", "time", "wrinkle_crests:across", "wrinkle_peak_crests:across",
                  "wrinkle_amplitude:across", "wrinkle_wavelength:across"]
        rows = [[k, 0.25 * k, 0 if k < 3 else 7, 7, 0.01 * k, 3.0] for k in range(1, 5)]
        fx.write_history(self.run, header, rows)
        plot.wrinkle_lines_figure(runs.read_history(self.run), self.dir.name)
        ax, twin = self.captured.figures["wrinkle_lines.png"].axes
        self.assertEqual([line.get_label() for line in ax.lines], ["across"])
        np.testing.assert_array_equal(ax.lines[0].get_ydata(), [0.01, 0.02, 0.03, 0.04])
        np.testing.assert_array_equal(twin.lines[0].get_ydata(), [0, 0, 7, 7])
        plot.wrinkle_lines_figure(self.h, self.dir.name + "/none")
        self.assertEqual(list(self.captured.figures), ["wrinkle_lines.png"])

    def test_no_moments_no_figure(self):
        fx.write_history(self.run, HEADER[:7], [r[:7] for r in ROWS])
        plot.moments_figure(runs.read_history(self.run), self.units, self.dir.name)
        self.assertNotIn("moments.png", self.captured.figures)


class CommandLineTest(unittest.TestCase):
    """plot.py run as `plisse plot` runs it, with a stand-in for plisse's `outputs history`."""

    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()
        self.run = os.path.join(self.dir.name, "run")
        fx.write_history(self.run, HEADER, ROWS)
        fx.write_summary(self.run, {"steps": 4})
        self.plisse = os.path.join(self.dir.name, "plisse")
        with open(self.plisse, "w") as f:
            f.write("#!/bin/sh\ncat <<'EOF'\n" + UNITS_TABLE + "EOF\n")
        os.chmod(self.plisse, 0o755)
        self.out = os.path.join(self.dir.name, "plots")

    def tearDown(self):
        self.dir.cleanup()

    def plot(self, *args):
        return subprocess.run([sys.executable, os.path.join(fx.SCRIPTS, "plot.py"), self.run,
                               self.out, self.plisse, *args], capture_output=True, text=True,
                              env={**os.environ, "MPLBACKEND": "Agg"}, timeout=120)

    def test_columns_figure_only(self):
        p = self.plot("--x", "uz:tip", "--y", "force_z:tip")
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(sorted(os.listdir(self.out)), ["columns.png"])

    def test_default_figures_include_the_moments(self):
        p = self.plot()
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertIn("moments.png", os.listdir(self.out))
        self.assertIn("forces.png", os.listdir(self.out))

    def test_missing_column_is_refused_with_the_columns_there_are(self):
        p = self.plot("--y", "moment_q:tip")
        self.assertEqual(p.returncode, 2)
        self.assertIn("history.csv has no column moment_q:tip; its columns: step, time", p.stderr)
        self.assertFalse(os.path.exists(os.path.join(self.out, "columns.png")))

    def test_abscissa_without_ordinate_is_refused(self):
        p = self.plot("--x", "uz:tip")
        self.assertEqual(p.returncode, 2)
        self.assertIn("--x needs at least one --y column", p.stderr)


def kuhn_cube(size=2.0):
    """The cube [0, size]^3 cut into 6 tetrahedra along its diagonal: points and corner lists."""
    corners = np.array([[i, j, k] for k in (0, 1) for j in (0, 1) for i in (0, 1)], dtype=float)
    index = {tuple(p): n for n, p in enumerate(corners)}
    tets = []
    for path in ((0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)):
        p = np.zeros(3)
        chain = [index[tuple(p)]]
        for axis in path:
            p = p.copy()
            p[axis] = 1.0
            chain.append(index[tuple(p)])
        tets.append(chain)
    return size * corners, np.array(tets)


def quadratic(points, tets):
    """The 10-node tetrahedra of `tets` (VTK order: corners, then the edges (0,1), (1,2), (0,2),
    (0,3), (1,3), (2,3)), their edge nodes at the midpoints."""
    points, cells, mid = list(points), [], {}
    for t in tets:
        row = list(t)
        for i, j in lines.TETRA10_EDGES:
            key = tuple(sorted((t[i], t[j])))
            if key not in mid:
                mid[key] = len(points)
                points.append(0.5 * (points[t[i]] + points[t[j]]))
            row.append(mid[key])
        cells.append(row)
    return np.array(points), np.array(cells)


class LineTest(unittest.TestCase):
    """plisse_study.lines: a linear field on 4-node tetrahedra and a quadratic one on 10-node
    tetrahedra are sampled exactly (to round-off); a cell field gives the value of the cell
    holding the point; points outside the body are left out; a shell's triangles take the points
    near their plane."""

    def test_linear_field_on_linear_tetrahedra(self):
        X, tets = kuhn_cube()
        A = np.array([[0.1, 0.2, -0.3], [0.0, 0.5, 0.1], [0.2, -0.1, 0.4]])
        u = X @ A.T + np.array([1.0, -2.0, 0.5])
        sigma = np.tile(np.arange(6.0), (len(tets), 1))
        header, rows, outside = lines.sample(X, tets, {"displacement": u},
                                             {"cauchy_stress": sigma}, [-1, 0.3, 0.7], [3, 1.7, 1.1], 41)
        self.assertEqual(header[:7], ["s", "X", "Y", "Z", "displacement_x", "displacement_y",
                                      "displacement_z"])
        self.assertEqual(header[7:], [f"cauchy_stress_{c}" for c in ("xx", "yy", "zz", "xy", "yz", "xz")])
        rows = np.array(rows)
        # x = -1 + 4 t lies in [0, 2] for t in [1/4, 3/4]: 21 of the 41 points.
        self.assertEqual(len(rows), 21)
        self.assertEqual(outside, 20)
        np.testing.assert_allclose(rows[:, 4:7], rows[:, 1:4] @ A.T + [1.0, -2.0, 0.5], atol=1e-12)
        np.testing.assert_allclose(rows[:, 7:], np.tile(np.arange(6.0), (21, 1)))
        np.testing.assert_allclose(rows[:, 0], np.linalg.norm(rows[:, 1:4] - [-1, 0.3, 0.7], axis=1),
                                   atol=1e-12)

    def test_quadratic_field_on_quadratic_tetrahedra(self):
        X, tets = quadratic(*kuhn_cube())
        f = X[:, 0] ** 2 - X[:, 1] * X[:, 2] + 3.0
        _, rows, outside = lines.sample(X, tets, {"f": f}, {}, [0.1, 0.2, 0.3], [1.9, 1.7, 1.3], 25)
        rows = np.array(rows)
        self.assertEqual(outside, 0)
        np.testing.assert_allclose(rows[:, 4], rows[:, 1] ** 2 - rows[:, 2] * rows[:, 3] + 3.0,
                                   atol=1e-12)

    def test_cell_field_is_the_holding_cells(self):
        X, tets = kuhn_cube()
        centre_x = X[tets].mean(axis=1)[:, 0]
        _, rows, _ = lines.sample(X, tets, {}, {"c": centre_x}, [0.05, 1.0, 1.0], [1.95, 1.0, 1.0], 9)
        for row in rows:
            holding = [k for k, t in enumerate(tets) if lines.locate_in_tetrahedra(
                X, tets[[k]], np.array(row[1:4])) is not None]
            self.assertIn(row[4], centre_x[holding])

    def test_shell_triangles_take_points_near_their_plane(self):
        X = np.array([[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0]], dtype=float)
        triangles = np.array([[0, 1, 2], [0, 2, 3]])
        u = np.column_stack([X[:, 0], np.zeros(4), 0.5 * X[:, 1]])
        _, rows, outside = lines.sample(X, triangles, {"displacement": u}, {"thickness": [0.2, 0.3]},
                                        [0.25, 1.0, 0.01], [3.25, 1.0, 0.01], 7)
        rows = np.array(rows)
        self.assertEqual(outside, 0)
        np.testing.assert_allclose(rows[:, 4], rows[:, 1], atol=1e-12)
        np.testing.assert_allclose(rows[:, 6], 0.5 * rows[:, 2], atol=1e-12)
        # Below the diagonal x = y the first triangle, above it the second.
        np.testing.assert_array_equal(rows[:, 7], np.where(rows[:, 1] > 1.0, 0.2, 0.3))
        _, far, outside = lines.sample(X, triangles, {"displacement": u}, {}, [0, 1, 5], [4, 1, 5], 5)
        self.assertEqual((len(far), outside), (0, 5))


def sheet(length=50.0, width=10.0, nx=100, ny=4):
    """A flat shell sheet in the x-y plane: points and triangles."""
    x, y = np.meshgrid(np.linspace(0.0, length, nx + 1), np.linspace(0.0, width, ny + 1))
    points = np.column_stack([x.ravel(), y.ravel(), np.zeros(x.size)])
    triangles = []
    for j in range(ny):
        for i in range(nx):
            a = j * (nx + 1) + i
            triangles += [[a, a + 1, a + nx + 2], [a, a + nx + 2, a + nx + 1]]
    return points, np.array(triangles)


class WavesTest(unittest.TestCase):
    """lines.waves on a sheet 50 mm long bent by 0.01 x^2 and wrinkled by 0.2 sin(2 pi 5 x / 50):
    along its length 5 waves of wavelength 10 mm stand out, 0.4 mm peak to peak within 4 %
    (measured -3.0 %: the samples see the sine through linear triangles of 0.5 mm, whose first
    harmonic is sinc^2(pi h / lambda) = 0.992 of it, and the quadratic fit that takes out the bend
    takes a share of the sine too); bent alone, no count stands out (the largest of 3 or more is
    1e-6 mm)."""

    def measure(self, w):
        X, triangles = sheet()
        u = np.column_stack([0 * X[:, 0], 0 * X[:, 0], w(X[:, 0])])
        header, rows, outside = lines.sample(X, triangles, {"displacement": u}, {}, [0, 5, 0],
                                             [50, 5, 0], 201)
        self.assertEqual(outside, 0)
        rows = np.array(rows)
        return lines.waves(rows[:, 0], rows[:, 1:4] + rows[:, 4:7])

    def test_wrinkled_sheet(self):
        count, wavelength, amplitude, peak, spectrum = self.measure(
            lambda x: 0.01 * x**2 + 0.2 * np.sin(2 * np.pi * 5 * x / 50.0))
        self.assertEqual(count, 5)
        self.assertAlmostEqual(wavelength, 10.0, places=12)
        self.assertAlmostEqual(amplitude, 0.4, delta=0.04 * 0.4)
        self.assertTrue(peak)
        self.assertEqual(spectrum[4][:2], (5, 10.0))

    def test_bent_sheet_has_no_waves(self):
        count, _, amplitude, peak, _ = self.measure(lambda x: 0.01 * x**2)
        self.assertFalse(peak)
        self.assertLess(amplitude, 1e-3)


class LineCommandTest(CommandLineTest):
    """plot.py --line on a run of two written steps: line.csv of the last one (or --step's)."""

    def setUp(self):
        super().setUp()
        X, tets = kuhn_cube()
        states = [(X, tets, {"displacement": 0.0 * X}, {"von_mises": np.zeros(len(tets))}),
                  (X, tets, {"displacement": 0.1 * X}, {"von_mises": np.ones(len(tets))})]
        fx.write_steps(self.run, states)
        fx.write_summary(self.run, {"steps": 4, "nodes": len(X)})

    def read_line(self):
        with open(os.path.join(self.out, "line.csv")) as f:
            header = f.readline().strip().split(",")
            return header, np.loadtxt(f, delimiter=",", ndmin=2)

    def test_last_step_along_the_line(self):
        p = self.plot("--line", "0,1,1:2,1,1", "--points", "11")
        self.assertEqual(p.returncode, 0, p.stderr)
        self.assertEqual(sorted(os.listdir(self.out)), ["line.csv", "line.png", "line_spectrum.csv"])
        header, data = self.read_line()
        self.assertEqual(data.shape, (11, len(header)))
        np.testing.assert_allclose(data[:, header.index("displacement_x")], 0.1 * data[:, 1],
                                   atol=1e-12)
        np.testing.assert_allclose(data[:, header.index("von_mises")], 1.0)

    def test_chosen_step(self):
        p = self.plot("--line", "0,1,1:2,1,1", "--points", "5", "--step", "0")
        self.assertEqual(p.returncode, 0, p.stderr)
        header, data = self.read_line()
        np.testing.assert_allclose(data[:, header.index("von_mises")], 0.0)

    def test_refusals(self):
        for args, message in ((("--line", "0,1,1:2,1"), "six numbers"),
                              (("--line", "1,1,1:1,1,1"), "the same point"),
                              (("--line", "5,5,5:6,6,6"), "none of its 200 points lies in the body"),
                              (("--line", "0,1,1:2,1,1", "--step", "3"), "--step 3: no such step"),
                              (("--line", "0,1,1:2,1,1", "--y", "time"), "one or the other")):
            p = self.plot(*args)
            self.assertEqual(p.returncode, 2, args)
            self.assertIn(message, p.stderr)


if __name__ == "__main__":
    unittest.main()
