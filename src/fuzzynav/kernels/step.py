"""The simulator's step for N robots, compiled: act (a compiled navigator, or commands given),
clip, move, stop tests, sense — one call per step (:class:`fuzzynav.sim.simulator.BatchSimulator`
documents the loop; :mod:`fuzzynav.sim.tasks` the tasks).

Arrays:

- ``setup`` (floats): the robot's parameters (:data:`fuzzynav.kernels.motion.ROBOT_FIELDS`),
  the sensor range (and, last, the sensors' half beam width), the task (:data:`SETUP_FIELDS`), then the sensor angles and the path's
  waypoints (x0, y0, x1, y1, …);
- ``state`` (N, :data:`STATE_FIELDS`) floats per robot; ``ranges`` (N, S);
- ``status`` (N, 3) ints per robot: outcome code (0 running), steps taken, waypoint index;
- ``base``, ``movers``, ``offsets``: the moving obstacles (:mod:`fuzzynav.kernels.traffic`),
  placed in ``scene_array`` at their offsets of step ``k`` before the robots move (none: a static
  world, whose scene is never written);
- ``imperfect``: the real robot's imperfections (:mod:`fuzzynav.kernels.imperfect`), or ``None``
  for the perfect robot (numba then compiles the step without them).

Finished robots are neither moved, judged nor sensed.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels import beams, imperfect as real, layers, navigators, robust, scene, traffic
from fuzzynav.kernels.motion import RADIUS, ROBOT_FIELDS, advance, clip, wrap
from fuzzynav.kernels.records import Clock, Layers, Navigator, Reading, Robot, StepNavigator

SETUP_FIELDS = ROBOT_FIELDS + ("max_range", "task", "tolerance", "forced_speed", "passed", "max_steps", "goal_x",
                               "goal_y", "n_angles", "half_beam")
(MAX_RANGE, TASK, TOLERANCE, FORCED_SPEED, PASSED, MAX_STEPS, GOAL_X, GOAL_Y, N_ANGLES,
 HALF_BEAM) = range(len(ROBOT_FIELDS), len(SETUP_FIELDS))
ANGLES = len(SETUP_FIELDS)  # sensor angles, then waypoints
GOAL, PATH, TARGET = range(3)  # task codes
STATE_FIELDS = ("x", "y", "theta", "steering", "speed", "target_x", "target_y", "obstacle_distance", "nearest_x",
                "nearest_y", "obstacle_column", "boundary", "obstacle_bearing", "behaviour")
(X, Y, THETA, STEERING, SPEED, TARGET_X, TARGET_Y, OBSTACLE_DISTANCE, NEAREST_X, NEAREST_Y, OBSTACLE_COLUMN, BOUNDARY,
 OBSTACLE_BEARING, BEHAVIOUR) = range(len(STATE_FIELDS))
OUTCOME, STEPS, WAYPOINT = range(3)
RUNNING, REACHED, COLLISION, TIMEOUT = range(4)
NO_NAVIGATOR = -1  # commands given in state[:, STEERING], state[:, SPEED]


def setup_array(robot, *, max_range: float = 0.0, task: int = GOAL, tolerance: float = -math.inf,
                forced_speed: float = math.nan, passed: bool = False, max_steps: float = math.inf, goal=(0.0, 0.0),
                angles=(), half_beam: float = 0.0, waypoints=()) -> np.ndarray:
    """The ``setup`` array (:data:`SETUP_FIELDS`) of a robot (``robot``:
    :meth:`~fuzzynav.robot.tricycle.TricycleParams.array`), its sensors (``max_range``, ``angles``,
    ``half_beam``) and its task: ``task`` code, ``goal`` (x, y) within ``tolerance`` (−∞: never
    reached), a path's ``forced_speed`` (NaN: none), ``passed`` rule and ``waypoints`` (n, 2), the
    time limit ``max_steps`` (∞: none)."""
    angles = np.asarray(angles, dtype=float).reshape(-1)
    return np.concatenate([np.asarray(robot, dtype=float),
                           [max_range, task, tolerance, forced_speed, float(passed), max_steps, *goal, len(angles),
                            half_beam], angles, np.asarray(waypoints, dtype=float).ravel()])


def idle_arguments() -> tuple:
    """The navigator of :func:`lean_arguments` without a compiled navigator (kind, then unused
    params, tables, state, memory, layer params and state)."""
    return (NO_NAVIGATOR, np.zeros(1), np.zeros(1), np.zeros((1, 4), dtype=np.int64), np.zeros((1, 1, 1, 3)),
            *layers.none())


def lean_arguments(navigator: tuple) -> tuple:
    """The navigator arguments of :func:`step` — ``(params, layer params, StepNavigator)`` — of a
    navigator's ``(kind, params, tables, state, memory, layer params, layer state)``, with ``None``
    for what the run does not use: the navigator's ``params`` without a navigator
    (:data:`NO_NAVIGATOR`), the layers' params and state when they are off. numba compiles one
    version of :func:`step` per pattern of ``None`` and prunes the branches they close, so a run
    compiles only the code it runs (the layers of the default navigator are most of the cold
    compile)."""
    kind, params, tables, cstate, memory, layer_params, layer_state = navigator
    if kind == NO_NAVIGATOR:
        return None, None, StepNavigator(kind, tables, cstate, memory, None, None)
    if layer_params[layers.ON] == 0.0:
        return params, None, StepNavigator(kind, tables, cstate, memory, None, None)
    return params, layer_params, StepNavigator(kind, tables, cstate, memory, layer_state, route_of(layer_params))


def route_of(layer_params: np.ndarray) -> np.ndarray | None:
    """``layer_params`` when the layers' route guidance or pace is on, else None: the step of a
    navigator that uses neither then compiles without their code (the car route's hybrid A* is
    most of the layers' compile time; :func:`fuzzynav.kernels.robust.decide`)."""
    guided = layer_params[layers.PARAM.guide] != 0.0 or layer_params[layers.PARAM.pace] != 0.0
    return layer_params if guided else None


@jit
def waypoint(setup, i):
    at = ANGLES + int(setup[N_ANGLES]) + 2 * i
    return setup[at], setup[at + 1]


@jit
def segment_distance(px, py, ax, ay, bx, by):
    """Distance from (px, py) to the segment a → b."""
    dx, dy = bx - ax, by - ay
    s = min(max(((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy), 0.0), 1.0)
    return math.hypot(ax + s * dx - px, ay + s * dy - py)


@jit
def n_waypoints(setup):
    return (setup.shape[0] - ANGLES - int(setup[N_ANGLES])) // 2


@jit
def passed(setup, i, px, py):
    """Has the robot at (px, py) passed interior waypoint i: beyond the bisector of the corner
    ((p − w_i)·(u_in + u_out) > 0, u the unit segment directions) and no farther from segment
    i → i + 1 than from segment i − 1 → i (:mod:`fuzzynav.sim.tasks`)."""
    if i < 1 or i >= n_waypoints(setup) - 1:
        return False
    ax, ay = waypoint(setup, i - 1)
    cx, cy = waypoint(setup, i)
    bx, by = waypoint(setup, i + 1)
    n_in, n_out = math.hypot(cx - ax, cy - ay), math.hypot(bx - cx, by - cy)
    fx, fy = (cx - ax) / n_in + (bx - cx) / n_out, (cy - ay) / n_in + (by - cy) / n_out
    return ((px - cx) * fx + (py - cy) * fy > 0
            and segment_distance(px, py, cx, cy, bx, by) <= segment_distance(px, py, ax, ay, cx, cy))


@jit
def task_update(setup, i, x, y):
    """(task done?, waypoint index, target x, y) of a robot now at (x, y) that aimed at waypoint
    ``i``: the goal or target reached within the tolerance; a path's waypoint left once inside
    its zone (or, with the ``passed`` rule, once passed), the path done in the last zone."""
    task = int(setup[TASK])
    gx, gy = setup[GOAL_X], setup[GOAL_Y]
    if task == PATH:
        gx, gy = waypoint(setup, i)
    inside = math.hypot(gx - x, gy - y) <= setup[TOLERANCE]
    if task != PATH:
        return inside, i, gx, gy
    done = inside and i == n_waypoints(setup) - 1
    if (inside and not done) or (setup[PASSED] != 0.0 and passed(setup, i, x, y)):
        i += 1
    gx, gy = waypoint(setup, i)
    return done, i, gx, gy


@jit
def settle(setup, scene_array, k, state, ranges, status, n, imperfect):
    """Stop tests and sensing of robot ``n`` at step ``k`` (the state after its move): collision
    (footprint vs obstacles and boundary) first, then the task, then the time limit; then the
    next target, the rays (as the real sensor reads them with ``imperfect``) and the nearest
    obstacle's bearing θ_o."""
    row = state[n]
    scene.nearest_one(scene_array, row[X], row[Y], row[OBSTACLE_DISTANCE:BOUNDARY + 1])
    collided = min(row[OBSTACLE_DISTANCE], row[BOUNDARY]) < setup[RADIUS]
    done, status[n, WAYPOINT], row[TARGET_X], row[TARGET_Y] = task_update(setup, status[n, WAYPOINT], row[X], row[Y])
    outcome = COLLISION if collided else (REACHED if done else RUNNING)
    if outcome == RUNNING and k >= setup[MAX_STEPS]:
        outcome = TIMEOUT
    status[n, OUTCOME] = outcome
    n_angles = int(setup[N_ANGLES])
    beams.read_one(scene_array, row[X], row[Y], row[THETA], setup[ANGLES:ANGLES + n_angles], setup[HALF_BEAM],
                   setup[MAX_RANGE], ranges[n])
    if imperfect is not None:
        real.sense(imperfect, n, ranges[n], setup[MAX_RANGE])
    finite = math.isfinite(row[OBSTACLE_DISTANCE])
    row[OBSTACLE_BEARING] = wrap(math.atan2(row[NEAREST_Y] - row[Y], row[NEAREST_X] - row[X]) - row[THETA]) \
        if finite else 0.0


@jit
def limit(setup, steering, speed):
    """The command robot takes of (α, V): clipped to its limits (:func:`~fuzzynav.kernels.motion.clip`),
    the speed replaced by a path's constant speed (thesis §V.2) when the task has one."""
    steering, speed = clip(steering, speed, setup)
    if setup[FORCED_SPEED] == setup[FORCED_SPEED]:
        speed = setup[FORCED_SPEED]
    return steering, speed


@jit
def move(setup, scene_array, k, robots, n, steering, speed, imperfect):
    """Robot ``n`` of ``robots`` (a :class:`~fuzzynav.kernels.records.Robots`) driven one step Δt
    by its command (α, V) of :func:`limit`, ``k`` the step count after it: the kinematics (eq IV.2, or the exact arc; with ``imperfect``, through the actuators
    and with slip), the command applied written in its state, the step counted, then
    :func:`settle` — the one transition every stepping loop uses (:func:`step`,
    :func:`fuzzynav.kernels.worlds.step`)."""
    state, ranges, status = robots.state, robots.ranges, robots.status
    row = state[n]
    x0, y0 = row[X], row[Y]
    if imperfect is None:
        row[X], row[Y], row[THETA] = advance(row[X], row[Y], row[THETA], steering, speed, setup)
    else:
        steering, speed = real.actuate(imperfect, n, steering, speed, k, setup)
        row[X], row[Y], row[THETA] = real.move(imperfect, n, row[X], row[Y], row[THETA], steering, speed, setup)
    row[STEERING], row[SPEED] = steering, speed
    status[n, STEPS] += 1
    swept(setup, scene_array, row, x0, y0)
    settle(setup, scene_array, k, state, ranges, status, n, imperfect)


@jit
def swept(setup, scene_array, row, x0, y0):
    """A step from (x0, y0) to the row's position that spans the robot's diameter 2r or more (a
    small robot moving fast) is tested along its chord too: the position is set back to the first
    of points at most r apart where the footprint meets an obstacle (the step then ends in a
    collision there), else left. A shorter step needs nothing: every obstacle point the centre
    crosses lies within r of one of its ends, where :func:`settle` tests it. Without this a 1 cm
    robot at 4 m/s passed through a 1 cm wall unseen."""
    r = setup[RADIUS]
    dx, dy = row[X] - x0, row[Y] - y0
    length = math.hypot(dx, dy)
    if not length >= 2.0 * r:  # the default robot's steps, and NaN
        return
    parts = int(math.ceil(length / r))
    for j in range(1, parts):
        px, py = x0 + dx * j / parts, y0 + dy * j / parts
        scene.nearest_one(scene_array, px, py, row[OBSTACLE_DISTANCE:BOUNDARY + 1])
        if min(row[OBSTACLE_DISTANCE], row[BOUNDARY]) < r:
            row[X], row[Y] = px, py
            return


@jit
def reset(setup, scene_array, state, ranges, status, imperfect):
    """Stop tests and sensing of every robot at step 0; returns how many still run."""
    running = 0
    for n in range(state.shape[0]):
        settle(setup, scene_array, 0, state, ranges, status, n, imperfect)
        running += status[n, OUTCOME] == RUNNING
    return running


@jit(nogil=True)
def step(params, layer_params, navigator, setup, world, k, robots, imperfect):
    """One step of every running robot, ``k`` being the step count after it; returns how many
    still run. The moving obstacles of ``world`` (a :class:`~fuzzynav.kernels.records.Traffic`)
    go first to their place at step ``k``, so the robots' stop tests and sensing see them there.
    ``navigator`` (a :class:`~fuzzynav.kernels.records.StepNavigator`) holds a
    :mod:`fuzzynav.kernels.navigators` code (its ``params``, rule tables, state and memory;
    ``layer_params`` and its ``layer_state``: the recovery and loop-escape layers around it,
    :mod:`fuzzynav.kernels.layers`) or :data:`NO_NAVIGATOR` (commands given in ``state``), the
    arguments as :func:`lean_arguments` passes them; ``robots`` (a
    :class:`~fuzzynav.kernels.records.Robots`) the arrays updated in place. With ``imperfect``
    (:mod:`fuzzynav.kernels.imperfect`), the controller is given its believed position and noisy
    distances, and its commands go through the actuators' queue, limits and slip. With
    ``robots.moves`` false, the step only acts and clips, the commands left in ``state`` for
    another plant (:mod:`fuzzynav.sim.plants`) to move the robots, then :func:`settle_moved`."""
    traffic.place(world.base, world.movers, world.offsets, world.scene)
    scene_array, state, ranges, status = world.scene, robots.state, robots.ranges, robots.status
    kind, tables, cstate, memory, layer_state = (navigator.kind, navigator.tables, navigator.state, navigator.memory,
                                                 navigator.layer_state)
    moves = robots.moves
    running = 0
    n_angles = int(setup[N_ANGLES])
    angles = setup[ANGLES:ANGLES + n_angles]
    for n in range(state.shape[0]):
        if status[n, OUTCOME] != RUNNING:
            state[n, SPEED] = 0.0
            continue
        row = state[n]
        steering, speed = row[STEERING], row[SPEED]
        x, y, distance = row[X], row[Y], row[OBSTACLE_DISTANCE]
        if imperfect is not None:
            x, y, distance = real.believed(imperfect, n, x, y, distance)
        if params is not None:  # None (commands given) and the None of layer_params below: branches pruned
            robot = Robot(x, y, row[THETA], row[SPEED], row[TARGET_X], row[TARGET_Y])
            seen = Reading(ranges[n], angles, setup[MAX_RANGE], distance, row[OBSTACLE_BEARING])
            if layer_params is None:  # at compile time, so a run compiles only the navigator code it uses
                steering, speed, code = navigators.act_one(Navigator(kind, params, tables), cstate[n], memory[n], robot,
                                                           seen, setup[0])
            else:
                steering, speed, code = robust.act_one(Navigator(kind, params, tables), cstate[n], memory[n],
                                                       Layers(layer_params, layer_state[n]), robot, seen,
                                                       Clock(setup[0], (k - 1) * setup[0]), navigator.route)
            row[BEHAVIOUR] = code
        steering, speed = limit(setup, steering, speed)
        if not moves:  # another plant moves the robot (fuzzynav.sim.plants): decide and clip only
            row[STEERING], row[SPEED] = steering, speed
            continue
        move(setup, scene_array, k, robots, n, steering, speed, imperfect)
        running += status[n, OUTCOME] == RUNNING
    return running


@jit
def settle_moved(setup, scene_array, k, state, ranges, status, moved, before):
    """Stop tests and sensing at step ``k`` of the robots another plant has just moved (``moved``
    (N,) bool, their poses written in ``state``, ``before`` (N, 2+) where they were), each counted
    one step and its move tested along the way as :func:`move` tests its own (:func:`swept`);
    returns how many still run."""
    running = 0
    for n in range(state.shape[0]):
        if moved[n]:
            status[n, STEPS] += 1
            swept(setup, scene_array, state[n], before[n, 0], before[n, 1])
            settle(setup, scene_array, k, state, ranges, status, n, None)
        running += status[n, OUTCOME] == RUNNING
    return running
