"""How far each echo of a range scan lies off the outline of the scan before, compiled: what tells
a moving obstacle from a standing surface in the yield layer and the scan trackers
(:func:`fuzzynav.control.sighting_tracks.off_outline`; docs/dynamic.md).

The outline is the polyline of the scan before: segments between neighbouring valid beams less
than ``bridge`` m apart (a gap wider than that is open space, not a surface). A point on a
surface that stands still lies on it; a point of a moving obstacle lies off it by what the
obstacle moved (the scan-differencing cue of moving-object detection: C.-C. Wang, C. Thorpe,
S. Thrun, "Online simultaneous localization and mapping with detection and tracking of moving
objects", ICRA 2003).

The nearest segment is found exactly (ties to the first in beam order): the segments are bucketed
in square cells, and each point searches the rings of cells round its own until a ring lies
farther than the best segment so far, skipping a cell or a segment's bounding box that does; the
first bound is the previous point's nearest segment (neighbouring echoes have neighbouring
nearest segments).
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit

BRIDGE = 0.3  # m: neighbouring echoes closer than this outline a surface (a wider gap is open space)
SLACK = 1e-9  # m: a segment whose box lies this much beyond the best distance cannot be nearer
CELL = 0.25  # m: the side of the cells the segments are bucketed in


@jit
def _segments(before, valid, bridge):
    """The outline's segments (module docstring): rows (a_x, a_y, e_x, e_y, box x0, x1, y0, y1),
    e the segment's vector from its first point a."""
    rows = np.empty((max(before.shape[0] - 1, 0), 8))
    n = 0
    for s in range(before.shape[0] - 1):
        ax, ay, bx, by = before[s, 0], before[s, 1], before[s + 1, 0], before[s + 1, 1]
        if valid[s] and valid[s + 1] and math.hypot(bx - ax, by - ay) < bridge:
            rows[n, 0], rows[n, 1], rows[n, 2], rows[n, 3] = ax, ay, bx - ax, by - ay
            rows[n, 4], rows[n, 5], rows[n, 6], rows[n, 7] = min(ax, bx), max(ax, bx), min(ay, by), max(ay, by)
            n += 1
    return rows[:n]


@jit
def _foot(px, py, row):
    """(distance, foot x, foot y) of the point (px, py) to one segment ``row`` of :func:`_segments`."""
    ax, ay, ex, ey = row[0], row[1], row[2], row[3]
    u = max(px * ex + py * ey - (ax * ex + ay * ey), 0.0)
    u = min(u / max(ex * ex + ey * ey, 1e-12), 1.0)
    fx, fy = ax + u * ex, ay + u * ey
    return math.hypot(px - fx, py - fy), fx, fy


@jit
def _grid(rows):
    """The segments ``rows`` bucketed by the square cells of side ``CELL`` their boxes touch:
    (x0, y0, nx, ny, start (nx ny + 1,), members): cell c = cx ny + cy holds the segments
    ``members[start[c]:start[c + 1]]``, in segment order."""
    x0, y0 = rows[:, 4].min(), rows[:, 6].min()
    nx, ny = int((rows[:, 5].max() - x0) / CELL) + 1, int((rows[:, 7].max() - y0) / CELL) + 1
    start = np.zeros(nx * ny + 1, dtype=np.int64)
    for k in range(rows.shape[0]):
        for cx in range(int((rows[k, 4] - x0) / CELL), int((rows[k, 5] - x0) / CELL) + 1):
            for cy in range(int((rows[k, 6] - y0) / CELL), int((rows[k, 7] - y0) / CELL) + 1):
                start[cx * ny + cy + 1] += 1
    start = np.cumsum(start)
    members, fill = np.empty(start[-1], dtype=np.int64), start[:-1].copy()
    for k in range(rows.shape[0]):
        for cx in range(int((rows[k, 4] - x0) / CELL), int((rows[k, 5] - x0) / CELL) + 1):
            for cy in range(int((rows[k, 6] - y0) / CELL), int((rows[k, 7] - y0) / CELL) + 1):
                members[fill[cx * ny + cy]] = k
                fill[cx * ny + cy] += 1
    return x0, y0, nx, ny, start, members


@jit
def off_outline(points, before, valid, bridge):
    """(distance (P,), nearest point (P, 2)) of each of ``points`` (P, 2) to the outline of the
    scan ``before`` (S, 2) with ``valid`` (S,) echoes (module docstring); distance inf and the
    point itself where the outline has no segment."""
    rows = _segments(before, valid, bridge)
    dist = np.full(points.shape[0], np.inf)
    foot = points.astype(np.float64)
    if rows.shape[0] == 0:
        return dist, foot
    x0, y0, nx, ny, start, members = _grid(rows)
    nearest = 0
    for p in range(points.shape[0]):
        px, py = points[p, 0], points[p, 1]
        cx, cy = int(math.floor((px - x0) / CELL)), int(math.floor((py - y0) / CELL))
        best, bx, by = _foot(px, py, rows[nearest])  # the previous point's nearest: a good first bound
        ring = max(0, -cx - 1, cx - nx, -cy - 1, cy - ny)  # the first ring that can reach the grid
        while (ring - 1) * CELL <= best + SLACK:  # a cell of this ring lies at least (ring − 1) CELL off
            for gx in range(max(cx - ring, 0), min(cx + ring, nx - 1) + 1):
                edge = gx == cx - ring or gx == cx + ring
                wx = max(x0 + gx * CELL - px, 0.0, px - x0 - (gx + 1) * CELL)
                for gy in range(max(cy - ring, 0), min(cy + ring, ny - 1) + 1):
                    if not edge and gy != cy - ring and gy != cy + ring:
                        continue
                    wy = max(y0 + gy * CELL - py, 0.0, py - y0 - (gy + 1) * CELL)
                    if math.sqrt(wx * wx + wy * wy) > best + SLACK:
                        continue  # the whole cell lies farther than the best so far
                    for m in range(start[gx * ny + gy], start[gx * ny + gy + 1]):
                        k = members[m]
                        gapx = max(rows[k, 4] - px, 0.0, px - rows[k, 5])
                        gapy = max(rows[k, 6] - py, 0.0, py - rows[k, 7])
                        if math.sqrt(gapx * gapx + gapy * gapy) > best + SLACK:
                            continue
                        d, fx, fy = _foot(px, py, rows[k])
                        if d < best or (d == best and k < nearest):
                            best, bx, by, nearest = d, fx, fy, k
            if cx - ring <= 0 and cx + ring >= nx - 1 and cy - ring <= 0 and cy + ring >= ny - 1:
                break  # the whole grid searched
            ring += 1
        dist[p], foot[p, 0], foot[p, 1] = best, bx, by
    return dist, foot
