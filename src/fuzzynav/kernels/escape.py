"""Loop and trap escape of the default navigators, compiled: circling detection and boundary
following, in the spirit of the Bug algorithms (V. Lumelsky, A. Stepanov, "Path-planning
strategies for a point mobile automaton moving amidst unknown obstacles of arbitrary shape",
Algorithmica 2, 1987; the leaving rule of DistBug, I. Kamon, E. Rivlin, IEEE Trans. Robotics and
Automation 13(6), 1997). What the layer does is told in :mod:`fuzzynav.control.robust`; these
are its steps for one robot, on its ``state`` row and ``places`` ring buffer
(:mod:`fuzzynav.kernels.layers` names the columns and ``params``).
"""

from __future__ import annotations

import math

from fuzzynav.jit import jit
from fuzzynav.kernels import route
from fuzzynav.kernels.layers import PARAM, STATE
from fuzzynav.kernels.motion import turn_remainder


@jit
def forget_places(state):
    """Forget the sampled places and the progress (after an escape starts or ends)."""
    state[STATE.best], state[STATE.t_best], state[STATE.first], state[STATE.places] = math.inf, math.nan, 0.0, 0.0


@jit
def circling(state, places, params, t, x, y, goal_distance):
    """Record this step; True when the robot circles: it is back within ``revisit`` of a place
    it passed at least ``min_lap`` ago (places are sampled every ``sample_every`` and kept for
    ``horizon``), and its best goal distance has not improved by ``loop_gain`` for ``patience``."""
    if state[STATE.t_best] != state[STATE.t_best] or goal_distance < state[STATE.best] - params[PARAM.loop_gain]:
        state[STATE.best], state[STATE.t_best] = goal_distance, t
    size, first, kept = places.shape[0], int(state[STATE.first]), int(state[STATE.places])
    if kept == 0 or t - places[(first + kept - 1) % size, 0] >= params[PARAM.sample_every] - 1e-9:
        if kept == size:  # not with the slots the controller gives (see fuzzynav.control.robust)
            first, kept = (first + 1) % size, kept - 1
        at = (first + kept) % size
        places[at, 0], places[at, 1], places[at, 2] = t, x, y
        kept += 1
    while kept and t - places[first, 0] > params[PARAM.horizon]:
        first, kept = (first + 1) % size, kept - 1
    state[STATE.first], state[STATE.places] = first, kept
    if t - state[STATE.t_best] < params[PARAM.patience]:
        return False
    for i in range(kept):
        at = (first + i) % size
        if (t - places[at, 0] >= params[PARAM.min_lap]
                and math.hypot(x - places[at, 1], y - places[at, 2]) < params[PARAM.revisit]):
            return True
    return False


@jit
def start(state, t, goal_distance, obstacle_bearing):
    """Begin following; the leaving rule must beat the smaller of ``goal_distance`` and the best
    distance reached. The side followed is the nearest obstacle's (Bug: follow what was hit), or
    the other one after a following on that side ran out of time or looped (a loop while
    following ends it as failed)."""
    if state[STATE.active]:
        state[STATE.failed] = state[STATE.side]
    side = 1.0 if obstacle_bearing >= 0 else -1.0
    state[STATE.active], state[STATE.side] = 1.0, -state[STATE.failed] if state[STATE.failed] != 0 else side
    state[STATE.hit], state[STATE.t_follow] = min(goal_distance, state[STATE.best]), t
    state[STATE.route_x], state[STATE.route_y], state[STATE.planned] = math.nan, math.nan, -math.inf


@jit
def stop(state, succeeded):
    """End the following (``succeeded``: by the leaving rule, not by time)."""
    state[STATE.failed] = 0.0 if succeeded else state[STATE.side]
    state[STATE.active] = 0.0


@jit
def timed_out(state, params, t):
    """True after ``follow_time`` of following."""
    return t - state[STATE.t_follow] > params[PARAM.follow_time]


@jit
def should_leave(state, params, distance, bearing, ranges, angles):
    """The leaving rule: the goal is ``leave_gain`` nearer than the hit distance and the ray
    nearest the goal direction (within the ring's ±90°) reads at least min(d, ``free``)."""
    if distance > state[STATE.hit] - params[PARAM.leave_gain] or abs(bearing) > math.pi / 2 + 1e-9:
        return False
    k, gap = 0, math.inf
    for i in range(angles.shape[0]):
        turn = turn_remainder(angles[i] - bearing + math.pi)  # in [0, 2π), as Python's remainder
        if abs(turn - math.pi) < gap:
            k, gap = i, abs(turn - math.pi)
    return ranges[k] >= min(distance, params[PARAM.free])


@jit
def virtual_goal(state, params, seen, robot, t, d_o, ranges, radius):
    """The point the navigator drives to while following (``robot`` a
    :class:`~fuzzynav.kernels.records.Robot` aiming at the goal): ``ahead`` m along the route round
    the remembered points ``seen`` (a :class:`~fuzzynav.kernels.records.Sightings`;
    :func:`fuzzynav.kernels.route.target`, keeping ``radius`` + ``room``,
    the room of a turn; where no such route exists, ``radius`` + ``tight``), planned again every
    ``replan`` s or when the robot is within 1 m of it; without a route, a point ``reach`` ahead
    and ``offset`` to the followed side with an obstacle within ``near`` (D_ro or a reading),
    ``search`` without (a wide arc that finds the boundary again, not a tight circle)."""
    x, y, theta, tx, ty = robot.x, robot.y, robot.theta, robot.tx, robot.ty
    stale = (state[STATE.route_x] != state[STATE.route_x]
             or math.hypot(state[STATE.route_x] - x, state[STATE.route_y] - y) < 1.0)
    if stale or t - state[STATE.planned] >= params[PARAM.replan] - 1e-9:
        found, rx, ry = route.target(seen, x, y, tx, ty, radius + params[PARAM.room], params[PARAM.ahead])
        if not found:
            found, rx, ry = route.target(seen, x, y, tx, ty, radius + params[PARAM.tight], params[PARAM.ahead])
        state[STATE.route_x], state[STATE.route_y] = (rx, ry) if found else (math.nan, math.nan)
        state[STATE.planned] = t
    if state[STATE.route_x] == state[STATE.route_x]:
        return state[STATE.route_x], state[STATE.route_y]
    nearest = d_o
    for r in ranges:
        nearest = min(nearest, r)
    angle = params[PARAM.offset] if nearest < params[PARAM.near] else params[PARAM.search]
    heading = theta + state[STATE.side] * angle
    return x + params[PARAM.reach] * math.cos(heading), y + params[PARAM.reach] * math.sin(heading)
