"""The one controller interface for everything that drives the robot (docs/ARCHITECTURE.md).

A controller maps an :class:`Observation` to a :class:`Command`; it knows nothing of the
episode loop. Fuzzy behaviours, supervisors, trackers, learned policies and baselines all
implement :class:`Controller`, so the same scenario runs with any of them by name.

Sign convention (docs/thesis.md, "The sign of the angle error") — solved in exactly one place, :func:`thesis_angle_error`:
geometry in this package uses the mathematical convention (angles CCW, a bearing > 0 means
"to the left", steering α > 0 turns left). The thesis' rule tables (IV.1, IV.2, V.1) are
consistent only if the angle error they read is θ_r − θ_d ("negative = target on the left").
Every table-driven controller feeds its tables through :func:`thesis_angle_error` and uses
their steering outputs unchanged.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass, field

import numpy as np

from fuzzynav.world.geometry import wrap_angle


def thesis_angle_error(bearing):
    """Angle input of the thesis' tables from a bearing (eq IV.8, eq V.4).

    ``bearing`` is θ_d − θ_r wrapped to (−π, π] (positive when the target is on the left).
    The published tables map a *negative* error to a *positive* (left) steering, so they are fed
    θ_r − θ_d = −bearing. This is the only place where the sign is flipped.
    """
    return -wrap_angle(bearing)


@dataclass(frozen=True)
class Observation:
    """What a controller sees at one step. Fields a task does not provide are ``None``.

    Angles are radians, bearings are relative to the robot heading, CCW positive (left).
    """

    t: float
    dt: float
    pose: np.ndarray  # (3,): x, y, θ (world frame, θ CCW from +x)
    speed: float  # current linear speed V_r (m/s), as applied at the previous step
    steering: float  # current steering α (rad), as applied at the previous step
    target: np.ndarray | None = None  # (2,): goal, current waypoint or moving target position
    ranges: np.ndarray | None = None  # (n_sensors,): range readings (m), capped at max_range
    sensor_angles: np.ndarray | None = None  # (n_sensors,): sensor directions relative to heading
    max_range: float = 0.0  # sensor range D_max (m)
    obstacle_distance: float | None = None  # D_ro: clearance to the nearest obstacle surface (m)
    obstacle_bearing: float | None = None  # bearing of that nearest point (rad)
    path: np.ndarray | None = None  # (n, 2) waypoints of a path task
    waypoint_index: int = 0  # index in ``path`` of the waypoint currently aimed at
    target_velocity: np.ndarray | None = None  # (2,) velocity of a moving target, if known
    extras: dict = field(default_factory=dict)

    @property
    def target_distance(self) -> float:
        """d_rg (eq IV.6): distance from the robot to ``target``."""
        return float(np.hypot(*(self.target - self.pose[:2])))

    @property
    def target_bearing(self) -> float:
        """θ_d − θ_r (eq IV.7–IV.8) wrapped to (−π, π]: positive when the target is on the left."""
        dx, dy = self.target - self.pose[:2]
        return wrap_angle(np.arctan2(dy, dx) - self.pose[2])


@dataclass(frozen=True)
class Command:
    """Steering α (rad, > 0 turns left) and linear speed V_r (m/s); the simulator clips both."""

    steering: float
    speed: float
    behaviour: str = ""  # name of the active behaviour, recorded in the trace (Fig IV.15 A…H)


class Controller(ABC):
    """Maps observations to commands. Subclasses set ``name`` and implement :meth:`act`.

    The controllers of this package decide for many robots at once and derive from
    :class:`BatchController`; a controller that can only decide for one robot at a time (a user's
    own, say) implements :meth:`act` alone and the simulator calls it robot by robot.
    """

    name: str = "controller"

    def reset(self, rng: np.random.Generator | None = None) -> None:
        """Forget any internal state before a new episode (default: stateless)."""

    @abstractmethod
    def act(self, obs: Observation) -> Command:
        """Return the command for this observation."""


class BatchController(Controller):
    """A controller whose one decision is :meth:`act_batch` over N robots; :meth:`act` is its
    one-robot case, inherited (one robot is a batch of one).

    ``act_batch`` takes a batch observation — arrays with a leading robot axis, as the simulator's
    ``BatchObservation`` — and returns ``(steering (N,), speed (N,), behaviours (N,))``. :meth:`act`
    views one :class:`Observation` as a batch of one through :meth:`one_robot` and returns the
    first command. The default view is the observation itself, for batch code that reads its
    arrays with ``np.atleast_2d`` / ``reshape(-1, …)``; a subclass whose batch code reads other
    fields overrides :meth:`one_robot` once for all its controllers.
    """

    @abstractmethod
    def act_batch(self, obs):
        """``(steering (N,), speed (N,), behaviours (N,))`` for a batch observation."""

    def one_robot(self, obs: Observation):
        """The batch of one that :meth:`act_batch` reads for the single observation ``obs``."""
        return obs

    def act(self, obs: Observation) -> Command:
        steering, speed, labels = self.act_batch(self.one_robot(obs))
        return Command(float(steering[0]), float(speed[0]), str(labels[0]))
