#!/usr/bin/python3
"""Writes the broken meshes of the bad-input corpus (tests/bad-inputs/README.md) into this folder.

Usage: /usr/bin/python3 make_meshes.py BUILD/bin/plisse
The valid meshes they are cut from come from
`plisse mesh cube --order 1 --edge 2 --divisions 2` (linear: the mesh command's default order is
2); the others are Gmsh 2.2 ASCII written here. Random bytes come from a fixed 64-bit LCG, so the files are the
same on every run.
"""
import os
import subprocess
import sys
import tempfile

os.chdir(os.path.dirname(os.path.abspath(__file__)))
plisse = sys.argv[1]
with tempfile.TemporaryDirectory() as tmp:
    def cube(name, *options):
        path = os.path.join(tmp, name)
        subprocess.run([plisse, 'mesh', 'cube', '--order', '1', '--edge', '2', '--divisions', '2',
                        '-o', path, *options], check=True, stdout=subprocess.DEVNULL)
        return path
    c4 = open(cube('c4.msh')).read()
    c4b = open(cube('c4b.msh', '--binary'), 'rb').read()
    c2 = open(cube('c2.msh', '--format', '2')).read()

open('cube.msh', 'w').write(c4)
open('empty.msh', 'w').write('')
# ASCII v4 cut in the middle of the $Elements section (mid-line).
lines = c4.split('\n')
i = lines.index('$Elements')
open('truncated-ascii.msh', 'w').write('\n'.join(lines[:i + 12]) + '\n7 3 ')
# v2 cut in the middle of the $Elements section.
lines = c2.split('\n')
i = lines.index('$Elements')
open('truncated-v2.msh', 'w').write('\n'.join(lines[:i + 30]) + '\n')
# binary v4 cut inside the element data.
j = c4b.index(b'$Elements')
open('truncated-binary.msh', 'wb').write(c4b[:j + 200])
# binary v4 cut inside the node block.
j = c4b.index(b'$Nodes')
open('truncated-binary-nodes.msh', 'wb').write(c4b[:j + 100])
# node tag 26 given a second time, to another point (v4: one more node in the last block)
lines = c4.split('\n')
i = lines.index('$Nodes')
blocks, n = [], i + 2
while not lines[n].startswith('$EndNodes'):
    count = int(lines[n].split()[3])
    blocks.append((n, count))
    n += 1 + 2 * count
last, count = blocks[-1]
tags = lines[last + 1:last + 1 + count]
coords = lines[last + 1 + count:last + 1 + 2 * count]
header = lines[last].split()
header[3] = str(count + 1)
total = lines[i + 1].split()
total[1] = str(int(total[1]) + 1)
dup = (lines[:i + 1] + [' '.join(total)] + lines[i + 2:last] + [' '.join(header)] + tags + ['26'] +
       coords + ['1 2 2.3'] + lines[last + 1 + 2 * count:])
open('duplicate-node-tag.msh', 'w').write('\n'.join(dup))
# deterministic pseudo-random bytes (64-bit LCG)
def garbage(n, seed):
    out = bytearray()
    x = seed
    for _ in range(n):
        x = (6364136223846793005 * x + 1442695040888963407) % (1 << 64)
        out.append(x >> 56)
    return bytes(out)
open('garbage.msh', 'wb').write(garbage(4096, 1))
open('garbage-after-header.msh', 'wb').write(b'$MeshFormat\n4.1 1 8\n' + garbage(4096, 2))
open('not-a-mesh.msh', 'w').write('mesh: {generate: cube}\nmaterial: {model: neo-hookean, c1: 0.2}\n')
# a node count of 10^12 in a short file
open('huge-node-count.msh', 'w').write('$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 999999999999 1 999999999999\n3 1 0 999999999999\n1\n')

def v2(nodes, elements, names):
    s = '$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n' % len(names)
    for dim, tag, name in names: s += '%d %d "%s"\n' % (dim, tag, name)
    s += '$EndPhysicalNames\n$Nodes\n%d\n' % len(nodes)
    for k, x in enumerate(nodes): s += '%d %s %s %s\n' % ((k + 1,) + tuple(x))
    s += '$EndNodes\n$Elements\n%d\n' % len(elements)
    for k, (typ, phys, conn) in enumerate(elements):
        s += '%d %d 2 %d %d %s\n' % (k + 1, typ, phys, phys, ' '.join(map(str, conn)))
    return s + '$EndElements\n'
unit = [(0,0,0),(1,0,0),(0,1,0),(1,1,0),(0,0,1),(1,0,1),(0,1,1),(1,1,1)]
# one hexahedron (Gmsh type 5) with its six quadrangle faces (type 3)
quads = [(1,3,4,2),(5,6,8,7),(1,2,6,5),(3,7,8,4),(1,5,7,3),(2,4,8,6)]
open('hexahedra.msh','w').write(v2(unit, [(3, 1, q) for q in quads] + [(5, 2, (1,2,4,3,5,6,8,7))],
                                   [(2, 1, 'outer'), (3, 2, 'body')]))
# only the twelve boundary triangles of a unit cube, no volume elements
tris = [(1,3,4),(1,4,2),(5,6,8),(5,8,7),(1,2,6),(1,6,5),(3,7,8),(3,8,4),(1,5,7),(1,7,3),(2,4,8),(2,8,6)]
open('triangles-only.msh','w').write(v2(unit, [(2, 1, t) for t in tris], [(2, 1, 'outer')]))
# two tetrahedra: a regular one and a flat one (its four nodes in the plane z = 0)
flat_nodes = [(0,0,0),(1,0,0),(0,1,0),(0,0,1),(1,1,0)]
open('degenerate-tet.msh','w').write(v2(flat_nodes, [(4, 1, (1,2,3,4)), (4, 1, (2,5,3,1))], [(3, 1, 'body')]))
# tangled: tetrahedra (1,2,3,4) and (1,2,3,5) share the face 123 and both lie above it (z > 0);
# each is positively numbered, but together they overlap: an inverted element in a mesh.
tangled_nodes = [(0,0,0),(1,0,0),(0,1,0),(0,0,1),(0.2,0.2,0.5)]
bnd = [(1,3,2),(1,2,4),(2,3,4),(1,4,3)]
open('tangled.msh','w').write(v2(tangled_nodes, [(2, 2, t) for t in bnd] + [(4, 1, (1,2,3,4)), (4, 1, (1,2,3,5))],
                                 [(3, 1, 'body'), (2, 2, 'outer')]))
# an element referencing node 99 of a file with 8 nodes
open('undefined-node.msh','w').write(v2(unit, [(4, 1, (1,2,4,99))], [(3, 1, 'body')]))
# NaN and infinite coordinates
bad = list(unit); bad[7] = ('nan', 1, 1); bad[6] = (0, 'inf', 1)
kuhn = [(1,2,4,8),(1,3,7,8),(1,5,6,8),(1,6,2,8),(1,7,5,8),(1,4,3,8)]
open('nan-coordinates.msh','w').write(v2(bad, [(4, 1, t) for t in kuhn], [(3, 1, 'body')]))
# two unit cubes (Kuhn's six tetrahedra each) side by side with a gap between them; the first
# has a `fixed` face z = 0, the second nothing: a piece that can move as a rigid body
second = [(x + 2, y, z) for x, y, z in unit]
bottom = [(1,3,4),(1,4,2)]
open('two-pieces.msh','w').write(v2(unit + second,
                                    [(2, 2, t) for t in bottom] + [(4, 1, t) for t in kuhn] +
                                    [(4, 1, tuple(v + 8 for v in t)) for t in kuhn],
                                    [(3, 1, 'body'), (2, 2, 'fixed')]))
# the unit cube scaled by 1e299: coordinates near 1e300, whose volumes overflow
huge = [tuple(repr(c * 1e299) for c in x) for x in unit]
open('huge-coordinates.msh','w').write(v2(huge, [(4, 1, t) for t in kuhn], [(3, 1, 'body')]))
# one 10-node tetrahedron (Gmsh type 11: corners, then edges 01, 12, 20, 30, 32, 31) whose edge
# node on 01 sits at 0.9 instead of 0.5: the element is turned inside out near corner 1
# (det(dX/dξ) < 0 there), as on a thin curved wall meshed with -order 2 without optimisation;
# its bottom face (z = 0) is a 6-node triangle (type 9) tagged `bottom`
curved_nodes = [(0,0,0),(1,0,0),(0,1,0),(0,0,1),(0.9,0,0),(0.5,0.5,0),(0,0.5,0),(0,0,0.5),
                (0,0.5,0.5),(0.5,0,0.5)]
open('curved-tet10.msh','w').write(v2(curved_nodes, [(9, 2, (1,3,2,7,6,5)),
                                                     (11, 1, (1,2,3,4,5,6,7,8,9,10))],
                                      [(3, 1, 'body'), (2, 2, 'bottom')]))
# Gmsh 2.2 ASCII: node 8 listed twice, at (1, 1, 1) and at (1, 1, 1.5) (Gmsh keeps the last)
twice = v2(unit, [(4, 1, t) for t in kuhn], [(3, 1, 'body')]).replace(
    '$Nodes\n8\n', '$Nodes\n9\n').replace('8 1 1 1\n', '8 1 1 1\n8 1 1 1.5\n')
open('duplicate-node-v2.msh', 'w').write(twice)
# The same in a binary Gmsh 2.2 file (file-type 1): node records are a 4-byte tag and three
# 8-byte coordinates, elements come in blocks of (type, count, tags) headers, native byte order.
import struct
def v2_binary(nodes, elements, names):
    b = b'$MeshFormat\n2.2 1 8\n' + struct.pack('=i', 1) + b'\n$EndMeshFormat\n'
    b += b'$PhysicalNames\n%d\n' % len(names)
    for dim, tag, name in names: b += b'%d %d "%s"\n' % (dim, tag, name.encode())
    b += b'$EndPhysicalNames\n$Nodes\n%d\n' % len(nodes)
    for tag, x in nodes: b += struct.pack('=iddd', tag, *map(float, x))
    b += b'\n$EndNodes\n$Elements\n%d\n' % len(elements)
    for k, (typ, phys, conn) in enumerate(elements):
        b += struct.pack('=iii', typ, 1, 2) + struct.pack('=i', k + 1) + struct.pack('=ii', phys, phys)
        b += struct.pack('=%di' % len(conn), *conn)
    return b + b'\n$EndElements\n'
open('duplicate-node-v2-binary.msh', 'wb').write(v2_binary(
    [(k + 1, x) for k, x in enumerate(unit)] + [(8, (1, 1, 1.5))],
    [(4, 1, t) for t in kuhn], [(3, 1, 'body')]))
