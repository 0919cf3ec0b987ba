"""The world: a rectangle [0, W] × [0, H] bounded by walls, with obstacles (docs/thesis.md: conventions).

Every figure of the thesis uses a 20 m × 20 m workspace with the origin bottom-left. The shapes
are packed into one array when the world is built (:func:`fuzzynav.kernels.layout.pack`, each
obstacle as its type's ``primitive`` and ``packed()`` row, :mod:`fuzzynav.world.shapes`); every
query runs the compiled kernels of :mod:`fuzzynav.kernels.scene` over all points / robots (numba is
imported at the first query).

Distances are *signed*: negative inside an obstacle (or outside the world for the boundary).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from fuzzynav.kernels import layout
from fuzzynav.world import limits
from fuzzynav.world.shapes import Shape


@dataclass(frozen=True)
class World:
    """Workspace ``width`` × ``height`` (m) with ``obstacles`` (the boundary is not one of them);
    ``motions``, empty or one per obstacle, gives each moving obstacle its
    :class:`~fuzzynav.world.moving.ObstacleMotion` (``None``: it stands still). ``scene`` packs
    the obstacles where they are at t = 0; :mod:`fuzzynav.world.moving` gives the moving ones'
    offsets over time and :attr:`movers` their rows in ``scene``."""

    width: float = 20.0
    height: float = 20.0
    obstacles: tuple[Shape, ...] = ()
    motions: tuple = ()
    scene: np.ndarray = field(init=False, repr=False, compare=False)  # the packed shapes
    order: np.ndarray = field(init=False, repr=False, compare=False)  # kernel column -> obstacle index (−1 -> −1)

    def __post_init__(self):
        object.__setattr__(self, "obstacles", tuple(self.obstacles))
        width, height = limits.world_size(self.width, self.height)
        object.__setattr__(self, "width", width)
        object.__setattr__(self, "height", height)
        limits.world_contents(self.obstacles, width, height)
        columns, order = _kernel_columns(self.obstacles)
        packed = layout.pack(self.width, self.height, *([self.obstacles[i].packed() for i in columns[primitive]]
                                                         for primitive in layout.PRIMITIVES))
        object.__setattr__(self, "scene", packed)
        object.__setattr__(self, "order", order)
        object.__setattr__(self, "motions", tuple(self.motions))
        if self.motions and len(self.motions) != len(self.obstacles):
            raise ValueError(f"{len(self.motions)} motions for {len(self.obstacles)} obstacles")

    @property
    def moving(self) -> tuple[int, ...]:
        """Indices of the obstacles that move (in obstacle order)."""
        return tuple(i for i, motion in enumerate(self.motions) if motion is not None)

    def standing(self) -> World:
        """This world without its moving obstacles (itself when none moves)."""
        if not self.motions:
            return self
        return World(self.width, self.height, tuple(s for s, m in zip(self.obstacles, self.motions) if m is None))

    @property
    def movers(self) -> np.ndarray:
        """Rows ``(M, 4)`` of the moving obstacles in ``scene`` (:func:`fuzzynav.kernels.layout.mover_rows`),
        in the order of :attr:`moving`."""
        column = {int(index): c for c, index in enumerate(self.order[:-1])}
        return layout.mover_rows(self.scene, [column[i] for i in self.moving])

    @classmethod
    def prepacked(cls, width: float, height: float, obstacles: tuple, scene: np.ndarray) -> World:
        """``World(width, height, obstacles)`` for ``obstacles`` the library has built and checked
        itself and already packed into ``scene`` (the array :func:`fuzzynav.kernels.layout.pack`
        gives for them; :func:`fuzzynav.kernels.courses.pack_walls` for the random wall courses
        of every training episode), without the constructor's checks of the obstacles and its
        packing. Worlds from user input go through the constructor."""
        world = object.__new__(cls)
        width, height = limits.world_size(width, height)
        obstacles = tuple(obstacles)
        columns, order = _kernel_columns(obstacles)
        counts = scene[[layout.N_CIRCLES, layout.N_POLYGONS, layout.N_ELLIPSES]].tolist()
        if counts != [len(columns[primitive]) for primitive in layout.PRIMITIVES]:
            raise ValueError("the packed scene does not hold these obstacles")
        for name, value in (("width", width), ("height", height), ("obstacles", obstacles), ("motions", ()),
                            ("scene", scene), ("order", order)):
            object.__setattr__(world, name, value)
        return world

    # -- distances ---------------------------------------------------------------------------
    def proximity(self, points):
        """Nearest obstacle (boundary excluded) and boundary distance of each point ``(N, 2)``:
        ``(distance (N,), point (N, 2), index (N,), boundary (N,))`` — signed distance to the
        obstacle's surface (inf / nan / −1 in a world without obstacles) and to the walls. D_ro
        and θ_o of Table IV.2 are measured to this point; the clearance is ``min(distance, boundary)``."""
        from fuzzynav.kernels import scene

        points = np.ascontiguousarray(np.asarray(points, dtype=float).reshape(-1, 2))
        out = np.empty((len(points), layout.NEAREST_COLUMNS))
        scene.nearest(self.scene, points, out)
        return out[:, 0], out[:, 1:3], self.order[out[:, 3].astype(int)], out[:, 4]

    def nearest_obstacle(self, points):
        """``(distance, point, index)`` of :meth:`proximity`."""
        return self.proximity(points)[:3]

    def boundary_distance(self, points):
        """Signed distance ``(N,)`` to the boundary walls (negative outside the world)."""
        points = np.asarray(points, dtype=float).reshape(-1, 2)
        x, y = points[:, 0], points[:, 1]
        return np.minimum(np.minimum(x, self.width - x), np.minimum(y, self.height - y))

    def clearance(self, points):
        """Signed distance ``(N,)`` from points to the nearest obstacle surface or boundary."""
        distance, _, _, boundary = self.proximity(points)
        return np.minimum(distance, boundary)

    def clearance_over_time(self, points, offsets):
        """:meth:`clearance` of point k (``points`` (T, 2)) with the moving obstacles at their
        offsets of time k (``offsets`` (T, M, 2), :func:`fuzzynav.world.moving.offsets`)."""
        from fuzzynav.kernels import traffic

        points = np.ascontiguousarray(np.asarray(points, dtype=float).reshape(-1, 2))
        out = np.empty((len(points), layout.NEAREST_COLUMNS))
        traffic.nearest_over_time(self.scene, self.movers, np.ascontiguousarray(offsets, dtype=float), points,
                                  self.scene.copy(), out)
        return np.minimum(out[:, 0], out[:, 4])

    def collides(self, points, radius: float = 0.0):
        """``(N,)`` bool: does a disc of ``radius`` at each point overlap an obstacle or the boundary."""
        return self.clearance(points) < radius

    def contains(self, points):
        """``(N,)`` bool: is each point inside the world rectangle (boundary included)."""
        return self.boundary_distance(points) >= 0.0

    # -- range sensors -----------------------------------------------------------------------
    def ranges(self, poses, angles, max_range: float, beam_width: float = 0.0):
        """Range readings ``(N, S)``: rays from each pose's (x, y) at heading θ + angle, cast
        against every obstacle and the boundary, capped at ``max_range`` (thesis §IV.7).

        A ray starting inside an obstacle measures the distance to its surface.
        ``beam_width`` > 0 (rad) reads the nearest echo inside each sensor's cone instead
        (:mod:`fuzzynav.kernels.beams`).
        """
        from fuzzynav.kernels import beams

        poses = np.ascontiguousarray(np.asarray(poses, dtype=float).reshape(-1, 3))
        angles = np.ascontiguousarray(np.asarray(angles, dtype=float).reshape(-1))
        readings = np.empty((len(poses), len(angles)))
        beams.read(self.scene, poses, angles, 0.5 * float(beam_width), float(max_range), readings)
        return readings


def _kernel_columns(obstacles) -> tuple[dict, np.ndarray]:
    """(obstacle indices of each kernel shape kind (:data:`fuzzynav.kernels.layout.PRIMITIVES`),
    the world's ``order``: kernel column -> obstacle index, and −1 -> −1)."""
    columns = {primitive: [i for i, s in enumerate(obstacles) if s.primitive == primitive]
               for primitive in layout.PRIMITIVES}
    return columns, np.array([i for primitive in layout.PRIMITIVES for i in columns[primitive]] + [-1], dtype=int)
