"""The world: a rectangle [0, W] × [0, H] bounded by walls, with obstacles (issue 3, SPEC §0).

Every figure of the thesis uses a 20 m × 20 m workspace with the origin bottom-left. All queries
are vectorised over many points / robots and over all obstacles at once: the shapes are packed
into arrays (circles, polygon edges — walls are rectangles —, ellipses) when the world is built.

Distances are *signed*: negative inside an obstacle (or outside the world for the boundary).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from fuzzynav.world import collision, limits
from fuzzynav.world.shapes import Circle, Ellipse, Shape


@dataclass(frozen=True)
class World:
    """Workspace ``width`` × ``height`` (m) with ``obstacles`` (the boundary is not one of them)."""

    width: float = 20.0
    height: float = 20.0
    obstacles: tuple[Shape, ...] = ()
    _packed: dict = field(init=False, repr=False, compare=False)
    _scalar: collision.ScalarScene = field(init=False, repr=False, compare=False)
    _order: list = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        object.__setattr__(self, "obstacles", tuple(self.obstacles))
        width, height = limits.world_size(self.width, self.height)
        object.__setattr__(self, "width", width)
        object.__setattr__(self, "height", height)
        limits.world_contents(self.obstacles, width, height)
        circles = [(i, s) for i, s in enumerate(self.obstacles) if isinstance(s, Circle)]
        ellipses = [(i, s) for i, s in enumerate(self.obstacles) if isinstance(s, Ellipse)]
        polygons = [(i, s) for i, s in enumerate(self.obstacles) if not isinstance(s, (Circle, Ellipse))]
        verts = [s.vertices for _, s in polygons]
        starts = np.cumsum([0] + [len(v) for v in verts[:-1]]).astype(int) if verts else np.zeros(0, int)
        seg_a = np.concatenate(verts) if verts else np.zeros((0, 2))
        seg_b = np.concatenate([np.roll(v, -1, axis=0) for v in verts]) if verts else np.zeros((0, 2))
        owner = np.repeat(np.arange(len(verts)), [len(v) for v in verts]) if verts else np.zeros(0, int)
        packed = {
            "circle_index": np.array([i for i, _ in circles], dtype=int),
            "circle_center": np.array([s.center for _, s in circles]).reshape(-1, 2),
            "circle_radius": np.array([s.radius for _, s in circles], dtype=float),
            "ellipse_index": np.array([i for i, _ in ellipses], dtype=int),
            "ellipse_center": np.array([s.center for _, s in ellipses]).reshape(-1, 2),
            "ellipse_radii": np.array([s.radii for _, s in ellipses]).reshape(-1, 2),
            "ellipse_angle": np.array([s.angle for _, s in ellipses], dtype=float),
            "polygon_index": np.array([i for i, _ in polygons], dtype=int),
            "polygon_start": starts,
            "seg_a": seg_a,
            "seg_b": seg_b,
            "seg_owner": owner,
        }
        # bounding discs for the broad phase: segments (midpoint, half length), ellipses (major)
        packed["seg_mid"] = 0.5 * (seg_a + seg_b)
        packed["seg_half"] = 0.5 * np.hypot(*(seg_b - seg_a).T) if len(seg_a) else np.zeros(0)
        packed["ellipse_reach"] = packed["ellipse_radii"].max(axis=1) if ellipses else np.zeros(0)
        order = np.concatenate([packed["circle_index"], packed["polygon_index"], packed["ellipse_index"]])
        packed["order"] = order.astype(int)  # column k of the (N, K) distance matrix -> obstacle index
        object.__setattr__(self, "_packed", packed)
        object.__setattr__(self, "_scalar", collision.ScalarScene(packed, self.width, self.height))
        object.__setattr__(self, "_order", packed["order"].tolist())

    # -- distances ---------------------------------------------------------------------------
    def _distances(self, points, prune: bool = False):
        """Signed distances ``(N, K)`` to every obstacle (columns in ``_packed["order"]``: circles,
        polygons and walls, ellipses) and a function giving the nearest surface points
        ``(N, 2)`` for one chosen column per point.

        With ``prune``, ellipses that cannot be the nearest obstacle of any point (their bounding
        disc is farther than another obstacle) skip the iterative foot-point solve and get a
        lower bound instead: the row minima stay exact, the other entries do not."""
        p = self._packed
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        n = len(points)
        dist, pickers = [], []
        if len(p["circle_radius"]):
            rel = points[:, None, :] - p["circle_center"][None]
            norm = np.hypot(rel[..., 0], rel[..., 1])
            dist.append(norm - p["circle_radius"][None])

            def circle_points(rows, k, rel=rel, norm=norm):
                unit = rel[rows, k] / np.where(norm[rows, k] > 0, norm[rows, k], 1.0)[:, None]
                unit[norm[rows, k] == 0] = (1.0, 0.0)
                return p["circle_center"][k] + p["circle_radius"][k, None] * unit

            pickers.append((len(p["circle_radius"]), circle_points))
        if len(p["polygon_start"]):
            edge_d, edge_near = collision.segment_distance(points, p["seg_a"], p["seg_b"])
            starts = p["polygon_start"]
            inside = np.add.reduceat(collision.crossings(points, p["seg_a"], p["seg_b"]), starts, axis=1) % 2 == 1
            poly_d = np.minimum.reduceat(edge_d, starts, axis=1)
            dist.append(np.where(inside, -poly_d, poly_d))

            def polygon_points(rows, k, edge_d=edge_d, edge_near=edge_near):
                mine = p["seg_owner"][None, :] == k[:, None]  # the chosen polygon's edges
                best = np.argmin(np.where(mine, edge_d[rows], np.inf), axis=1)
                return edge_near[rows, best]

            pickers.append((len(starts), polygon_points))
        if len(p["ellipse_angle"]):
            local = collision.ellipse_frame(points, p["ellipse_center"], p["ellipse_angle"])
            lower = np.hypot(local[..., 0], local[..., 1]) - p["ellipse_reach"][None]
            need = np.arange(len(p["ellipse_angle"]))
            if prune and dist:
                others = np.min([d.min(axis=1) for d in dist], axis=0)
                need = np.flatnonzero(np.any(lower < others[:, None], axis=0))
            foot = np.full(local.shape, np.nan)
            foot[:, need] = collision.ellipse_nearest(local[:, need], p["ellipse_radii"][need])
            gap = np.hypot(local[..., 0] - foot[..., 0], local[..., 1] - foot[..., 1])
            inside = np.sum((local / p["ellipse_radii"][None]) ** 2, axis=-1) < 1.0
            signed = np.where(inside, -gap, gap)
            skipped = np.setdiff1d(np.arange(signed.shape[1]), need)
            signed[:, skipped] = lower[:, skipped]
            dist.append(signed)

            def ellipse_points(rows, k, foot=foot):
                f = foot[rows, k]
                c, s = np.cos(p["ellipse_angle"][k]), np.sin(p["ellipse_angle"][k])
                return p["ellipse_center"][k] + np.stack([c * f[:, 0] - s * f[:, 1], s * f[:, 0] + c * f[:, 1]], -1)

            pickers.append((len(p["ellipse_angle"]), ellipse_points))
        if not dist:
            return np.zeros((n, 0)), None
        distances = np.concatenate(dist, axis=1) if len(dist) > 1 else dist[0]

        def nearest_points(columns):
            out = np.empty((n, 2))
            offset = 0
            for count, pick in pickers:
                rows = np.flatnonzero((columns >= offset) & (columns < offset + count))
                if len(rows):
                    out[rows] = pick(rows, columns[rows] - offset)
                offset += count
            return out

        return distances, nearest_points

    def obstacle_distances(self, points):
        """Signed distances ``(N, K)`` from points to every obstacle surface (negative inside),
        column k being obstacle ``self._packed["order"][k]`` (circles, polygons and walls,
        ellipses)."""
        return self._distances(points)[0]

    def nearest_obstacle(self, points):
        """Nearest obstacle (boundary excluded) to each point: ``(distance (N,), point (N, 2),
        index (N,))`` — signed distance to its surface (inf / nan / −1 in a world without
        obstacles). D_ro and θ_o of Table IV.2 are measured to this point.

        One point goes through the scalar path (:class:`~fuzzynav.world.collision.ScalarScene`),
        many through the vectorised one; both give the same answers."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        if len(points) == 1:
            return self._nearest_one(*points[0].tolist())
        dist, nearest_points = self._distances(points, prune=True)
        n = dist.shape[0]
        if dist.shape[1] == 0:
            return np.full(n, np.inf), np.full((n, 2), np.nan), np.full(n, -1)
        k = np.argmin(dist, axis=1)
        return dist[np.arange(n), k], nearest_points(k), self._packed["order"][k]

    def proximity(self, points):
        """:meth:`nearest_obstacle` and :meth:`boundary_distance` in one call:
        ``(distance, point, index, boundary)``; the clearance is ``min(distance, boundary)``."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        if len(points) == 1:
            x, y = points[0].tolist()
            boundary = min(x, self.width - x, y, self.height - y) if x == x and y == y else math.nan
            return (*self._nearest_one(x, y), np.array([boundary]))
        return (*self.nearest_obstacle(points), self.boundary_distance(points))

    def _nearest_one(self, x: float, y: float):
        """:meth:`nearest_obstacle` of one point, by the scalar path."""
        d, px, py, k = self._scalar.nearest(x, y)
        return np.array([d]), np.array([[px, py]]), np.array([self._order[k] if k >= 0 else -1])

    def boundary_distance(self, points):
        """Signed distance ``(N,)`` to the boundary walls (negative outside the world)."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        x, y = points[:, 0], points[:, 1]
        return np.minimum(np.minimum(x, self.width - x), np.minimum(y, self.height - y))

    def clearance(self, points):
        """Signed distance ``(N,)`` from points to the nearest obstacle surface or boundary."""
        distance, _, _, boundary = self.proximity(points)
        return np.minimum(distance, boundary)

    def collides(self, points, radius: float = 0.0):
        """``(N,)`` bool: does a disc of ``radius`` at each point overlap an obstacle or the boundary."""
        return self.clearance(points) < radius

    def contains(self, points):
        """``(N,)`` bool: is each point inside the world rectangle (boundary included)."""
        return self.boundary_distance(points) >= 0.0

    # -- range sensors -----------------------------------------------------------------------
    def ranges(self, poses, angles, max_range: float, noise_std: float = 0.0, rng: np.random.Generator | None = None):
        """Range readings ``(N, S)``: rays from each pose's (x, y) at heading θ + angle, cast
        against every obstacle and the boundary at once, capped at ``max_range`` (SPEC §3.3).

        ``noise_std`` > 0 adds Gaussian noise from ``rng`` (required then), clipped to
        [0, max_range]. A ray starting inside an obstacle measures the distance to its surface.
        """
        poses = np.asarray(poses, dtype=float).reshape(-1, 3)
        angles = np.asarray(angles, dtype=float).reshape(-1)
        n, s = len(poses), len(angles)
        if n == 1:  # one robot: the scalar path (NumPy's per-call cost would dominate)
            x, y, theta = poses[0].tolist()
            readings = np.array([self._scalar.ranges(x, y, theta, angles.tolist(), max_range)])
            return self._add_noise(readings, max_range, noise_std, rng)
        heading = poses[:, 2:3] + angles[None, :]
        directions = np.stack([np.cos(heading), np.sin(heading)], axis=-1).reshape(-1, 2)
        origins = np.repeat(poses[:, :2], s, axis=0)
        p = self._packed
        best = collision.ray_box(origins, directions, self.width, self.height)

        def reachable(centers, radii):  # broad phase: shapes whose bounding disc some robot reaches
            gap = np.hypot(poses[:, None, 0] - centers[None, :, 0], poses[:, None, 1] - centers[None, :, 1])
            return np.flatnonzero(np.any(gap - radii[None, :] < max_range, axis=0))

        k = reachable(p["circle_center"], p["circle_radius"])
        if len(k):
            hits = collision.ray_circles(origins, directions, p["circle_center"][k], p["circle_radius"][k])
            best = np.minimum(best, hits.min(axis=1))
        k = reachable(p["seg_mid"], p["seg_half"])
        if len(k):
            hits = collision.ray_segments(origins, directions, p["seg_a"][k], p["seg_b"][k])
            best = np.minimum(best, hits.min(axis=1))
        k = reachable(p["ellipse_center"], p["ellipse_reach"])
        if len(k):
            hits = collision.ray_ellipses(origins, directions, p["ellipse_center"][k], p["ellipse_radii"][k],
                                          p["ellipse_angle"][k])
            best = np.minimum(best, hits.min(axis=1))
        return self._add_noise(np.minimum(best, max_range).reshape(n, s), max_range, noise_std, rng)

    @staticmethod
    def _add_noise(readings, max_range, noise_std, rng):
        """Readings plus Gaussian noise of ``noise_std`` from ``rng``, clipped to [0, max_range]."""
        if noise_std > 0.0:
            if rng is None:
                raise ValueError("noisy ranges need an explicit numpy.random.Generator (rng)")
            readings = np.clip(readings + rng.normal(0.0, noise_std, readings.shape), 0.0, max_range)
        return readings
