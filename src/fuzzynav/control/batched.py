"""Batch-first controllers: one NumPy decision over many robots, a one-robot ``act`` on top.

The chapter IV navigators map what N robots sense to (α, V) — with per-robot memory where they
have one (the behaviour switch, the recent range hits), kept in arrays over the robot axis — so each
implements :meth:`BatchedController.act_batch` over a
:class:`~fuzzynav.sim.observation.BatchObservation`-like object (arrays with a leading robot
axis) and inherits :meth:`act`, which views one :class:`~fuzzynav.control.base.Observation` as a
batch of one (DESIGN.md: "a scalar convenience call may wrap the batch path").
"""

from __future__ import annotations

from abc import abstractmethod
from dataclasses import dataclass

import numpy as np

from fuzzynav.control.base import Command, Controller, Observation
from fuzzynav.errors import InputError
from fuzzynav.world.geometry import wrap_angle


@dataclass(frozen=True)
class OneRobot:
    """An :class:`Observation` seen as a batch of one (the fields the navigators read)."""

    target_distance: np.ndarray
    target_bearing: np.ndarray
    ranges: np.ndarray | None
    sensor_angles: np.ndarray | None
    speed: np.ndarray
    obstacle_distance: np.ndarray
    obstacle_bearing: np.ndarray
    pose: np.ndarray  # (1, 3)
    dt: float
    max_range: float

    @classmethod
    def of(cls, obs: Observation) -> "OneRobot":
        def one(value, default=np.inf):
            return np.array([default if value is None else value], dtype=float)

        return cls(one(obs.target_distance), one(obs.target_bearing),
                   None if obs.ranges is None else np.asarray(obs.ranges, dtype=float)[None, :],
                   obs.sensor_angles, one(obs.speed, 0.0), one(obs.obstacle_distance), one(obs.obstacle_bearing, 0.0),
                   np.asarray(obs.pose, dtype=float)[None, :], float(obs.dt), float(obs.max_range))


class BatchedController(Controller):
    """A controller whose decision is :meth:`act_batch`; :meth:`act` is its one-robot case."""

    @abstractmethod
    def act_batch(self, obs):
        """``(steering (N,), speed (N,), behaviours (N,))`` for a batch observation."""

    def act(self, obs: Observation) -> Command:
        steering, speed, labels = self.act_batch(OneRobot.of(obs))
        return Command(float(steering[0]), float(speed[0]), str(labels[0]))


def evaluate(system, X) -> np.ndarray:
    """``system.evaluate(X)`` for a batch ``(N, n_in)``; a single row takes the fuzzy library's
    plain-Python scalar path (:meth:`FuzzySystem.evaluate_one`, a few µs instead of the ~0.1 ms
    of NumPy's per-call overhead), which matters for one robot stepped at a time."""
    if len(X) == 1:
        return np.array([system.evaluate_one(*X[0].tolist())])
    return system.evaluate(X)


def evaluate_columns(system, *columns) -> np.ndarray:
    """:func:`evaluate` on inputs given as columns ``(N,)`` each; one robot skips the stacking."""
    if len(columns[0]) == 1:
        return np.array([system.evaluate_one(*[float(column[0]) for column in columns])])
    return system.evaluate(np.column_stack(columns))


def sensor_columns(angles, wanted_deg, source: str = "sensors") -> np.ndarray:
    """Indices of the readings pointing at ``wanted_deg`` (degrees, CCW from the heading).

    The navigators address the thesis' sensors C1…C7 by direction (thesis §IV.7), so any ring that
    contains those directions works; a missing one raises :class:`InputError`.
    """
    if angles is None:
        raise InputError("this controller needs range sensors", field=source)
    angles = np.asarray(angles, dtype=float)
    wanted = np.deg2rad(np.asarray(wanted_deg, dtype=float))
    gap = np.abs(wrap_angle(angles[None, :] - wanted[:, None]))
    idx = np.argmin(gap, axis=1)
    missing = gap[np.arange(len(wanted)), idx] > np.deg2rad(5.0)
    if missing.any():
        raise InputError(f"needs sensors at {', '.join(f'{w:g}°' for w in np.asarray(wanted_deg)[missing])} "
                         f"(ring has {', '.join(f'{a:.0f}°' for a in np.rad2deg(angles))})", field=source)
    return idx
