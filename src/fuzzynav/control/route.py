"""A route to the goal around the obstacles seen so far, for the loop escape of the default
navigators (:mod:`fuzzynav.control.escape`).

The robot knows no map, but it remembers where its rays hit (:class:`ObstacleMemory`). Planning
on those points with every unseen place assumed free — the *freespace assumption* of D*
(A. Stentz, "Optimal and efficient path planning for partially-known environments", ICRA 1994)
and D* Lite (S. Koenig, M. Likhachev, 2002) — gives the shortest way round what is known to be
in the way: it runs along the boundaries of the seen obstacles, on the side the memory says is
shorter. :func:`route_target` returns a point ``ahead`` metres along that route; the navigator's
own behaviours drive towards it and avoid what the memory has not seen yet.

Grid: cells of ``CELL`` m over the box holding the robot, the goal and the remembered points
(plus ``MARGIN``); a cell is blocked within ``inflate`` of a point (a disc of the robot's radius
plus a margin, so the route keeps room to turn); distances to the goal by a breadth-first
wavefront over the 8-neighbour grid (:func:`scipy.ndimage.distance_transform_edt` for the
inflation).
"""

from __future__ import annotations

import numpy as np
from scipy import ndimage

CELL = 0.25  # m
MARGIN = 3.0  # m of grid around the robot, the goal and the points
NEIGHBOURS = ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (1, -1), (-1, 1), (-1, -1))


def route_target(points: np.ndarray, start, goal, inflate: float, ahead: float = 2.5,
                 cell_size: float = CELL) -> np.ndarray | None:
    """A point ``ahead`` m along the shortest route, on a grid of ``cell_size`` m, from ``start``
    to ``goal`` that keeps ``inflate`` from every point ``(P, 2)`` (world frame), or ``None`` when
    no route exists."""
    start, goal = np.asarray(start, dtype=float)[:2], np.asarray(goal, dtype=float)[:2]
    corners = np.vstack([points, start, goal]) if len(points) else np.vstack([start, goal])
    low = corners.min(axis=0) - MARGIN
    shape = tuple((np.ceil((corners.max(axis=0) + MARGIN - low) / cell_size)).astype(int) + 1)
    cell = lambda p: tuple(np.clip(((np.asarray(p) - low) / cell_size).astype(int), 0, np.array(shape) - 1))
    occupied = np.zeros(shape, dtype=bool)
    if len(points):
        occupied[tuple(np.clip(((points - low) / cell_size).astype(int), 0, np.array(shape) - 1).T)] = True
    blocked = ndimage.distance_transform_edt(~occupied) * cell_size < inflate
    blocked[cell(start)] = blocked[cell(goal)] = False
    blocked = np.pad(blocked, 1, constant_values=True)  # a blocked rim: no bounds checks below
    width = blocked.shape[1]
    index = lambda c: (c[0] + 1) * width + c[1] + 1
    offsets = [dx * width + dy for dx, dy in NEIGHBOURS]
    s, g = index(cell(start)), index(cell(goal))
    steps = _wavefront(~blocked, divmod(g, width), divmod(s, width)).ravel().tolist()
    if steps[s] < 0:
        return None
    here, travelled = s, 0.0
    while here != g and travelled < ahead:
        here = min((here + o for o in offsets if steps[here + o] >= 0), key=steps.__getitem__)
        travelled += cell_size
    return low + (np.array(divmod(here, width)) - 0.5) * cell_size


def _wavefront(free: np.ndarray, goal: tuple, start: tuple) -> np.ndarray:
    """Steps (8-neighbour moves) from the free cells of the grid to ``goal``, −1 where not reached:
    the breadth-first wavefront, grown one ring per dilation, until it reaches ``start`` (the
    route down from ``start`` only visits cells nearer the goal than ``start``)."""
    steps = np.full(free.shape, -1, dtype=np.int64)
    steps[goal] = 0
    front = np.zeros(free.shape, dtype=bool)
    front[goal] = True
    reached, ring, d = front.copy(), np.ones((3, 3), dtype=bool), 0
    while front.any() and steps[start] < 0:
        d += 1
        front = ndimage.binary_dilation(front, ring) & free & ~reached
        steps[front] = d
        reached |= front
    return steps
