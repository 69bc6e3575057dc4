"""What the unit tests of bench/'s generated blocks share: the first line of a block rendered from
measurements marked as taken with uncommitted changes and on a loaded machine, a page with two
blocks rewritten by one table's update, and the checks every benchmark's block gets."""
import copy
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def provenance_line(render_block, measurements, load=(0.9, 1.1)):
    """The first line of render_block(m), m the measurements with local_changes set and the load
    average `load` (when the run began, when it ended)."""
    m = copy.deepcopy(measurements)
    m["local_changes"] = True
    m["load_average"] = list(load)
    return render_block(m).splitlines()[0]


def update_beside_the_peers(update_file, markers, measurements, peer_table):
    """(the block of `markers`, the peers' block, the page) after update_file(page, measurements)
    on a page that holds an old block of `markers` and the peers' block; and the page without any
    block after update_file raised peer_table.BlockError on it (None when it did not)."""
    begin, end = markers
    page = (f"# Title\n\nProse.\n\n{begin}\nold\n{end}\n\n"
            f"{peer_table.BEGIN}\nthe peers' block\n{peer_table.END}\n")
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "page.md"
        path.write_text(page, encoding="utf-8")
        update_file(path, measurements)
        text = path.read_text(encoding="utf-8")
        bare = "# Title\n\nno block here\n"
        path.write_text(bare, encoding="utf-8")
        refused = None
        try:
            update_file(path, measurements)
        except peer_table.BlockError:
            refused = path.read_text(encoding="utf-8")
    return peer_table.read_block(text, markers), peer_table.read_block(text), text, refused


class BlockChecks:
    """The checks of the generated block of a benchmark of bench/ (bench/shell-vs-solid,
    bench/e2e-shell, ...), mixed into a unittest.TestCase that sets: `table` (its table module),
    `measurements` and `expected` (fixed measurements and the block they make) and `record` (the
    name of the benchmark's measurements under docs/performance/)."""

    def test_block_from_fixed_measurements(self):
        self.assertEqual(self.table.render_block(self.measurements), self.expected)

    def test_uncommitted_changes_and_load_are_said(self):
        first = provenance_line(self.table.render_block, self.measurements)
        self.assertIn("at commit abc1234 with uncommitted changes on", first)
        self.assertIn("load average of 0.9 when the run began and 1.1 when it ended", first)

    def test_update_leaves_the_other_blocks_alone(self):
        block, peers, _, refused = update_beside_the_peers(
            self.table.update_file, self.table.MARKERS, self.measurements, self.table.peer_table)
        self.assertEqual(block, self.expected)
        self.assertEqual(peers, "the peers' block\n")
        self.assertEqual(refused, "# Title\n\nno block here\n")

    def test_docs_hold_what_the_last_run_wrote(self):
        page = (ROOT / "docs" / "performance.md").read_text(encoding="utf-8")
        record = ROOT / "docs" / "performance" / f"{self.record}.json"
        self.assertTrue(record.exists(),
                        f"run bench/{self.record} --update docs/performance.md")
        self.assertEqual(self.table.peer_table.read_block(page, self.table.MARKERS),
                         self.table.render_block(self.table.load(record)))
