"""Writes a step file whose zlib-compressed arrays inflate to gigabytes: a VTU in plisse's format
(header_type UInt64, vtkZLibDataCompressor, appended raw data) of 2^28 points and one cell, its
point arrays runs of zeros that deflate about 700 times. For tests/regression: a reader must refuse
it from its header, before it inflates anything.

Usage: /usr/bin/python3 vtu_zlib_bomb.py OUT.vtu
"""
import struct
import sys
import zlib

N_POINTS = 1 << 28
BLOCK = 1 << 15


def compressed(n_bytes):
    """plisse's block layout: [blocks, block size, last block size or 0, sizes...] then blocks."""
    full, last = divmod(n_bytes, BLOCK)
    zero_block = zlib.compress(bytes(BLOCK), 9)
    blocks = [zero_block] * full + ([zlib.compress(bytes(last), 9)] if last else [])
    head = struct.pack("<QQQ", len(blocks), BLOCK, last) + b"".join(
        struct.pack("<Q", len(b)) for b in blocks)
    return head + b"".join(blocks)


def main(out):
    arrays = [  # (section, type, name, components, bytes)
        ("PointData", "Float64", "displacement", 3, N_POINTS * 24),
        ("CellData", "Float64", "cauchy_stress", 6, 48),
        ("CellData", "Float64", "J", 1, 8),
        ("Points", "Float64", "Points", 3, N_POINTS * 24),
        ("Cells", "Int64", "connectivity", 1, 32),
        ("Cells", "Int64", "offsets", 1, 8),
        ("Cells", "UInt8", "types", 1, 1),
    ]
    data, tags, offset = [], {}, 0
    for section, kind, name, components, n_bytes in arrays:
        block = compressed(n_bytes)
        tags.setdefault(section, []).append(
            f'<DataArray type="{kind}" Name="{name}" NumberOfComponents="{components}" '
            f'format="appended" offset="{offset}"/>')
        data.append(block)
        offset += len(block)
    xml = ('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0" '
           'byte_order="LittleEndian" header_type="UInt64" compressor="vtkZLibDataCompressor">\n'
           f'<UnstructuredGrid>\n<Piece NumberOfPoints="{N_POINTS}" NumberOfCells="1">\n')
    for section in ("PointData", "CellData", "Points", "Cells"):
        xml += f"<{section}>\n" + "\n".join(tags[section]) + f"\n</{section}>\n"
    xml += '</Piece>\n</UnstructuredGrid>\n<AppendedData encoding="raw">\n_'
    with open(out, "wb") as f:
        f.write(xml.encode())
        for block in data:
            f.write(block)
        f.write(b"\n</AppendedData>\n</VTKFile>\n")


if __name__ == "__main__":
    main(sys.argv[1])
