"""Scenario files: world, robot start and task, validated (every key: docs/guide/scenarios.md).

```yaml
name: fig-IV-15a                      # optional (default: the file name)
description: one line for `fuzzynav scenarios`   # optional
world: {width: 20.0, height: 20.0}    # optional, default 20 x 20; origin bottom-left
robot: {x: 1.0, y: 1.0, theta: 0.0}   # metres, radians CCW from +x (theta optional, 0)
# optional robot keys (defaults: robot.tricycle.TricycleParams): radius (footprint disc, 0.3 m),
# wheelbase (0.5 m), max_steering (π/4 rad), max_speed (4 m/s), max_reverse_speed (0.5 m/s; 0: no reverse)
# and the real robot's imperfections, all off by default (fuzzynav.robot.imperfections):
#   sensor_noise: {range_sigma, dropout, max_range}, actuation: {latency, steering_rate, acceleration, slip},
#   odometry: {drift}
goal: {x: 18.0, y: 18.0, tolerance: 0.3}
obstacles:
  - circle: {center: [5, 5], radius: 1.0}
  - polygon: {points: [[8, 8], [10, 8], [10, 10]]}
  - wall: {start: [2, 12], end: [10, 12], thickness: 0.2}
  - ellipse: {center: [14, 6], radii: [2.0, 1.0], angle: 0.3}
  - circle: {center: [5, 9], radius: 0.3}           # any obstacle may move (fuzzynav.world.moving):
    motion: {type: line, velocity: [0.6, 0.0]}       # line | circle | sinusoid | waypoints
max_time: 120                         # seconds, optional
controllers: [fuzzy-2b]               # optional: the controllers the thesis runs here (demo)
sensors: lidar                        # optional: thesis | beam | lidar (default: the controller's ring)
```
Exactly one task: ``goal`` (chapter IV), ``path: [[x, y], ...]`` (two or more waypoints, no
two consecutive ones equal) with optional ``path_tolerance`` (the waypoint tolerance zone, thesis
§4, default 0.5 m), ``path_switching`` (``passed``, the default: a waypoint is also left once the
robot is past it; ``zone``: the thesis' tolerance zone only; :mod:`fuzzynav.sim.tasks`) and
``speed`` (the constant tracking speed, default 1 m/s, at most the robot's 4 m/s), or ``target: {x, y, tolerance, motion: {type: static |
line | circle | sinusoid, ...}}`` (thesis §V.5, parameters in :mod:`fuzzynav.world.motion`).

Every problem raises :class:`~fuzzynav.errors.InputError` naming the file, the field (e.g.
``obstacles[2].circle.radius``) and what is wrong; unknown keys get the closest known key as a
hint. YAML is read safely by the YAML 1.2 rules (:mod:`fuzzynav.yaml_loader`: ``1:20`` is not
80, ``1e3`` is a float, duplicate keys refused); every value is bounded by the documented limits
of :mod:`fuzzynav.world.limits` (``docs/limits.md``), and a goal the robot's body can never reach
or an obstacle wholly outside the world is refused.
"""

from __future__ import annotations

import difflib
import math
from dataclasses import dataclass, field, replace
from pathlib import Path

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.robot import imperfections as real
from fuzzynav.robot.tricycle import DEFAULT_PARAMS, TricycleParams
from fuzzynav.world import limits
from fuzzynav.world.checks import Checks, ShapeFields
from fuzzynav.world.motion import MOTION_PARAMS, TargetMotion, read_motion
from fuzzynav.world.moving import parse_motion
from fuzzynav.world.shapes import SHAPES
from fuzzynav.world.world import World

BUILTIN_DIR = Path(__file__).with_name("scenarios")
DEFAULT_MAX_TIME = 120.0
DEFAULT_GOAL_TOLERANCE = 0.3
DEFAULT_PATH_TOLERANCE = 0.5
DEFAULT_PATH_SPEED = 1.0
PATH_SWITCHING = ("passed", "zone")  # waypoint switching rules, :mod:`fuzzynav.sim.tasks`

TOP_KEYS = ("name", "description", "world", "robot", "goal", "path", "path_tolerance", "path_switching", "speed",
            "target", "obstacles", "max_time", "controllers", "sensors")
ROBOT_KEYS = ("radius", "wheelbase", "max_steering", "max_speed", "max_reverse_speed")  # TricycleParams fields
ROBOT_UNITS = {"radius": "m", "wheelbase": "m", "max_steering": "rad", "max_speed": "m/s", "max_reverse_speed": "m/s"}


@dataclass(frozen=True)
class Goal:
    """Goal-seeking task (chapter IV): reach ``position`` within ``tolerance`` (m)."""

    position: np.ndarray
    tolerance: float = DEFAULT_GOAL_TOLERANCE


@dataclass(frozen=True)
class PathTask:
    """Path tracking (thesis §V.2): waypoints ``(n, 2)``, tolerance zone (m), constant speed (m/s) and
    waypoint switching rule (``passed`` | ``zone``, :mod:`fuzzynav.sim.tasks`)."""

    waypoints: np.ndarray
    tolerance: float = DEFAULT_PATH_TOLERANCE
    speed: float = DEFAULT_PATH_SPEED
    switching: str = "passed"


@dataclass(frozen=True)
class TargetTask:
    """Moving-target pursuit (thesis §V.5): captured when within ``tolerance`` (m) of the target."""

    motion: TargetMotion
    tolerance: float = DEFAULT_GOAL_TOLERANCE


@dataclass(frozen=True)
class Scenario:
    """A validated scenario: the world, the robot's start pose ``(3,)`` and exactly one task;
    ``robot`` holds the robot's size and limits (the simulator's default parameters)."""

    name: str
    world: World
    start: np.ndarray
    goal: Goal | None = None
    path: PathTask | None = None
    target: TargetTask | None = None
    max_time: float = DEFAULT_MAX_TIME
    description: str = ""
    source: str | None = None
    controllers: tuple[str, ...] = ()  # the controllers the thesis runs on it (``fuzzynav demo``)
    robot: TricycleParams = field(default=DEFAULT_PARAMS)
    sensors: str | None = None  # the sensor ring by name (fuzzynav.robot.sensors.RINGS); None: the controller's
    imperfections: real.Imperfections = field(default=real.NONE)  # the real robot's (all off: the perfect one)

    @property
    def task(self) -> str:
        """``"goal"``, ``"path"`` or ``"target"``."""
        return "goal" if self.goal is not None else "path" if self.path is not None else "target"

    def to_dict(self) -> dict:
        """The scenario-file form (round-trips through :func:`scenario_from_dict`)."""
        doc: dict = {"name": self.name}
        if self.description:
            doc["description"] = self.description
        doc.update({"controllers": list(self.controllers)} if self.controllers else {})
        doc.update({"sensors": self.sensors} if self.sensors is not None else {})
        doc["world"] = {"width": self.world.width, "height": self.world.height}
        doc["robot"] = {"x": float(self.start[0]), "y": float(self.start[1]), "theta": float(self.start[2])}
        doc["robot"].update({key: getattr(self.robot, key) for key in ROBOT_KEYS
                             if getattr(self.robot, key) != getattr(DEFAULT_PARAMS, key)})
        doc["robot"].update(self.imperfections.to_dict())
        if self.goal is not None:
            doc["goal"] = {"x": float(self.goal.position[0]), "y": float(self.goal.position[1]),
                           "tolerance": self.goal.tolerance}
        if self.path is not None:
            doc["path"] = self.path.waypoints.tolist()
            doc["path_tolerance"] = self.path.tolerance
            doc["path_switching"] = self.path.switching
            doc["speed"] = self.path.speed
        if self.target is not None:
            m = self.target.motion
            motion = {"type": m.type}
            for key in MOTION_PARAMS[m.type]:
                value = getattr(m, key)
                motion[key] = value.tolist() if isinstance(value, np.ndarray) else value
            doc["target"] = {"x": float(m.start[0]), "y": float(m.start[1]),
                             "tolerance": self.target.tolerance, "motion": motion}
        motions = self.world.motions or (None,) * len(self.world.obstacles)
        doc["obstacles"] = [{**shape.to_dict(), **({"motion": motion.to_dict()} if motion is not None else {})}
                            for shape, motion in zip(self.world.obstacles, motions)]
        doc["max_time"] = self.max_time
        return doc


def _obstacle(check: Checks, entry, field: str):
    """``(shape, motion or None)`` of the scenario entry ``{kind: {parameters}, motion: {...}}``
    (``motion`` optional: :func:`fuzzynav.world.moving.parse_motion`)."""
    if not isinstance(entry, dict) or "motion" not in entry:
        return _shape(check, entry, field), None
    entry = dict(entry)
    motion = entry.pop("motion")
    shape = _shape(check, entry, field)
    return shape, parse_motion(check, motion, f"{field}.motion", shape)


def _shape(check: Checks, entry, field: str):
    """The obstacle of the scenario entry ``{kind: {parameters}}``, by its type in the registry
    :data:`fuzzynav.world.shapes.SHAPES` (schema, defaults and parsing)."""
    if not isinstance(entry, dict) or len(entry) != 1:
        check.fail(field, "must be a mapping with exactly one of: " + ", ".join(SHAPES) + " (and optionally motion)")
    (kind, params), = check.mapping(entry, field, SHAPES).items()
    shape, keys = SHAPES[kind], SHAPES[kind].schema()
    f = f"{field}.{kind}"
    params = check.mapping(params, f, keys, required=[k for k, v in keys.items() if v is None])
    try:
        return shape.parse(ShapeFields(check, {k: params.get(k, default) for k, default in keys.items()}, f))
    except InputError as error:
        if error.source:
            raise
        check.fail(f"{f}.{error.field}", error.problem)


def _reachable(check: Checks, world: World, point, tolerance: float, radius: float, field: str, what: str):
    """Some centre within ``tolerance`` of ``point`` keeps the robot's body (a disc of ``radius``)
    inside the world and off the nearest obstacle; otherwise the task can never be done."""
    x, y = point
    lo_x, hi_x, lo_y, hi_y = radius, world.width - radius, radius, world.height - radius
    if lo_x > hi_x or lo_y > hi_y:
        check.fail("world", f"the {world.width:g} x {world.height:g} m world is smaller than the robot "
                            f"(radius {radius:g} m)")
    gap = math.hypot(x - min(max(x, lo_x), hi_x), y - min(max(y, lo_y), hi_y))
    if gap >= tolerance:
        check.fail(field, f"{what} ({x:g}, {y:g}) cannot be reached within its tolerance {tolerance:g} m: the "
                          f"robot (radius {radius:g} m) cannot come closer than {gap:g} m at the world boundary")
    if world.obstacles:
        dist, _, index = world.nearest_obstacle(np.asarray(point, dtype=float).reshape(1, 2))
        if dist[0] + tolerance < radius:
            check.fail(field, f"{what} ({x:g}, {y:g}) cannot be reached within its tolerance {tolerance:g} m: "
                              f"obstacles[{index[0]}] keeps the robot (radius {radius:g} m) away")


def _not_done_at_start(check: Checks, start, point, tolerance: float, field: str, what: str):
    """A goal or target within its tolerance of the start would end the episode, reached, before
    its first step (a tolerance of 30 for 0.3, or the start's coordinates given to it)."""
    gap = math.hypot(point[0] - start[0], point[1] - start[1])
    if gap <= tolerance:
        check.fail(field, f"the start ({start[0]:g}, {start[1]:g}) is {gap:g} m from the {what}, within its tolerance "
                          f"{tolerance:g} m: the episode would end, reached, before its first step")


def _place(check: Checks, world: World, point, field: str, what: str, radius: float = 0.0):
    """A point must lie in the world and outside every obstacle (a disc of ``radius`` around it)."""
    point = np.asarray(point, dtype=float).reshape(1, 2)
    if not world.contains(point)[0]:
        check.fail(field, f"{what} ({point[0, 0]:g}, {point[0, 1]:g}) is outside the "
                          f"{world.width:g} x {world.height:g} m world")
    x, y = point[0]
    if radius > 0 and min(x, y, world.width - x, world.height - y) < radius:
        check.fail(field, f"{what} ({x:g}, {y:g}) is within the robot footprint ({radius:g} m) of the world boundary")
    dist, _, index = world.nearest_obstacle(point)
    if dist[0] < radius:
        where = "inside" if dist[0] < 0 else f"within the robot footprint ({radius:g} m) of"
        kind = world.obstacles[index[0]].kind
        check.fail(field, f"{what} ({point[0, 0]:g}, {point[0, 1]:g}) is {where} obstacles[{index[0]}] ({kind})")


def _not_another_kind(document, source: str) -> None:
    """A model file or a fuzzy system given where a scenario is read is named as what it is (its
    first unknown key said nothing of it)."""
    if not isinstance(document, dict) or "robot" in document:
        return
    if isinstance(document.get("kind"), str):
        raise InputError(f"a model file (kind {document['kind']!r}), not a scenario: a model drives a scenario "
                         "(`fuzzynav run SCENARIO --model FILE`)", source=source, field="kind")
    if {"inputs", "outputs", "rules"} <= document.keys():
        raise InputError("a fuzzy system, not a scenario: it stands in for a controller's rule table "
                         "(`fuzzynav run SCENARIO --fis ROLE=FILE`; `fuzzynav fis show FILE` shows it)", source=source)


def scenario_from_dict(document, source: str = "<scenario>", name: str | None = None,
                       robot_radius: float = DEFAULT_PARAMS.radius) -> Scenario:
    """Validate a parsed scenario document and build the :class:`Scenario`.

    ``robot_radius`` is the footprint that must fit at the start pose, and that must be able
    to bring its centre within tolerance of the goal or of a static target, when the document's
    ``robot`` gives no ``radius`` (default: the default robot's); otherwise the document's own
    ``robot.radius`` is used for both checks.
    """
    check = Checks(source)
    _not_another_kind(document, source)
    doc = check.mapping(document, "", TOP_KEYS, required=["robot"])
    tasks = [key for key in ("goal", "path", "target") if key in doc]
    if len(tasks) != 1:
        check.fail("goal", "a scenario needs exactly one task: goal, path or target"
                   + (f" (found {', '.join(tasks)})" if tasks else ""))
    for key in ("path_tolerance", "path_switching", "speed"):
        if key in doc and "path" not in doc:
            check.fail(key, "only allowed with a path task")

    world_doc = check.mapping(doc.get("world", {}), "world", ("width", "height"))
    width, height = limits.world_size(world_doc.get("width", 20.0), world_doc.get("height", 20.0), source)
    obstacles_doc = validation.sequence([] if doc.get("obstacles") is None else doc["obstacles"], source,
                                        "obstacles", max_length=limits.MAX_OBSTACLES)  # 0, false, {}: refused
    entries = [_obstacle(check, o, f"obstacles[{i}]") for i, o in enumerate(obstacles_doc)]
    obstacles = tuple(shape for shape, _ in entries)
    limits.world_contents(obstacles, width, height, source)
    motions = tuple(motion for _, motion in entries)
    world = World(width, height, obstacles, motions if any(m is not None for m in motions) else ())

    robot = check.mapping(doc["robot"], "robot", ("x", "y", "theta", *ROBOT_KEYS, *real.KEYS), required=("x", "y"))
    start = np.array([check.number(robot["x"], "robot.x"), check.number(robot["y"], "robot.y"),
                      limits.angle(robot.get("theta", 0.0), source, "robot.theta")])
    robot_limits = _robot_params(check, robot)
    radius = robot_limits.radius if "radius" in robot else robot_radius
    _place(check, world, start[:2], "robot", "start", radius)
    limits.steps_see_collisions(world, robot_limits, robot_limits.radius, source)  # the radius simulated

    goal = path = target = None
    if "goal" in doc:
        g = check.mapping(doc["goal"], "goal", ("x", "y", "tolerance"), required=("x", "y"))
        position = np.array([check.number(g["x"], "goal.x"), check.number(g["y"], "goal.y")])
        _place(check, world, position, "goal", "goal")
        goal = Goal(position, check.number(g.get("tolerance", DEFAULT_GOAL_TOLERANCE), "goal.tolerance", True))
        _reachable(check, world, position, goal.tolerance, radius, "goal", "goal")
        _not_done_at_start(check, start, position, goal.tolerance, "goal", "goal")
    elif "path" in doc:
        waypoints = check.points(doc["path"], "path", 2, limits.MAX_WAYPOINTS)
        for i, waypoint in enumerate(waypoints):
            _place(check, world, waypoint, f"path[{i}]", "waypoint")
            if i and np.array_equal(waypoint, waypoints[i - 1]):
                check.fail(f"path[{i}]", f"repeats path[{i - 1}] (zero-length segment)")
        speed = check.number(doc.get("speed", DEFAULT_PATH_SPEED), "speed", True)
        if speed > robot_limits.max_speed:
            check.fail("speed", f"must be at most the robot's {robot_limits.max_speed:g} m/s, got {speed:g}")
        switching = validation.choice(doc.get("path_switching", PATH_SWITCHING[0]), PATH_SWITCHING, source,
                                      "path_switching")
        path = PathTask(waypoints,
                        check.number(doc.get("path_tolerance", DEFAULT_PATH_TOLERANCE), "path_tolerance", True),
                        speed, switching)
    else:
        t = check.mapping(doc["target"], "target", ("x", "y", "tolerance", "motion"), required=("x", "y"))
        position = np.array([check.number(t["x"], "target.x"), check.number(t["y"], "target.y")])
        _place(check, world, position, "target", "target")
        kind, values = read_motion(check, t.get("motion", {"type": "static"}), "target.motion", MOTION_PARAMS)
        if kind == "circle" and np.allclose(values["center"], position):
            check.fail("target.motion.center", "must differ from the target start (zero radius)")
        target = TargetTask(TargetMotion(type=kind, start=position, **values),
                            check.number(t.get("tolerance", DEFAULT_GOAL_TOLERANCE), "target.tolerance", True))
        if kind == "static":
            _reachable(check, world, position, target.tolerance, radius, "target", "target")
        _not_done_at_start(check, start, position, target.tolerance, "target", "target")

    return Scenario(
        name=check.label(doc.get("name", name or "scenario"), "name"),  # it names runs and plots
        world=world,
        start=start,
        goal=goal,
        path=path,
        target=target,
        max_time=validation.number(doc.get("max_time", DEFAULT_MAX_TIME), source, "max_time", lo=0.0, lo_open=True,
                                   hi=limits.MAX_TIME),
        description=check.text(doc.get("description", ""), "description"),
        source=source,
        controllers=_controller_names(check, doc.get("controllers", [])),
        robot=robot_limits,
        imperfections=real.read(robot, source),
        sensors=limits.sensor_ring(doc.get("sensors"), source),
    )


def _robot_params(check: Checks, robot: dict) -> TricycleParams:
    """The robot's size and limits from the optional keys of ``robot`` (others: the defaults)."""
    values = {}
    for key in ROBOT_KEYS:
        if key in robot:
            unit = ROBOT_UNITS[key]
            values[key] = validation.number(robot[key], check.source, f"robot.{key}", hi=limits.MAX_LENGTH, lo=0.0,
                                            lo_open=key != "max_reverse_speed")
            if key != "max_reverse_speed" and values[key] < limits.MIN_LENGTH:
                check.fail(f"robot.{key}", f"must be at least {limits.MIN_LENGTH:g} {unit}, got {values[key]!r}")
    if values.get("max_steering", 0.0) >= math.pi / 2:
        check.fail("robot.max_steering", f"must be below π/2 (90°), got {values['max_steering']:g}")
    return replace(DEFAULT_PARAMS, **values) if values else DEFAULT_PARAMS


def _controller_names(check: Checks, names) -> tuple[str, ...]:
    """The optional ``controllers`` key: a list of controller names (checked when they are run)."""
    if not isinstance(names, list) or not all(isinstance(name, str) and 0 < len(name) <= 100 for name in names):
        check.fail("controllers", "must be a list of controller names, e.g. [goal-seeking, fuzzy-5b]")
    return tuple(names)


def read_yaml(path: Path):
    """Parse a YAML file safely and within bounds (:func:`fuzzynav.validation.load_document`):
    unreadable files raise InputError naming the file (and line)."""
    return validation.load_document(path, "yaml")


def list_scenarios() -> dict[str, str]:
    """Built-in scenarios (``world/scenarios/*.yaml``): name -> one-line description."""
    listing = {}
    for file in sorted(BUILTIN_DIR.glob("*.yaml")):
        doc = read_yaml(file)
        listing[file.stem] = str(doc.get("description", "")) if isinstance(doc, dict) else ""
    return listing


def load_scenario(path_or_name) -> Scenario:
    """Load a scenario file, or a built-in scenario by name (see :func:`list_scenarios`)."""
    if isinstance(path_or_name, str) and not path_or_name.strip():  # "" is the current folder to Path
        raise InputError("is empty: give a scenario file or a built-in scenario's name", field="SCENARIO")
    path = validation.file_path(path_or_name, field="scenario")
    if not (path.exists() or path.is_symlink()) or path.is_dir():  # a device, pipe or loop of links: refused below
        builtin = BUILTIN_DIR / f"{path_or_name}.yaml"
        if path.is_dir() and not builtin.is_file():
            raise InputError("is a directory; give one scenario file (`fuzzynav bench FOLDER` runs a folder)",
                             source=str(path_or_name), field="SCENARIO")
        if not builtin.is_file():
            names = sorted(f.stem for f in BUILTIN_DIR.glob("*.yaml"))
            close = difflib.get_close_matches(str(path_or_name), names, n=3)
            hint = f" (did you mean {', '.join(close)}?)" if close else ""
            raise InputError(f"no such scenario file or built-in scenario{hint}; "
                             f"`fuzzynav scenarios` lists the built-ins", source=str(path_or_name),
                             field="SCENARIO")
        path = builtin
    return scenario_from_dict(read_yaml(path), source=str(path), name=path.stem)
