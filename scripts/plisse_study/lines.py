"""Fields of a written step along a straight line of the undeformed body (`plisse plot --line`):
what ParaView's Plot Over Line gives, from the step file alone.

A sample point X of the segment [a, b] is located in the reference mesh: in the tetrahedron that
holds it (its barycentric coordinates under the corner nodes' map), or on a shell's mid-surface in
the triangle nearest to it, within half that triangle's longest edge. Point fields are
interpolated with the element's shape functions (the 4 or 10 of a tetrahedron, the 3 of a
triangle), cell fields are the value of the element that holds the point. Points outside the body
are left out."""
import numpy as np

# The names of a field's components in the columns: vectors x, y, z; symmetric tensors in the
# step file's order (ParaView's); principal values 1, 2, 3 (largest first).
COMPONENTS = {3: ("x", "y", "z"), 6: ("xx", "yy", "zz", "xy", "yz", "xz")}
# VTK's quadratic tetrahedron: corners 0-3, then the edge nodes of (0,1), (1,2), (0,2), (0,3),
# (1,3), (2,3).
TETRA10_EDGES = ((0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3))


def segment(a, b, n):
    """n points from a to b, equally spaced, and their distances from a."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    t = np.linspace(0.0, 1.0, n)
    return a + np.outer(t, b - a), t * np.linalg.norm(b - a)


def locate_in_tetrahedra(points, corners, X):
    """(cell, L) of the tetrahedron holding X (L: barycentric coordinates, 4), or None. Of several
    (X on a shared face), the one whose smallest coordinate is largest."""
    P = points[corners]  # (m, 4, 3)
    scale = np.ptp(points, axis=0).max()
    eps = 1e-9 * scale
    low, high = P.min(axis=1), P.max(axis=1)
    candidates = np.flatnonzero(np.all((low - eps <= X) & (X <= high + eps), axis=1))
    best = None
    for c in candidates:
        T = (P[c, 1:] - P[c, 0]).T
        try:
            lam = np.linalg.solve(T, X - P[c, 0])
        except np.linalg.LinAlgError:
            continue
        L = np.concatenate([[1.0 - lam.sum()], lam])
        if L.min() >= -1e-9 and (best is None or L.min() > best[1].min()):
            best = (int(c), L)
    return best


def locate_on_triangles(points, triangles, X):
    """(cell, L) of the triangle nearest X whose plane X projects into (L: 3 barycentric
    coordinates), if X lies within half that triangle's longest edge of it; else None."""
    P = points[triangles[:, :3]]  # (m, 3, 3)
    e1, e2 = P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]
    d = X - P[:, 0]
    a11, a12, a22 = (e1 * e1).sum(1), (e1 * e2).sum(1), (e2 * e2).sum(1)
    b1, b2 = (d * e1).sum(1), (d * e2).sum(1)
    det = a11 * a22 - a12 * a12
    with np.errstate(divide="ignore", invalid="ignore"):
        l1 = (a22 * b1 - a12 * b2) / det
        l2 = (a11 * b2 - a12 * b1) / det
    L = np.stack([1.0 - l1 - l2, l1, l2], axis=1)
    foot = P[:, 0] + l1[:, None] * e1 + l2[:, None] * e2
    distance = np.linalg.norm(X - foot, axis=1)
    edge = np.sqrt(np.maximum(np.maximum(a11, a22), ((P[:, 2] - P[:, 1]) ** 2).sum(1)))
    ok = np.isfinite(distance) & (L.min(axis=1) >= -1e-9) & (distance <= 0.5 * edge)
    if not ok.any():
        return None
    c = int(np.flatnonzero(ok)[np.argmin(distance[ok])])
    return c, L[c]


def shape_functions(L, n_nodes):
    """The element's shape functions at barycentric L: linear (3 or 4 nodes) or the quadratic
    tetrahedron's 10."""
    if n_nodes in (3, 4):
        return np.asarray(L)
    if n_nodes == 10:
        corners = [L[i] * (2.0 * L[i] - 1.0) for i in range(4)]
        return np.array(corners + [4.0 * L[i] * L[j] for i, j in TETRA10_EDGES])
    raise ValueError(f"no shape functions for an element of {n_nodes} nodes")


def columns_of(name, values):
    """The column names of a field whose values are (n,) or (n, k)."""
    k = 1 if values.ndim == 1 else values.shape[1]
    if k == 1:
        return [name]
    if name.startswith("principal_"):  # largest, middle, smallest
        return [f"{name}_{i + 1}" for i in range(k)]
    return [f"{name}_{c}" for c in COMPONENTS.get(k, [str(i) for i in range(k)])]


def sample(points, cells, point_data, cell_data, a, b, n):
    """The fields along [a, b] at n points: (header, rows), one row per point inside the body,
    [s, X, Y, Z, the point fields' components..., the cell fields' components...]; and the number
    of points left out. `cells`: the elements' nodes (tetrahedra of 4 or 10 nodes, or triangles)."""
    cells = np.asarray(cells)
    shell = cells.shape[1] in (3, 6)
    header = ["s", "X", "Y", "Z"]
    point_fields = [(name, np.asarray(v, dtype=float)) for name, v in sorted(point_data.items())]
    cell_fields = [(name, np.asarray(v, dtype=float)) for name, v in sorted(cell_data.items())]
    for name, v in point_fields + cell_fields:
        header += columns_of(name, v)
    rows, outside = [], 0
    X_all, s_all = segment(a, b, n)
    for X, s in zip(X_all, s_all):
        found = (locate_on_triangles(points, cells, X) if shell
                 else locate_in_tetrahedra(points, cells[:, :4], X))
        if found is None:
            outside += 1
            continue
        c, L = found
        nodes = cells[c, :3] if shell else cells[c]
        N = shape_functions(L, len(nodes))
        row = [s, *X]
        for _, v in point_fields:
            row += list(np.atleast_1d(N @ v[nodes]))
        for _, v in cell_fields:
            row += list(np.atleast_1d(v[c]))
        rows.append(row)
    return header, rows, outside


def waves(s, x, min_count=3, peak_ratio=2.0):
    """The waves along a sampled path: the deformed points x (n, 3) at the equally spaced
    distances s along it, less a quadratic fit in s of each coordinate (the path's own bending),
    projected on their principal direction, give a deviation w(s); its discrete Fourier series
    over the path's length L (the last sample closes the period) has amplitudes A_k, half the peak
    to peak of harmonic k, k waves along the path, wavelength L / k. Returns (count, wavelength,
    amplitude, peak) of the largest harmonic with k >= min_count, the amplitude peak to peak
    (2 A_k), peak when A_k is more than `peak_ratio` times both its neighbours' A_(k-1), A_(k+1)
    (waves that stand out of the path's smooth shape, whose spectrum falls steadily), and the
    spectrum as rows (k, L / k, A_k); None when fewer than 2 (min_count + 1) samples."""
    s, x = np.asarray(s, dtype=float), np.asarray(x, dtype=float)
    n = len(s) - 1
    if n < 2 * (min_count + 1):
        return None
    fit = np.column_stack([np.polyval(np.polyfit(s, x[:, c], 2), s) for c in range(3)])
    d = x - fit
    _, _, vt = np.linalg.svd(d - d.mean(axis=0), full_matrices=False)
    w = d[:n] @ vt[0]
    A = 2.0 * np.abs(np.fft.rfft(w)) / n
    length = s[-1] - s[0]
    ks = np.arange(min_count, n // 2)
    if len(ks) == 0:
        return None
    k = int(ks[np.argmax(A[ks])])
    peak = bool(A[k] > peak_ratio * max(A[k - 1], A[k + 1]))
    spectrum = [(int(j), length / j, float(A[j])) for j in range(1, n // 2)]
    return k, length / k, 2.0 * float(A[k]), peak, spectrum
