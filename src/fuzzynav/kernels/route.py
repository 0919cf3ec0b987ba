"""A route to the goal around the obstacles seen so far, compiled, for the loop escape of the
default navigators and the route guidance of ``fuzzy-5b`` (the default) (:mod:`fuzzynav.kernels.layers`).

The robot knows no map, but it remembers where its rays hit (:mod:`fuzzynav.kernels.sightings`).
Planning on those points with every unseen place assumed free — the *freespace assumption* of D*
(A. Stentz, "Optimal and efficient path planning for partially-known environments", ICRA 1994)
and D* Lite (S. Koenig, M. Likhachev, 2002) — gives the shortest way round what is known to be
in the way: it runs along the boundaries of the seen obstacles, on the side the memory says is
shorter. :func:`target` returns a point ``ahead`` metres along that route; the navigator's own
behaviours drive towards it and avoid what the memory has not seen yet.

Grid: cells of ``cell`` m (``CELL`` unless given) over the box holding the robot, the goal and
the remembered points (plus ``MARGIN``); a cell is blocked when the Euclidean distance between
its centre and that of a cell holding a point, times ``cell``, is below ``inflate`` (a disc of
the robot's radius plus a margin, so the route keeps room to turn); the cells of the robot and
the goal are free.
Distances to the goal are counted in 8-neighbour moves by a breadth-first wavefront from the
goal, until it reaches the robot; the route goes down from the robot, to the first neighbour
(in the order of ``NEIGHBOURS_X``, ``NEIGHBOURS_Y``) nearest the goal at each move.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit

CELL = 0.25  # m
MARGIN = 3.0  # m of grid around the robot, the goal and the points
MAX_CELLS = 1_000_000  # the largest grid a search builds (a box of 250 m here, 100 m for the car route's
# 0.1 m cells): a goal farther than that is left to the reactive layers until it comes nearer, where
# the search's arrays (several times the cells, 8 bytes each) would otherwise exhaust the memory
NEIGHBOURS_X = (1, -1, 0, 0, 1, 1, -1, -1)  # the 8 neighbours (x, y index steps), in the order tried
NEIGHBOURS_Y = (0, 0, 1, -1, 1, -1, 1, -1)


@jit
def index(value, low, size, cell):
    """The grid index of coordinate ``value`` (``low``: the grid's lower edge; cells of ``cell``
    m), clipped to the grid."""
    return min(max(int((value - low) / cell), 0), size - 1)


@jit
def blocked_grid(points, count, low_x, low_y, nx, ny, inflate, cell):
    """(nx + 2, ny + 2) grid, 1 where blocked: within ``inflate`` of a cell holding a point, and a
    blocked rim (so no neighbour needs a bounds check)."""
    occupied = np.zeros((nx, ny), dtype=np.uint8)
    for p in range(count):
        occupied[index(points[p, 0], low_x, nx, cell), index(points[p, 1], low_y, ny, cell)] = 1
    blocked = np.ones((nx + 2, ny + 2), dtype=np.uint8)
    blocked[1:nx + 1, 1:ny + 1] = 0
    reach = int(inflate / cell) + 1
    for i in range(nx):
        for j in range(ny):
            if occupied[i, j]:
                for di in range(max(-reach, -i), min(reach, nx - 1 - i) + 1):
                    for dj in range(max(-reach, -j), min(reach, ny - 1 - j) + 1):
                        if math.sqrt(float(di * di + dj * dj)) * cell < inflate:
                            blocked[i + di + 1, j + dj + 1] = 1
    return blocked


@jit
def target(seen, sx, sy, gx, gy, inflate, ahead, cell=CELL):
    """(found, x, y): a point ``ahead`` m along the shortest route, on a grid of ``cell`` m, from
    (sx, sy) to (gx, gy) that keeps ``inflate`` from the first ``count`` of the ``points`` (P, 2)
    of ``seen`` (a :class:`~fuzzynav.kernels.records.Sightings`), world frame; ``found`` is False
    when no route exists, or when the grid would exceed :data:`MAX_CELLS`."""
    points, count = seen.points, seen.count
    low_x, low_y, high_x, high_y = min(sx, gx), min(sy, gy), max(sx, gx), max(sy, gy)
    for p in range(count):
        low_x, low_y = min(low_x, points[p, 0]), min(low_y, points[p, 1])
        high_x, high_y = max(high_x, points[p, 0]), max(high_y, points[p, 1])
    low_x, low_y = low_x - MARGIN, low_y - MARGIN
    nx = int(math.ceil((high_x + MARGIN - low_x) / cell)) + 1
    ny = int(math.ceil((high_y + MARGIN - low_y) / cell)) + 1
    if nx * ny > MAX_CELLS:
        return False, 0.0, 0.0
    blocked = blocked_grid(points, count, low_x, low_y, nx, ny, inflate, cell)
    width = ny + 2
    start = (index(sx, low_x, nx, cell) + 1) * width + index(sy, low_y, ny, cell) + 1
    goal = (index(gx, low_x, nx, cell) + 1) * width + index(gy, low_y, ny, cell) + 1
    flat = blocked.reshape(-1)
    flat[start] = flat[goal] = 0
    offsets = np.empty(8, dtype=np.int64)
    for k in range(8):
        offsets[k] = NEIGHBOURS_X[k] * width + NEIGHBOURS_Y[k]
    steps = np.full(flat.shape[0], -1, dtype=np.int64)
    queue = np.empty(flat.shape[0], dtype=np.int64)
    steps[goal], queue[0] = 0, goal
    head, tail = 0, 1
    while head < tail and steps[start] < 0:
        here = queue[head]
        head += 1
        for o in offsets:
            there = here + o
            if not flat[there] and steps[there] < 0:
                steps[there] = steps[here] + 1
                queue[tail] = there
                tail += 1
    if steps[start] < 0:
        return False, 0.0, 0.0
    here, travelled = start, 0.0
    while here != goal and travelled < ahead:
        best = -1
        for o in offsets:
            if steps[here + o] >= 0 and (best < 0 or steps[here + o] < steps[best]):
                best = here + o
        here, travelled = best, travelled + cell
    return True, low_x + (here // width - 0.5) * cell, low_y + (here % width - 0.5) * cell
