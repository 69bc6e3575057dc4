#!/usr/bin/python3
"""Independent reader for the plisse output tests (tests/unit/output).

Reads a file written by plisse with third-party code and prints what it found as JSON on stdout,
so the C++ test can compare numbers exactly. Every real number is printed as float.hex(), which
round-trips bit for bit (also -0.0, subnormals, inf and nan).

Usage: /usr/bin/python3 read_output.py vtu|pvd|csv PATH
  vtu: meshio.read()        -> points, cells (meshio type name, connectivity), point/cell data
  pvd: xml.etree parse      -> root attributes and the DataSet entries
  csv: the csv module       -> header and rows
"""
import csv
import json
import sys
import xml.etree.ElementTree as ET


def hexes(array):
    """Nested lists of float.hex strings for a numpy array (any shape)."""
    if array.ndim == 0:
        return float(array).hex()
    return [hexes(a) for a in array]


def read_vtu(path):
    import meshio

    mesh = meshio.read(path, file_format="vtu")
    return {
        "points_dtype": str(mesh.points.dtype),
        "points": hexes(mesh.points),
        "cells": [{"type": block.type, "data": block.data.tolist()} for block in mesh.cells],
        "point_data": {name: hexes(values) for name, values in mesh.point_data.items()},
        "cell_data": {
            name: [hexes(block) for block in blocks] for name, blocks in mesh.cell_data.items()
        },
    }


def read_pvd(path):
    root = ET.parse(path).getroot()
    datasets = [
        {"timestep": float(d.get("timestep")).hex(), "file": d.get("file")}
        for d in root.iter("DataSet")
    ]
    return {"tag": root.tag, "type": root.get("type"), "datasets": datasets}


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return {"header": rows[0], "rows": [[float(x).hex() for x in row] for row in rows[1:]]}


if __name__ == "__main__":
    kind, path = sys.argv[1], sys.argv[2]
    reader = {"vtu": read_vtu, "pvd": read_pvd, "csv": read_csv}[kind]
    json.dump(reader(path), sys.stdout)
