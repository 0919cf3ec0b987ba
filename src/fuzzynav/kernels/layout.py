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
    polygon_rows, edge_rows, start = [], [], 0
    for vertices in polygons:
        a = np.asarray(vertices, dtype=float)
        b = np.roll(a, -1, axis=0)
        e = b - a
        mid = a.mean(axis=0)
        reach = float(np.hypot(*(a - mid).T).max())
        polygon_rows.append((start, start + len(a), mid[0], mid[1], reach))
        edge_rows.append(np.column_stack([a, b, e, e[:, 0] ** 2 + e[:, 1] ** 2]))
        start += len(a)
    ellipse_rows = [(cx, cy, ra, rb, math.cos(angle), math.sin(angle), max(ra, rb))
                    for cx, cy, ra, rb, angle in np.array(ellipses, dtype=float).reshape(-1, 5).tolist()]
    parts = [circle_rows.ravel(), np.array(polygon_rows, dtype=float).ravel(),
             np.concatenate(edge_rows).ravel() if edge_rows else np.zeros(0),
             np.array(ellipse_rows, dtype=float).ravel()]
    header = np.zeros(HEADER)
    header[[WIDTH, HEIGHT]] = width, height
    header[N_CIRCLES:N_ELLIPSES + 1] = len(circle_rows), len(polygon_rows), start, len(ellipse_rows)
    offsets = HEADER + np.cumsum([0] + [len(p) for p in parts[:-1]])
    header[AT_CIRCLES:AT_ELLIPSES + 1] = offsets
    return np.concatenate([header, *parts])
