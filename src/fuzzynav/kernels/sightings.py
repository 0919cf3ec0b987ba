"""Obstacle points a robot has seen during its episode, compiled: the map of the recovery and
loop-escape layers of the default navigators (:mod:`fuzzynav.kernels.layers`).

A robot remembers, in the world frame, the hits of its ring (readings below the range) and the
nearest obstacle point (D_ro, θ_o, which the observation gives all round, so obstacles behind it
are known without rear sensors), one point per ``CELL`` grid cell — the first seen there.
Arrays of one robot: ``points`` (P, 2) in the order seen (the count is kept by the caller) and
``cells`` (H,) floats, an open-addressing hash set of their grid cells (point index + 1, 0:
empty; H a power of two, at least twice P), so a point is added in constant time whatever the
count.
"""

from __future__ import annotations

import math

from fuzzynav.jit import jit

CELL = 0.05  # m: obstacle points closer than this on a grid are remembered once


@jit
def cell_of(px, py):
    """The grid cell (i, j) of the point (px, py)."""
    return math.floor(px / CELL), math.floor(py / CELL)


@jit
def add(points, cells, count, px, py):
    """Remember (px, py) unless a point of its cell is remembered; returns the new count."""
    cx, cy = cell_of(px, py)
    mask = cells.shape[0] - 1
    s = ((cx * 73856093) ^ (cy * 19349663)) & mask
    while cells[s] != 0:
        i = int(cells[s]) - 1
        qx, qy = cell_of(points[i, 0], points[i, 1])
        if qx == cx and qy == cy:
            return count
        s = (s + 1) & mask
    points[count, 0], points[count, 1] = px, py
    cells[s] = count + 1
    return count + 1


@jit
def rehash(points, count, cells):
    """Fill the (emptied, possibly larger) hash set ``cells`` with the cells of the first
    ``count`` points."""
    cells[:] = 0
    kept = 0
    for i in range(count):
        kept = add(points, cells, kept, points[i, 0], points[i, 1])


@jit
def see(points, cells, count, pose, seen):
    """Remember the hits of the ring read at ``pose`` (a :class:`~fuzzynav.kernels.records.Pose`)
    and the nearest obstacle point of ``seen`` (a :class:`~fuzzynav.kernels.records.Reading`: D_ro =
    ``d_o``, θ_o = ``b_o``; ``inf``: none); returns the new count (at most S + 1 more)."""
    x, y, theta, ranges, angles = pose.x, pose.y, pose.theta, seen.ranges, seen.angles
    max_range, d_o, b_o = seen.max_range, seen.d_o, seen.b_o
    for i in range(ranges.shape[0]):
        r = ranges[i]
        if math.isfinite(r) and r < max_range - 1e-9:
            count = add(points, cells, count, x + r * math.cos(theta + angles[i]), y + r * math.sin(theta + angles[i]))
    if math.isfinite(d_o):
        d, b = max(d_o, 0.0), theta + b_o
        count = add(points, cells, count, x + d * math.cos(b), y + d * math.sin(b))
    return count


@jit
def clearance(points, count, x, y):
    """Distance from (x, y) to the nearest remembered point (``inf`` with none)."""
    best = math.inf
    for i in range(count):
        best = min(best, math.hypot(points[i, 0] - x, points[i, 1] - y))
    return best


@jit
def side_room(points, count, x, y, theta, cap):
    """(left, right): distance to the nearest point on each side of the heading θ at (x, y) —
    ahead of the rear of the body, 0.3 m behind the centre — capped at ``cap``."""
    left = right = cap
    c, s = math.cos(theta), math.sin(theta)
    for i in range(count):
        rx, ry = points[i, 0] - x, points[i, 1] - y
        if c * rx + s * ry > -0.3:
            d = math.hypot(rx, ry)
            if c * ry - s * rx > 0:
                left = min(left, d)
            else:
                right = min(right, d)
    return left, right
