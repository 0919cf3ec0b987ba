"""``act`` of the chapter IV navigators and the hand-made wall follower, compiled.

One robot's decision is :func:`act_one`; :func:`act` loops it over a batch. What each navigator
does is documented in its controller module (:mod:`fuzzynav.control.goal_seeking`,
:mod:`~fuzzynav.control.avoidance`, :mod:`~fuzzynav.control.five_behaviours`,
:mod:`~fuzzynav.control.wall_following`); the controller packs its parameters into ``params``
(the indices below), its rule bases into ``tables`` (:func:`fuzzynav.kernels.ts0.pack`, in the
order of its roles) and keeps its per-robot state: ``state`` (N, 4) ints — behaviour mode (−1:
none yet), steps held, turn side (0: none), steps remembered — and the hit memory ``memory``
(N, steps, S + 1, 3) of :mod:`fuzzynav.kernels.guard`.
"""

from __future__ import annotations

import math

from fuzzynav.fuzzy.constants import ALPHA_MAX
from fuzzynav.jit import jit
from fuzzynav.kernels import gaps, guard, ts0
from fuzzynav.kernels.motion import wrap
from fuzzynav.kernels.records import Pose, Reading, Robot, TurnRoom

GOAL_SEEKING, TWO_BEHAVIOURS, FIVE_BEHAVIOURS, WALL_FOLLOWER, CONSTANT = range(5)
MODE, HELD, SIDE, COUNT = range(4)
# params: shared, then per navigator
WHEELBASE, DWELL, LANE, ROOM_MARGIN, STOP_MARGIN, V_TURN, TURN_RADIUS, BODY, HALF_CONE = range(9)
DETECTION, SECTOR, FRONT, RISK, RELEASE = range(9, 14)  # fuzzy-2b
V_MAX, SENSED, FRONT_5B, KEEP, CLEAR, VISION, KEPT_DETECTION, KEPT_KEEP, KEPT_CLEAR, COLUMNS = range(9, 19)  # fuzzy-5b
WALL_COLUMNS = 9  # wall-follow: d_d, d_f, d_g
STEERING, SPEED = 9, 10  # a constant command
# shared again, after the longest block: readings by sector, gap finding (kernels.gaps)
READING_HALF, GAP, GAP_CLEARANCE, GAP_LOOK, GAP_FIELD = range(COLUMNS + 7, COLUMNS + 12)
# the optional layers this package adds to the published navigators (1.0 on, 0.0 off;
# fuzzynav.control.batched.LAYERS)
ORBIT_GUARD, TURNING_ROOM, SAFETY_STOP, HYSTERESIS = range(GAP_FIELD + 1, GAP_FIELD + 5)
N_PARAMS = HYSTERESIS + 1
GSB_VRB, TURN, GAP_5B = 4, 5, 6  # fuzzy-5b modes beyond guard.GSB, FOA, ROA, LOA
RANK_5B = (0, 3, 2, 2, 1, 4, 2)  # caution ranks of the fuzzy-5b modes
GAP_2B = 3
GAP_BRAKE = 1.5  # 1/s: through a gap, V ≤ this × the body's clearance to the nearest reading
RANK_2B = (0, 1, 2, 1)  # GSB, OA, OA at full lock, through the gap


@jit
def guarded_goal_seeking(tables, system, distance, bearing, wheelbase):
    """(α, V, guard) of Table IV.1 with the anti-orbit guard: the arc through the goal
    α_arc = atan(2 l sin β / d) when the table steers less, straight on when even α_max is too
    wide (:mod:`fuzzynav.control.goal_seeking`); ``wheelbase`` 0 is the table alone (no guard)."""
    table, speed = ts0.evaluate(tables, system, distance, -wrap(bearing), 0.0)
    if wheelbase <= 0.0:
        return table, speed, 0
    arc = math.atan(2.0 * wheelbase * math.sin(bearing) / max(distance, 1e-9))
    if abs(arc) > ALPHA_MAX:
        return 0.0, speed, 2
    return (arc, speed, 1) if abs(table) < abs(arc) else (table, speed, 0)


@jit
def goal_seeking_all(tables, system, distance, bearing, wheelbase, out):
    """:func:`guarded_goal_seeking` of every (distance, bearing): ``out`` (N, 3) = α, V, guard
    (0 the table, 1 the arc through the goal, 2 straight out of the turning circle)."""
    for n in range(distance.shape[0]):
        out[n, 0], out[n, 1], out[n, 2] = guarded_goal_seeking(tables, system, distance[n], bearing[n], wheelbase)


@jit
def guard_wheelbase(params):
    """The wheelbase the anti-orbit guard works with: 0 (the table alone) with that layer off."""
    return params[WHEELBASE] if params[ORBIT_GUARD] != 0.0 else 0.0


@jit
def dwell(params):
    """Steps a behaviour is held before a change that removes caution: none without hysteresis."""
    return params[DWELL] if params[HYSTERESIS] != 0.0 else 0.0


@jit
def watch(params, state, memory, robot, seen, dt, goal_bearing, turning):
    """Remember this step's hits and ask the turning-room guard: (turn wanted?, side)."""
    pose = Pose(robot.x, robot.y, robot.theta)
    guard.remember(memory, state[COUNT], pose, seen, params[HALF_CONE])
    state[COUNT] += 1
    wanted, side = guard.turn_wanted(memory, pose, robot.v * dt, turning, goal_bearing, state[SIDE],
                                     TurnRoom(params[LANE], params[ROOM_MARGIN], params[BODY], params[TURN_RADIUS]))
    state[SIDE] = side
    return wanted and params[TURNING_ROOM] != 0.0, side


@jit
def safety_stop(params, memory, x, y, theta, speed, dt):
    """0 when one step at ``speed`` would bring the body within the stop margin of a hit (never
    with that layer off)."""
    if params[SAFETY_STOP] == 0.0:
        return speed
    return 0.0 if guard.step_clearance(memory, x, y, theta, speed * dt, params[BODY]) < params[STOP_MARGIN] else speed


@jit
def through_gap(params, ranges, angles, bearing):
    """(found, heading) of :func:`fuzzynav.kernels.gaps.gap_heading` with this navigator's
    clearance, look-ahead and field — where no passage keeps that margin, the one that keeps half
    of it, then a quarter; never found where gap finding is off."""
    if params[GAP] == 0.0:
        return False, 0.0
    margin = params[GAP_CLEARANCE] - params[BODY]
    for share in (1.0, 0.5, 0.25):
        found, heading, _ = gaps.gap_heading(ranges, angles, bearing, params[BODY] + share * margin,
                                             params[GAP_LOOK], params[GAP_FIELD], params[TURN_RADIUS])
        if found:
            return True, heading
    return False, 0.0


@jit
def two_behaviours(navigator, state, memory, robot, distance, bearing, seen, dt):
    """fuzzy-2b (Fig IV.9): (α, V, mode 0 GSB / 1 OA / 2 OA at full lock)."""
    params, tables, ranges, angles = navigator.params, navigator.tables, seen.ranges, seen.angles
    steering, speed, _ = guarded_goal_seeking(tables, 0, distance, bearing, guard_wheelbase(params))
    d_ro, theta_o = seen.d_o, seen.b_o
    k = 0
    for j in range(1, ranges.shape[0]):
        if ranges[j] < ranges[k]:
            k = j
    if ranges[k] < d_ro:  # a boundary wall, which D_ro leaves out, as the ring sees it
        d_ro, theta_o = ranges[k], angles[k]
    d_ro = d_ro - params[RISK]
    sector = params[SECTOR]
    in_way = abs(theta_o) <= params[FRONT] or (abs(theta_o) <= sector and abs(wrap(theta_o - bearing)) <= sector)
    avoid = d_ro < params[DETECTION] and in_way and distance > d_ro
    before = max(state[MODE], 0)
    if params[HYSTERESIS] != 0.0 and before >= 1 and d_ro < params[DETECTION] + params[RELEASE] and abs(theta_o) <= sector + math.radians(15.0) \
            and distance > d_ro:
        avoid = True
    turn, side = watch(params, state, memory, robot, seen, dt, bearing, before == 2)
    gap, heading = through_gap(params, ranges, angles, bearing) if avoid else (False, 0.0)
    turn = turn and not gap  # a passage that fits and can be turned to: no full-lock turn needed
    mode = guard.switch(state, 2 if turn else ((GAP_2B if gap else 1) if avoid else 0), True, RANK_2B,
                        dwell(params))
    if mode >= 1:
        steering, speed = ts0.evaluate(tables, 1, d_ro if math.isfinite(d_ro) else 1e3, -wrap(theta_o), 0.0)
    if mode == GAP_2B and not gap:  # held by the switch: this step's gap, if any
        gap, heading = through_gap(params, ranges, angles, bearing)
    if mode == GAP_2B and gap:  # Table IV.1 towards the gap, at the avoider's speed
        steering = guarded_goal_seeking(tables, 0, distance, heading, guard_wheelbase(params))[0]
    if mode == 2:
        steering, speed = side * ALPHA_MAX, params[V_TURN]
    return steering, safety_stop(params, memory, robot.x, robot.y, robot.theta, speed, dt), mode


@jit
def five_behaviours(navigator, state, memory, robot, distance, bearing, seen, dt):
    """fuzzy-5b (Fig IV.16): (α, V, mode GSB / FOA / ROA / LOA / GSB+VRB / full-lock turn)."""
    params, tables, ranges, angles, v = navigator.params, navigator.tables, seen.ranges, seen.angles, robot.v
    c = COLUMNS
    if params[READING_HALF] > 0.0:
        d0, d1, d2, d3, d4, d5, d6 = gaps.sector_readings(ranges, angles, params[READING_HALF], seen.max_range)
    else:
        d0, d1, d2, d3, d4, d5 = (ranges[int(params[c])], ranges[int(params[c + 1])], ranges[int(params[c + 2])],
                                  ranges[int(params[c + 3])], ranges[int(params[c + 4])], ranges[int(params[c + 5])])
        d6 = ranges[int(params[c + 6])]
    d = (d0, d1, d2, d3, d4, d5, d6)
    before = state[MODE]
    if params[HYSTERESIS] != 0.0 and (before == guard.GSB or before == GSB_VRB):  # goal seeking keeps the robot under relaxed thresholds
        choice = guard.select(d, distance, bearing, params[KEPT_DETECTION], params[FRONT_5B], params[KEPT_KEEP],
                              params[KEPT_CLEAR], params[VISION])
    else:
        choice = guard.select(d, distance, bearing, params[SENSED], params[FRONT_5B], params[KEEP], params[CLEAR],
                              params[VISION])
    dmin = min(min(min(d0, d1), min(d2, d3)), min(min(d4, d5), d6))
    turn, side = watch(params, state, memory, robot, seen, dt, bearing, before == TURN)
    wanted = TURN if turn else (GSB_VRB if choice == guard.GSB and dmin < params[SENSED] else choice)
    gap, heading = through_gap(params, ranges, angles, bearing) if wanted != guard.GSB else (False, 0.0)
    if gap:  # a passage that fits and can be turned to: no full-lock turn needed
        wanted, turn = GAP_5B, False
    mode = guard.switch(state, wanted, dmin < params[KEEP] or turn or gap, RANK_5B, dwell(params))
    if mode == GAP_5B and not gap:  # held by the switch: this step's gap, else the front avoider
        gap, heading = through_gap(params, ranges, angles, bearing)
    steering = speed = 0.0
    if mode == guard.GSB or mode == GSB_VRB or (mode == GAP_5B and gap):
        steering, speed, _ = guarded_goal_seeking(tables, 0, distance, heading if mode == GAP_5B else bearing,
                                                  guard_wheelbase(params))
    elif mode == TURN:
        steering, speed = side * ALPHA_MAX, params[V_TURN]
    if mode != guard.GSB and mode != TURN:
        adjust, _ = ts0.evaluate(tables, 4, v, dmin, 0.0)
        v_vrb = min(max(v + adjust, params[V_TURN]), params[V_MAX])  # eq IV.9
        if mode == GAP_5B and gap:  # slow enough to turn before the nearest post
            speed = min(min(speed, v_vrb), max(params[V_TURN], GAP_BRAKE * (dmin - params[BODY])))
        elif mode == GSB_VRB:
            speed = min(speed, v_vrb)
        else:
            if mode == guard.FOA or mode == GAP_5B:
                steering, _ = ts0.evaluate(tables, 1, d0, d1, d2)
            elif mode == guard.ROA:
                steering, _ = ts0.evaluate(tables, 2, d1, d3, d5)
            else:
                steering, _ = ts0.evaluate(tables, 3, d2, d4, d6)
            speed = v_vrb
    return steering, safety_stop(params, memory, robot.x, robot.y, robot.theta, speed, dt), mode


@jit
def act_one(navigator, state, memory, robot, seen, dt):
    """(α, V, behaviour code) of ``navigator`` (a :class:`~fuzzynav.kernels.records.Navigator`)
    for one ``robot`` (:class:`~fuzzynav.kernels.records.Robot`: at (x, y, θ) moving at ``v``,
    aiming at (tx, ty)) reading ``seen`` (:class:`~fuzzynav.kernels.records.Reading`)."""
    kind, params, tables, ranges = navigator.kind, navigator.params, navigator.tables, seen.ranges
    distance = math.hypot(robot.tx - robot.x, robot.ty - robot.y)
    bearing = wrap(math.atan2(robot.ty - robot.y, robot.tx - robot.x) - robot.theta)
    if kind == GOAL_SEEKING:
        steering, speed, _ = guarded_goal_seeking(tables, 0, distance, bearing, guard_wheelbase(params))
        return steering, speed, 0
    if kind == TWO_BEHAVIOURS:
        return two_behaviours(navigator, state, memory, robot, distance, bearing, seen, dt)
    if kind == FIVE_BEHAVIOURS:
        return five_behaviours(navigator, state, memory, robot, distance, bearing, seen, dt)
    if kind == CONSTANT:
        return params[STEERING], params[SPEED], 0
    steering, speed = ts0.evaluate(tables, 0, ranges[int(params[WALL_COLUMNS])], ranges[int(params[WALL_COLUMNS + 1])],
                                   ranges[int(params[WALL_COLUMNS + 2])])
    return steering, speed, 0


@jit
def act(navigator, state, memory, seen, dt, out):
    """:func:`act_one` of every active robot of ``seen`` (a
    :class:`~fuzzynav.kernels.records.Readings`): ``out`` (N, 3) = α, V, behaviour code."""
    for n in range(seen.poses.shape[0]):
        if seen.active[n]:
            out[n, 0], out[n, 1], out[n, 2] = act_one(navigator, state[n], memory[n], robot_of(seen, n),
                                                      reading_of(seen, n), dt)


@jit
def robot_of(seen, n):
    """Robot ``n`` of a :class:`~fuzzynav.kernels.records.Readings` as a :class:`~fuzzynav.kernels.records.Robot`."""
    return Robot(seen.poses[n, 0], seen.poses[n, 1], seen.poses[n, 2], seen.speeds[n], seen.targets[n, 0],
                 seen.targets[n, 1])


@jit
def reading_of(seen, n):
    """What robot ``n`` of a :class:`~fuzzynav.kernels.records.Readings` reads, as a
    :class:`~fuzzynav.kernels.records.Reading`."""
    return Reading(seen.ranges[n], seen.angles, seen.max_range, seen.obstacle[n, 0], seen.obstacle[n, 1])


@jit
def guard_all(params, state, memory, seen, dt, goal_bearing, turning, out):
    """The turning-room guard of every robot of ``seen`` (a :class:`~fuzzynav.kernels.records.Readings`,
    its targets and ``active`` unused; :func:`watch`): ``out`` (N, 2) = turn wanted (0/1), side."""
    for n in range(seen.poses.shape[0]):
        wanted, side = watch(params, state[n], memory[n], robot_of(seen, n), reading_of(seen, n), dt, goal_bearing[n],
                             turning[n])
        out[n, 0], out[n, 1] = wanted, side


@jit
def stop_all(params, memory, poses, speeds, dt, out):
    """The safety stop of every robot (:func:`safety_stop`) into ``out`` (N,)."""
    for n in range(poses.shape[0]):
        out[n] = safety_stop(params, memory[n], poses[n, 0], poses[n, 1], poses[n, 2], speeds[n], dt)
