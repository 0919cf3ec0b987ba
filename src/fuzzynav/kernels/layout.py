"""How a world's shapes are packed for the kernels of :mod:`fuzzynav.kernels.scene` (no numba here,
so a world can be built without compiling anything).

One flat float array: a header (:data:`HEADER` fields), then circles (cx, cy, r), polygons (first
edge, end edge, centre x, y, bounding radius), polygon edges (ax, ay, bx, by, ex, ey, |e|²; walls
are rectangles) and ellipses (cx, cy, a, b, cos φ, sin φ, bounding radius). Obstacle *columns*
count circles, then polygons, then ellipses (:data:`PRIMITIVES`; the obstacle types of
:mod:`fuzzynav.world.shapes` each pack as one of them).
"""

from __future__ import annotations

import math

import numpy as np

WIDTH, HEIGHT, N_CIRCLES, N_POLYGONS, N_EDGES, N_ELLIPSES, AT_CIRCLES, AT_POLYGONS, AT_EDGES, AT_ELLIPSES = range(10)
HEADER = 10
PRIMITIVES = ("circle", "polygon", "ellipse")  # the shape kinds the kernels know, in column order (code = index)
NEAREST_COLUMNS = 5  # rows of nearest(): signed distance, nearest x, nearest y, column (-1: none), boundary


def pack(width: float, height: float, circles, polygons, ellipses) -> np.ndarray:
    """The flat scene array of a world: ``circles`` as (cx, cy, r), ``polygons`` as vertex
    arrays ``(V, 2)`` (walls as their rectangles), ``ellipses`` as (cx, cy, a, b, angle)."""
    circle_rows = np.array(circles, dtype=float).reshape(-1, 3)
    polygon_rows, edge_rows, start = _polygon_rows([np.asarray(vertices, dtype=float) for vertices in polygons])
    ellipse_rows = [(cx, cy, ra, rb, math.cos(angle), math.sin(angle), max(ra, rb))
                    for cx, cy, ra, rb, angle in np.array(ellipses, dtype=float).reshape(-1, 5).tolist()]
    parts = [circle_rows.ravel(), polygon_rows.ravel(), edge_rows.ravel(), np.array(ellipse_rows, dtype=float).ravel()]
    header = np.zeros(HEADER)
    header[[WIDTH, HEIGHT]] = width, height
    header[N_CIRCLES:N_ELLIPSES + 1] = len(circle_rows), len(polygon_rows), start, len(ellipse_rows)
    offsets = HEADER + np.cumsum([0] + [len(p) for p in parts[:-1]])
    header[AT_CIRCLES:AT_ELLIPSES + 1] = offsets
    return np.concatenate([header, *parts])


def _polygon_rows(polygons: list) -> tuple[np.ndarray, np.ndarray, int]:
    """(polygon rows ``(P, 5)``, edge rows ``(E, 7)``, E) of vertex arrays ``(V, 2)``, computed
    for all polygons at once: each polygon's edges from vertex k to k + 1 (the last back to its
    first), its centre (the mean of its vertices, taken over the polygons of each vertex count
    together so the sums run in the same order as one polygon's) and its bounding radius."""
    a = np.concatenate(polygons) if polygons else np.zeros((0, 2))
    counts = [len(p) for p in polygons]
    ends = np.cumsum(counts, dtype=int)
    starts = ends - counts
    following = np.arange(1, len(a) + 1)
    following[ends - 1] = starts
    edges = np.empty((len(a), 7))
    edges[:, :2], edges[:, 2:4] = a, a[following]
    np.subtract(edges[:, 2:4], a, out=edges[:, 4:6])
    edges[:, 6] = edges[:, 4] ** 2 + edges[:, 5] ** 2
    rows = np.empty((len(polygons), 5))
    rows[:, 0], rows[:, 1] = starts, ends
    for count in set(counts):
        same = np.flatnonzero(np.equal(counts, count)) if len(set(counts)) > 1 else slice(None)
        group = a[starts[same, None] + np.arange(count)]  # (P, count, 2)
        rows[same, 2:4] = centres = np.add.reduce(group, axis=1) / count
        rows[same, 4] = np.hypot(group[:, :, 0] - centres[:, None, 0], group[:, :, 1] - centres[:, None, 1]).max(axis=1)
    return rows, edges, len(a)


def mover_rows(scene: np.ndarray, columns) -> np.ndarray:
    """Rows ``(M, 4)`` int of the obstacle ``columns`` that move, for
    :func:`fuzzynav.kernels.traffic.place`: (primitive code, offset of its row in ``scene``,
    first edge, end edge — both 0 for a disc or an ellipse)."""
    n_c, n_p = int(scene[N_CIRCLES]), int(scene[N_POLYGONS])
    rows = np.zeros((len(columns), 4), dtype=np.int64)
    for m, column in enumerate(columns):
        if column < n_c:
            rows[m, :2] = 0, int(scene[AT_CIRCLES]) + 3 * column
        elif column < n_c + n_p:
            at = int(scene[AT_POLYGONS]) + 5 * (column - n_c)
            rows[m] = 1, at, int(scene[at]), int(scene[at + 1])
        else:
            rows[m, :2] = 2, int(scene[AT_ELLIPSES]) + 7 * (column - n_c - n_p)
    return rows
