"""Where a batch of training episodes starts: worlds, start poses and goals (§VI.2, §VI.5).

A layout has ``sample(rng, batch) -> (world, poses (B, 3), targets (B, 2) or None)`` and draws
all its randomness from ``rng``, so training resumed from a checkpoint replays the same episodes.

- :class:`FixedGoal` — the same start and goal every episode (Figs VI.1–VI.2, VI.7–VI.8);
- :class:`RandomGoal` — random start pose and goal in the empty workspace (Figs VI.3–VI.4,
  VI.9–VI.16: "each episode starts from a random position");
- :class:`RandomObstacles` — a new random world of obstacles per batch, the robot starting in
  free space heading towards its goal (§VI.5.2: "the robot starts in a zone free of obstacles
  and heads towards the goal");
- :class:`WallCourse` — a new random course of walls and sharp-cornered polygons per batch, the
  robot starting beside a wall, parallel to it (§VI.5.3, Figs VI.27–VI.30).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fuzzynav.world.shapes import Circle, Polygon, Wall
from fuzzynav.world.world import World

EMPTY = World()
WALL_THICKNESS = 0.3  # m: the walls of the random wall courses


@dataclass(frozen=True)
class FixedGoal:
    """Every episode from ``start`` (x, y, θ) to ``goal`` (x, y) in ``world``."""

    start: tuple = (2.0, 2.0, 0.0)
    goal: tuple = (16.0, 16.0)
    world: World = EMPTY

    def sample(self, rng, batch):
        return (self.world, np.tile(np.asarray(self.start, dtype=float), (batch, 1)),
                np.tile(np.asarray(self.goal, dtype=float), (batch, 1)))


def _free_points(rng, world: World, batch: int, margin: float, clearance: float, tries: int = 64) -> np.ndarray:
    """``batch`` points uniform in the workspace shrunk by ``margin``, ≥ ``clearance`` from obstacles."""
    lo = np.array([margin, margin])
    hi = np.array([world.width - margin, world.height - margin])
    points = lo + rng.random((batch, tries, 2)) * (hi - lo)
    ok = (world.clearance(points.reshape(-1, 2)) >= clearance).reshape(batch, tries)
    return points[np.arange(batch), np.argmax(ok, axis=1)]


@dataclass(frozen=True)
class RandomGoal:
    """Uniform start position and heading, and a goal at least ``min_distance`` away."""

    margin: float = 1.5
    min_distance: float = 3.0
    world: World = EMPTY

    def sample(self, rng, batch):
        lo = np.array([self.margin, self.margin])
        hi = np.array([self.world.width - self.margin, self.world.height - self.margin])
        points = lo + rng.random((2, batch, 8, 2)) * (hi - lo)
        far = np.hypot(*(points[1] - points[0]).transpose(2, 0, 1)) >= self.min_distance
        pick = np.argmax(far, axis=1)
        start, goal = points[0, np.arange(batch), pick], points[1, np.arange(batch), pick]
        theta = rng.uniform(-np.pi, np.pi, batch)
        return self.world, np.column_stack([start, theta]), goal


def random_obstacle_world(rng, n_obstacles=(4, 8), size=(0.5, 1.6), area=(4.0, 16.0)) -> World:
    """A 20 m × 20 m world with random discs and rotated boxes (the evaluation worlds of §VI.5.2)."""
    count = int(rng.integers(n_obstacles[0], n_obstacles[1] + 1))
    shapes = []
    for _ in range(count):
        center = rng.uniform(area[0], area[1], 2)
        if rng.random() < 0.5:
            shapes.append(Circle(center, rng.uniform(*size)))
        else:
            half = rng.uniform(size[0], size[1], 2)
            c, s = np.cos(angle := rng.uniform(0, np.pi)), np.sin(angle)
            corners = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]]) * half
            shapes.append(Polygon(center + corners @ np.array([[c, s], [-s, c]])))
    return World(20.0, 20.0, tuple(shapes))


@dataclass(frozen=True)
class RandomObstacles:
    """A random obstacle world per batch; starts and goals ≥ ``clearance`` from obstacles and
    ≥ ``min_distance`` apart, the robot heading towards its goal."""

    clearance: float = 1.2
    min_distance: float = 8.0
    margin: float = 1.5

    def sample(self, rng, batch):
        world = random_obstacle_world(rng)
        start = _free_points(rng, world, batch, self.margin, self.clearance)
        goal = _free_points(rng, world, batch, self.margin, self.clearance)
        near = np.hypot(*(goal - start).T) < self.min_distance
        goal[near] = np.array([world.width, world.height]) - start[near]  # mirror: far across the world
        bad = world.clearance(goal) < self.clearance
        goal[bad] = _free_points(rng, world, int(bad.sum()), self.margin, self.clearance)
        theta = np.arctan2(goal[:, 1] - start[:, 1], goal[:, 0] - start[:, 0])
        return world, np.column_stack([start, theta]), goal


def wall_course(rng, thickness: float = WALL_THICKNESS) -> World:
    """A course for wall following, like Figs VI.27–VI.28: an open polyline of 3–5 walls, 3–7 m
    each, turning by 30°–150° either way at every joint (sharp corners), inside the workspace
    (drawn from ``rng`` by :func:`fuzzynav.kernels.courses.draw_course`, whose docstring gives
    the order of the draws)."""
    return _course(rng, thickness)[1]


def _course(rng, thickness: float) -> tuple[np.ndarray, World]:
    """(corners (W + 1, 2), world) of :func:`wall_course`."""
    from fuzzynav.kernels import courses

    corners = np.empty((courses.MAX_CORNERS, 2))
    corners = corners[:courses.draw_course(rng, corners)]
    walls = Wall.chain(corners, thickness)
    scene = courses.pack_walls(20.0, 20.0, np.array([wall.vertices for wall in walls]))
    return corners, World.prepacked(20.0, 20.0, walls, scene)


@dataclass(frozen=True)
class WallCourse:
    """A random wall course per batch; each robot starts ``offset`` from a wall, parallel to it,
    with the wall on its ``side`` (+1 left, the side the follower of Table VI.2 keeps; −1 right),
    placed by :func:`fuzzynav.kernels.courses.place_starts`."""

    offset: float = 1.0
    side: float = 1.0

    def sample(self, rng, batch):
        from fuzzynav.kernels import courses

        corners, world = _course(rng, WALL_THICKNESS)
        starts = np.empty((batch, 4))
        courses.place_starts(rng, world.scene, corners, float(self.offset), float(self.side), starts)
        poses = np.empty((batch, 3))
        poses[:, :2] = starts[:, :2]
        poses[:, 2] = np.arctan2(starts[:, 3], starts[:, 2])
        return world, poses, None
