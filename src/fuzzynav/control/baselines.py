"""Classic geometric path trackers, the baselines of the chapter V comparison.

Both run on the same tricycle (eq IV.1, θ̇ = V tan α / l, (x, y) the rear-axle reference point)
with the same limits (|α| ≤ π/4, the simulator clips) and the same constant speed as the thesis'
trackers. They read the path polyline and the simulator's current waypoint index k from the
observation and search three segments only — the one before the current one (the simulator
switches inside the tolerance zone, before the corner), the current one (k − 1 → k) and the next
— so progress along the path is monotonic.

- :class:`PurePursuit` — R. C. Coulter, *Implementation of the Pure Pursuit Path Tracking
  Algorithm*, CMU-RI-TR-92-01, 1992: the goal point is where the circle of radius L (look-ahead)
  around the robot meets the path furthest along; with η its bearing, the arc through it has
  curvature γ = 2 sin η / L (Coulter's γ = 2 x / L², x the lateral offset), and the steering is
  α = atan(l γ).
- :class:`Stanley` — S. Thrun et al., *Stanley: the robot that won the DARPA Grand Challenge*,
  J. Field Robotics 23(9), 2006, eq. (11) (§9.2); G. M. Hoffmann et al., *Autonomous automobile
  trajectory tracking for off-road driving*, ACC 2007, eq. (5): with the front axle at
  p_f = (x + l cos θ, y + l sin θ), ψ the heading error to the nearest path segment and e the
  signed cross-track error of p_f (> 0 left of the path), α = ψ − atan(k e / (k_soft + V)).

Without a path (moving-target pursuit, §V.5) both aim at ``obs.target``: pure pursuit with
L = the distance to the target, Stanley with zero cross-track error (α = the bearing).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.control.base import BatchController
from fuzzynav.settings import LENGTH, RATE, SPEED, checked
from fuzzynav.world.geometry import wrap_angle

DEFAULT_SPEED = 1.0
WHEELBASE = 0.5  # l of the default robot (docs/ARCHITECTURE.md)


def _window(path: np.ndarray, index: np.ndarray):
    """Segments k − 2, k − 1, k of every robot (k the current waypoint): starts, ends ``(N, 3, 2)``,
    segment indices and validity ``(N, 3)``."""
    j = np.clip(index[:, None] - 1, 0, None) + np.arange(3)[None, :] - 1
    valid = (j >= 0) & (j < len(path) - 1)
    j = np.clip(j, 0, len(path) - 2)
    return path[j], path[j + 1], j, valid


class _PathBaseline(BatchController):
    """Constant speed, batch and single-robot entry points; subclasses give ``_steer(obs)`` and check
    the settings (:func:`~fuzzynav.settings.checked`)."""

    label = "track"

    def __init__(self, speed: float, wheelbase: float):
        self.speed, self.wheelbase = float(speed), float(wheelbase)

    def act_batch(self, obs):
        alpha = self._steer(np.atleast_2d(obs.pose), np.atleast_2d(obs.target), obs.path,
                            np.atleast_1d(obs.waypoint_index), np.atleast_1d(obs.speed))
        return alpha, np.full(len(alpha), self.speed), [self.label] * len(alpha)


class PurePursuit(_PathBaseline):
    """Pure pursuit (Coulter 1992), look-ahead distance ``lookahead`` L (m)."""

    name = "pure-pursuit"

    @checked(lookahead=LENGTH, speed=SPEED, wheelbase=LENGTH)
    def __init__(self, lookahead: float = 1.0, speed: float = DEFAULT_SPEED, wheelbase: float = WHEELBASE):
        super().__init__(speed, wheelbase)
        self.lookahead = float(lookahead)

    def goal_points(self, pose, target, path, index) -> np.ndarray:
        """Goal point ``(N, 2)``: the furthest-along intersection of the look-ahead circle with the path.

        With no intersection in the window (robot farther than L from the path) the current
        waypoint; near the end, the last waypoint once it is inside the circle.
        """
        if path is None:
            return target
        a, b, j, valid = _window(path, index)
        p = pose[:, None, :2]
        e = b - a
        f = a - p
        qa = np.einsum("nmk,nmk->nm", e, e)
        qb = 2.0 * np.einsum("nmk,nmk->nm", f, e)
        qc = np.einsum("nmk,nmk->nm", f, f) - self.lookahead ** 2
        disc = qb * qb - 4.0 * qa * qc
        u = (-qb + np.sqrt(np.maximum(disc, 0.0))) / (2.0 * qa)  # the forward root
        hit = valid & (disc >= 0) & (u >= 0) & (u <= 1)
        key = np.where(hit, j + u, -np.inf)
        best = np.argmax(key, axis=1)
        rows = np.arange(len(pose))
        goal = a[rows, best] + u[rows, best, None] * e[rows, best]
        goal = np.where(hit.any(axis=1)[:, None], goal, target)
        last = path[-1]
        near_end = np.hypot(*(last - pose[:, :2]).T) <= self.lookahead
        return np.where(near_end[:, None] & (index == len(path) - 1)[:, None], last, goal)

    def _steer(self, pose, target, path, index, speed):
        goal = self.goal_points(pose, target, path, index)
        d = goal - pose[:, :2]
        eta = np.arctan2(d[:, 1], d[:, 0]) - pose[:, 2]
        distance = np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-9)  # L, or less at the path's end
        curvature = 2.0 * np.sin(eta) / distance
        return np.arctan(self.wheelbase * curvature)


class Stanley(_PathBaseline):
    """Stanley steering (Thrun et al. 2006; Hoffmann et al. 2007): gain ``gain`` k (1/s), softening ``softening`` (m/s)."""

    name = "stanley"

    @checked(gain=RATE, softening=RATE, speed=SPEED, wheelbase=LENGTH)
    def __init__(self, gain: float = 2.5, softening: float = 1.0, speed: float = DEFAULT_SPEED,
                 wheelbase: float = WHEELBASE):
        super().__init__(speed, wheelbase)
        self.gain, self.softening = float(gain), float(softening)

    def _steer(self, pose, target, path, index, speed):
        theta = pose[:, 2]
        if path is None:
            d = target - pose[:, :2]
            return wrap_angle(np.arctan2(d[:, 1], d[:, 0]) - theta)
        front = pose[:, :2] + self.wheelbase * np.column_stack([np.cos(theta), np.sin(theta)])
        a, b, _, valid = _window(path, index)
        e = b - a
        rel = front[:, None, :] - a
        u = np.clip(np.einsum("nmk,nmk->nm", rel, e) / np.einsum("nmk,nmk->nm", e, e), 0.0, 1.0)
        offset = rel - u[..., None] * e
        distance = np.where(valid, np.hypot(offset[..., 0], offset[..., 1]), np.inf)
        best = 2 - np.argmin(distance[:, ::-1], axis=1)  # ties (past a corner's vertex): the later segment
        rows = np.arange(len(pose))
        tangent = e[rows, best] / np.hypot(*e[rows, best].T)[:, None]
        off = offset[rows, best]
        cross_track = tangent[:, 0] * off[:, 1] - tangent[:, 1] * off[:, 0]  # > 0: left of the path
        psi = wrap_angle(np.arctan2(tangent[:, 1], tangent[:, 0]) - theta)
        v = np.where(speed > 0, speed, self.speed)
        return psi - np.arctan(self.gain * cross_track / (self.softening + v))


def pure_pursuit(**options) -> PurePursuit:
    """Factory of ``pure-pursuit`` (options: ``lookahead``, ``speed``, ``wheelbase``)."""
    return PurePursuit(**options)


def stanley(**options) -> Stanley:
    """Factory of ``stanley`` (options: ``gain``, ``softening``, ``speed``, ``wheelbase``)."""
    return Stanley(**options)
