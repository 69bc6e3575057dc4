"""Unit tests of scripts/plot.py (`plisse plot`): the figure of chosen columns (--x, --y) draws
exactly those columns, with their units; moments.png draws each cap's largest moment component;
a column the history lacks, or --x without --y, is refused with exit status 2."""
import os
import subprocess
import sys
import tempfile
import unittest

import numpy as np

import study_fixtures as fx
import plot
from plisse_study import runs

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


if __name__ == "__main__":
    unittest.main()
