"""Turning room of a tricycle from its range readings (used by the supervisor of ``fuzzy-5b``).

The thesis' robot (§IV.4) has no reverse gear and a bounded steering angle: its tightest turn,
at the largest steering singleton α_max = π/5 of Fig IV.7, has radius R = l / tan(π/5)
(0.69 m for l = 0.5 m, eq IV.1), and slowing down does not shrink it. So an obstacle must be
turned away from while a full-lock turn is still free. (Turning at the robot's steering limit
π/4 instead, R = 0.5 m, was tried: on 100 mixed worlds it avoided half of the collisions, but it
sent the robot of Fig IV.22a round an extra loop, out of its time.) This module measures that room:

- :class:`HitMemory` keeps, per robot, the points where the range rays of the last ``steps``
  steps hit something, in the world frame (the pose comes from the robot's odometry, §IV.4), and
  returns them in the current robot frame. The ring C1…C7 is 30° apart, so a thin wall end or a
  corner can lie between two rays at one step; the rays swept over the last second fill part of
  the gaps. The rest is a modelling matter: the simulator's rays are lines, but the thesis'
  sensors are ultrasonic (§IV.7), and a sonar returns the nearest echo within its cone (about
  30° wide). :func:`cone_echo` stands for those cones: the nearest obstacle point (D_ro, θ_o of
  the observation) counts as a hit when it lies within the ring's coverage, the 7 directions
  ±15°. A robot driving straight at a wall end that sits between the 0° and ±30° rays, inside
  its own lane, would otherwise see it only when it is already too late to turn.
- :func:`step_clearance` is the last resort: the gap between the body after the next step and
  the remembered hits (below a few centimetres the navigator stops, :mod:`five_behaviours`).
- :func:`turning_room` gives, for the half-turn at full lock to the left and to the right, the
  smallest gap between the swept body (a disc of radius ``body`` whose centre runs on the circle
  of radius R through the robot, centre at (0, ±R) in the robot frame) and those points, and the
  free length of the straight lane ahead (points within ``body`` of the heading line).

Robot frame: x ahead, y to the left (α > 0 turns left, docs/thesis.md).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from fuzzynav.robot.tricycle import DEFAULT_PARAMS

ALPHA_MAX = math.pi / 5  # largest steering singleton of Fig IV.7
TURN_RADIUS = DEFAULT_PARAMS.wheelbase / math.tan(ALPHA_MAX)  # R = l / tan(π/5), eq IV.1 (m)


class HitMemory:
    """The range hits of the last ``steps`` steps of N robots, stored in the world frame."""

    def __init__(self, steps: int = 10):
        self.steps = int(steps)
        self.reset()

    def reset(self) -> None:
        """Forget every point (a new episode)."""
        self._x = self._y = None  # (N, steps, S) world frame
        self._valid = None  # (N, steps, S) bool
        self._k = 0

    def update(self, pose, ranges, angles, max_range: float) -> tuple[np.ndarray, np.ndarray]:
        """Store this step's hits and return every remembered point in the current robot frames:
        ``(points (N, steps·S, 2), valid (N, steps·S) bool)``. ``ranges`` ``(N, S)`` are read along
        ``angles`` ``(S,)`` or ``(N, S)`` (relative to each heading); a reading at ``max_range`` or
        beyond (or not finite) is no hit. One robot's new hits are placed with ``math`` (the same
        formulas; here ``math.cos``/``math.sin`` give NumPy's values bit for bit). ``points[..., 0]`` and
        ``points[..., 1]`` are contiguous (a transposed view of x and y rows)."""
        pose = np.asarray(pose, dtype=float)
        ranges = np.asarray(ranges, dtype=float)
        n, s = ranges.shape
        if self._x is None or self._x.shape != (n, self.steps, s):
            self._x, self._y = np.zeros((n, self.steps, s)), np.zeros((n, self.steps, s))
            self._valid = np.zeros((n, self.steps, s), dtype=bool)
            self._k = 0
        slot = self._k % self.steps
        self._k += 1
        if n == 1:
            x, y, theta = pose[0].tolist()
            limit = max_range - 1e-9
            readings = ranges[0].tolist()
            hit = [r < limit and math.isfinite(r) for r in readings]
            heading = [theta + a for a in np.asarray(angles, dtype=float).reshape(-1).tolist()]  # (S,) or (1, S)
            self._x[0, slot] = [x + r * math.cos(h) if ok else x for r, h, ok in zip(readings, heading, hit)]
            self._y[0, slot] = [y + r * math.sin(h) if ok else y for r, h, ok in zip(readings, heading, hit)]
            self._valid[0, slot] = hit
            c, si = math.cos(theta), math.sin(theta)
        else:
            heading = pose[:, 2:3] + np.broadcast_to(np.asarray(angles, dtype=float), ranges.shape)
            hit = np.isfinite(ranges) & (ranges < max_range - 1e-9)
            ranges = np.where(hit, ranges, 0.0)
            self._x[:, slot] = pose[:, 0:1] + ranges * np.cos(heading)
            self._y[:, slot] = pose[:, 1:2] + ranges * np.sin(heading)
            self._valid[:, slot] = hit
            c, si, x, y = np.cos(pose[:, 2:3]), np.sin(pose[:, 2:3]), pose[:, 0:1], pose[:, 1:2]
        rx, ry = self._x.reshape(n, -1) - x, self._y.reshape(n, -1) - y
        local = np.empty((n, 2, rx.shape[1]))
        np.add(c * rx, si * ry, out=local[:, 0])
        np.subtract(c * ry, si * rx, out=local[:, 1])
        return local.transpose(0, 2, 1), self._valid.reshape(n, -1)


def cone_echo(ranges, angles, distance, bearing, half_cone: float = math.radians(15.0)):
    """``(ranges (N, S+1), angles (N, S+1))``: the ring's readings plus the nearest obstacle point
    (``distance``, ``bearing`` ``(N,)``) where it falls within ``half_cone`` of a sensor direction
    (the sonar cones of the module docstring), ``inf`` elsewhere. One robot takes ``math``."""
    ranges = np.asarray(ranges, dtype=float)
    angles = np.asarray(angles, dtype=float)
    bearing = np.asarray(bearing, dtype=float)
    if len(ranges) == 1 and angles.ndim == 1:
        b, listed = float(bearing[0]), angles.tolist()
        gap = min([abs(math.remainder(b - a, math.tau)) for a in listed])  # exact wrap to [−π, π]
        echo = float(np.asarray(distance, dtype=float)[0]) if gap <= half_cone else math.inf
        return np.array([ranges[0].tolist() + [echo]]), np.array([listed + [b]])
    gap = np.abs(np.angle(np.exp(1j * (bearing[:, None] - angles[None, :])))).min(axis=1)
    echo = np.where(gap <= half_cone, np.asarray(distance, dtype=float), np.inf)
    return (np.column_stack([ranges, echo]),
            np.column_stack([np.broadcast_to(angles, ranges.shape), bearing]))


def step_clearance(points, valid, speed, dt: float, body: float = DEFAULT_PARAMS.radius) -> np.ndarray:
    """Gap ``(N,)`` between the body after one step at ``speed`` ``(N,)`` and the robot-frame points
    ``(N, P, 2)`` (``inf`` with none valid). Eq IV.2 moves the robot by V Δt along its current
    heading whatever the steering, so the next position is (V Δt, 0) in the robot frame. (The
    ``"arc"`` integrator bends off it by (V Δt)² tan α / (2 l): under 1 mm at the turn speed
    0.3 m/s, up to 12 cm at 4 m/s and full lock.)"""
    speed = np.asarray(speed, dtype=float)
    ahead = points[..., 0] - (float(speed[0]) * dt if len(speed) == 1 else (speed * dt)[:, None])
    return np.minimum.reduce(np.hypot(ahead, points[..., 1]) - body, axis=1, initial=np.inf, where=valid)


def turning_room(points, valid, body: float = DEFAULT_PARAMS.radius, radius: float = TURN_RADIUS):
    """``(room_left (N,), room_right (N,), ahead (N,))`` from robot-frame points ``(N, P, 2)``.

    ``room_left`` / ``room_right``: smallest distance between the body of a robot that turns
    half a circle at full lock to that side and any valid point (negative: the turn would hit
    it). A point ahead of the robot (x ≥ 0) is passed by the half circle at | |p − c| − R |, one
    behind it at the nearer end of the half circle (the start or the point 2R to the side).
    ``ahead``: free length of the straight lane of half-width ``body`` in front of the robot.
    Points nowhere: ``inf``. Both sides are computed in one pass (a leading axis of 2).
    """
    x, y = points[..., 0], points[..., 1]
    offsets = _turn_offsets(radius)
    # distances from the turn centres (left, right), the robot, the far ends (left, right): one hypot
    h = np.hypot(x, y - offsets)
    passing = np.abs(h[:2] - radius)
    ends = np.minimum(h[2], h[3:])
    left, right = np.minimum.reduce(np.where(x >= 0.0, passing, ends) - body, axis=2, initial=np.inf, where=valid)
    lane = valid & (x > 0.0) & (np.abs(y) < body)
    ahead = np.minimum.reduce(x - body, axis=1, initial=np.inf, where=lane)
    return left, right, ahead


@functools.lru_cache(maxsize=8)
def _turn_offsets(radius: float) -> np.ndarray:
    """y of the two full-lock turn centres (left, right) in the robot frame, of the robot (0) and
    of the far ends of the two half turns, shaped ``(5, 1, 1)`` to broadcast over ``(N, P)`` points."""
    centre = np.array([1.0 * radius, -1.0 * radius])
    offsets = np.concatenate([centre, [0.0], 2.0 * centre])[:, None, None]
    offsets.flags.writeable = False  # shared by every call
    return offsets


class TurnGuard:
    """When a robot must start its full-lock turn, and to which side (thesis §IV.4: no reverse).

    The turn is wanted when the straight lane ahead is blocked within ``lane`` (m) and the
    better full-lock half turn keeps less than ``margin`` (m) from every remembered hit — both
    after one more step at the current speed; a turn under way goes on until lane and room
    exceed those thresholds by 0.5 m and 0.2 m. The side is the roomier one (within 0.1 m, the
    goal's side), chosen when the turn starts and kept until it ends. Hits: the range ring plus
    the sonar-cone echo of the nearest obstacle point (:func:`cone_echo`), over ``memory`` steps;
    :meth:`clearance` measures the next step against the hits of the last call.
    """

    def __init__(self, lane: float, margin: float, memory: int = 10):
        self.lane, self.margin = float(lane), float(margin)
        self.memory = HitMemory(memory)
        self.reset()

    def reset(self) -> None:
        """Forget the hits and the sides (a new episode)."""
        self.memory.reset()
        self._side = None
        self._hits = None

    def __call__(self, obs, turning, bearing) -> tuple[np.ndarray, np.ndarray]:
        """``(wanted (N,) bool, side (N,) ±1)`` for a batch observation; ``turning`` marks the
        robots already in their turn, ``bearing`` is the goal bearing (N,)."""
        ranges, angles = cone_echo(obs.ranges, obs.sensor_angles, obs.obstacle_distance, obs.obstacle_bearing)
        points, valid = self.memory.update(obs.pose, ranges, angles, obs.max_range)
        self._hits = points, valid
        left, right, ahead = turning_room(points, valid)
        if len(left) == 1:  # one robot: the same tests on floats
            (l, r, a), t = (float(v[0]) for v in (left, right, ahead)), bool(np.asarray(turning)[0])
            step = float(np.asarray(obs.speed)[0]) * obs.dt
            wanted = (a - step < (self.lane + 0.5 if t else self.lane)
                      and max(l, r) - step < (self.margin + 0.2 if t else self.margin))
            if abs(l - r) < 0.1:  # inf − inf (both sides free) is NaN: not close
                side = 1 if float(np.asarray(bearing)[0]) >= 0 else -1
            else:
                side = 1 if l > r else -1
            if not (t and self._side is not None and len(self._side) == 1):
                self._side = np.array([side])
            return np.array([wanted]), self._side
        step = np.asarray(obs.speed, dtype=float) * obs.dt
        lane = np.where(turning, self.lane + 0.5, self.lane)
        margin = np.where(turning, self.margin + 0.2, self.margin)
        wanted = (ahead - step < lane) & (np.maximum(left, right) - step < margin)
        with np.errstate(invalid="ignore"):  # inf − inf where both sides are free
            close = np.abs(left - right) < 0.1
        side = np.where(close, np.where(np.asarray(bearing) >= 0, 1, -1), np.where(left > right, 1, -1))
        if self._side is None or len(self._side) != len(side):
            self._side = side
        self._side = np.where(turning, self._side, side)
        return wanted, self._side

    def clearance(self, speed, dt: float) -> np.ndarray:
        """:func:`step_clearance` of one step at ``speed`` ``(N,)`` against the hits of the last call."""
        return step_clearance(*self._hits, speed, dt)

    def stop(self, speed, dt: float, margin: float) -> np.ndarray:
        """The safety stop of the navigators: ``speed`` ``(N,)`` with 0 where the next step would
        bring the body within ``margin`` (m) of a hit of the last call (:meth:`clearance`)."""
        speed = np.asarray(speed, dtype=float)
        return np.where(self.clearance(speed, dt) < margin, 0.0, speed)
