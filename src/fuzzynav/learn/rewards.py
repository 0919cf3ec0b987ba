"""Reinforcement signals of the thesis' learning tasks (chapter VI), vectorised over a batch.

Each reward is a small frozen dataclass called as ``reward(before, after, collided, reached)``
with two :class:`~fuzzynav.learn.envs.env.RobotState` (the state before and after one step) and
two boolean arrays (B,); it returns the reinforcement (B,). Conditions are tested in the order
listed (the first that holds gives the value).

- :class:`GoalSteeringReward` — eq VI.2 (tabular goal seeking §VI.2 and the steering of FQL goal
  seeking §VI.5.1);
- :class:`GoalSpeedReward` — eq VI.14, its values read in the text's order (see the class);
- :class:`AvoidSteeringReward` — eq VI.20, :class:`AvoidSpeedReward` — eq VI.21 (§VI.5.2);
- :class:`WallSteeringReward` — eq VI.21 of §VI.5.3.2 (the thesis numbers two equations VI.21),
  :class:`WallSpeedReward` — eq VI.22.

"Decreases" / "increases" compare the values after and before the step, with a dead band
``eps`` so that floating-point noise of an unchanged quantity counts as neither.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

EPS = 1e-9


def _first(conditions, values, default: float = 0.0) -> np.ndarray:
    """Value of the first condition that holds, row by row (``default`` when none does): the
    conditions written last to first, so the first that holds is written last (``np.select``'s
    answer, at a fraction of its cost on the short rows of one robot)."""
    out = np.full(np.broadcast_shapes(*(np.shape(c) for c in conditions)), float(default))
    for condition, value in zip(reversed(conditions), reversed(values)):
        np.copyto(out, float(value), where=condition)
    return out


@dataclass(frozen=True)
class GoalSteeringReward:
    """Eq VI.2: +4 goal reached; +3 d_rg decreases and θ_rg = 0; +2 d_rg and |θ_rg| decrease;
    −1 d_rg decreases and |θ_rg| increases; −2 d_rg increases; −3 the robot hits the walls.

    "θ_rg = 0" is read as |θ_rg| ≤ ``aligned`` (a continuous angle is never exactly 0). A step
    where d_rg decreases and |θ_rg| neither decreases nor is aligned counts as an increase (−1):
    the robot passes the goal by. A wall hit outranks everything (the episode ends there).
    """

    aligned: float = math.radians(5.0)
    eps: float = EPS

    def __call__(self, before, after, collided, reached):
        d0, a0 = before.goal[:, 0], np.abs(before.goal[:, 1])
        d1, a1 = after.goal[:, 0], np.abs(after.goal[:, 1])
        closer = d1 < d0 - self.eps
        return _first([collided, reached, ~closer, a1 <= self.aligned, a1 < a0 - self.eps],
                      [-3.0, 4.0, -2.0, 3.0, 2.0], default=-1.0)


@dataclass(frozen=True)
class GoalSpeedReward:
    """Eq VI.14 (speed of FQL goal seeking, §VI.5.1), read in the order the text gives it.

    The extracted text lists the conditions "si d_rg, θ_rg diminuent et la vitesse augmente",
    "si θ_rg diminue, la vitesse et d_rg augmentent", "si le robot atteint la cible avec une faible
    vitesse", "ailleurs" and the values −1, −1, 1, 0 — in the same order, as the values of eq
    VI.2 are (its extraction prints them in order with "r =" in the middle). So:

    - −1 if d_rg and |θ_rg| decrease and V_r increases (speeding up on the way in);
    - −1 if |θ_rg| decreases while V_r and d_rg increase (speeding up while turning back);
    - +1 if the goal is reached with V_r ≤ ``low`` (a low speed);
    - 0 otherwise.

    This reading fits Fig VI.9 (b), a curve of small negative values rising towards 0. ``low``
    is 0.2 m/s, the arrival speed of a robot that stops (Table IV.1 concludes Z = 0 at the goal).
    Added (not in the thesis, which only says episodes end at the walls): −1 when the robot
    hits the walls, so that a speed that ends an episode early is never neutral.
    """

    low: float = 0.2
    eps: float = EPS

    def __call__(self, before, after, collided, reached):
        d0, a0 = before.goal[:, 0], np.abs(before.goal[:, 1])
        d1, a1 = after.goal[:, 0], np.abs(after.goal[:, 1])
        faster = after.speed > before.speed + self.eps
        closer, farther = d1 < d0 - self.eps, d1 > d0 + self.eps
        turning_in = a1 < a0 - self.eps
        return _first([collided, reached & (after.speed <= self.low + self.eps), closer & turning_in & faster,
                       turning_in & faster & farther],
                      [-1.0, 1.0, -1.0, -1.0])


def _side_decrease(before, after, limit: float, eps: float) -> np.ndarray:
    """Some side distance d_i decreases and (after the step) d_i < ``limit``."""
    return ((after.sides < before.sides - eps) & (after.sides < limit)).any(axis=1)


@dataclass(frozen=True)
class AvoidSteeringReward:
    """Eq VI.20 (steering of the FQL obstacle avoider, §VI.5.2): −4 the robot hits an obstacle;
    −1 if a distance d_i decreases and d_i < D_max / 2; 0 otherwise (d_i: front, right, left)."""

    d_max: float = 4.0
    eps: float = EPS

    def __call__(self, before, after, collided, reached):
        return _first([collided, _side_decrease(before, after, 0.5 * self.d_max, self.eps)], [-4.0, -1.0])


@dataclass(frozen=True)
class AvoidSpeedReward:
    """Eq VI.21 (speed of the FQL obstacle avoider, §VI.5.2): −4 the robot hits an obstacle;
    −1 if the distances are beyond D_max (nothing sensed: every reading at the sensor range) and
    V_r is low (≤ ``low``); −1 if some d_i < D_max and V_r increases; 0 otherwise."""

    d_max: float = 4.0
    low: float = 1.0
    eps: float = EPS

    def __call__(self, before, after, collided, reached):
        clear = (after.sides >= self.d_max - self.eps).all(axis=1)
        faster = after.speed > before.speed + self.eps
        return _first([collided, clear & (after.speed <= self.low + self.eps), ~clear & faster],
                      [-4.0, -1.0, -1.0])


@dataclass(frozen=True)
class WallSteeringReward:
    """Eq VI.21 of §VI.5.3.2 (steering of the FQL wall follower): −2 the robot hits an obstacle;
    −1 if some d_i < d_m (i = 1…3); 0 otherwise."""

    d_min: float = 0.6
    eps: float = EPS

    def __call__(self, before, after, collided, reached):
        return _first([collided, (after.sides < self.d_min).any(axis=1)], [-2.0, -1.0])


@dataclass(frozen=True)
class WallSpeedReward:
    """Eq VI.22 (speed of the FQL wall follower): −2 the robot hits an obstacle; −1 if some
    d_i < d_s and V_r increases; 0 otherwise."""

    d_safe: float = 2.0
    eps: float = EPS

    def __call__(self, before, after, collided, reached):
        faster = after.speed > before.speed + self.eps
        return _first([collided, (after.sides < self.d_safe).any(axis=1) & faster], [-2.0, -1.0])
