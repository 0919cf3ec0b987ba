"""``act`` of the default navigators, compiled: any compiled navigator
(:func:`fuzzynav.kernels.navigators.act_one`) inside the recovery and loop-escape layers of
:mod:`fuzzynav.control.robust`, optionally aimed by the route guidance
(:mod:`fuzzynav.kernels.guidance`: the navigator's target, the goal or the loop escape's virtual
goal, replaced by a point towards the route round what was seen; its pending arc dropped when
the loop escape begins or ends). The navigator runs every step
(its hit memory and behaviour switch stay current); a layer in charge replaces its command.
Behaviour codes are the navigator's, then ``n_labels`` + 0, 1, 2 for ``REC-BACK``, ``REC-TURN``,
``BF``, + 3, 4 for ``CAR-BACK``, ``CAR-FWD`` (the guidance's car route driven by the layer).
"""

from __future__ import annotations

import math

from fuzzynav.jit import jit
from fuzzynav.kernels import clearing, escape, guidance, latency, navigators, pace, recovery, sightings
from fuzzynav.kernels.layers import NO_PHASE, PARAM, STATE, TABLES_AT
from fuzzynav.kernels.motion import wrap
from fuzzynav.kernels.records import Layers, Pose, Robot, Sightings
from fuzzynav.kernels.row_blocks import cells_of, places_of, points_of


@jit
def act_one(navigator, cstate, memory, layer, robot, seen, clock, route):
    """(α, V, behaviour code) of one robot at the time of ``clock`` (a
    :class:`~fuzzynav.kernels.records.Clock`: the step's period dt and the time t; the other
    arguments those of :func:`fuzzynav.kernels.navigators.act_one`, plus ``layer``, a
    :class:`~fuzzynav.kernels.records.Layers`: the layers' parameters and the robot's state row,
    :mod:`fuzzynav.kernels.layers`; ``route``: those parameters when the route guidance or the
    pace is on, None when both are off — their code is then pruned at compile time,
    :func:`fuzzynav.kernels.step.route_of`). The obstacle points seen are remembered where they are seen;
    with an actuation delay (``params[PARAM.delay]`` steps) the decision is taken at the pose
    where the command will act, on the scan moved there (:mod:`fuzzynav.kernels.latency`), and
    the command is remembered as sent."""
    p, state = layer.params, layer.state
    if p[PARAM.on] == 0.0:
        return navigators.act_one(navigator, cstate, memory, robot, seen, clock.dt)
    here, count = Pose(robot.x, robot.y, robot.theta), int(state[STATE.count])
    if p[PARAM.forget] != 0.0:  # moving obstacles: forget where they were (kernels.clearing)
        count = clearing.clear(points_of(p, state), cells_of(p, state), count, here, seen)
    count = sightings.see(points_of(p, state), cells_of(p, state), count, here, seen)
    state[STATE.count] = count
    if p[PARAM.delay] == 0.0:
        return decide(navigator, cstate, memory, layer, robot, seen, clock, route)
    later, moved = latency.ahead(p, state, robot, seen)
    steering, speed, code = decide(navigator, cstate, memory, layer, later, moved, clock, route)
    latency.sent(p, state, steering, speed)
    return steering, speed, code


@jit
def decide(navigator, cstate, memory, layer, robot, seen, clock, route):
    """:func:`act_one` of a robot at ``robot``'s pose reading ``seen``, once what it sees is remembered."""
    p, state = layer.params, layer.state
    dt, t = clock.dt, clock.t
    x, y, theta, tx, ty = robot.x, robot.y, robot.theta, robot.tx, robot.ty
    ranges, angles, max_range, d_o, b_o = seen.ranges, seen.angles, seen.max_range, seen.d_o, seen.b_o
    points = points_of(p, state)
    pose = Pose(x, y, theta)
    count = int(state[STATE.count])
    remembered = Sightings(points, count)
    if count + ranges.shape[0] + 1 > points.shape[0]:  # the next step could fill the slots
        p[PARAM.grow] = 1.0
    distance = math.hypot(tx - x, ty - y)
    bearing = wrap(math.atan2(ty - y, tx - x) - theta)
    aim_x, aim_y, following = tx, ty, False
    if p[PARAM.escape] != 0.0:
        if state[STATE.active] != 0.0 and (escape.should_leave(state, p, distance, bearing, ranges, angles)
                                     or escape.timed_out(state, p, t)):
            escape.stop(state, not escape.timed_out(state, p, t))
            escape.forget_places(state)
            guidance.drop(state)
        if escape.circling(state, places_of(p, state), p, t, x, y, distance) and (
                p[PARAM.recovery] == 0.0 or state[STATE.phase] == NO_PHASE):
            escape.start(state, t, distance, b_o)
            escape.forget_places(state)
            guidance.drop(state)
        if state[STATE.active] != 0.0:
            following = True
            aim_x, aim_y = escape.virtual_goal(state, p, remembered, robot, t, d_o, ranges, p[PARAM.radius])
    heading_for = Robot(x, y, theta, robot.v, aim_x, aim_y)
    if route is not None and p[PARAM.guide] != 0.0:  # (route None: pruned at compile time, as below)
        aim_x, aim_y = guidance.aim(state, p, remembered, heading_for, t, p[PARAM.radius])
    steering, speed, code = navigators.act_one(navigator, cstate, memory, Robot(x, y, theta, robot.v, aim_x, aim_y),
                                               seen, dt)
    if route is not None and p[PARAM.pace] != 0.0 and speed > 0.0:
        faster = pace.pace(ranges, angles, max_range, steering, p, distance)
        if faster > speed and navigators.safety_stop(navigator.params, memory, x, y, theta, faster, dt) > 0.0:
            speed = faster
    labels = int(p[PARAM.n_labels])
    if following:
        code = labels + 2
    if route is not None and p[PARAM.guide] != 0.0 and state[STATE.phase] == NO_PHASE:
        quick = pace.car_pace(ranges, angles, max_range, p, state, distance)
        backing = state[STATE.guide_gear] < 0.0
        moving, a, u = guidance.manoeuvre(state, p, remembered, x, y, theta, dt, quick)
        if not moving and backing and p[PARAM.guide_car_chain] != 0.0:  # the back-up is over: plan on now
            guidance.plan(state, p, remembered, heading_for, t, p[PARAM.radius])
            moving, a, u = guidance.manoeuvre(state, p, remembered, x, y, theta, dt,
                                              pace.car_pace(ranges, angles, max_range, p, state, distance))
        if moving:
            return a, u, labels + (3 if u < 0 else 4)
    if p[PARAM.recovery] == 0.0 or p[PARAM.max_reverse_speed] <= 0:
        return steering, speed, code
    if state[STATE.phase] != NO_PHASE:
        moving, a, u, phase = recovery.command(state, p, remembered, pose, ranges, angles, dt, t)
        if moving:
            return a, u, labels + phase - 1
    state[STATE.stopped] = state[STATE.stopped] + dt if speed == 0.0 and distance > 0.5 else 0.0
    if state[STATE.stopped] >= p[PARAM.stop_wait] - 1e-9:
        state[STATE.stopped] = 0.0
        recovery.start(state, p, p[TABLES_AT:], remembered, pose, bearing, max_range, t)
        moving, a, u, phase = recovery.command(state, p, remembered, pose, ranges, angles, dt, t)
        if moving:
            return a, u, labels + phase - 1
    return steering, speed, code


@jit
def act(navigator, cstate, memory, layers, seen, clock, route, out):
    """:func:`act_one` of every active robot of ``seen`` (a :class:`~fuzzynav.kernels.records.Readings`)
    at the time of ``clock``, ``layers`` holding every robot's state rows: ``out`` (N, 3) = α, V, behaviour code."""
    for n in range(seen.poses.shape[0]):
        if seen.active[n]:
            out[n, 0], out[n, 1], out[n, 2] = act_one(navigator, cstate[n], memory[n],
                                                      Layers(layers.params, layers.state[n]),
                                                      navigators.robot_of(seen, n), navigators.reading_of(seen, n),
                                                      clock, route)


@jit
def rehash_all(params, state):
    """Fill every robot's hash set of cells again (after its point slots grew)."""
    for n in range(state.shape[0]):
        row = state[n]
        sightings.rehash(points_of(params, row), int(row[STATE.count]), cells_of(params, row))
