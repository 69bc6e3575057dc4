"""What the unit tests of bench/'s generated blocks share: the first line of a block rendered from
measurements marked as taken with uncommitted changes and on a loaded machine, and a page with
two blocks rewritten by one table's update."""
import copy
import tempfile
from pathlib import Path


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
