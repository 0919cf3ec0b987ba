"""Random wall courses for wall following (thesis §VI.5.3, Figs VI.27–VI.28), drawn and packed in
compiled code: training and the Gymnasium wall-following environment start a new course every
episode, so a course costs microseconds, not a world built shape by shape.

The draws take the caller's ``numpy.random.Generator``: numba's draws (``integers``, ``uniform``,
``random``) consume its stream exactly as NumPy's do and return the same numbers, so a course and
its start poses are the ones NumPy code drawing in the same order would give (tested bit for bit).
:func:`pack_walls` writes the scene array :func:`fuzzynav.kernels.layout.pack` gives for the
course's walls (tested bit for bit), for walls already checked
(:meth:`fuzzynav.world.shapes.Wall.chain`). The callers are
:func:`fuzzynav.learn.envs.layouts.wall_course` and :class:`fuzzynav.learn.envs.layouts.WallCourse`.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels import layout
from fuzzynav.kernels.layout import NEAREST_COLUMNS
from fuzzynav.kernels.scene import nearest_one

MAX_CORNERS = 6  # a course of at most five walls
CLEAR = 0.6  # m: a start pose needs this clearance from the walls and the boundary


@jit
def draw_course(rng, corners):
    """Corners of an open polyline of 3–5 walls, 3–7 m each, turning by 30°–150° either way at
    every joint, inside [2, 18]²: written to ``corners`` (:data:`MAX_CORNERS`, 2); returns how many.

    Each try draws, in this order: the wall count (``integers(3, 6)``), the first heading
    (``uniform(−π, π)``), the first point (``uniform(5, 15, 2)``), then per wall its turn's side
    (``integers(0, 2)``: right, left) and angle (``uniform(π/6, 5π/6)``) from the second wall on,
    and its length (``uniform(3, 7)``); a course leaving [2, 18]² is drawn again (at most 100
    tries; the last one is kept)."""
    count = 0
    for _ in range(100):
        walls = rng.integers(3, 6)
        heading = rng.uniform(-math.pi, math.pi)
        first = rng.uniform(5.0, 15.0, 2)
        x, y = first[0], first[1]
        corners[0, 0], corners[0, 1] = x, y
        inside = 2.0 <= x <= 18.0 and 2.0 <= y <= 18.0
        for k in range(walls):
            if k:
                side = -1.0 if rng.integers(0, 2) == 0 else 1.0
                heading += side * rng.uniform(math.pi / 6, 5 * math.pi / 6)
            length = rng.uniform(3.0, 7.0)
            x, y = x + length * math.cos(heading), y + length * math.sin(heading)
            corners[k + 1, 0], corners[k + 1, 1] = x, y
            inside = inside and 2.0 <= x <= 18.0 and 2.0 <= y <= 18.0
        count = walls + 1
        if inside:
            break
    return count


@jit
def place_starts(rng, scene, corners, offset, side, out):
    """Start poses beside the walls of a course into ``out`` (B, 4): x, y and the unit heading
    (cos, sin), parallel to a wall, ``offset`` from it with the wall on ``side`` (+1 left).

    ``corners`` (W + 1, 2) are the course's corners, ``scene`` its packed world
    (:mod:`fuzzynav.kernels.layout`). Draws, each for all B robots before the next: the wall
    (``integers(0, W, B)``), where along it (``uniform(0.3, 0.7, B)`` of its length) and the
    direction (``random(B)`` < 0.5: against the wall's). A start
    closer than :data:`CLEAR` to an obstacle or the boundary turns to the other direction, once;
    if that one is blocked too, the heading turns back while the position stays (the rule the
    training courses were drawn with)."""
    batch = out.shape[0]
    which = rng.integers(0, corners.shape[0] - 1, batch)
    along = rng.uniform(0.3, 0.7, batch)
    against = rng.random(batch)
    near = np.empty(NEAREST_COLUMNS)
    shift = side * offset
    for n in range(batch):
        w = which[n]
        ax, ay = corners[w, 0], corners[w, 1]
        dx, dy = corners[w + 1, 0] - ax, corners[w + 1, 1] - ay
        px, py = ax + along[n] * dx, ay + along[n] * dy
        length = np.hypot(dx, dy)
        hx, hy = dx / length, dy / length
        if against[n] < 0.5:
            hx, hy = -hx, -hy
        for _ in range(2):
            x, y = px - shift * -hy, py - shift * hx
            nearest_one(scene, x, y, near)
            if not (near[0] < CLEAR or near[4] < CLEAR):
                break
            hx, hy = -hx, -hy
        out[n, 0], out[n, 1], out[n, 2], out[n, 3] = x, y, hx, hy


@jit
def pack_walls(width, height, vertices):
    """The scene array of a ``width`` × ``height`` world whose obstacles are the rectangles
    ``vertices`` (W, 4, 2) (walls' corners): bit for bit ``layout.pack(width, height, [],
    vertices, [])`` — each centre summed vertex after vertex and divided by the vertex count,
    each squared edge length ``ex·ex + ey·ey``, the bounding radius the largest ``hypot`` to a
    corner."""
    walls, count = vertices.shape[0], vertices.shape[1]
    at_edges = layout.HEADER + 5 * walls
    end = at_edges + 7 * walls * count
    scene = np.empty(end)
    scene[layout.WIDTH], scene[layout.HEIGHT] = width, height
    scene[layout.N_CIRCLES], scene[layout.N_POLYGONS] = 0.0, walls
    scene[layout.N_EDGES], scene[layout.N_ELLIPSES] = walls * count, 0.0
    scene[layout.AT_CIRCLES], scene[layout.AT_POLYGONS] = layout.HEADER, layout.HEADER
    scene[layout.AT_EDGES], scene[layout.AT_ELLIPSES] = at_edges, end
    for p in range(walls):
        row = layout.HEADER + 5 * p
        cx, cy = vertices[p, 0, 0], vertices[p, 0, 1]
        for k in range(1, count):
            cx += vertices[p, k, 0]
            cy += vertices[p, k, 1]
        cx, cy = cx / count, cy / count
        radius = -math.inf
        for k in range(count):
            radius = max(radius, np.hypot(vertices[p, k, 0] - cx, vertices[p, k, 1] - cy))
            at = at_edges + 7 * (p * count + k)
            nxt = (k + 1) % count
            ax, ay, bx, by = vertices[p, k, 0], vertices[p, k, 1], vertices[p, nxt, 0], vertices[p, nxt, 1]
            ex, ey = bx - ax, by - ay
            scene[at], scene[at + 1], scene[at + 2], scene[at + 3] = ax, ay, bx, by
            scene[at + 4], scene[at + 5], scene[at + 6] = ex, ey, ex * ex + ey * ey
        scene[row], scene[row + 1] = p * count, (p + 1) * count
        scene[row + 2], scene[row + 3], scene[row + 4] = cx, cy, radius
    return scene
