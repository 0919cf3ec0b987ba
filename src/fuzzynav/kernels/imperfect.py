"""The real robot's imperfections inside the compiled step (:mod:`fuzzynav.robot.imperfections`
says what each one is): noisy and dropped range readings, a command queue, rate limits, slip and
odometry drift.

They travel as one record, ``imperfect = (params, memory, queue, rng)``:

- ``params`` (floats, :data:`fuzzynav.robot.imperfections.PARAM_FIELDS`);
- ``memory`` (N, :data:`MEMORY_FIELDS`) per robot: the last applied commands, the believed
  pose's error and the drift's direction in the robot's frame;
- ``queue`` (N, max(delay, 1), 2): the commands on their way to the wheels;
- ``rng`` (N,) uint64: each robot's random stream (SplitMix64, Steele, Lea & Flood 2014), seeded
  from the episode's seed.

A plant outside the compiled step (:mod:`fuzzynav.sim.plants`) gets the same imperfections around
it (``plant_*``): the queue, limits and slip on the set points it is given, the drift on the
distance it drove, the noise and dropout on its readings.

The step passes ``None`` for a perfect robot: numba then compiles none of this, and the step is
the one without imperfections, bit for bit.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.jit import jit
from fuzzynav.kernels.motion import DT, advance

RANGE_SIGMA, DROPOUT, REACH, DELAY, STEERING_RATE, ACCELERATION, SLIP, DRIFT = range(8)
MEMORY_FIELDS = ("applied_steering", "applied_speed", "error_x", "error_y", "drift_angle")
APPLIED_STEERING, APPLIED_SPEED, ERROR_X, ERROR_Y, DRIFT_ANGLE = range(len(MEMORY_FIELDS))


def record(imperfections, dt: float, n: int, seed: np.random.SeedSequence):
    """The ``imperfect`` record of ``n`` robots for an
    :class:`~fuzzynav.robot.imperfections.Imperfections`, every draw from ``seed``; ``None`` for
    the perfect robot."""
    if imperfections.off:
        return None
    params = imperfections.array(dt)
    rng = np.random.default_rng(seed)
    memory = np.zeros((n, len(MEMORY_FIELDS)))
    memory[:, DRIFT_ANGLE] = rng.uniform(-math.pi, math.pi, n)
    queue = np.zeros((n, max(int(params[DELAY]), 1), 2))
    return params, memory, queue, rng.integers(0, 2**64, n, dtype=np.uint64)


@jit
def uniform(rng, n):
    """The next number in [0, 1) of robot ``n``'s stream (SplitMix64)."""
    z = rng[n] + np.uint64(0x9E3779B97F4A7C15)
    rng[n] = z
    z = (z ^ (z >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
    z = (z ^ (z >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    z = z ^ (z >> np.uint64(31))
    return float(z >> np.uint64(11)) * (1.0 / 9007199254740992.0)


@jit
def gauss(rng, n):
    """A standard normal draw of robot ``n``'s stream (Box–Muller)."""
    u = 1.0 - uniform(rng, n)
    return math.sqrt(-2.0 * math.log(u)) * math.cos(2.0 * math.pi * uniform(rng, n))


@jit
def sense(imperfect, n, ranges, max_range):
    """Robot ``n``'s ``ranges`` as the real sensor reads them: no echo (the reach) beyond its
    reach or at a dropout; the echoes get Gaussian noise (kept within [0, reach])."""
    params, _, _, rng = imperfect
    reach = min(max_range, params[REACH])
    for j in range(ranges.shape[0]):
        if ranges[j] >= reach or (params[DROPOUT] > 0.0 and uniform(rng, n) < params[DROPOUT]):
            ranges[j] = reach
        elif params[RANGE_SIGMA] > 0.0:
            ranges[j] = min(max(ranges[j] + params[RANGE_SIGMA] * gauss(rng, n), 0.0), reach)


@jit
def believed(imperfect, n, x, y, distance):
    """What robot ``n``'s controller is given: its believed position (the true one plus the
    odometry's error) and the nearest obstacle's distance with the range noise."""
    params, memory, _, rng = imperfect
    if params[RANGE_SIGMA] > 0.0 and math.isfinite(distance):
        distance = max(distance + params[RANGE_SIGMA] * gauss(rng, n), 0.0)
    return x + memory[n, ERROR_X], y + memory[n, ERROR_Y], distance


@jit
def limited(value, previous, rate):
    """``value`` moved at most ``rate`` from ``previous``."""
    return previous + min(max(value - previous, -rate), rate)


@jit
def actuate(imperfect, n, steering, speed, k, robot):
    """The commands robot ``n``'s wheels apply at step ``k``: the ones decided ``delay`` steps
    ago (the queue), moved from the last applied ones at most by the rate limits."""
    params, memory, queue, _ = imperfect
    delay = int(params[DELAY])
    if delay > 0:
        slot = k % delay
        steering, queue[n, slot, 0] = queue[n, slot, 0], steering
        speed, queue[n, slot, 1] = queue[n, slot, 1], speed
    dt = robot[DT]
    steering = limited(steering, memory[n, APPLIED_STEERING], params[STEERING_RATE] * dt)
    speed = limited(speed, memory[n, APPLIED_SPEED], params[ACCELERATION] * dt)
    memory[n, APPLIED_STEERING], memory[n, APPLIED_SPEED] = steering, speed
    return steering, speed


@jit
def slipped(imperfect, n, steering, speed):
    """The applied (α, V) after the slip: a random part of the speed and of the heading rate lost."""
    params, _, _, rng = imperfect
    if params[SLIP] > 0.0:
        speed_kept = 1.0 - 2.0 * params[SLIP] * uniform(rng, n)
        turn_kept = 1.0 - 2.0 * params[SLIP] * uniform(rng, n)
        steering = math.atan(math.tan(steering) * turn_kept / speed_kept)  # ω = V tan α / l loses turn_kept
        speed *= speed_kept
    return steering, speed


@jit
def drift(imperfect, n, x, y, theta, new_x, new_y):
    """The odometry's error of robot ``n`` grows by ``drift`` times the distance it drove from
    (x, y) to (new_x, new_y), in the drift's direction in its frame (heading θ before the step)."""
    params, memory, _, _ = imperfect
    if params[DRIFT] > 0.0:
        error = params[DRIFT] * math.hypot(new_x - x, new_y - y)
        memory[n, ERROR_X] += error * math.cos(theta + memory[n, DRIFT_ANGLE])
        memory[n, ERROR_Y] += error * math.sin(theta + memory[n, DRIFT_ANGLE])


@jit
def move(imperfect, n, x, y, theta, steering, speed, robot):
    """Robot ``n``'s pose after one step under the applied (α, V), with the slip
    (:func:`slipped`); the odometry's error grows (:func:`drift`)."""
    steering, speed = slipped(imperfect, n, steering, speed)
    new_x, new_y, new_theta = advance(x, y, theta, steering, speed, robot)
    drift(imperfect, n, x, y, theta, new_x, new_y)
    return new_x, new_y, new_theta


# -- another plant (fuzzynav.sim.plants) moves the robots: the same imperfections around it ------
@jit
def plant_commands(imperfect, k, state, rows, robot, steering_column, speed_column):
    """The set points another plant is given at step ``k``, written over the clipped commands in
    ``state`` of the ``rows`` it moves: through the queue and rate limits (:func:`actuate`), then
    the slip (:func:`slipped`), a loss of the set points of the steering servo and wheel speeds."""
    for n in range(state.shape[0]):
        if rows[n]:
            steering, speed = actuate(imperfect, n, state[n, steering_column], state[n, speed_column], k, robot)
            state[n, steering_column], state[n, speed_column] = slipped(imperfect, n, steering, speed)


@jit
def plant_moved(imperfect, before, state, rows):
    """The odometry's error after another plant moved the ``rows`` from the poses ``before``
    (N, 3) to those of ``state`` (x, y first): :func:`drift` on the distance it really drove."""
    for n in range(state.shape[0]):
        if rows[n] and math.isfinite(state[n, 0]) and math.isfinite(state[n, 1]):
            drift(imperfect, n, before[n, 0], before[n, 1], before[n, 2], state[n, 0], state[n, 1])


@jit
def plant_sense(imperfect, ranges, rows, max_range):
    """Another plant's readings of the ``rows`` as the real sensor reads them (:func:`sense`)."""
    for n in range(ranges.shape[0]):
        if rows[n]:
            sense(imperfect, n, ranges[n], max_range)
