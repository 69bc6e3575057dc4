"""Unit tests of scripts/verification_report.py's render and check steps on a small record written
by hand (one row per table): the page is a function of the record alone, the numbers are printed
as the tables print them, and --check fails on a number changed in the page."""
import contextlib
import copy
import io
import json
import os
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

import study_fixtures  # noqa: F401  (scripts/ on the import path)
import verification_report as vr

RECORD = {
    "command": "scripts/verification-report",
    "commit": "abc1234",
    "date": "2024-01-02",
    "run_time_seconds": 1860.0,
    "tables": {
        "cube_tension": {"tolerance": 1e-10, "rows": [
            {"run": "cube-tension-fung", "case": "cube-tension-fung", "element": "mini",
             "material": {"model": "fung", "mu": 0.5, "gamma": 0.1}, "steps": 20,
             "newton_iterations": 41, "max_relative_error_sigma_zz": 1.2345e-12}]},
        "cube_sticking": {
            "rows": [{"run": "cube-tension-sticking", "divisions": 6, "tetrahedra": 1296,
                      "unknowns": 2000, "steps": 20, "newton_iterations": 90,
                      "die_force": 123.45678, "ratio_to_homogeneous": 1.23456}],
            "homogeneous_force": 100.0, "observed_order": 0.876, "extrapolated_force": 110.126,
            "extrapolated_ratio_to_homogeneous": 1.10126},
        "inelastic_cubes": {"tolerance": 1e-11, "rows": [
            {"run": "cube-cycles-mullins-th", "case": "cube-cycles-mullins",
             "element": "taylor-hood", "steps": 60, "newton_iterations": 180,
             "max_error_over_p_inf": 6.9e-12}]},
        "sphere_inflation": {"rows": [
            {"run": "sphere-inflation-th-2.0-1", "material": "neo-Hookean",
             "element": "taylor-hood", "element_size": 2.0, "layers": 1, "tetrahedra": 498,
             "unknowns": 3276, "max_relative_error_p": 0.01012}]},
        "balloon_limit_point": {
            "run": "balloon-limit-point", "tetrahedra": 3000, "steps": 40,
            "newton_iterations": 120, "plisse": {"stretch": 1.404744, "pressure": 0.0121184},
            "closed_form": {"stretch": 1.404671, "pressure": 0.0120914},
            "thin_membrane_stretch": 7 ** (1 / 6)},
        "balloon_ogden": {"rows": [
            {"run": "balloon-ogden-th", "element_and_mesh": "Taylor-Hood, 1 layer of 3 mm",
             "tetrahedra": 200, "steps": 50, "newton_iterations": 150,
             "max_relative_error_p": 3.456e-05}]},
    },
}


def run_main(args):
    """verification_report.main(args) -> (exit status, what it printed on stderr)."""
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        status = vr.main(args)
    return status, err.getvalue()


class RenderTest(unittest.TestCase):
    def test_render_prints_the_record_as_the_tables_print_it(self):
        page = vr.render(RECORD)
        self.assertIn("Last run: commit abc1234, 2024-01-02, run time 31 min;", page)
        self.assertIn("| `cube-tension-fung` | mini | fung (mu = 0.5 MPa, gamma = 0.1) | 20 | 41 | "
                      "1.23e-12 |", page)
        self.assertIn("asserts every error below 1e-10,", page)
        self.assertIn("| 6 | 1296 | 2000 | 20 | 90 | 123.4568 | 1.2346 |", page)
        self.assertIn("Homogeneous closed form at λ = 5: 100.0000 N.", page)
        self.assertIn("under halving of h: 0.88;", page)
        self.assertIn("meshes: 110.13 N (1.101 times", page)
        self.assertIn("| `cube-cycles-mullins` | taylor-hood | 60 | 180 | 6.90e-12 |", page)
        self.assertIn("below 1e-11 P∞(λ = 2), and, as a", page)
        self.assertIn("| neo-Hookean | taylor-hood | 2.0 | 1 | 498 | 3276 | 0.0101 |", page)
        self.assertIn("| 1.40474 | 0.012118 |", page)
        self.assertIn("| closed form, thick wall | 1.40467 | 0.012091 |", page)
        self.assertIn("| thin-membrane limit 7^(1/6) | 1.38309 | |", page)  # 7^(1/6) = 1.383088
        self.assertIn("(3000 tetrahedra)", page)
        self.assertIn("40 steps, 120 Newton iterations in total.", page)
        self.assertIn("| Taylor-Hood, 1 layer of 3 mm | 200 | 50 | 150 | 3.46e-05 |", page)

    def test_run_time_when_given_and_when_not(self):
        self.assertEqual(vr.run_time_text(None), "not measured")
        self.assertEqual(vr.run_time_text(75), "75 s")
        self.assertEqual(vr.run_time_text(1860.0), "31 min")
        record = copy.deepcopy(RECORD)
        record["run_time_seconds"] = None
        self.assertIn("run time not measured;", vr.render(record))

    def test_render_is_deterministic(self):
        page = vr.render(RECORD)
        self.assertEqual(vr.render(copy.deepcopy(RECORD)), page)
        # Through the file as write_record keeps it: floats come back exactly.
        self.assertEqual(vr.render(json.loads(json.dumps(RECORD, indent=1))), page)

    def test_claim_holds_refuses_an_error_at_or_above_the_tolerance(self):
        vr.claim_holds("cube", 9.9e-11, 1e-10)
        for error in (1e-10, 2e-10, float("nan")):
            with self.assertRaises(SystemExit):
                vr.claim_holds("cube", error, 1e-10)


class CheckTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.docs = Path(self.tmp.name)
        (self.docs / "verification").mkdir()
        (self.docs / "verification" / "record.json").write_text(json.dumps(RECORD, indent=1))
        self.assertEqual(run_main(["--render", str(self.docs)])[0], 0)
        self.page = self.docs / "verification.md"

    def tearDown(self):
        self.tmp.cleanup()

    def test_the_rendered_page_passes(self):
        self.assertEqual(self.page.read_text(), vr.render(RECORD))
        self.assertEqual(run_main(["--check", str(self.docs)]), (0, ""))

    def test_a_number_changed_by_hand_fails(self):
        text = self.page.read_text()
        self.assertEqual(text.count("| 123.4568 |"), 1)
        self.page.write_text(text.replace("| 123.4568 |", "| 123.4569 |"))
        status, message = run_main(["--check", str(self.docs)])
        self.assertEqual(status, 1)
        self.assertIn("is not what", message)
        self.assertIn("+| 6 | 1296 | 2000 | 20 | 90 | 123.4569 | 1.2346 |", message)
        # The command line says so with its exit status.
        done = subprocess.run([sys.executable, vr.__file__, "--check", str(self.docs)],
                              capture_output=True, text=True,
                              env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1"))
        self.assertEqual(done.returncode, 1)
        self.assertIn("123.4569", done.stderr)
        # --render puts the record's number back.
        self.assertEqual(run_main(["--render", str(self.docs)])[0], 0)
        self.assertEqual(run_main(["--check", str(self.docs)])[0], 0)

    def test_a_changed_record_fails_against_the_old_page(self):
        record = copy.deepcopy(RECORD)
        record["tables"]["cube_tension"]["rows"][0]["max_relative_error_sigma_zz"] = 1.2445e-12
        (self.docs / "verification" / "record.json").write_text(json.dumps(record))
        self.assertEqual(run_main(["--check", str(self.docs)])[0], 1)

    def test_a_missing_page_fails(self):
        self.page.unlink()
        self.assertEqual(run_main(["--check", str(self.docs)])[0], 1)


if __name__ == "__main__":
    unittest.main()
