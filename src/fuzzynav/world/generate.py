"""Seeded random worlds for benchmarking navigators (``fuzzynav evaluate``).

Two families on the thesis' 20 m × 20 m workspace:

- ``"circles"`` — 8 to 14 discs of radius 0.4–1.4 m, the obstacles of Table IV.2 / Fig IV.15;
- ``"mixed"`` — 8 to 12 obstacles drawn among circles, convex polygons, walls (thick segments,
  2–6 m long) and ellipses, the shapes of §IV.7 / Fig IV.22.

Start and goal are at least 10 m apart, ≥ 2.5 m from the boundary walls and ≥ 1.5 m from every
obstacle; the start heading is uniform. Only **solvable** worlds are returned: on an occupancy grid of 0.2 m cells, the cells
where the robot's footprint disc plus a margin fits (clearance ≥ ``robot_radius + margin``) must
connect the start to the goal. The default margin is the tightest turning radius
l / tan(π/5) = 0.69 m: a tricycle that cannot reverse needs passages where it can turn around
(width ≥ 2 (0.3 + 0.69) ≈ 2 m), not merely passages it fits through (4-connected flood fill, :func:`scipy.ndimage.label`); otherwise the
draw is rejected and redrawn. World ``i`` of ``generate_worlds(kind, n, seed)`` depends only on
``(kind, seed, i)`` (one child :class:`numpy.random.SeedSequence` per world), so the first 10 of
100 worlds are the 10 worlds of ``n = 10``.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.errors import InputError
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.world.scenario import Scenario, scenario_from_dict
from fuzzynav.world.shapes import Circle, Ellipse, Polygon, Wall
from fuzzynav.world.world import World

KINDS = ("circles", "mixed")
WIDTH = HEIGHT = 20.0
MIN_START_GOAL = 10.0  # m between start and goal
POINT_CLEARANCE = 1.5  # m of free space around start and goal
BORDER = 2.5  # m, start and goal keep this far from the boundary walls (room to turn from any heading)
GRID = 0.2  # m, occupancy-grid cell
MAX_DRAWS = 200
TURNING_MARGIN = DEFAULT_PARAMS.wheelbase / np.tan(np.pi / 5)  # m, l / tan(α_max) = 0.69 m


def _circle(rng):
    return {"circle": {"center": rng.uniform(1.0, 19.0, 2).round(2).tolist(),
                       "radius": round(float(rng.uniform(0.4, 1.4)), 2)}}


def _polygon(rng):
    center = rng.uniform(1.5, 18.5, 2)
    n = int(rng.integers(3, 7))
    angles = np.linspace(0, 2 * np.pi, n, endpoint=False) + rng.uniform(0, 2 * np.pi)
    radius = rng.uniform(0.6, 1.6) * rng.uniform(0.8, 1.0, n)  # a jittered regular fan: simple, star-shaped
    points = center + np.column_stack([radius * np.cos(angles), radius * np.sin(angles)])
    return {"polygon": {"points": points.round(2).tolist()}}


def _wall(rng):
    start = rng.uniform(1.0, 19.0, 2)
    heading = rng.uniform(0, np.pi)
    end = np.clip(start + rng.uniform(2.0, 6.0) * np.array([np.cos(heading), np.sin(heading)]), 0.5, 19.5)
    return {"wall": {"start": start.round(2).tolist(), "end": end.round(2).tolist(),
                     "thickness": round(float(rng.uniform(0.2, 0.4)), 2)}}


def _ellipse(rng):
    radii = rng.uniform(0.4, 1.6, 2)
    return {"ellipse": {"center": rng.uniform(1.5, 18.5, 2).round(2).tolist(), "radii": radii.round(2).tolist(),
                        "angle": round(float(rng.uniform(-np.pi / 2, np.pi / 2)), 3)}}


_CLASSES = {"circle": Circle, "polygon": Polygon, "wall": Wall, "ellipse": Ellipse}
_MAKERS = {"circles": (_circle,), "mixed": (_circle, _polygon, _wall, _ellipse)}
_COUNTS = {"circles": (8, 14), "mixed": (8, 12)}


def free_space(world: World, radius: float) -> tuple[np.ndarray, np.ndarray]:
    """Occupancy grid of ``world``: ``(free (ny, nx) bool, centres (ny, nx, 2))``, a cell free
    when a disc of ``radius`` around its centre touches neither an obstacle nor the boundary."""
    xs = np.arange(GRID / 2, world.width, GRID)
    ys = np.arange(GRID / 2, world.height, GRID)
    centres = np.stack(np.meshgrid(xs, ys), axis=-1)
    free = world.clearance(centres.reshape(-1, 2)).reshape(centres.shape[:2]) >= radius
    return free, centres


def connected(world: World, start, goal, radius: float) -> bool:
    """True when ``start`` and ``goal`` lie in one connected region of :func:`free_space`."""
    from scipy import ndimage  # imported when first needed (not at start-up)

    free, _ = free_space(world, radius)
    labels, _ = ndimage.label(free)
    cell = lambda p: (min(int(p[1] / GRID), labels.shape[0] - 1), min(int(p[0] / GRID), labels.shape[1] - 1))
    a, b = labels[cell(start)], labels[cell(goal)]
    return bool(a) and a == b


def random_world(kind: str, rng: np.random.Generator, *, name: str = "random", max_time: float = 120.0,
                 robot_radius: float = DEFAULT_PARAMS.radius, margin: float = TURNING_MARGIN) -> Scenario:
    """One solvable random world of family ``kind`` (see the module docstring), drawn from ``rng``."""
    if kind not in KINDS:
        raise InputError(f"unknown world family {kind!r} (known: {', '.join(KINDS)})", field="kind")
    makers = _MAKERS[kind]
    lo, hi = _COUNTS[kind]
    for _ in range(MAX_DRAWS):
        while True:
            start, goal = rng.uniform(BORDER, WIDTH - BORDER, (2, 2))
            if np.hypot(*(goal - start)) >= MIN_START_GOAL:
                break
        obstacles = []
        for _ in range(int(rng.integers(lo, hi + 1))):
            shape = makers[int(rng.integers(len(makers)))](rng)
            (kind_key, params), = shape.items()
            alone = World(WIDTH, HEIGHT, (_CLASSES[kind_key](**params),))
            if (alone.nearest_obstacle(np.array([start, goal]))[0] >= POINT_CLEARANCE).all():
                obstacles.append(shape)
        document = {
            "name": name,
            "description": f"random {kind} world",
            "robot": {"x": round(float(start[0]), 2), "y": round(float(start[1]), 2),
                      "theta": round(float(rng.uniform(-np.pi, np.pi)), 3)},
            "goal": {"x": round(float(goal[0]), 2), "y": round(float(goal[1]), 2)},
            "obstacles": obstacles,
            "max_time": max_time,
        }
        scenario = scenario_from_dict(document, source=name)
        if connected(scenario.world, scenario.start[:2], scenario.goal.position, robot_radius + margin):
            return scenario
    raise RuntimeError(f"no solvable {kind} world in {MAX_DRAWS} draws")  # pragma: no cover - never seen


def generate_worlds(kind: str, n: int, seed: int = 0, **options) -> list[Scenario]:
    """``n`` solvable worlds of family ``kind``; world ``i`` depends only on ``(kind, seed, i)``."""
    if kind not in KINDS:
        raise InputError(f"unknown world family {kind!r} (known: {', '.join(KINDS)})", field="--worlds")
    if int(n) < 1:
        raise InputError(f"must be >= 1, got {n!r}", field="--n")
    children = np.random.SeedSequence([int(seed), KINDS.index(kind)]).spawn(int(n))
    return [random_world(kind, np.random.default_rng(child), name=f"{kind}-{seed}-{i:03d}", **options)
            for i, child in enumerate(children)]


def generated_world(name: str) -> Scenario | None:
    """World ``i`` of ``generate_worlds(kind, n, seed)`` from its name ``<kind>-<seed>-<i>`` (as
    ``fuzzynav evaluate`` names them), or ``None`` when ``name`` is not such a name."""
    parts = name.rsplit("-", 2)
    if len(parts) != 3 or parts[0] not in KINDS or not (parts[1].isdigit() and parts[2].isdigit()):
        return None
    kind, seed, index = parts[0], int(parts[1]), int(parts[2])
    child = np.random.SeedSequence([seed, KINDS.index(kind)]).spawn(index + 1)[index]
    return random_world(kind, np.random.default_rng(child), name=f"{kind}-{seed}-{index:03d}")
