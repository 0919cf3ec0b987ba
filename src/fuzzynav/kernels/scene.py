"""Rays and nearest obstacle of many robots in one world, compiled (thesis §IV.7, Table IV.2), over
the packed shapes of :mod:`fuzzynav.kernels.layout`.

Rays are ``origin + t · direction``; a ray starting inside a shape measures the distance to its
surface. Distances are signed: negative inside an obstacle (or outside the world rectangle).
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels.layout import (
    AT_CIRCLES,
    AT_EDGES,
    AT_ELLIPSES,
    AT_POLYGONS,
    HEIGHT,
    N_CIRCLES,
    N_ELLIPSES,
    N_POLYGONS,
    WIDTH,
)
from fuzzynav.kernels.motion import ring_gap


@jit
def quadratic_first_hit(half_b, c, a):
    """Smallest t ≥ 0 of a t² + 2 half_b t + c = 0, or inf."""
    disc = half_b * half_b - a * c
    if disc < 0.0:
        return math.inf
    root = math.sqrt(disc)
    t = (-half_b - root) / a
    if t < 0.0:
        t = (-half_b + root) / a
    return t if t >= 0.0 else math.inf


@jit
def ray_polygon(scene, first, end, x, y, dx, dy):
    """Nearest hit of the ray on the edges ``first … end − 1`` (inf when none)."""
    best = math.inf
    for i in range(first, end):
        at = int(scene[AT_EDGES]) + 7 * i
        ex, ey = scene[at + 4], scene[at + 5]
        denom = dx * ey - dy * ex
        if denom == 0.0:
            continue
        inverse = 1.0 / denom
        rx, ry = scene[at] - x, scene[at + 1] - y
        t = (rx * ey - ry * ex) * inverse
        if 0.0 <= t < best:
            u = (rx * dy - ry * dx) * inverse
            if 0.0 <= u <= 1.0:
                best = t
    return best


@jit
def bounding_disc(scene, column):
    """(kind 0 circle / 1 polygon / 2 ellipse, row offset, cx, cy, bounding radius) of a column."""
    n_c, n_p = int(scene[N_CIRCLES]), int(scene[N_POLYGONS])
    if column < n_c:
        at = int(scene[AT_CIRCLES]) + 3 * column
        return 0, at, scene[at], scene[at + 1], scene[at + 2]
    if column < n_c + n_p:
        at = int(scene[AT_POLYGONS]) + 5 * (column - n_c)
        return 1, at, scene[at + 2], scene[at + 3], scene[at + 4]
    at = int(scene[AT_ELLIPSES]) + 7 * (column - n_c - n_p)
    return 2, at, scene[at], scene[at + 1], scene[at + 6]


@jit
def near_columns(scene, x, y, max_range, near):
    """Broad phase: list in ``near`` (scratch, one slot per column) the shapes whose bounding
    disc (grown by a rounding margin) comes within ``max_range`` of (x, y); returns how many."""
    total = int(scene[N_CIRCLES] + scene[N_POLYGONS] + scene[N_ELLIPSES])
    count = 0
    for column in range(total):
        _, _, cx, cy, radius = bounding_disc(scene, column)
        reach = max_range + radius * (1.0 + 1e-9) + 1e-6  # a superset of the discs within range
        if (cx - x) ** 2 + (cy - y) ** 2 < reach * reach:
            near[count] = column
            count += 1
    return count


@jit
def ranges_one(scene, x, y, theta, angles, max_range, out, near):
    """Readings of rays from (x, y) at headings θ + angles, capped at ``max_range``, into ``out``
    (``near``: scratch of :func:`near_columns`)."""
    cast(scene, x, y, theta, angles, max_range, out, near[:near_columns(scene, x, y, max_range, near)])


@jit
def cast(scene, x, y, theta, angles, max_range, out, near):
    """The rays of :func:`ranges_one` against the walls and the shapes listed in ``near`` (the
    columns of :func:`near_columns`); a ray skips a disc it misses or meets beyond its best hit
    so far."""
    count = near.shape[0]
    width, height = scene[WIDTH], scene[HEIGHT]
    for j in range(angles.shape[0]):
        heading = theta + angles[j]
        dx, dy = math.cos(heading), math.sin(heading)
        tx = (width - x) / dx if dx > 0 else (-x / dx if dx < 0 else math.inf)
        ty = (height - y) / dy if dy > 0 else (-y / dy if dy < 0 else math.inf)
        best = ty if ty < tx else tx
        if best < 0.0:
            best = 0.0
        if max_range < best:
            best = max_range
        for q in range(count):
            kind, at, cx, cy, radius = bounding_disc(scene, near[q])
            grown = radius * (1.0 + 1e-9) + 1e-9
            rx, ry = cx - x, cy - y
            rr = rx * rx + ry * ry
            along = rx * dx + ry * dy
            if along + grown < 0.0 or along - grown >= best or rr - along * along > grown * grown:
                continue
            if kind == 1:
                t = ray_polygon(scene, int(scene[at]), int(scene[at + 1]), x, y, dx, dy)
            elif kind == 0:
                t = quadratic_first_hit(-along, rr - scene[at + 2] ** 2, 1.0)
            else:
                ra, rb, c, s = scene[at + 2], scene[at + 3], scene[at + 4], scene[at + 5]
                ox, oy = (c * -rx + s * -ry) / ra, (-s * -rx + c * -ry) / rb
                ux, uy = (c * dx + s * dy) / ra, (-s * dx + c * dy) / rb
                t = quadratic_first_hit(ox * ux + oy * uy, ox * ox + oy * oy - 1.0, ux * ux + uy * uy)
            if t < best:
                best = t
        out[j] = best


@jit
def polygon_distance(scene, first, end, px, py):
    """(distance to the boundary of the polygon of edges first … end − 1, nearest x, y, inside)
    (first nearest edge on ties; inside by the even-odd rule)."""
    best, bx, by, crossing = math.inf, math.nan, math.nan, False
    for i in range(first, end):
        at = int(scene[AT_EDGES]) + 7 * i
        ax, ay, bx_, by_, ex, ey, length2 = (scene[at], scene[at + 1], scene[at + 2], scene[at + 3],
                                             scene[at + 4], scene[at + 5], scene[at + 6])
        u = ((px - ax) * ex + (py - ay) * ey) / length2
        u = 0.0 if u < 0.0 else (1.0 if u > 1.0 else u)
        nx, ny = ax + u * ex, ay + u * ey
        d = ring_gap(px - nx, py - ny, 0.0, best)
        if d < best:
            best, bx, by = d, nx, ny
        if (ay > py) != (by_ > py) and px < ax + (py - ay) * (bx_ - ax) / (by_ - ay):
            crossing = not crossing
    return best, bx, by, crossing


@jit
def ellipse_foot(lx, ly, a, b):
    """Foot point on the ellipse of radii a, b (its own frame) nearest to (lx, ly): a fixed-point
    iteration on the evolute (the curvature-centre method), 4 steps, first quadrant by symmetry."""
    c2 = a * a - b * b
    ka, kb = c2 / a, -c2 / b
    px, py = abs(lx), abs(ly)
    tx = ty = math.sqrt(0.5)
    for _ in range(4):
        ex, ey = ka * tx * tx * tx, kb * ty * ty * ty
        qx, qy = px - ex, py - ey
        ratio = math.hypot(a * tx - ex, b * ty - ey) / max(math.hypot(qx, qy), 1e-12)
        tx = min(max((qx * ratio + ex) / a, 0.0), 1.0)
        ty = min(max((qy * ratio + ey) / b, 0.0), 1.0)
        norm = math.hypot(tx, ty)
        tx, ty = tx / norm, ty / norm
    return math.copysign(a * tx, lx), math.copysign(b * ty, ly)


@jit
def nearest_one(scene, px, py, out):
    """Nearest obstacle (boundary excluded) to (px, py) into ``out`` (:data:`NEAREST_COLUMNS`):
    (inf, nan, nan, −1) without obstacles. Polygons and ellipses whose bounding disc cannot beat
    the best so far are skipped."""
    width, height = scene[WIDTH], scene[HEIGHT]
    n_c, n_p, n_e = int(scene[N_CIRCLES]), int(scene[N_POLYGONS]), int(scene[N_ELLIPSES])
    out[4] = min(min(px, width - px), min(py, height - py)) if px == px and py == py else math.nan
    if px != px or py != py:
        out[0], out[1], out[2], out[3] = (math.nan if n_c + n_p + n_e else math.inf), math.nan, math.nan, 0
        return
    best, bx, by, col = math.inf, math.nan, math.nan, -1
    for k in range(n_c):
        at = int(scene[AT_CIRCLES]) + 3 * k
        cx, cy, r = scene[at], scene[at + 1], scene[at + 2]
        rx, ry = px - cx, py - cy
        norm = ring_gap(rx, ry, 0.0, best + r)
        if norm - r < best:
            best, col = norm - r, k
            if norm > 0:
                bx, by = cx + r * (rx / norm), cy + r * (ry / norm)
            else:
                bx, by = cx + r, cy
    for k in range(n_p):
        at = int(scene[AT_POLYGONS]) + 5 * k
        if math.sqrt((px - scene[at + 2]) ** 2 + (py - scene[at + 3]) ** 2) - scene[at + 4] > best + 2e-9:
            continue  # a lower bound of the signed distance (the polygon lies in its bounding disc)
        d, nx, ny, inside = polygon_distance(scene, int(scene[at]), int(scene[at + 1]), px, py)
        d = -d if inside else d
        if d < best:
            best, bx, by, col = d, nx, ny, n_c + k
    others = best
    for k in range(n_e):
        at = int(scene[AT_ELLIPSES]) + 7 * k
        cx, cy, ra, rb, c, s = scene[at], scene[at + 1], scene[at + 2], scene[at + 3], scene[at + 4], scene[at + 5]
        rx, ry = px - cx, py - cy
        lx, ly = c * rx + s * ry, -s * rx + c * ry
        if not math.sqrt(lx * lx + ly * ly) - scene[at + 6] < others + 1e-9:
            continue  # beyond every circle and polygon
        fx, fy = ellipse_foot(lx, ly, ra, rb)
        gap = math.hypot(lx - fx, ly - fy)
        d = -gap if (lx / ra) ** 2 + (ly / rb) ** 2 < 1.0 else gap
        if d < best:
            best, col = d, n_c + n_p + k
            bx, by = cx + (c * fx - s * fy), cy + (s * fx + c * fy)
    out[0], out[1], out[2], out[3] = best, bx, by, col


@jit
def nearest(scene, points, out):
    """:func:`nearest_one` of every row of ``points`` (N, 2) into ``out`` (N, 5)."""
    for n in range(points.shape[0]):
        nearest_one(scene, points[n, 0], points[n, 1], out[n])


@jit
def nearest_worlds(scenes, bounds, points, out):
    """:func:`nearest_one` of point n (``points`` (N, 2)) in its own world: the scene array
    ``scenes[bounds[n, 0]:bounds[n, 1]]`` (several worlds' arrays concatenated) into ``out`` (N, 5)."""
    for n in range(points.shape[0]):
        nearest_one(scenes[bounds[n, 0]:bounds[n, 1]], points[n, 0], points[n, 1], out[n])


@jit
def joined(scene, xs, ys, radius, start, goal):
    """Do the grid cells ``start`` and ``goal`` (row, column) lie in one 4-connected region of the
    free cells — those whose centre (``xs[column]``, ``ys[row]``) keeps ``radius`` from every
    obstacle and the boundary? A flood fill from ``start`` that measures a cell's clearance
    (:func:`nearest_one`) only when it reaches it, and stops at ``goal``."""
    ny, nx = ys.shape[0], xs.shape[0]
    seen = np.zeros(ny * nx, dtype=np.bool_)  # reached, or found blocked
    queue = np.empty(ny * nx, dtype=np.int64)
    out = np.empty(5)
    first, target = start[0] * nx + start[1], goal[0] * nx + goal[1]
    head = tail = 0
    queue[tail], tail, seen[first] = first, tail + 1, True
    while head < tail:
        here = queue[head]
        head += 1
        row, col = here // nx, here % nx
        nearest_one(scene, xs[col], ys[row], out)
        if not min(out[0], out[4]) >= radius:
            continue
        if here == target:
            return True
        for dr, dc in ((1, 0), (-1, 0), (0, 1), (0, -1)):
            r, c = row + dr, col + dc
            if 0 <= r < ny and 0 <= c < nx and not seen[r * nx + c]:
                seen[r * nx + c] = True
                queue[tail], tail = r * nx + c, tail + 1
    return False
