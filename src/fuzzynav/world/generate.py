"""Seeded random worlds for benchmarking navigators (``fuzzynav evaluate``).

Families on the thesis' 20 m × 20 m workspace:

- ``"circles"`` — 8 to 14 discs of radius 0.4–1.4 m, the obstacles of Table IV.2 / Fig IV.15;
- ``"mixed"`` — 8 to 12 obstacles drawn among circles, convex polygons, walls (thick segments,
  2–6 m long) and ellipses, the shapes of §IV.7 / Fig IV.22;
- ``"dense"`` — the shapes of ``mixed``, 14 to 20 drawn (as in every family, those within 1.5 m
  of the start or the goal are dropped: 12 to 20 remain);
- ``"utrap"`` — a U-shaped trap of three walls (opening 3–5 m wide, 2–4 m deep) across the line
  from the start to the goal, its opening towards the start (the local minimum of reactive
  navigation, Fig IV.23's U-wall), plus 2 to 5 discs;
- ``"dynamic"`` — 3 to 6 standing discs and polygons plus 4 to 8 moving obstacles (crossing
  pedestrians, patrols, oncoming traffic at 0.3–1.5 m/s, :mod:`fuzzynav.world.traffic`), none of
  which ever comes within 1 m of the start or the goal; solvability is tested on the standing ones;
- ``"dynabarn"`` — DynaBARN's set-up (:mod:`fuzzynav.world.dynabarn`): 2 to 5 cylinders crossing
  a walled 20 m arena on polynomial tracks, its fixed start, goal and 100 s limit (the other
  families' start, goal and solvability rules do not apply to it);
- ``"office"`` — rooms along one or two corridors, joined by doors 0.9–1.5 m wide
  (:mod:`fuzzynav.world.office`), start and goal in two rooms;
- ``"maze"`` — a braided grid maze of 6 to 8 cells a side over the whole world
  (:mod:`fuzzynav.world.maze`), start and goal at two cells' centres;
- ``"forest"`` — thin posts (radius 0.05–0.15 m) over the whole world, a Poisson-disc sample at
  least 1.1–1.8 m apart (:mod:`fuzzynav.world.forest`).

Start and goal are at least 10 m apart, ≥ 2.5 m from the boundary walls and ≥ 1.5 m from every
obstacle (in ``office`` and ``maze``: the centres of two rooms or cells at least 10 m apart); the
start heading is uniform. Only **solvable** worlds are returned: on an occupancy grid of 0.2 m cells, the cells
where the robot's footprint disc plus a margin fits (clearance ≥ ``robot_radius + margin``) must
connect the start to the goal. The default margin is the tightest turning radius
l / tan(π/5) = 0.69 m: a tricycle that cannot reverse needs passages where it can turn around
(width ≥ 2 (0.3 + 0.69) ≈ 2 m), not merely passages it fits through (4-connected flood fill); otherwise the
draw is rejected and redrawn. Doors and posts leave less room than that: ``office`` and ``forest``
check their own margin of centimetres (with reverse, the car can follow any path of its
footprint that keeps some clearance: :mod:`fuzzynav.world.office`); ``maze`` keeps the turning
margin (its corridors are sized for it). World ``i`` of ``generate_worlds(kind, n, seed)`` depends only on
``(kind, seed, i)`` (one child :class:`numpy.random.SeedSequence` per world), so the first 10 of
100 worlds are the 10 worlds of ``n = 10``.
"""

from __future__ import annotations

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.constants import ALPHA_MAX
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.world import dynabarn, forest, limits, maze, office, traffic
from fuzzynav.world.scenario import Scenario, scenario_from_dict
from fuzzynav.world.shapes import SHAPES
from fuzzynav.world.world import World

KINDS = ("circles", "mixed", "dense", "utrap", "dynamic", "dynabarn", "office", "maze", "forest")  # append only: the index seeds each family
WIDTH = HEIGHT = 20.0
MIN_START_GOAL = 10.0  # m between start and goal
POINT_CLEARANCE = 1.5  # m of free space around start and goal
BORDER = 2.5  # m, start and goal keep this far from the boundary walls (room to turn from any heading)
GRID = 0.2  # m, occupancy-grid cell
MAX_DRAWS = 200
TURNING_MARGIN = DEFAULT_PARAMS.wheelbase / np.tan(ALPHA_MAX)  # m, l / tan(α_max) = 0.69 m


def _u_trap(rng, start, goal) -> list[dict]:
    """Three walls forming a U across the start–goal line, its opening towards the start."""
    direction = (goal - start) / np.hypot(*(goal - start))
    normal = np.array([-direction[1], direction[0]])
    width, depth = rng.uniform(3.0, 5.0), rng.uniform(2.0, 4.0)
    back_centre = start + rng.uniform(0.6, 0.75) * np.hypot(*(goal - start)) * direction
    corners = [back_centre + side * width / 2 * normal for side in (-1, 1)]
    mouths = [corner - depth * direction for corner in corners]
    segments = [(corners[0], corners[1]), (corners[0], mouths[0]), (corners[1], mouths[1])]
    return [{"wall": {"start": np.clip(a, 0.5, 19.5).round(2).tolist(), "end": np.clip(b, 0.5, 19.5).round(2).tolist(),
                      "thickness": 0.3}} for a, b in segments]


# the obstacle types each family draws (:data:`fuzzynav.world.shapes.SHAPES`, each type's ``random``); a
# family's list is part of its worlds: extend it and its worlds change — add a family instead
_MAKERS = {"circles": ("circle",), "mixed": ("circle", "polygon", "wall", "ellipse"),
           "dense": ("circle", "polygon", "wall", "ellipse"), "utrap": ("circle",), "dynamic": ("circle", "polygon")}
_COUNTS = {"circles": (8, 14), "mixed": (8, 12), "dense": (14, 20), "utrap": (2, 5), "dynamic": (3, 6)}
# the families whose module draws the whole world, start and goal (a scenario document)
_PLANS = {"office": office.office_document, "maze": maze.maze_document}
_MARGINS = {"office": office.MARGIN, "forest": forest.MARGIN}  # solvability margins other than TURNING_MARGIN


def _clear_of(shapes: list[dict], start, goal) -> bool:
    """True when every shape keeps ``POINT_CLEARANCE`` from the start and the goal."""
    shapes = [SHAPES[kind](**params) for shape in shapes for kind, params in shape.items()]
    return bool((World(WIDTH, HEIGHT, tuple(shapes)).nearest_obstacle(np.array([start, goal]))[0] >= POINT_CLEARANCE).all())


def connected(world: World, start, goal, radius: float) -> bool:
    """True when ``start`` and ``goal`` lie in one 4-connected region of the free cells of the
    occupancy grid (cells of ``GRID`` m; free when a disc of ``radius`` round the centre touches
    neither an obstacle nor the boundary): a flood fill from the start that measures only the
    cells it reaches (:func:`fuzzynav.kernels.scene.joined`)."""
    from fuzzynav.kernels import scene

    xs, ys = np.arange(GRID / 2, world.width, GRID), np.arange(GRID / 2, world.height, GRID)
    cell = lambda p: (min(int(p[1] / GRID), len(ys) - 1), min(int(p[0] / GRID), len(xs) - 1))
    return bool(scene.joined(world.scene, xs, ys, float(radius), cell(start), cell(goal)))


def check_kind(kind: str, field: str = "--worlds") -> str:
    """``kind`` when it is a world family of :data:`KINDS`, else an InputError naming ``field``."""
    if kind not in KINDS:
        raise InputError(f"unknown world family {kind!r} (known: {', '.join(KINDS)})", field=field)
    return kind


def random_world(kind: str, rng: np.random.Generator, *, name: str = "random", max_time: float = 120.0,
                 robot_radius: float = DEFAULT_PARAMS.radius, margin: float | None = None) -> Scenario:
    """One solvable random world of family ``kind`` (see the module docstring), drawn from ``rng``;
    ``margin`` (m) replaces the family's solvability margin."""
    check_kind(kind, "kind")
    limits.length(robot_radius, field="robot_radius")  # the room a world keeps solvable: never below the body
    if margin is not None:
        validation.number(margin, field="margin", lo=0.0, hi=limits.MAX_LENGTH)
    if kind == "dynabarn":
        return scenario_from_dict(dynabarn.dynabarn_document(rng, name), source=name)
    room = robot_radius + (_MARGINS.get(kind, TURNING_MARGIN) if margin is None else margin)
    if kind in _PLANS:
        for _ in range(MAX_DRAWS):
            scenario = scenario_from_dict(_PLANS[kind](rng, name, size=WIDTH, min_start_goal=MIN_START_GOAL,
                                                       max_time=max_time), source=name)
            if connected(scenario.world, scenario.start[:2], scenario.goal.position, room):
                return scenario
        raise RuntimeError(f"no solvable {kind} world in {MAX_DRAWS} draws")  # pragma: no cover - never seen
    makers = _MAKERS.get(kind, ())
    lo, hi = _COUNTS.get(kind, (0, 0))  # forest: its posts only
    for _ in range(MAX_DRAWS):
        while True:
            start, goal = rng.uniform(BORDER, WIDTH - BORDER, (2, 2))
            if np.hypot(*(goal - start)) >= MIN_START_GOAL:
                break
        obstacles = _u_trap(rng, start, goal) if kind == "utrap" else []
        if obstacles and not _clear_of(obstacles, start, goal):
            continue
        if kind == "forest":
            obstacles = forest.forest_entries(rng, WIDTH, HEIGHT, (start, goal), POINT_CLEARANCE)
        for _ in range(int(rng.integers(lo, hi + 1))):
            shape = SHAPES[makers[int(rng.integers(len(makers)))]].random(rng)
            if _clear_of([shape], start, goal):
                obstacles.append(shape)
        standing = len(obstacles)
        if kind == "dynamic":
            movers = traffic.moving_obstacles(rng, start, goal)
            if not _clear_of([{k: v for k, v in entry.items() if k != "motion"} for entry in movers], start, goal):
                continue
            obstacles += movers
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
        world = scenario.world
        if world.moving:
            if not traffic.keeps_clear(world, (scenario.start[:2], scenario.goal.position), max_time):
                continue
            world = World(world.width, world.height, world.obstacles[:standing])
        if connected(world, scenario.start[:2], scenario.goal.position, room):
            return scenario
    raise RuntimeError(f"no solvable {kind} world in {MAX_DRAWS} draws")  # pragma: no cover - never seen


def family_reference(kind: str) -> dict:
    """Reference data of every world of family ``kind`` for the benchmark (as a folder's
    ``benchmark.json`` gives per world): the BARN score's path lengths of ``dynabarn``, else none."""
    return dict(dynabarn.REFERENCE) if kind == "dynabarn" else {}


def generate_world(kind: str, seed: int, i: int, **options) -> Scenario:
    """World ``i`` of :func:`generate_worlds` ``(kind, n, seed)`` for any ``n > i``, drawn alone."""
    check_kind(kind)
    child = np.random.SeedSequence([int(seed), KINDS.index(kind)], spawn_key=(int(i),))
    return random_world(kind, np.random.default_rng(child), name=f"{kind}-{seed}-{i:03d}", **options)


def check_family(kind: str, n: int, seed: int) -> tuple[int, int]:
    """``(n, seed)`` of a request for ``n`` worlds of family ``kind``, checked (an
    :class:`~fuzzynav.errors.InputError` names the option at fault)."""
    check_kind(kind)
    return validation.count(n, field="--n", hi=validation.MAX_WORLDS), validation.seed(seed, field="--seed")


def generate_worlds(kind: str, n: int, seed: int = 0, **options) -> list[Scenario]:
    """``n`` solvable worlds of family ``kind``; world ``i`` depends only on ``(kind, seed, i)``
    (:func:`generate_world`)."""
    n, seed = check_family(kind, n, seed)
    return [generate_world(kind, seed, i, **options) for i in range(n)]


def generated_world(name: str) -> Scenario | None:
    """World ``i`` of ``generate_worlds(kind, n, seed)`` from its name ``<kind>-<seed>-<i>`` (as
    ``fuzzynav evaluate`` names them), or ``None`` when ``name`` is not such a name."""
    parts = name.rsplit("-", 2)
    if len(parts) != 3 or parts[0] not in KINDS or not all(p.isascii() and p.isdigit() for p in parts[1:]):
        return None
    shown = name if len(name) <= 80 else f"{name[:60]}…"
    if len(parts[1]) > 20 or int(parts[1]) > validation.MAX_SEED:
        raise InputError(f"its SEED must be a whole number from 0 to {validation.MAX_SEED:,}", source=shown)
    if len(parts[2]) > 6 or int(parts[2]) >= validation.MAX_WORLDS:
        raise InputError(f"its world index must be a whole number from 0 to {validation.MAX_WORLDS - 1:,}",
                         source=shown)
    return generate_world(parts[0], int(parts[1]), int(parts[2]))
