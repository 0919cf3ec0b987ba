"""Latency compensation of the default navigator (``fuzzy-5b``), compiled: a Smith predictor (Smith 1957,
"Closer control of loops with dead time") on the robot's own motion.

A robot whose commands reach the wheels ``delay`` steps late (the scenario's
``robot.actuation.latency``, :mod:`fuzzynav.robot.imperfections`) applies the command decided
now only after it has driven on the ``delay`` commands already on their way. The navigator
remembers the commands it sent (a queue of ``delay`` slots in its layers' state row,
:func:`fuzzynav.kernels.row_blocks.queue_of`, zeros at the start as the robot's own queue), rolls them
forward from the pose it is given through the stepping core's kinematics
(:func:`fuzzynav.kernels.motion.advance`, the model :func:`fuzzynav.kernels.step.move` drives
the robot with; the slip, rate limits and drift are not predicted) and decides at the predicted
pose, with the scan moved into it (:func:`shifted`). With ``delay`` 0 none of this runs.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels.layers import PARAM, STATE
from fuzzynav.kernels.motion import ROBOT_FIELDS, advance, clip, wrap
from fuzzynav.kernels.records import Reading, Robot
from fuzzynav.kernels.row_blocks import queue_of


@jit
def robot_of(params):
    """The robot's array (:data:`~fuzzynav.kernels.motion.ROBOT_FIELDS`) in the layers' ``params``."""
    return params[PARAM.plant_dt:PARAM.plant_dt + len(ROBOT_FIELDS)]


@jit
def predicted(params, row, robot):
    """(x, y, θ, V) of ``robot`` (a :class:`~fuzzynav.kernels.records.Robot`) once the commands in
    its queue have been applied, oldest first; V the last of them, the speed it will be driving at."""
    queue, sent, delay = queue_of(params, row), int(row[STATE.sent]), int(params[PARAM.delay])
    plant = robot_of(params)
    x, y, theta, v = robot.x, robot.y, robot.theta, robot.v
    for i in range(delay):
        steering, v = queue[(sent + i) % delay, 0], queue[(sent + i) % delay, 1]
        x, y, theta = advance(x, y, theta, steering, v, plant)
    return x, y, theta, v


@jit
def sent(params, row, steering, speed):
    """Remember the command (α, V) sent now, clipped to the robot's limits as the robot clips it."""
    queue, delay = queue_of(params, row), int(params[PARAM.delay])
    slot = int(row[STATE.sent]) % delay
    queue[slot, 0], queue[slot, 1] = clip(steering, speed, robot_of(params))
    row[STATE.sent] += 1.0


@jit
def ray_of(angles, a):
    """The index of the ray of ascending ``angles`` nearest the direction ``a`` (rad, robot frame),
    −1 when ``a`` is farther than half the spacing beyond the first or last ray."""
    size = angles.shape[0]
    i = np.searchsorted(angles, a)
    if i == 0:
        half = 0.5 * (angles[1] - angles[0]) if size > 1 else math.pi
        return 0 if angles[0] - a <= half else -1
    if i == size:
        half = 0.5 * (angles[size - 1] - angles[size - 2]) if size > 1 else math.pi
        return size - 1 if a - angles[size - 1] <= half else -1
    return i if angles[i] - a < a - angles[i - 1] else i - 1


@jit
def shifted(seen, dx, dy, dtheta, join, out):
    """The scan of ``seen`` (a :class:`~fuzzynav.kernels.records.Reading`, ascending angles) as
    read from a pose (dx, dy, dθ) from it in its frame, into ``out`` (S,); returns (D_ro, θ_o)
    from there. Every echo moves to the ray nearest its new direction (the nearest echo per ray);
    the rays between two neighbouring echoes less than ``join`` apart (a gap the body cannot pass)
    read the nearer of the two, so a wall seen closer stays closed; a ray no echo reaches reads
    nothing within reach. The nearest obstacle point moves the same way (the nearer of it and the
    echoes)."""
    ranges, angles, max_range = seen.ranges, seen.angles, seen.max_range
    c, s = math.cos(dtheta), math.sin(dtheta)
    out[:] = max_range
    d_o, b_o = math.inf, 0.0
    if math.isfinite(seen.d_o):
        px, py = seen.d_o * math.cos(seen.b_o) - dx, seen.d_o * math.sin(seen.b_o) - dy
        d_o, b_o = math.hypot(px, py), wrap(math.atan2(c * py - s * px, c * px + s * py))
    last_x = last_y = last_r = last_a = math.nan
    for j in range(ranges.shape[0]):
        r = ranges[j]
        if not (math.isfinite(r) and r < max_range - 1e-9):
            last_x = math.nan
            continue
        px, py = r * math.cos(angles[j]) - dx, r * math.sin(angles[j]) - dy
        qx, qy = c * px + s * py, c * py - s * px
        rr, aa = math.hypot(qx, qy), math.atan2(qy, qx)
        if rr < d_o:
            d_o, b_o = rr, aa
        i = ray_of(angles, aa)
        if i >= 0:
            out[i] = min(out[i], rr)
        if last_x == last_x and math.hypot(qx - last_x, qy - last_y) < join and abs(aa - last_a) < math.pi:
            low, high, nearer = min(aa, last_a), max(aa, last_a), min(rr, last_r)
            k = np.searchsorted(angles, low)
            while k < ranges.shape[0] and angles[k] <= high:
                out[k] = min(out[k], nearer)
                k += 1
        last_x, last_y, last_r, last_a = qx, qy, rr, aa
    return d_o, b_o


@jit
def ahead(params, row, robot, seen):
    """(robot, reading) at the pose where the command decided now will act (:func:`predicted`),
    with the scan moved there (:func:`shifted`; ``join``: the body's diameter)."""
    x, y, theta, v = predicted(params, row, robot)
    c, s = math.cos(robot.theta), math.sin(robot.theta)
    dx, dy = c * (x - robot.x) + s * (y - robot.y), c * (y - robot.y) - s * (x - robot.x)
    out = np.empty_like(seen.ranges)
    d_o, b_o = shifted(seen, dx, dy, wrap(theta - robot.theta), 2.0 * params[PARAM.plant_radius], out)
    return (Robot(x, y, theta, v, robot.tx, robot.ty),
            Reading(out, seen.angles, seen.max_range, d_o, b_o))
