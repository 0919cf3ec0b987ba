"""Angles, command limits and tricycle kinematics, compiled (docs/thesis.md conventions, thesis eq IV.1–IV.2).

Robot parameters travel as one float array (:data:`ROBOT_FIELDS` order, built by
:meth:`fuzzynav.robot.tricycle.TricycleParams.array`).
"""

from __future__ import annotations

import math

from fuzzynav.jit import jit

TURN = 2.0 * math.pi


@jit
def turn_remainder(x):
    """``x % 2π`` (Python's remainder), the library call that computes it (the costly part of
    wrapping an angle) skipped where ``x`` already lies in (0, 2π): there the remainder is ``x``
    itself, so the result is the same number, bit for bit (zero is left to the modulo, which
    turns −0.0 into 0.0)."""
    return x if 0.0 < x < TURN else x % TURN


@jit
def wrap(angle):
    """:func:`~fuzzynav.kernels.angles.wrap_formula` of one float, by :func:`turn_remainder`: the
    same number, bit for bit."""
    return math.pi - turn_remainder(math.pi - angle)

ROBOT_FIELDS = ("dt", "wheelbase", "radius", "max_steering", "lowest_speed", "max_speed", "arc")
DT, WHEELBASE, RADIUS, MAX_STEERING, LOWEST_SPEED, MAX_SPEED, ARC = range(len(ROBOT_FIELDS))


@jit
def ring_gap(x, y, radius, limit):
    """| |(x, y)| − radius |, exact (``math.hypot``) wherever it may be below ``limit``; elsewhere
    from the cheaper sqrt(x² + y²), then still ≥ ``limit``. So a minimum over many points, or a
    test against ``limit``, comes out as with ``math.hypot`` everywhere, at a fraction of its cost."""
    q = math.sqrt(x * x + y * y)
    if abs(q - radius) < limit + 1e-9 * (1.0 + q):
        return abs(math.hypot(x, y) - radius)
    return abs(q - radius)


@jit
def clip(steering, speed, robot):
    """(α, V) within |α| ≤ max_steering, lowest_speed ≤ V ≤ max_speed (NaN stays NaN); the
    lowest speed is −max_reverse_speed for a robot that reverses (V < 0), else min_speed."""
    steering = steering if steering != steering else min(max(steering, -robot[MAX_STEERING]), robot[MAX_STEERING])
    speed = speed if speed != speed else min(max(speed, robot[LOWEST_SPEED]), robot[MAX_SPEED])
    return steering, speed


@jit
def advance(x, y, theta, steering, speed, robot):
    """Pose after one step Δt under (α, V), θ wrapped. Euler (eq IV.2): x += Δt V cos θ,
    y += Δt V sin θ, θ += Δt V tan(α) / l. Exact arc (eq IV.1, α and V constant over the step):
    with ω = V tan(α) / l, the chord 2 V sin(ω Δt / 2) / ω along θ + ω Δt / 2, written with
    sinc(x) = sin(πx) / (πx) so that it stays well conditioned as ω → 0."""
    dt = robot[DT]
    omega = speed * math.tan(steering) / robot[WHEELBASE]
    new_theta = wrap(theta + omega * dt)
    if robot[ARC] == 0.0:
        chord, direction = dt * speed, theta
    else:
        half = 0.5 * omega * dt
        z = half / math.pi
        z = math.pi * (1.0e-20 if z == 0 else z)
        chord = dt * speed * (math.sin(z) / z)
        direction = theta + half
    return x + chord * math.cos(direction), y + chord * math.sin(direction), new_theta


@jit
def advance_all(poses, steering, speed, robot, out):
    """:func:`advance` of every row of ``poses`` (N, 3) into ``out`` (N, 3)."""
    for n in range(poses.shape[0]):
        out[n, 0], out[n, 1], out[n, 2] = advance(poses[n, 0], poses[n, 1], poses[n, 2], steering[n], speed[n], robot)
