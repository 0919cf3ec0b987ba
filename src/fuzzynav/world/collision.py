"""Vectorised geometric kernels: distances to and ray hits on many shapes at once.

Every function takes ``points`` / ray ``origins`` ``(N, 2)`` and a packed set of K shapes, and
returns ``(N, K)`` arrays, so one call answers for all robots (or all sensor rays) and all
obstacles together. Rays are ``origin + t · direction`` with unit directions; a ray that misses
gives ``t = inf``. Used by :class:`fuzzynav.world.world.World`.
"""

from __future__ import annotations

import math

import numpy as np


def segment_distance(points, a, b):
    """Distances ``(N, M)`` and nearest points ``(N, M, 2)`` from points to segments a–b ``(M, 2)``."""
    e = b - a  # (M, 2)
    length2 = np.einsum("ij,ij->i", e, e)
    rel = points[:, None, :] - a[None, :, :]  # (N, M, 2)
    u = np.clip(np.einsum("nmk,mk->nm", rel, e) / length2, 0.0, 1.0)
    nearest = a[None, :, :] + u[..., None] * e[None, :, :]
    diff = points[:, None, :] - nearest
    return np.hypot(diff[..., 0], diff[..., 1]), nearest


def crossings(points, a, b):
    """Even-odd test parts ``(N, M)``: does the ray from each point towards +x cross segment a–b."""
    px, py = points[:, 0:1], points[:, 1:2]
    ay, by = a[None, :, 1], b[None, :, 1]
    straddles = (ay > py) != (by > py)
    with np.errstate(divide="ignore", invalid="ignore"):
        x_cross = a[None, :, 0] + (py - ay) * (b[None, :, 0] - a[None, :, 0]) / (by - ay)
    return straddles & (px < x_cross)


def ellipse_frame(points, centers, angles):
    """Points ``(N, 2)`` in the frames of K ellipses, ``(N, K, 2)`` (rotated, not scaled)."""
    c, s = np.cos(angles), np.sin(angles)
    rel = points[:, None, :] - centers[None, :, :]
    return np.stack([c * rel[..., 0] + s * rel[..., 1], -s * rel[..., 0] + c * rel[..., 1]], axis=-1)


def ellipse_nearest(local, radii, iterations: int = 4):
    """Nearest points on ellipses (frame coordinates) to ``local`` ``(N, K, 2)``.

    A fixed-point iteration on the evolute (the curvature-centre method): it converges from
    inside and outside in a few steps and needs no branches, so it vectorises. Works in the
    first quadrant (the ellipse is symmetric) and restores the signs at the end.
    """
    a, b = radii[:, 0], radii[:, 1]
    c2 = a * a - b * b
    ka, kb = c2 / a, -c2 / b
    px, py = np.abs(local[..., 0]), np.abs(local[..., 1])
    tx = np.full(px.shape, np.sqrt(0.5))
    ty = tx.copy()
    for _ in range(iterations):
        ex, ey = ka * tx * tx * tx, kb * ty * ty * ty  # centre of curvature at (a tx, b ty)
        qx, qy = px - ex, py - ey
        ratio = np.hypot(a * tx - ex, b * ty - ey) / np.maximum(np.hypot(qx, qy), 1e-12)
        tx = np.minimum(np.maximum((qx * ratio + ex) / a, 0.0), 1.0)
        ty = np.minimum(np.maximum((qy * ratio + ey) / b, 0.0), 1.0)
        norm = np.hypot(tx, ty)
        tx, ty = tx / norm, ty / norm
    return np.stack([np.copysign(a * tx, local[..., 0]), np.copysign(b * ty, local[..., 1])], axis=-1)


def ray_segments(origins, directions, a, b):
    """Hit distances ``(R, M)`` of rays on segments a–b (2-D broadcasting, no (R, M, 2) temporaries)."""
    ex, ey = (b[:, 0] - a[:, 0])[None, :], (b[:, 1] - a[:, 1])[None, :]
    dx, dy = directions[:, 0:1], directions[:, 1:2]
    rx, ry = a[None, :, 0] - origins[:, 0:1], a[None, :, 1] - origins[:, 1:2]
    denom = dx * ey - dy * ex
    with np.errstate(divide="ignore", invalid="ignore"):
        inverse = 1.0 / denom
        t = (rx * ey - ry * ex) * inverse
        u = (rx * dy - ry * dx) * inverse
    hit = (t >= 0.0) & (u >= 0.0) & (u <= 1.0)  # parallel rays give inf/nan and fail these tests
    return np.where(hit, t, np.inf)


def _quadratic_first_hit(half_b, c, a=1.0):
    """Smallest t ≥ 0 solving a t² + 2 half_b t + c = 0 (inf when none)."""
    disc = half_b * half_b - a * c
    root = np.sqrt(np.maximum(disc, 0.0))
    t1 = (-half_b - root) / a
    t2 = (-half_b + root) / a
    t = np.where(t1 >= 0.0, t1, t2)
    return np.where((disc >= 0.0) & (t >= 0.0), t, np.inf)


def ray_circles(origins, directions, centers, radii):
    """Hit distances ``(R, C)`` of rays on circles (from inside: distance to the surface)."""
    f = origins[:, None, :] - centers[None, :, :]
    half_b = np.einsum("rck,rk->rc", f, directions)
    c = np.einsum("rck,rck->rc", f, f) - radii[None, :] ** 2
    return _quadratic_first_hit(half_b, c)


def ray_ellipses(origins, directions, centers, radii, angles):
    """Hit distances ``(R, E)`` of rays on ellipses: rays mapped to the ellipse frame, scaled to
    the unit circle, where |o' + t d'| = 1 is a quadratic in the same t."""
    o = ellipse_frame(origins, centers, angles) / radii[None, :, :]
    d = ellipse_frame(directions, np.zeros_like(centers), angles) / radii[None, :, :]
    a = np.einsum("rek,rek->re", d, d)
    half_b = np.einsum("rek,rek->re", o, d)
    c = np.einsum("rek,rek->re", o, o) - 1.0
    return _quadratic_first_hit(half_b, c, a)


def ray_box(origins, directions, width, height):
    """Distances ``(R,)`` from origins inside [0, W] × [0, H] to its sides along the rays."""
    with np.errstate(divide="ignore", invalid="ignore"):
        tx = np.where(directions[:, 0] > 0, (width - origins[:, 0]) / directions[:, 0],
                      np.where(directions[:, 0] < 0, -origins[:, 0] / directions[:, 0], np.inf))
        ty = np.where(directions[:, 1] > 0, (height - origins[:, 1]) / directions[:, 1],
                      np.where(directions[:, 1] < 0, -origins[:, 1] / directions[:, 1], np.inf))
    return np.maximum(np.minimum(tx, ty), 0.0)


class ScalarScene:
    """The packed shapes of a world as plain Python floats, for queries of one point / one
    robot at a time, where NumPy's fixed cost per call would dominate (the one-robot simulator
    step). Same formulas and the same tie-breaking as the vectorised kernels above
    (``tests/world/test_scalar_scene.py`` checks them against each other); a bounding-disc
    broad phase skips the shapes that cannot change an answer.

    Columns ``k`` follow :class:`~fuzzynav.world.world.World`'s ``_packed["order"]``: circles,
    then polygons and walls, then ellipses.
    """

    def __init__(self, packed: dict, width: float, height: float):
        self.width, self.height = float(width), float(height)
        k = 0
        self.circles = []  # (column, cx, cy, r)
        for (cx, cy), r in zip(packed["circle_center"].tolist(), packed["circle_radius"].tolist()):
            self.circles.append((k, cx, cy, r))
            k += 1
        self.polygons = []  # (column, mx, my, reach, edges); edge = (ax, ay, bx, by, ex, ey, |e|²)
        ends = list(packed["polygon_start"][1:]) + [len(packed["seg_a"])]
        for start, end in zip(packed["polygon_start"].tolist(), ends):
            a, b = packed["seg_a"][start:end], packed["seg_b"][start:end]
            mid = a.mean(axis=0)
            reach = float(np.hypot(*(a - mid).T).max())
            edges = tuple((ax, ay, bx, by, bx - ax, by - ay, (bx - ax) ** 2 + (by - ay) ** 2)
                          for (ax, ay), (bx, by) in zip(a.tolist(), b.tolist()))
            self.polygons.append((k, float(mid[0]), float(mid[1]), reach, edges))
            k += 1
        self.ellipses = []  # (column, cx, cy, a, b, cos, sin, reach)
        for (cx, cy), (ra, rb), angle, reach in zip(packed["ellipse_center"].tolist(), packed["ellipse_radii"].tolist(),
                                                    packed["ellipse_angle"].tolist(), packed["ellipse_reach"].tolist()):
            self.ellipses.append((k, cx, cy, ra, rb, math.cos(angle), math.sin(angle), reach))
            k += 1
        # (kind, shape, cx, cy, bounding radius) for the ray broad phase; kind 0 circle, 1 polygon, 2 ellipse
        self.discs = ([(0, s, s[1], s[2], s[3]) for s in self.circles]
                      + [(1, s, s[1], s[2], s[3]) for s in self.polygons]
                      + [(2, s, s[1], s[2], s[7]) for s in self.ellipses])
        self._reach_cache = (math.nan, math.nan, math.nan, ())  # see _reachable

    # -- distances ---------------------------------------------------------------------------
    def nearest(self, px: float, py: float):
        """Nearest obstacle to (px, py): ``(signed distance, x, y, column)``, or
        ``(inf, nan, nan, -1)`` without obstacles — :meth:`World.nearest_obstacle` for one point."""
        if px != px or py != py:  # NaN: as the vectorised argmin over a row of NaNs
            return (math.nan, math.nan, math.nan, 0) if self.discs else (math.inf, math.nan, math.nan, -1)
        best, bx, by, col = math.inf, math.nan, math.nan, -1
        hypot = math.hypot
        for k, cx, cy, r in self.circles:
            rx, ry = px - cx, py - cy
            norm = hypot(rx, ry)
            if norm - r < best:
                best, col = norm - r, k
                if norm > 0:
                    bx, by = cx + r * (rx / norm), cy + r * (ry / norm)
                else:
                    bx, by = cx + r, cy
        for k, mx, my, reach, edges in self.polygons:
            if hypot(px - mx, py - my) - reach > best + 1e-9:  # lower bound of the signed distance
                continue
            d, nx, ny, inside = polygon_distance(px, py, edges)
            d = -d if inside else d
            if d < best:
                best, bx, by, col = d, nx, ny, k
        others = best  # ellipses whose bounding disc is beyond every circle and polygon are skipped
        for k, cx, cy, ra, rb, c, s, reach in self.ellipses:
            rx, ry = px - cx, py - cy
            lx, ly = c * rx + s * ry, -s * rx + c * ry
            lower = hypot(lx, ly) - reach
            if not lower < others:  # never below ``best``: the vectorised path's pruning
                continue
            fx, fy = ellipse_foot(lx, ly, ra, rb)
            gap = hypot(lx - fx, ly - fy)
            d = -gap if (lx / ra) ** 2 + (ly / rb) ** 2 < 1.0 else gap
            if d < best:
                best, col = d, k
                bx, by = cx + (c * fx - s * fy), cy + (s * fx + c * fy)
        return best, bx, by, col

    # -- rays --------------------------------------------------------------------------------
    SLACK = 1.0  # (m) a robot moves this far before its set of reachable shapes is rebuilt

    def _reachable(self, x: float, y: float, max_range: float):
        """Shapes whose bounding disc comes within ``max_range`` of (x, y), as (kind, shape, cx,
        cy, R grown by a rounding margin). Cached for the last place asked: the set built there
        for ``max_range + SLACK`` holds every such shape anywhere within SLACK of it."""
        x0, y0, horizon, shapes = self._reach_cache
        if horizon == max_range and math.hypot(x - x0, y - y0) <= self.SLACK - 1e-6:
            return shapes
        shapes = tuple((kind, shape, cx, cy, radius * (1.0 + 1e-9) + 1e-9)
                       for kind, shape, cx, cy, radius in self.discs
                       if math.hypot(cx - x, cy - y) - radius < max_range + self.SLACK)
        self._reach_cache = (x, y, max_range, shapes)
        return shapes

    def ranges(self, x: float, y: float, theta: float, angles, max_range: float) -> list[float]:
        """Readings of rays from (x, y) at headings θ + angle, capped at ``max_range`` —
        :meth:`World.ranges` for one pose without noise."""
        near = []  # (kind, rx, ry, |r|², R, what the exact test needs from this origin)
        for kind, shape, cx, cy, grown in self._reachable(x, y, max_range):
            rx, ry = cx - x, cy - y
            rr = rx * rx + ry * ry
            if kind == 0:  # circle: origin − centre is (−rx, −ry); the constant of its quadratic
                extra = rr - shape[3] ** 2
            elif kind == 1:  # polygon: its edges
                extra = shape[4]
            else:  # ellipse: origin in the unit-circle frame and the constant of its quadratic
                _, _, _, ra, rb, c, s, _ = shape
                ox, oy = (c * -rx + s * -ry) / ra, (-s * -rx + c * -ry) / rb
                extra = (ox, oy, ox * ox + oy * oy - 1.0, c, s, ra, rb)
            near.append((kind, rx, ry, rr, grown, extra))
        width, height = self.width, self.height
        out = []
        for angle in angles:
            heading = theta + angle
            dx, dy = math.cos(heading), math.sin(heading)
            tx = (width - x) / dx if dx > 0 else (-x / dx if dx < 0 else math.inf)
            ty = (height - y) / dy if dy > 0 else (-y / dy if dy < 0 else math.inf)
            best = ty if ty < tx else tx  # = max(min(tx, ty), 0), then the range cap
            if best < 0.0:
                best = 0.0
            if max_range < best:
                best = max_range
            for kind, rx, ry, rr, grown, extra in near:
                along = rx * dx + ry * dy
                if along + grown < 0.0 or along - grown >= best or rr - along * along > grown * grown:
                    continue  # the ray misses the bounding disc, or meets it beyond the best hit
                if kind == 1:
                    t = ray_polygon(x, y, dx, dy, extra)
                elif kind == 0:
                    t = quadratic_first_hit(-along, extra, 1.0)
                else:
                    ox, oy, const, c, s, ra, rb = extra
                    ux, uy = (c * dx + s * dy) / ra, (-s * dx + c * dy) / rb
                    t = quadratic_first_hit(ox * ux + oy * uy, const, ux * ux + uy * uy)
                if t < best:
                    best = t
            out.append(best)
        return out


def quadratic_first_hit(half_b: float, c: float, a: float) -> float:
    """Scalar :func:`_quadratic_first_hit`: smallest t ≥ 0 of a t² + 2 half_b t + c = 0, or inf."""
    disc = half_b * half_b - a * c
    if disc < 0.0:
        return math.inf
    root = math.sqrt(disc)
    t = (-half_b - root) / a
    if t < 0.0:
        t = (-half_b + root) / a
    return t if t >= 0.0 else math.inf


def ray_polygon(x, y, dx, dy, edges) -> float:
    """Scalar :func:`ray_segments` over one polygon's edges: the nearest hit (inf when none)."""
    best = math.inf
    for ax, ay, _, _, ex, ey, _ in edges:
        denom = dx * ey - dy * ex
        if denom == 0.0:
            continue
        inverse = 1.0 / denom
        rx, ry = ax - x, ay - y
        t = (rx * ey - ry * ex) * inverse
        if 0.0 <= t < best:
            u = (rx * dy - ry * dx) * inverse
            if 0.0 <= u <= 1.0:
                best = t
    return best


def polygon_distance(px, py, edges):
    """Scalar :func:`segment_distance` and :func:`crossings` over one polygon's edges:
    ``(distance to the boundary, nearest x, nearest y, inside)`` (first nearest edge on ties)."""
    best, bx, by, crossing = math.inf, math.nan, math.nan, False
    for ax, ay, bx_, by_, ex, ey, length2 in edges:
        u = ((px - ax) * ex + (py - ay) * ey) / length2
        u = 0.0 if u < 0.0 else (1.0 if u > 1.0 else u)
        nx, ny = ax + u * ex, ay + u * ey
        d = math.hypot(px - nx, py - ny)
        if d < best:
            best, bx, by = d, nx, ny
        if (ay > py) != (by_ > py) and px < ax + (py - ay) * (bx_ - ax) / (by_ - ay):
            crossing = not crossing
    return best, bx, by, crossing


def ellipse_foot(lx: float, ly: float, a: float, b: float, iterations: int = 4):
    """Scalar :func:`ellipse_nearest`: foot point on the ellipse (frame coordinates) nearest to
    (lx, ly), by the same curvature-centre iteration."""
    c2 = a * a - b * b
    ka, kb = c2 / a, -c2 / b
    px, py = abs(lx), abs(ly)
    tx = ty = math.sqrt(0.5)
    for _ in range(iterations):
        ex, ey = ka * tx * tx * tx, kb * ty * ty * ty
        qx, qy = px - ex, py - ey
        ratio = math.hypot(a * tx - ex, b * ty - ey) / max(math.hypot(qx, qy), 1e-12)
        tx = min(max((qx * ratio + ex) / a, 0.0), 1.0)
        ty = min(max((qy * ratio + ey) / b, 0.0), 1.0)
        norm = math.hypot(tx, ty)
        tx, ty = tx / norm, ty / norm
    return math.copysign(a * tx, lx), math.copysign(b * ty, ly)
