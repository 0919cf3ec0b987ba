"""The recovery manoeuvre of the default navigators, compiled: back out of a dead end on an arc,
then turn the other way (a K-turn; ``REC-BACK``, ``REC-TURN``). What it does and why is told in
:mod:`fuzzynav.control.recovery`; these are its steps for one robot, on its ``state`` row
(:mod:`fuzzynav.kernels.layers` names the columns and ``params``) and the obstacle points it has
seen (:mod:`fuzzynav.kernels.sightings`).
"""

from __future__ import annotations

import math

from fuzzynav.fuzzy.constants import ALPHA_MAX
from fuzzynav.jit import jit
from fuzzynav.kernels import sightings, ts0
from fuzzynav.kernels.layers import BACK, NO_PHASE, PARAM, STATE, TURN

LANE_HALF = math.radians(31)  # the rays that must read the lane free to end the turn early


@jit
def remainder(x, y):
    """IEEE 754 remainder of x by y > 0, in (−y/2, y/2] (Python's ``math.remainder``, exact)."""
    ax = abs(x)
    m = ax % y  # fmod: both positive
    c = y - m
    if m < c:
        r = m
    elif m > c:
        r = -c
    else:  # half-way: the even multiple
        r = m - 2.0 * ((0.5 * (ax - m)) % y)
    return math.copysign(1.0, x) * r


@jit
def start(state, params, tables, seen, pose, goal_bearing, cap, t):
    """Begin a manoeuvre at ``pose`` (a :class:`~fuzzynav.kernels.records.Pose`), the remembered
    points ``seen`` (a :class:`~fuzzynav.kernels.records.Sightings`): the back-up arc's steering
    from the rule base (room on the left − room on the right within ``cap``, the goal bearing); a
    second recovery within 1 m of the last one swings the other way (full lock towards the goal
    when the rule base says straight)."""
    points, count, x, y, theta = seen.points, seen.count, pose.x, pose.y, pose.theta
    left, right = sightings.side_room(points, count, x, y, theta, cap)
    steering = ts0.evaluate(tables, 0, left - right, goal_bearing, 0.0)[0]
    again = (state[STATE.last_x] == state[STATE.last_x]
             and math.hypot(x - state[STATE.last_x], y - state[STATE.last_y]) < 1.0)
    state[STATE.flip] = (1.0 - state[STATE.flip]) if again else 0.0
    if state[STATE.flip]:
        steering = -steering if abs(steering) > 1e-9 else ALPHA_MAX * (1.0 if goal_bearing >= 0 else -1.0)
    state[STATE.last_x], state[STATE.last_y] = x, y
    state[STATE.phase], state[STATE.start_x], state[STATE.start_y], state[STATE.t_recovery] = BACK, x, y, t
    state[STATE.back_steering] = steering
    state[STATE.back_speed] = -min(params[PARAM.v_back], params[PARAM.max_reverse_speed])


@jit
def command(state, params, seen, pose, ranges, angles, dt, t):
    """(moving, α, V, phase) of this step of the manoeuvre at ``pose`` among the remembered points
    ``seen`` (:class:`~fuzzynav.kernels.records.Pose`, :class:`~fuzzynav.kernels.records.Sightings`);
    ``moving`` is False when it has ended (the navigator takes over). Backing ends after
    ``back_distance`` or when the next step would not be safe; the turn at full lock the other way
    (only after an arc) ends after
    ``turn_angle``, when the rays within ±31° read the lane free, or when not safe; the whole
    manoeuvre after ``recovery_time``."""
    x, y, theta = pose.x, pose.y, pose.theta
    if t - state[STATE.t_recovery] > params[PARAM.recovery_time]:
        state[STATE.phase] = NO_PHASE
    if state[STATE.phase] == BACK:
        backed = math.hypot(x - state[STATE.start_x], y - state[STATE.start_y])
        within = params[PARAM.barrier_within]
        gamma = params[PARAM.barrier] if within == 0.0 or backed < within else 0.0
        if backed < params[PARAM.back_distance] and may_step(params, seen, pose, state[STATE.back_speed], dt, gamma):
            return True, state[STATE.back_steering], state[STATE.back_speed], BACK
        state[STATE.phase] = TURN if abs(state[STATE.back_steering]) > ALPHA_MAX / 4 else NO_PHASE
        state[STATE.heading] = theta
    if state[STATE.phase] == TURN:
        turned = abs(remainder(theta - state[STATE.heading], math.tau))
        steering = -math.copysign(ALPHA_MAX, state[STATE.back_steering])
        lane_free = True
        for i in range(angles.shape[0]):
            if abs(angles[i]) <= LANE_HALF and not ranges[i] >= params[PARAM.lane]:
                lane_free = False
        gamma = params[PARAM.barrier] if params[PARAM.barrier_within] == 0.0 else 0.0
        if turned < params[PARAM.turn_angle] and not lane_free and may_step(params, seen, pose,
                                                                       params[PARAM.v_turn], dt, gamma):
            return True, steering, params[PARAM.v_turn], TURN
        state[STATE.phase] = NO_PHASE
    return False, 0.0, 0.0, NO_PHASE


@jit
def safe(params, points, count, x, y, theta, speed, dt):
    """True when one step at speed V (eq IV.2: the position moves along the present heading,
    whatever the steering) leaves the body ``margin`` from every remembered point, or at least
    no nearer to them than now (and clear of them)."""
    now = sightings.clearance(points, count, x, y)
    after = sightings.clearance(points, count, x + speed * dt * math.cos(theta), y + speed * dt * math.sin(theta))
    radius = params[PARAM.radius]
    return after >= radius + params[PARAM.margin] or (after >= now and after > radius + 0.01)


@jit
def may_step(params, seen, pose, speed, dt, gamma):
    """:func:`safe` at ``pose`` among ``seen``, or, with the barrier γ > 0, a step that closes at
    most the share γ of the body's gap h = clearance − radius to the nearest remembered point,
    h(after) ≥ (1 − γ) h(now) > 0: the discrete-time control barrier function condition
    (A. Agrawal, K. Sreenath, "Discrete control barrier functions for safety-critical control of
    discrete systems with application to bipedal robot navigation", RSS 2017). The gap never
    closes, yet a body wedged between two points within ``margin`` (each step nearer to one of
    them) may still back out on its arc, which the present heading alone never allows. γ is
    :attr:`~fuzzynav.kernels.layers.Recovery.barrier`, or 0 where
    :attr:`~fuzzynav.kernels.layers.Recovery.barrier_within` says it no longer holds."""
    points, count, x, y, theta = seen.points, seen.count, pose.x, pose.y, pose.theta
    if safe(params, points, count, x, y, theta, speed, dt):
        return True
    radius = params[PARAM.radius]
    now = sightings.clearance(points, count, x, y) - radius
    after = sightings.clearance(points, count, x + speed * dt * math.cos(theta), y + speed * dt * math.sin(theta)) - radius
    return gamma > 0.0 and now > 0.0 and after >= (1.0 - gamma) * now
