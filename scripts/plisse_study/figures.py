"""The figures the studies share: saving, the deformed surface coloured by its normal deviation
from the axisymmetric mean shape, and a quarter model's disc mirrored to the full disc.

Importing this module selects matplotlib's file-only backend (Agg). Lengths in the run's units.
"""
import os
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from . import runs  # noqa: E402


class LinkRefused(Exception):
    """A figure's path, or its folder, is a symbolic link: plisse writes no file through one."""


def refuse_link(path):
    """Raises LinkRefused when `path` is a symbolic link."""
    if os.path.islink(path):
        raise LinkRefused(f"{path}: is a symbolic link; plisse writes no file through a link "
                          "(its target could be any file the user may write): remove the link")


def save(fig, path, dpi=130):
    """Lays out `fig`, writes it to `path` as PNG at `dpi` and closes it. The PNG is written to a
    temporary beside `path`, then renamed over it, so a reader never sees half a file and a link
    is never written through: a `path` or folder that is a symbolic link raises LinkRefused."""
    path = os.fspath(path)
    folder = os.path.dirname(path) or "."
    try:
        refuse_link(folder)
        refuse_link(path)
        fig.tight_layout()
        fd, temporary = tempfile.mkstemp(prefix=f".{os.path.basename(path)}.tmp.{os.getpid()}.",
                                         dir=folder)
        try:
            with os.fdopen(fd, "wb") as f:
                fig.savefig(f, dpi=dpi, format="png")
                umask = os.umask(0)
                os.umask(umask)
                os.fchmod(f.fileno(), 0o666 & ~umask)  # as a new file would be, not mkstemp's 0600
            os.replace(temporary, path)
        except BaseException:
            os.unlink(temporary)
            raise
    finally:
        plt.close(fig)


def outer_surface(points, tets, center):
    """Boundary faces of the tetrahedra (corner nodes, outward order) whose outward normal
    points away from `center` (cosine above 0.3)."""
    faces = np.concatenate([tets[:, [0, 2, 1]], tets[:, [0, 1, 3]], tets[:, [1, 2, 3]],
                            tets[:, [0, 3, 2]]])
    key = np.sort(faces, axis=1)
    _, inverse, counts = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    boundary = faces[counts[inverse.ravel()] == 1]
    p = points[boundary]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    r = p.mean(axis=1) - center
    cosine = np.einsum("ij,ij->i", n, r) / (np.linalg.norm(n, axis=1) * np.linalg.norm(r, axis=1)
                                            + 1e-300)
    return boundary[cosine > 0.3]


def normal_deviation(X, x, axis, center):
    """Deviation of the deformed points x from the mean deformed shape of their reference latitude,
    along the mean shape's normal (bins of 0.5 degree of reference latitude)."""
    a = np.zeros(3)
    a[axis] = 1.0

    def cyl(p):
        r = p - center
        h = r @ a
        rho = np.linalg.norm(r - np.outer(h, a), axis=1)
        return rho, h

    rho0, h0 = cyl(X)
    lat = np.degrees(np.arctan2(h0, rho0))
    rho, h = cyl(x)
    bins = np.round(lat / 0.5).astype(int)
    uniq, inv = np.unique(bins, return_inverse=True)
    inv = inv.ravel()
    mean_rho = np.bincount(inv, rho) / np.bincount(inv)
    mean_h = np.bincount(inv, h) / np.bincount(inv)
    # Meridian tangent of the mean curve by differences over latitude; the normal is its rotation.
    t_rho = np.gradient(mean_rho) if len(uniq) > 1 else np.zeros_like(mean_rho)
    t_h = np.gradient(mean_h) if len(uniq) > 1 else np.ones_like(mean_h)
    norm = np.hypot(t_rho, t_h) + 1e-300
    n_rho, n_h = t_h / norm, -t_rho / norm
    return (rho - mean_rho[inv]) * n_rho[inv] + (h - mean_h[inv]) * n_h[inv]


def surface_figure(vtu, settings, path, title):
    """The deformed measured surface of `vtu` coloured by its normal deviation from the mean
    (axisymmetric) shape at the same reference latitude, with the rings of settings["rings_deg"]
    drawn on the mean shape. `settings`: the case's output.wrinkles (axis, center, rings_deg).
    False when the file has no tetrahedra or displacement."""
    state = runs.read_state(vtu)
    X = state.points
    tets = state.corners
    if tets is None or "displacement" not in state.mesh.point_data:
        return False
    x = state.deformed
    axis = runs.AXES.get(settings.get("axis", "y"), 1)
    center = np.array(settings.get("center", [0.0, 0.0, 0.0]), dtype=float)
    tris = outer_surface(X, tets, center)
    if len(tris) == 0:
        return False
    used = np.unique(tris)
    dev = np.zeros(len(X))
    dev[used] = normal_deviation(X[used], x[used], axis, center)
    face_dev = dev[tris].mean(axis=1)
    limit = max(np.percentile(np.abs(face_dev), 99), 1e-9)
    fig = plt.figure(figsize=(6.4, 5.2))
    ax = fig.add_subplot(projection="3d")
    ax.computed_zorder = False  # the rings are drawn over the surface
    order = [(axis + 1) % 3, (axis + 2) % 3, axis]  # the rings' axis vertical
    surf = ax.plot_trisurf(x[:, order[0]], x[:, order[1]], x[:, order[2]], triangles=tris,
                           cmap="coolwarm", linewidth=0, antialiased=False, shade=False)
    surf.set_array(face_dev)
    surf.set_clim(-limit, limit)
    fig.colorbar(surf, ax=ax, shrink=0.7, label="normal deviation [mm]")
    # The rings, on the deformed mean shape: the mean distance from the axis and height of the
    # surface nodes near each ring's reference latitude (within a node spacing), drawn over the
    # modelled sector's azimuths.
    a = np.zeros(3)
    a[axis] = 1.0
    r0 = X[used] - center
    h0 = r0 @ a
    rho0 = np.linalg.norm(r0 - np.outer(h0, a), axis=1)
    latitude = np.degrees(np.arctan2(h0, rho0))
    e_u, e_v = np.eye(3)[order[0]], np.eye(3)[order[1]]
    azimuth = np.arctan2(r0 @ e_v, r0 @ e_u)
    edges = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]]])
    spacing = np.degrees(np.median(np.linalg.norm(X[edges[:, 0]] - X[edges[:, 1]], axis=1))
                         / max(np.median(np.linalg.norm(r0, axis=1)), 1e-12))
    xc = x[used] - center
    hc = xc @ a
    rhoc = np.linalg.norm(xc - np.outer(hc, a), axis=1)
    for ring in settings.get("rings_deg") or []:
        near = np.abs(latitude - float(ring)) < max(0.5, spacing)
        if not near.any():
            continue
        phi = np.linspace(azimuth[near].min(), azimuth[near].max(), 200)
        rho, h = rhoc[near].mean(), hc[near].mean()
        p = center + rho * (np.outer(np.cos(phi), e_u) + np.outer(np.sin(phi), e_v)) + h * a
        ax.plot(p[:, order[0]], p[:, order[1]], p[:, order[2]], "k-", linewidth=1.2, zorder=10)
    ax.set_box_aspect(np.ptp(x[used][:, order], axis=0) + 1e-9)
    ax.view_init(elev=35, azim=-55)
    ax.set_axis_off()
    ax.set_title(title, fontsize=10)
    save(fig, path, dpi=110)
    return True


def unrolled_map(X, x, triangles, axis, center):
    """A surface of revolution about `axis` through `center` unrolled: for each triangle (nodes of
    X, the reference points) the reference arc length s = mean radius times azimuth and the axial
    coordinate h of its nodes, and its normal deviation (the mean of its nodes' normal_deviation
    of the deformed points x). Triangles across the azimuth's seam at +-pi are left out. Returns
    (s, h, triangles, deviation per triangle)."""
    a = np.zeros(3)
    a[axis] = 1.0
    r = X - center
    h = r @ a
    e_u, e_v = np.eye(3)[(axis + 1) % 3], np.eye(3)[(axis + 2) % 3]
    azimuth = np.arctan2(r @ e_v, r @ e_u)
    used = np.unique(triangles)
    rho = np.linalg.norm(r[used] - np.outer(h[used], a), axis=1).mean()
    dev = np.zeros(len(X))
    dev[used] = normal_deviation(X[used], x[used], axis, center)
    keep = np.ptp(azimuth[triangles], axis=1) < np.pi
    triangles = triangles[keep]
    return rho * azimuth, h, triangles, dev[triangles].mean(axis=1)


def unrolled_figure(vtu, settings, path, title):
    """The measured surface of `vtu` (a tube's or any surface of revolution's: the outer faces of
    the tetrahedra, or a shell's triangles) unrolled about settings["axis"]: arc length around
    against the axial coordinate, coloured by the normal deviation from the mean axisymmetric
    shape (unrolled_map). False when the file has no cells or displacement."""
    state = runs.read_state(vtu)
    if "displacement" not in state.mesh.point_data:
        return False
    X, x = state.points, state.deformed
    axis = runs.AXES.get(settings.get("axis", "y"), 1)
    center = np.array(settings.get("center", [0.0, 0.0, 0.0]), dtype=float)
    blocks = state.mesh.cells_dict
    if state.corners is not None:
        tris = outer_surface(X, state.corners, center)
    elif "triangle" in blocks or "triangle6" in blocks:
        tris = blocks.get("triangle", blocks.get("triangle6"))[:, :3]
    else:
        return False
    if len(tris) == 0:
        return False
    s, h, tris, face_dev = unrolled_map(X, x, tris, axis, center)
    if len(tris) == 0:
        return False
    limit = max(np.percentile(np.abs(face_dev), 99), 1e-9)
    fig, ax = plt.subplots(figsize=(7.0, 4.2))
    mesh = ax.tripcolor(s, h, tris, facecolors=face_dev, cmap="coolwarm", vmin=-limit,
                        vmax=limit)
    fig.colorbar(mesh, ax=ax, label="normal deviation [mm]")
    names = "xyz"
    ax.set_xlabel(f"arc length around the {names[axis]} axis (mean radius times azimuth) [mm]")
    ax.set_ylabel(f"{names[axis]} [mm]")
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=10)
    save(fig, path, dpi=110)
    return True


def mirrored_quarter(x, z, values):
    """The points (x, z, value) of a quarter model's disc (mirrors x = 0 and z = 0) mirrored to
    the full disc, rounded to 1e-9 and without repeats (the nodes on the mirrors): an (n, 3)
    array."""
    px = np.concatenate([x, -x, x, -x])
    pz = np.concatenate([z, z, -z, -z])
    pv = np.concatenate([values, values, values, values])
    return np.unique(np.round(np.c_[px, pz, pv], 9), axis=0)


def disc_map(ax, points, levels, cmap):
    """Filled contours of the points (x, z, value) of mirrored_quarter on `ax`, over their
    Delaunay triangulation; returns the contour set (for a colour bar)."""
    import matplotlib.tri as mtri

    tri = mtri.Triangulation(points[:, 0], points[:, 1])
    return ax.tricontourf(tri, points[:, 2], levels=levels, cmap=cmap, extend="both")
