"""What the reactive classic navigators know of the world: the range hits of the last second.

The same perception as the thesis' five-behaviour navigator (its compiled hit memory,
:func:`fuzzynav.kernels.guard.remember`): the points where the seven rays hit something over the
last ``memory`` steps, plus the nearest obstacle point when it lies in a sensor's 15° cone, in the
current robot frame (x ahead, y left).
The robot's geometry (:class:`Body`) is a parameter of every navigator, never a constant.

:class:`TrackedMap` is what ``dwa-tracks`` and ``vfh-tracks`` know (they read the lidar): the
same memory of the echoes that stood still, the echoes that moved at this step only, and the
moving obstacles tracked over successive scans with their constant-velocity prediction — the
tracker of ``fuzzy-5b-yield-tracks`` (:class:`~fuzzynav.control.sighting_tracks.ScanTracker`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from fuzzynav.control.sighting_tracks import JOIN, MARGIN, ScanTracker
from fuzzynav.kernels import guard
from fuzzynav.kernels.records import Pose, Reading
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.settings import BODY, within


@dataclass(frozen=True)
class Body:
    """The robot as the classic navigators model it: footprint disc ``radius``, ``wheelbase`` l,
    steering limit ``max_steering`` (rad) and the top speed they command ``max_speed`` (m/s)."""

    radius: float = DEFAULT_PARAMS.radius
    wheelbase: float = DEFAULT_PARAMS.wheelbase
    max_steering: float = DEFAULT_PARAMS.max_steering
    max_speed: float = 2.0

    def __post_init__(self):
        for name, bounds in BODY.items():
            within(getattr(self, name), name, bounds)

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


class TrackedMap(LocalMap):
    """A :class:`LocalMap` of the echoes that stood still, plus the moving obstacles tracked from
    the scans (module docstring). An echo that moved is remembered for this step only, so a moving
    obstacle leaves no trail of points to avoid where it was; an echo near a believed track (within
    its radius plus ``JOIN``) is left out even then, the track's predicted disc (:meth:`predicted`)
    standing for it. The nearest-obstacle
    echo is not remembered (the lidar sees what it would add, and it may be a moving one)."""

    def __init__(self, memory: int = 10, tracker: ScanTracker | None = None):
        self.tracker = tracker if tracker is not None else ScanTracker()
        super().__init__(memory)

    def reset(self) -> None:
        super().reset()
        self.tracker.reset()

    def points(self, obs) -> np.ndarray:
        moved = self.tracker.observe(obs)
        ranges = np.asarray(obs.ranges, dtype=float)
        x, y, theta = (float(v) for v in obs.pose)
        heading = theta + np.asarray(obs.sensor_angles, dtype=float)
        echoes = np.column_stack([x + ranges * np.cos(heading), y + ranges * np.sin(heading)])
        self._now = float(obs.t)
        on_track = np.zeros(len(ranges), dtype=bool)
        for track in self.tracker.confirmed():  # echoes this close belong to the tracked obstacle (clusters' JOIN)
            on_track |= np.hypot(*(echoes - track.predict(self._now)).T) <= track.radius + JOIN
        still = super().points(replace(obs, ranges=np.where(moved | on_track, obs.max_range, ranges),
                                       obstacle_distance=None))
        c, s = math.cos(theta), math.sin(theta)
        rx, ry = echoes[moved & ~on_track, 0] - x, echoes[moved & ~on_track, 1] - y
        return np.vstack([still, np.column_stack([c * rx + s * ry, c * ry - s * rx])])

    def predicted(self, obs, times) -> tuple[np.ndarray, np.ndarray]:
        """(centres (M, *times.shape, 2) in the current robot frame, radii (M,)) of the believed
        tracks ``times`` s after this step, at constant velocity (call after :meth:`points`)."""
        tracks = self.tracker.confirmed()
        times = np.asarray(times, dtype=float)
        if not tracks:
            return np.zeros((0, *times.shape, 2)), np.zeros(0)
        x, y, theta = (float(v) for v in obs.pose)
        c, s = math.cos(theta), math.sin(theta)
        rotate = np.array([[c, s], [-s, c]])  # world → robot frame
        now = (np.array([track.predict(self._now) for track in tracks]) - (x, y)) @ rotate.T
        velocity = np.array([track.velocity for track in tracks]) @ rotate.T
        grow = (1,) * times.ndim
        where = now.reshape(-1, *grow, 2) + velocity.reshape(-1, *grow, 2) * times[None, ..., None]
        return where, np.array([track.radius for track in tracks])


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
    return before_contact((gap < body).any(axis=2), lengths, horizon)


def before_contact(hit: np.ndarray, lengths: np.ndarray, horizon: float) -> np.ndarray:
    """Free length ``(...)`` of arcs sampled at ``lengths`` ``(K,)`` with contacts ``hit`` ``(..., K)``:
    the last sample before the first contact (``horizon`` when there is none)."""
    first = np.where(hit.any(axis=-1), hit.argmax(axis=-1), len(lengths))
    free = np.concatenate([[0.0], lengths])[first]
    return np.where(first == len(lengths), horizon, free)


def moving_free_length(curvatures: np.ndarray, speeds: np.ndarray, predict, body: float, horizon: float,
                       within: float, margin: float = MARGIN, step: float = 0.05) -> np.ndarray:
    """Arc length ``(A, V)`` each arc (curvature ``(A,)``) driven at each speed of ``speeds``
    ``(V,)`` can be driven before the disc of radius ``body`` touches a moving disc where the robot
    is at time length / speed (``horizon`` when it does not within ``within`` s); ``predict(times)``
    gives the discs' robot-frame centres ``(M, *times.shape, 2)`` at ``times`` s from now and their
    radii ``(M,)`` (:meth:`TrackedMap.predicted`). The dynamic window's collision test (Fox et al.
    1997, §4.2) with the obstacles moved along their predicted tracks over the arc's time."""
    lengths = np.arange(step, horizon + step / 2, step)
    times = lengths[None, :] / np.maximum(speeds[:, None], 1e-9)  # (V, K)
    soon = times <= within
    where, radii = predict(np.where(soon, times, 0.0))  # (M, V, K, 2), (M,)
    if len(radii) == 0:
        return np.full((len(curvatures), len(speeds)), horizon)
    path = arcs(curvatures, lengths)[None, :, None]  # (1, A, 1, K, 2)
    gap = np.hypot(path[..., 0] - where[:, None, ..., 0], path[..., 1] - where[:, None, ..., 1])  # (M, A, V, K)
    now = np.hypot(*predict(np.zeros(1))[0][:, 0].T)  # (M,) centre distances now
    reach = np.minimum(body + margin + radii, np.maximum(now - 0.05, 0.0))
    hit = ((gap < reach[:, None, None, None]) & soon[None, None]).any(axis=0)  # (A, V, K)
    return before_contact(hit, lengths, horizon)
