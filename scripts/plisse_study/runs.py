"""Readers of a plisse run directory (docs/architecture.md, "Interface contract"; docs/output.md).

Every reader takes the run directory and leaves what is missing to its caller: an absent file
gives an empty result ({} or []), not an error, so that a study can report a run that failed or
was not run (the readers of history.csv and summary.json raise FileNotFoundError instead when
asked with `required`). Units are the run's (the examples' mm, N, MPa, s).
"""
import csv
import json
import os
import re
import xml.etree.ElementTree as ET

import numpy as np

AXES = {"x": 0, "y": 1, "z": 2}  # an axis name of the case file (output.wrinkles.axis) -> index


def history_columns(path, required=False):
    """Column name -> numpy array of a history.csv file, or {} when the file has no complete row
    or is missing (FileNotFoundError instead with `required`). An empty cell or `nan` is NaN; a
    row of another length than the header is one a killed run left unterminated (or one a running
    run is writing) and is left out."""
    if not required and not os.path.isfile(path):
        return {}
    with open(path) as f:
        rows = list(csv.reader(f))
    if len(rows) < 2:
        return {}
    cols = rows[0]
    data = np.array([[float(x) if x not in ("", "nan") else np.nan for x in r]
                     for r in rows[1:] if len(r) == len(cols)])
    if len(data) == 0:
        return {}
    return {c: data[:, i] for i, c in enumerate(cols)}


def run_name(run):
    """The last part of a run directory's path (`a-50-n15` for runs/a-50-n15/)."""
    return os.path.basename(os.path.normpath(run))


def read_history(run, required=False):
    """The columns of `run`/history.csv (history_columns)."""
    return history_columns(os.path.join(run, "history.csv"), required)


def read_summary(run, required=False):
    """`run`/summary.json as a dict, or {} when the run has none (not finished, or not run;
    FileNotFoundError instead with `required`)."""
    path = os.path.join(run, "summary.json")
    if not required and not os.path.isfile(path):
        return {}
    with open(path) as f:
        return json.load(f)


def largest_ring(summary):
    """The ring of largest amplitude in a summary's wrinkle table, or None."""
    rings = (summary.get("wrinkles") or {}).get("rings", [])
    return max(rings, key=lambda g: g.get("amplitude", 0.0), default=None)


def step_of(path):
    """The step number of a step file's name: 12 for step_0012.vtu or step_0012.pvtu."""
    return int(re.search(r"(\d+)", os.path.basename(path)).group(1))


def written_steps(run, initial=False):
    """(step, path) of the step files listed in `run`/solution.pvd, in the order written; step 0
    (the body before the first step) only with `initial`. [] without solution.pvd."""
    pvd = os.path.join(run, "solution.pvd")
    if not os.path.isfile(pvd):
        return []
    files = [d.get("file") for d in ET.parse(pvd).getroot().iter("DataSet")]
    steps = [(step_of(name), os.path.join(run, name)) for name in files]
    return [(k, path) for k, path in steps if initial or k > 0]


def step_files(run):
    """Paths of all the step files of `run`, step 0 first (written_steps with the initial one)."""
    return [path for _, path in written_steps(run, initial=True)]


def last_vtu(run):
    """Path of the last written step file of `run`, or None."""
    steps = written_steps(run, initial=True)
    return steps[-1][1] if steps else None


def log_instabilities(run):
    """(step, time) of each line of `run`/log.txt that reports a new instability
    ("step N: t = T: new instability, ..."), in order; [] without log.txt."""
    found = []
    path = os.path.join(run, "log.txt")
    if not os.path.isfile(path):
        return found
    with open(path) as f:
        for line in f:
            m = re.search(r"step (\d+): t = ([0-9.eE+-]+)", line)
            if m and "new instability" in line:
                found.append((int(m.group(1)), float(m.group(2))))
    return found


def summary_instabilities(summary):
    """The instabilities of a summary (each with `step`, `time`, `file`), first first."""
    return (summary.get("stability") or {}).get("instabilities", [])


def stable_column(h):
    """Per history row, 1.0 when the state was stable and 0.0 when not, or None when the run did
    not check. A state is unstable with more negative pivots than a stable state has (a state
    with the expected count and a null pivot is singular, not unstable); without those columns,
    the column `stable`."""
    if "negative_pivots" in h and "expected_negative_pivots" in h and len(h["time"]):
        return (h["negative_pivots"] <= h["expected_negative_pivots"]).astype(float)
    return h.get("stable")


def first_unstable_time(h):
    """Time of the first unstable row of the history columns `h`, or None (stable_column)."""
    stable = stable_column(h)
    if stable is None or not len(stable):
        return None
    bad = np.where(stable < 0.5)[0]
    return h["time"][bad[0]] if len(bad) else None


def read_spectrum(run):
    """The rows of `run`/wrinkle_spectrum.csv as dicts of strings (one per ring, harmonic and
    written step), or [] without the file."""
    path = os.path.join(run, "wrinkle_spectrum.csv")
    if not os.path.isfile(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def case_wrinkle_settings(case_path):
    """The `output.wrinkles` map of a case file (axis, center, rings_deg, ...), or {}."""
    import yaml

    with open(case_path) as f:
        c = yaml.safe_load(f)
    return ((c or {}).get("output") or {}).get("wrinkles") or {}


def set_values(summary):
    """key -> value (strings) of the `--set` overrides a run was made with (summary.json's
    `overrides`)."""
    return dict(item.split("=", 1) for item in summary.get("overrides", []) if "=" in item)


def cauchy_tensors(components):
    """(n, 3, 3) symmetric tensors from the (n, 6) components of the VTU field cauchy_stress
    (xx, yy, zz, xy, yz, xz)."""
    return np.asarray(components)[:, [0, 3, 5, 3, 1, 4, 5, 4, 2]].reshape(-1, 3, 3)


VTU_TYPES = {"Float64": "<f8", "Float32": "<f4", "Int64": "<i8", "Int32": "<i4", "UInt8": "u1",
             "UInt64": "<u8", "UInt32": "<u4"}
VTK_CELLS = {5: "triangle", 10: "tetra", 22: "triangle6", 24: "tetra10"}


def read_raw_vtu(path):
    """A step file as plisse writes it (raw appended data, UInt64 headers, zlib-compressed blocks
    or none, one cell type) as a meshio.Mesh; None for any other layout. meshio's own reader of raw
    appended data mixes up arrays when an array's new offset equals another's old one (a run's
    step 6 had its velocity read as its Cauchy stress), so plisse's files are read here."""
    import zlib

    import meshio

    with open(path, "rb") as f:
        raw = f.read()
    start = raw.find(b"<AppendedData")
    if start < 0:
        return None
    begin = raw.index(b"_", raw.index(b">", start)) + 1
    root = ET.fromstring(raw[:start] + b"</VTKFile>")
    if root.get("header_type", "UInt32") != "UInt64" or root.get("byte_order") != "LittleEndian":
        return None
    compressed = root.get("compressor") == "vtkZLibDataCompressor"
    if root.get("compressor") not in (None, "vtkZLibDataCompressor"):
        return None

    def array(tag):
        if tag.get("format") != "appended" or tag.get("type") not in VTU_TYPES:
            raise ValueError(f"{path}: array {tag.get('Name')} is not raw appended data")
        at = begin + int(tag.get("offset"))
        if compressed:
            blocks = int(np.frombuffer(raw, "<u8", 1, at)[0])
            sizes = np.frombuffer(raw, "<u8", blocks, at + 24)
            at += 8 * (3 + blocks)
            data = b""
            for size in sizes:
                data += zlib.decompress(raw[at:at + int(size)])
                at += int(size)
        else:
            size = int(np.frombuffer(raw, "<u8", 1, at)[0])
            data = raw[at + 8:at + 8 + size]
        values = np.frombuffer(data, VTU_TYPES[tag.get("type")])
        n = tag.get("NumberOfComponents")  # as meshio: (n, k) when given, 1 included
        return values if n is None else values.reshape(-1, int(n))

    piece = root.find("UnstructuredGrid/Piece")
    fields = {}
    for kind in ("PointData", "CellData"):
        fields[kind] = {t.get("Name"): array(t) for t in piece.find(kind) or []}
    points = array(piece.find("Points/DataArray"))
    cell_arrays = {t.get("Name"): array(t) for t in piece.find("Cells")}
    types = np.unique(cell_arrays["types"])
    if len(types) != 1 or int(types[0]) not in VTK_CELLS:
        return None
    offsets = cell_arrays["offsets"]
    width = int(offsets[0])
    cells = cell_arrays["connectivity"].reshape(-1, width)
    return meshio.Mesh(points, [(VTK_CELLS[int(types[0])], cells)], point_data=fields["PointData"],
                       cell_data={k: [v] for k, v in fields["CellData"].items()})


class State:
    """One written step: reference points, displacement, the tetrahedra (their corner nodes in
    `corners`, all their nodes in `cells`), point and cell fields (read_raw_vtu for plisse's own
    files, meshio for others)."""

    def __init__(self, path):
        import meshio

        self.path = path
        self.mesh = read_raw_vtu(path) or meshio.read(path)
        self.points = self.mesh.points
        cells = self.mesh.cells_dict
        self.cells = cells.get("tetra10", cells.get("tetra"))
        self.corners = None if self.cells is None else self.cells[:, :4]

    @property
    def displacement(self):
        """Displacement per node, (n, 3)."""
        return self.mesh.point_data["displacement"]

    @property
    def deformed(self):
        """Current positions of the nodes, (n, 3)."""
        return self.points + self.displacement

    def stress(self):
        """Cauchy stress per tetrahedron, (n, 3, 3) (cauchy_tensors)."""
        return cauchy_tensors(self.mesh.cell_data["cauchy_stress"][0])


def read_state(path):
    """The written step at `path` (State)."""
    return State(path)
