"""What the reactive classic navigators know of the world: the range hits of the last second.

The same perception as the thesis' five-behaviour navigator (its compiled hit memory,
:func:`fuzzynav.kernels.guard.remember`): the points where the seven rays hit something over the
last ``memory`` steps, plus the nearest obstacle point when it lies in a sensor's 15° cone, in the
current robot frame (x ahead, y left).
The robot's geometry (:class:`Body`) is a parameter of every navigator, never a constant.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from fuzzynav.kernels import guard
from fuzzynav.kernels.records import Pose, Reading
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.validation import positive


@dataclass(frozen=True)
class Body:
    """The robot as the classic navigators model it: footprint disc ``radius``, ``wheelbase`` l,
    steering limit ``max_steering`` (rad) and the top speed they command ``max_speed`` (m/s)."""

    radius: float = DEFAULT_PARAMS.radius
    wheelbase: float = DEFAULT_PARAMS.wheelbase
    max_steering: float = DEFAULT_PARAMS.max_steering
    max_speed: float = 2.0

    def __post_init__(self):
        for name in ("radius", "wheelbase", "max_steering", "max_speed"):
            positive(getattr(self, name), field=name)

    @property
    def turn_radius(self) -> float:
        """Tightest turn l / tan(α_max) (m), eq IV.1."""
        return self.wheelbase / math.tan(self.max_steering)

    def steer_towards(self, bearing: float, distance: float) -> float:
        """Steering α that puts the robot on the arc through a point at ``bearing`` (rad) and
        ``distance`` (m): curvature 2 sin(bearing) / distance (the pure-pursuit arc, Coulter 1992),
        α = atan(l · curvature), clipped to the steering limit; full lock towards a point behind."""
        if abs(bearing) > math.pi / 2:
            return math.copysign(self.max_steering, bearing)
        alpha = math.atan(self.wheelbase * 2.0 * math.sin(bearing) / max(distance, 1e-6))
        return min(max(alpha, -self.max_steering), self.max_steering)


class LocalMap:
    """The remembered hits of one robot (module docstring); :meth:`points` after each observation."""

    HALF_CONE = math.radians(15.0)  # the sonar cone of the thesis navigators' hit memory

    def __init__(self, memory: int = 10):
        self.steps = int(memory)
        self.reset()

    def reset(self) -> None:
        """Forget every point (a new episode)."""
        self._memory, self._count = None, 0

    def points(self, obs) -> np.ndarray:
        """Robot-frame obstacle points ``(P, 2)`` seen in the last ``memory`` steps."""
        angles = np.ascontiguousarray(obs.sensor_angles, dtype=float)
        if self._memory is None or self._memory.shape[1] != len(angles) + 1:
            self._memory, self._count = np.zeros((self.steps, len(angles) + 1, 3)), 0
        x, y, theta = (float(v) for v in obs.pose)
        distance = math.inf if obs.obstacle_distance is None else float(obs.obstacle_distance)
        guard.remember(self._memory, self._count, Pose(x, y, theta),
                       Reading(np.ascontiguousarray(obs.ranges, dtype=float), angles, float(obs.max_range), distance,
                               float(obs.obstacle_bearing or 0.0)), self.HALF_CONE)
        self._count += 1
        valid = self._memory[..., 2] > 0.0
        rx, ry = self._memory[..., 0][valid] - x, self._memory[..., 1][valid] - y
        c, s = math.cos(theta), math.sin(theta)
        return np.column_stack([c * rx + s * ry, c * ry - s * rx])


def arcs(curvatures: np.ndarray, lengths: np.ndarray) -> np.ndarray:
    """Robot-frame positions ``(A, K, 2)`` after driving the arc lengths ``lengths`` ``(K,)`` on
    circles of curvature ``curvatures`` ``(A,)`` (1/m, > 0 to the left; eq IV.1 with α fixed)."""
    k = curvatures[:, None]
    s = lengths[None, :]
    straight = np.abs(k) < 1e-9
    safe = np.where(straight, 1.0, k)
    x = np.where(straight, s, np.sin(safe * s) / safe)
    y = np.where(straight, 0.0, (1.0 - np.cos(safe * s)) / safe)
    return np.stack([x, y], axis=-1)


def free_length(curvatures: np.ndarray, points: np.ndarray, body: float, horizon: float, step: float = 0.05) -> np.ndarray:
    """Arc length ``(A,)`` each arc can be driven before the disc of radius ``body`` touches one of
    the robot-frame ``points`` ``(P, 2)`` (``horizon`` when it never does within it)."""
    lengths = np.arange(step, horizon + step / 2, step)
    if len(points) == 0:
        return np.full(len(curvatures), horizon)
    path = arcs(curvatures, lengths)
    gap = np.hypot(path[:, :, None, 0] - points[None, None, :, 0], path[:, :, None, 1] - points[None, None, :, 1])
    hit = (gap < body).any(axis=2)
    first = np.where(hit.any(axis=1), hit.argmax(axis=1), len(lengths))
    free = np.concatenate([[0.0], lengths])[first]  # the last sample before the first contact
    return np.where(first == len(lengths), horizon, free)

