"""Unit tests of scripts/validate.py: the generated tables of docs/validation.md and their checks.

Run by CTest (label unit) with Debian's python3; needs no build and runs no plisse.
"""
import json
import os
import sys
import tempfile
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "scripts"))
import validate  # noqa: E402


def claim(row, measured, reference, low, high, kind="validation", difference="relative",
          test="Suite.Test"):
    d = measured / reference - 1 if difference == "relative" else measured - reference
    return {"row": row, "subject": "a sheet", "quantity": "q", "mesh": "h = 1", "measured": measured,
            "reference": reference, "source": "Someone 2001", "difference_kind": difference,
            "difference": d, "low": low, "high": high, "why": "because", "kind": kind,
            "held": low <= d <= high, "test": test}


def record(claims, tests=None):
    return {"tier": "ci", "command": "scripts/validate --tier ci", "commit": "abc1234",
            "date": "2026-01-01", "jobs": 2, "seconds": 90.0,
            "tests": tests or {"Suite.Test": {"seconds": 90.0, "status": "passed"}},
            "claims": claims}


class Page(unittest.TestCase):
    """A page and a record in a temporary folder, in place of docs/."""

    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        root = Path(self.folder.name)
        self.page = root / "validation.md"
        self.records = root / "records"
        self.saved = (validate.PAGES, validate.RECORDS, validate.ROOT)
        # The check lists the tiers from the build it is pointed at; this folder has none, so the
        # result does not depend on which build runs these tests (the sanitizer build has no tiers).
        self.saved_build = os.environ.get("PLISSE_BUILD_DIR")
        os.environ["PLISSE_BUILD_DIR"] = str(root / "build")
        validate.PAGES, validate.RECORDS, validate.ROOT = [self.page], self.records, root

    def tearDown(self):
        validate.PAGES, validate.RECORDS, validate.ROOT = self.saved
        if self.saved_build is None:
            os.environ.pop("PLISSE_BUILD_DIR", None)
        else:
            os.environ["PLISSE_BUILD_DIR"] = self.saved_build
        self.folder.cleanup()

    def write(self, text, ci=None):
        self.page.write_text(text)
        if ci is not None:
            self.records.mkdir(exist_ok=True)
            (self.records / "ci.json").write_text(json.dumps(ci))

    def blocks(self):
        return "\n\n".join("\n".join(validate.markers(t)) for t in validate.TIERS)


class TablesTest(Page):
    def test_update_writes_the_rows_and_check_then_passes(self):
        self.write("# page\n\n" + self.blocks() + "\n",
                   record([claim("a/b", 0.97, 1.0, -0.04, -0.02)]))
        self.assertEqual(validate.check(), 1, "the page still has the empty blocks")
        validate.update()
        text = self.page.read_text()
        self.assertIn("| a sheet | q | 0.97 | 1 (Someone 2001) | -3.00 % | [-4, -2] %", text)
        self.assertIn("abc1234", text)
        self.assertIn("Not run yet", text, "the full tier has no record")
        self.assertEqual(validate.check(), 0)

    def test_a_hand_edited_number_fails_the_check(self):
        self.write("# page\n\n" + self.blocks() + "\n",
                   record([claim("a/b", 0.97, 1.0, -0.04, -0.02)]))
        validate.update()
        self.page.write_text(self.page.read_text().replace("0.97 |", "0.98 |"))
        self.assertEqual(validate.check(), 1)

    def test_a_table_row_outside_the_blocks_fails_the_check(self):
        self.write("# page\n\n| a | b |\n|---|---|\n| 1 | 2 |\n\n" + self.blocks() + "\n",
                   record([claim("a/b", 0.97, 1.0, -0.04, -0.02)]))
        validate.update()
        self.assertEqual(validate.rows_outside_blocks(self.page.read_text()), [3, 4, 5])
        self.assertEqual(validate.check(), 1)

    def test_a_row_without_its_test_fails_the_check(self):
        self.write("# page\n\n" + self.blocks() + "\n",
                   record([claim("a/b", 0.97, 1.0, -0.04, -0.02, test="Gone.Test")]))
        validate.update()
        self.assertEqual(validate.check(), 1)

    def test_only_a_build_of_the_slow_tests_can_list_the_tiers(self):
        build = Path(self.folder.name) / "build"
        self.assertFalse(validate.builds_the_tiers(build), "no build at all")
        build.mkdir()
        (build / "CTestTestfile.cmake").write_text("")
        (build / "CMakeCache.txt").write_text("PLISSE_SLOW_TESTS:BOOL=OFF\n")
        self.assertFalse(validate.builds_the_tiers(build), "the sanitizer build registers no tier")
        (build / "CMakeCache.txt").write_text("PLISSE_SLOW_TESTS:BOOL=ON\n")
        self.assertTrue(validate.builds_the_tiers(build))

    def test_a_partial_run_drops_the_rows_of_a_test_no_longer_in_the_tier(self):
        old = record([claim("a/b", 0.97, 1.0, -0.04, -0.02, test="Suite.Renamed"),
                      claim("a/c", 0.97, 1.0, -0.04, -0.02, test="Suite.Kept"),
                      claim("a/d", 0.97, 1.0, -0.04, -0.02, test="Suite.Run")],
                     tests={name: {"seconds": 9.0, "status": "passed"}
                            for name in ("Suite.Renamed", "Suite.Kept", "Suite.Run")})
        current = {"Suite.Kept": 1, "Suite.Run": 1, "Suite.NewName": 1}
        self.assertEqual(validate.gone(old, current), ["Suite.Renamed"])
        ran = {"Suite.Run": {"seconds": 5.0, "status": "passed"},
               "Suite.NewName": {"seconds": 7.0, "status": "passed"}}
        fresh = [claim("a/d", 0.98, 1.0, -0.04, -0.02, test="Suite.Run"),
                 claim("a/b", 0.97, 1.0, -0.04, -0.02, test="Suite.NewName")]
        tests, claims = validate.merged(old, ran, fresh, current)
        self.assertEqual(sorted(tests), ["Suite.Kept", "Suite.NewName", "Suite.Run"])
        self.assertEqual(tests["Suite.Run"]["seconds"], 5.0)
        self.assertEqual(sorted((c["row"], c["test"]) for c in claims),
                         [("a/b", "Suite.NewName"), ("a/c", "Suite.Kept"), ("a/d", "Suite.Run")])

    def test_a_failed_claim_and_a_regression_guard_are_marked_so(self):
        self.write("# page\n\n" + self.blocks() + "\n",
                   record([claim("a/b", 0.95, 1.0, -0.04, -0.02),
                           claim("a/c", 3.0, 3.1, -0.2, 0.2, kind="regression",
                                 difference="absolute")]))
        validate.update()
        text = self.page.read_text()
        self.assertIn("-5.00 % **failed**", text)
        self.assertLess(text.index("Against published results"), text.index("Regression guards"))
        self.assertIn("| -0.1 | [-0.2, +0.2]", text)

    def test_a_partial_run_says_which_tests_it_ran(self):
        partial = record([claim("a/b", 0.97, 1.0, -0.04, -0.02)])
        partial["regex"] = "Sheet"
        self.write("# page\n\n" + self.blocks() + "\n", partial)
        validate.update()
        self.assertIn("ran the tests matching `Sheet` in 1.5 minutes", self.page.read_text())

    def test_a_share_says_which_share_it_ran(self):
        partial = record([claim("a/b", 0.97, 1.0, -0.04, -0.02)])
        partial["share"] = "2/4"
        self.write("# page\n\n" + self.blocks() + "\n", partial)
        validate.update()
        self.assertIn("ran share 2 of 4 of the tier's tests in 1.5 minutes", self.page.read_text())

    def test_markers_out_of_order_are_refused(self):
        begin, end = validate.markers("ci")
        self.write(f"{end}\n{begin}\n", record([]))
        with self.assertRaises(SystemExit):
            validate.update()


class SharesTest(unittest.TestCase):
    """--share K/N: the tier's tests in N lists of about equal cost."""

    def test_every_test_lands_in_exactly_one_share(self):
        tests = {f"T.{c}": 1 for c in "abcdefghij"}
        seconds = {t: 10.0 * (i + 1) for i, t in enumerate(sorted(tests))}
        split = validate.shares(tests, seconds, 4)
        self.assertEqual(sorted(t for share in split for t in share), sorted(tests))
        self.assertEqual(len(split), 4)

    def test_costs_are_balanced_longest_first(self):
        # Costs 60, 50, 40, 30, 20, 10 in 2 shares: longest first into the lighter share gives
        # {60, 30, 20} and {50, 40, 10}, 110 and 100 (a split by name alone gives 120 and 90).
        tests = {f"T.{c}": 1 for c in "abcdef"}
        seconds = dict(zip(sorted(tests), [60.0, 50.0, 40.0, 30.0, 20.0, 10.0]))
        split = validate.shares(tests, seconds, 2)
        self.assertEqual(split, [["T.a", "T.d", "T.e"], ["T.b", "T.c", "T.f"]])

    def test_a_test_on_two_processors_weighs_twice(self):
        tests = {"T.wide": 2, "T.x": 1, "T.y": 1}
        seconds = {"T.wide": 50.0, "T.x": 60.0, "T.y": 45.0}
        self.assertEqual(validate.shares(tests, seconds, 2), [["T.wide"], ["T.x", "T.y"]])

    def test_a_test_without_a_recorded_time_weighs_the_mean(self):
        tests = {"T.new": 1, "T.x": 1, "T.y": 1}
        seconds = {"T.x": 100.0, "T.y": 20.0}
        # T.new weighs 60: after T.x (100) it goes to the empty share, then T.y joins it.
        self.assertEqual(validate.shares(tests, seconds, 2), [["T.x"], ["T.new", "T.y"]])

    def test_the_split_does_not_depend_on_the_listing_order(self):
        tests = {f"T.{c}": 1 for c in "abcdefg"}
        seconds = {t: 30.0 for t in tests}
        reverse = dict(reversed(list(tests.items())))
        self.assertEqual(validate.shares(tests, seconds, 3), validate.shares(reverse, seconds, 3))


class ThenOthersTest(unittest.TestCase):
    """--share K/N --then-others MINUTES: the day's share, then the others that fit."""

    def plan(self, costs, first_takes, others_take=None):
        """Runs run_then_others on share 1 of len(costs), with shares of the recorded `costs`
        [processor-seconds], a first share that takes `first_takes` wall seconds and others that
        take `others_take` (default: their cost at the first one's pace); returns the regexes
        run after the first and the exit status."""
        clock = [0.0]
        pace = first_takes / costs[0]
        plan = [[f"T.s{i}"] for i in range(len(costs))]
        ran = []

        def fake_run(tier, regex, jobs, share=None):
            if share:
                clock[0] += first_takes
            else:
                ran.append(regex)
                index = int(regex[len("^(T\\.s"):-2])
                clock[0] += others_take if others_take is not None else costs[index] * pace
            return 1 if regex == "^(T\\.s2)$" else 0

        names = ("run", "planned_shares", "read_record", "record_path", "update")
        saved = [getattr(validate, name) for name in names] + [validate.subprocess.run,
                                                               validate.time.monotonic]
        tmp = tempfile.TemporaryDirectory()
        self.joined = Path(tmp.name) / "ci.json"  # the record the runs leave together
        validate.run = fake_run
        validate.planned_shares = lambda build, tier, n: (plan, costs)
        validate.read_record = lambda tier: record([])
        validate.record_path = lambda tier: self.joined
        validate.update = lambda: None
        validate.subprocess.run = lambda *a, **k: None
        validate.time.monotonic = lambda: clock[0]
        try:
            status = validate.run_then_others("ci", 2, (1, len(costs)), 15)
        finally:
            for name, value in zip(names, saved):
                setattr(validate, name, value)
            validate.subprocess.run, validate.time.monotonic = saved[-2:]
            tmp_record = json.loads(self.joined.read_text()) if self.joined.exists() else None
            tmp.cleanup()
        self.joined = tmp_record
        return ran, status

    def test_the_other_share_runs_when_it_fits_with_its_margin(self):
        # 300 s for a share of cost 600: the other one (600) expected 300 s, 375 with the margin,
        # within the 600 s left of 15 minutes. The record then holds both runs as the whole tier.
        self.assertEqual(self.plan([600.0, 600.0], 300.0), (["^(T\\.s1)$"], 0))
        self.assertEqual((self.joined["command"], self.joined["regex"], self.joined["seconds"]),
                         ("scripts/validate --tier ci --share 1/2 --then-others 15", None, 600.0))

    def test_a_share_alone_leaves_its_own_record(self):
        self.assertEqual(self.plan([600.0, 600.0], 401.0), ([], 0))
        self.assertIsNone(self.joined)

    def test_some_of_three_shares_record_the_tests_they_ran(self):
        self.plan([100.0, 500.0, 300.0], 100.0)
        self.assertEqual(self.joined["regex"], "^(T\\.s0|T\\.s1)$")

    def test_the_other_share_is_left_out_when_its_margin_does_not_fit(self):
        # 400 s for the first: the other expects 400 s, 500 with the margin, and 500 are left:
        # it runs. After 401 s it expects 501.25 with 499 left and is left out.
        self.assertEqual(self.plan([600.0, 600.0], 400.0)[0], ["^(T\\.s1)$"])
        self.assertEqual(self.plan([600.0, 600.0], 401.0)[0], [])

    def test_the_pace_scales_each_shares_own_cost(self):
        # The first share (cost 100) took 100 s: the second (cost 500) expects 500 s, 625 with
        # its margin, within the 800 s left: it runs and ends at 600 s. The third (cost 300)
        # then expects 375 s with 300 left and is left out.
        ran, _ = self.plan([100.0, 500.0, 300.0], 100.0)
        self.assertEqual(ran, ["^(T\\.s1)$"])

    def test_a_failing_other_share_fails_the_whole(self):
        ran, status = self.plan([100.0, 100.0, 100.0], 60.0)
        self.assertEqual(ran, ["^(T\\.s1)$", "^(T\\.s2)$"])
        self.assertEqual(status, 1)


class JoinedRecordTest(unittest.TestCase):
    def test_the_runs_together_read_as_the_whole_tier(self):
        last = record([claim("r", 1.0, 1.0, -0.1, 0.1)])
        last.update(regex="^(T\\.b)$", share=None, seconds=300.0)
        joined = validate.joined_record(last, "scripts/validate --tier ci --share 1/2 "
                                        "--then-others 15", 612.34, None)
        self.assertEqual((joined["regex"], joined["share"], joined["seconds"]), (None, None, 612.3))
        self.assertEqual(joined["claims"], last["claims"])
        text = validate.block_text("ci", joined)
        self.assertIn("`scripts/validate --tier ci --share 1/2 --then-others 15` at commit abc1234",
                      text)
        self.assertIn("1 test in 10.2 minutes", text)


class NumbersTest(unittest.TestCase):
    def test_numbers_keep_four_digits_and_small_ones_an_exponent(self):
        self.assertEqual(validate.number(0.93512), "0.9351")
        self.assertEqual(validate.number(3.48e-5), "3.480e-05")
        self.assertEqual(validate.number(-0.24), "-0.24")
        self.assertEqual(validate.difference_text("relative", -0.0296), "-2.96 %")
        self.assertEqual(validate.band_text("absolute", -0.03, 0.03), "[-0.03, +0.03]")
        self.assertEqual(validate.band_text("absolute", 1e-9, 0.015), "[+0, +0.015]")
        self.assertEqual(validate.band_text("relative", -0.0025, 0.0948276), "[-0.25, +9.48] %")


if __name__ == "__main__":
    unittest.main()
