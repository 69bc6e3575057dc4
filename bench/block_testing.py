"""What the unit tests of bench/'s generated blocks share: the first line of a block rendered from
measurements marked as taken with uncommitted changes and on a loaded machine."""
import copy


def provenance_line(render_block, measurements, load=(0.9, 1.1)):
    """The first line of render_block(m), m the measurements with local_changes set and the load
    average `load` (when the run began, when it ended)."""
    m = copy.deepcopy(measurements)
    m["local_changes"] = True
    m["load_average"] = list(load)
    return render_block(m).splitlines()[0]
