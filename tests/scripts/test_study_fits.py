"""Unit tests of plisse_study.fits: brackets and slopes on logarithmic axes, by hand."""
import math
import unittest

import numpy as np

import study_fixtures  # noqa: F401  (scripts/ on the import path)
from plisse_study import fits


class FitsTest(unittest.TestCase):
    def test_bracket_and_middle(self):
        values = np.array([1.0, 2.0, 4.0])
        self.assertEqual(fits.bracket(values, 0), (0.0, 1.0))  # before the first step: 0
        self.assertEqual(fits.bracket(values, 2), (2.0, 4.0))
        self.assertIsInstance(fits.bracket(values, 1)[0], float)
        self.assertEqual(fits.middle((2.0, 4.0)), 3.0)

    def test_log_slope_of_a_power_law(self):
        points = [(x, 3.0 * x**1.5) for x in (1.0, 2.0, 4.0, 8.0)]
        self.assertAlmostEqual(fits.log_slope(points), 1.5, places=12)
        # Two points: the slope through them, log(10/2) / log(5/1) = 1.
        self.assertAlmostEqual(fits.log_slope([(1.0, 2.0), (5.0, 10.0)]), 1.0, places=12)
        # Least squares over (1, 1), (2, 2), (4, 8): log y = (0, 1, 3) log 2 against
        # log x = (0, 1, 2) log 2: slope sum (x - 1)(y - 4/3) / sum (x - 1)^2 = 3 / 2.
        self.assertAlmostEqual(fits.log_slope([(1.0, 1.0), (2.0, 2.0), (4.0, 8.0)]), 1.5,
                               places=12)

    def test_local_slopes(self):
        # Sorted by x; the pair of equal x is left out.
        slopes = fits.local_slopes([(4.0, 16.0), (1.0, 1.0), (2.0, 4.0), (2.0, 5.0)])
        self.assertEqual([(a, b) for a, b, _ in slopes], [(1.0, 2.0), (2.0, 4.0)])
        self.assertAlmostEqual(slopes[0][2], 2.0, places=12)
        self.assertAlmostEqual(slopes[1][2], math.log(16.0 / 5.0) / math.log(2.0), places=12)


if __name__ == "__main__":
    unittest.main()
