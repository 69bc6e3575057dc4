"""Unit tests of scripts/airbag_full_size.py: Paulsen's Mylar balloon against its own profile
integrated independently, the seam's fold count, large folds and total depth on synthetic seams,
and the table over seeds."""
import math
import sys
import unittest
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
import airbag_full_size as bag  # noqa: E402


class PaulsenTest(unittest.TestCase):
    def test_the_closed_forms_agree_with_the_profile(self):
        a, h, volume = bag.paulsen(350.0)
        self.assertAlmostEqual(350.0 / a, 1.3110287771, places=9)  # Paulsen's r / a
        self.assertAlmostEqual(h / a, 0.5990701174, places=9)
        x, z = bag.paulsen_profile(350.0, n=2000)
        self.assertAlmostEqual(z[-1], h, delta=1e-3 * h)  # the crown, at x = 0
        self.assertEqual(z[0], 0.0)  # the rim
        # The meridian's length is the disc's radius, and the volume 2 pi int x z dx, twice.
        length = np.sum(np.hypot(np.diff(x), np.diff(z)))
        self.assertAlmostEqual(length / 350.0, 1.0, delta=2e-3)
        order = np.argsort(x)
        both = 2.0 * 2.0 * math.pi * np.trapz(x[order] * z[order], x[order])
        self.assertAlmostEqual(both / volume, 1.0, delta=2e-3)


class FoldsTest(unittest.TestCase):
    def test_counts_the_maxima_that_rise_above_their_neighbours(self):
        angle = np.linspace(0.0, 0.5 * math.pi, 401)
        r = 270.0 + 2.0 * np.cos(12 * angle)  # 3 interior maxima in the quarter, 4 mm deep
        peaks, rises = bag.folds(r, 0.35)
        self.assertEqual(len(peaks), 2)  # the ends are not maxima: 2 interior crests at 30, 60 deg
        for rise in rises:
            self.assertAlmostEqual(rise, 4.0, delta=1e-3)

    def test_a_ripple_below_the_prominence_is_no_fold(self):
        angle = np.linspace(0.0, 0.5 * math.pi, 401)
        r = 270.0 + 0.1 * np.cos(40 * angle) - 10.0 * np.exp(-((angle - 0.7) / 0.05) ** 2)
        peaks, rises = bag.folds(r, 0.35)
        self.assertEqual(len(peaks), 0)  # the deep fold is a minimum; the ripple is 0.2 mm

    def test_the_large_folds_are_those_within_a_fifth_of_the_deepest(self):
        # 20 mm deepest: a fifth is 4 mm, so 4.0 counts and 3.9 does not; their mean is
        # (20 + 10 + 4) / 3.
        deepest, large = bag.large_folds([3.9, 20.0, 1.0, 10.0, 4.0])
        self.assertEqual(deepest, 20.0)
        self.assertEqual(large, [20.0, 10.0, 4.0])
        self.assertEqual(bag.large_folds([]), (0.0, []))

    def test_the_total_depth_sums_every_folds_rise_over_the_full_circle(self):
        # Three crests in the quarter between minima at 270: rises 4, 9 and 1 mm, the middle one
        # between the other two; the full circle has four such quarters: 4 (4 + 9 + 1) = 56 mm.
        r = np.array([270.0, 274.0, 270.0, 279.0, 270.0, 271.0, 270.0])
        peaks, rises = bag.folds(r, 0.35)
        self.assertEqual(sorted(rises), [1.0, 4.0, 9.0])
        self.assertAlmostEqual(4.0 * sum(rises), 56.0, places=12)


class EnsembleTest(unittest.TestCase):
    def test_one_row_a_mesh_with_the_median_and_the_range_over_its_seeds(self):
        def row(unknowns, seed, folds, total):
            return {"unknowns": unknowns, "seed": seed, "folds": folds, "depth [mm]": 20.0,
                    "large folds": 16, "large folds' depth [mm]": 12.0, "total depth [mm]": total,
                    "reach [mm]": 35.0}

        table = bag.ensemble([row(100, 1, 60, 330.0), row(200, 1, 64, 354.0),
                              row(100, 2, 56, 334.0), row(100, 3, 48, 333.0)])
        self.assertEqual([t["unknowns"] for t in table], [100, 200])
        self.assertEqual(table[0]["seeds"], "1,2,3")
        self.assertEqual(table[0]["folds"], (56.0, 48.0, 60.0))
        self.assertEqual(table[0]["total depth [mm]"], (333.0, 330.0, 334.0))
        self.assertEqual(table[1]["total depth [mm]"], (354.0, 354.0, 354.0))

    def test_each_mesh_against_the_next_coarser_one(self):
        def row(unknowns, seed, depth):
            return {"unknowns": unknowns, "seed": seed, "folds": 60, "depth [mm]": depth,
                    "large folds": 16, "large folds' depth [mm]": 12.0, "total depth [mm]": 330.0,
                    "reach [mm]": 35.0}

        # Given finest first: the table still runs coarsest first, and the steps compare
        # neighbours (30 -> 33 is +10 %), not each mesh with the first (20 -> 33 would be +65 %).
        table = bag.ensemble([row(300, 1, 33.0), row(100, 1, 20.0), row(200, 1, 30.0)])
        steps = bag.mesh_steps(table)
        self.assertEqual([(c, f) for c, f, _ in steps], [(100, 200), (200, 300)])
        self.assertAlmostEqual(steps[0][2]["depth [mm]"], 0.5, places=12)
        self.assertAlmostEqual(steps[1][2]["depth [mm]"], 0.1, places=12)
        self.assertEqual(steps[1][2]["total depth [mm]"], 0.0)


if __name__ == "__main__":
    unittest.main()
