"""Resource limits of a world and of a scenario, and the checks of a world's size and contents.

Each limit keeps one scenario's cost (memory, time per step, steps per run) bounded whatever a
file says; past a limit the scenario is refused with an :class:`~fuzzynav.errors.InputError`
naming the field. The table of every limit of fuzzynav is ``docs/limits.md``.
"""

from __future__ import annotations

import math

from fuzzynav import validation

MAX_WORLD_SIZE = 10_000.0  # m: world width and height
MAX_COORDINATE = 100_000.0  # m: |x| and |y| of any point of a scenario
MIN_LENGTH = 1e-3  # m: smallest radius, semi-axis, wall thickness and tolerance
MAX_LENGTH = 100_000.0  # m: largest radius, semi-axis, wall thickness and tolerance
MAX_ANGLE = math.tau  # rad: |angle| of a pose or an ellipse (a larger one is most likely in degrees)
MAX_OBSTACLES = 2_000
MAX_POLYGON_VERTICES = 1_000
MAX_TOTAL_VERTICES = 20_000  # polygon vertices the kernels hold (4 per wall), over the whole world
MAX_WAYPOINTS = 10_000
MAX_TIME = 3_600.0  # s: a run's simulated time (36,000 steps of the default 0.1 s)
MAX_TARGET_SPEED = 100.0  # m/s: speed of a moving target


def coordinate(value, source=None, field=None) -> float:
    """One coordinate (m) of a point: finite, at most :data:`MAX_COORDINATE` in magnitude."""
    return validation.number(value, source, field, lo=-MAX_COORDINATE, hi=MAX_COORDINATE)


def length(value, source=None, field=None) -> float:
    """A radius, semi-axis, thickness or tolerance (m): in [MIN_LENGTH, MAX_LENGTH]."""
    result = validation.number(value, source, field, lo=0.0, lo_open=True, hi=MAX_LENGTH)
    if result < MIN_LENGTH:
        validation.fail(f"must be at least {MIN_LENGTH:g} m, got {result!r}", source, field)
    return result


def angle(value, source=None, field=None) -> float:
    """An angle (rad): finite, at most :data:`MAX_ANGLE` (2π) in magnitude — beyond one turn it
    is most likely degrees (``theta: 90``), which are refused with their value in radians."""
    result = validation.number(value, source, field)
    if abs(result) > MAX_ANGLE:
        validation.fail(f"must be in radians, at most 2π = {MAX_ANGLE:.4f} in magnitude, got {validation.shown(value)}"
                        f" (if that is degrees: {math.radians(result):.4f} rad)", source, field)
    return result


def world_size(width, height, source=None, field: str = "world") -> tuple[float, float]:
    """Width and height (m) of a world: each in (0, MAX_WORLD_SIZE]."""
    return tuple(validation.number(value, source, f"{field}.{name}", lo=0.0, lo_open=True, hi=MAX_WORLD_SIZE)
                 for name, value in (("width", width), ("height", height)))


def world_contents(obstacles, width: float, height: float, source=None, field: str = "obstacles") -> None:
    """At most :data:`MAX_OBSTACLES` obstacles and :data:`MAX_TOTAL_VERTICES` vertices, each
    obstacle meeting the ``width`` × ``height`` world (one wholly outside it is a mistake)."""
    if len(obstacles) > MAX_OBSTACLES:
        validation.fail(f"at most {MAX_OBSTACLES} obstacles, got {len(obstacles)}", source, field)
    total = 0
    for i, shape in enumerate(obstacles):
        if not callable(getattr(shape, "vertex_count", None)):
            validation.fail(f"must be an obstacle shape (fuzzynav.world.shapes.SHAPES), got {type(shape).__name__}",
                            source, f"{field}[{i}]")
        lo, hi = shape.bounds()
        if hi[0] < 0 or hi[1] < 0 or lo[0] > width or lo[1] > height:
            validation.fail(f"{shape.kind} lies wholly outside the {width:g} x {height:g} m world", source,
                            f"{field}[{i}]")
        total += shape.vertex_count()
    if total > MAX_TOTAL_VERTICES:
        validation.fail(f"at most {MAX_TOTAL_VERTICES} polygon and wall vertices in a world, got {total}", source,
                        field)


def steps_see_collisions(world, robot, radius: float, source=None) -> None:
    """Collisions are tested once a step of Δt, and along a step that spans the robot's diameter
    (:func:`fuzzynav.kernels.step.swept`), against where the obstacles are at the step's end:
    refuse a moving obstacle of ``world`` that could pass through the robot (``robot`` a
    :class:`~fuzzynav.robot.tricycle.TricycleParams` of footprint ``radius``) between two steps —
    the two closing 2r or more in a step (the robot at its top speed V, forwards or backwards,
    the obstacle at its own)."""
    dt, diameter = robot.dt, 2.0 * radius
    speed = max(robot.max_speed, -robot.lowest_speed)  # backwards: max_reverse_speed, or a negative min_speed
    for index in world.moving:
        mover = world.motions[index].top_speed()
        if (mover + speed) * dt >= diameter:
            validation.fail(f"at up to {mover:g} m/s, with the robot's {speed:g} m/s, it closes {(mover + speed) * dt:g}"
                            f" m in a step of {dt:g} s, not less than the robot's diameter {diameter:g} m: the two "
                            f"could pass through each other between steps; give it a speed below "
                            f"{diameter / dt - speed:g} m/s (or the robot a lower max_speed)", source,
                            f"obstacles[{index}].motion")


def sensor_ring(name, source=None, field: str = "sensors") -> str | None:
    """The scenario's optional ``sensors`` key: a ring of :data:`fuzzynav.robot.sensors.RINGS`
    (``thesis``, ``beam``, ``lidar``), or None where absent (the controller's ring)."""
    from fuzzynav.robot.sensors import RINGS

    return None if name is None else validation.choice(name, tuple(RINGS), source, field)
