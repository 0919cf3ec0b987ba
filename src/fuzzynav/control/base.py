"""The one controller interface for everything that drives the robot (docs/ARCHITECTURE.md).

A controller maps an :class:`Observation` (one robot) to a :class:`Command`, or — a
:class:`BatchController`, as every controller of the package — a :class:`BatchObservation` (N
robots, the same fields with a leading robot axis) to N commands; it knows nothing of the episode
loop. Fuzzy behaviours, supervisors, trackers, learned policies and baselines all
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
    θ_r − θ_d = −bearing. This is the only place where the sign is flipped, but for the compiled
    learned controllers, which flip it the same way in :func:`fuzzynav.kernels.learned.goal_inputs`.
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
class BatchObservation:
    """Observations of N robots. Angles in radians, bearings relative to each heading (CCW).

    ``obstacle_distance`` is D_ro (Table IV.2): signed distance from the robot centre to the
    nearest scenario obstacle surface, boundary excluded (``inf`` with no obstacles, bearing 0).
    ``active`` marks robots whose episode is still running; finished robots keep their last
    values and their commands are ignored.
    """

    t: float
    dt: float
    pose: np.ndarray  # (N, 3)
    speed: np.ndarray  # (N,) applied at the previous step
    steering: np.ndarray  # (N,) applied at the previous step
    target: np.ndarray  # (N, 2) goal, current waypoint or target position
    ranges: np.ndarray  # (N, S)
    sensor_angles: np.ndarray  # (S,)
    max_range: float
    obstacle_distance: np.ndarray  # (N,)
    obstacle_bearing: np.ndarray  # (N,)
    active: np.ndarray  # (N,) bool
    path: np.ndarray | None = None  # (n, 2) waypoints of a path task
    waypoint_index: np.ndarray | None = None  # (N,) int
    target_velocity: np.ndarray | None = None  # (N, 2) for a moving target
    extras: dict = field(default_factory=dict)

    @property
    def n(self) -> int:
        return int(self.pose.shape[0])

    @property
    def target_distance(self) -> np.ndarray:
        """d_rg (eq IV.6) for every robot, ``(N,)``."""
        d = self.target - self.pose[:, :2]
        return np.hypot(d[:, 0], d[:, 1])

    @property
    def target_bearing(self) -> np.ndarray:
        """θ_d − θ_r (eq IV.7–IV.8), wrapped, ``(N,)``: positive when the target is on the left."""
        d = self.target - self.pose[:, :2]
        return wrap_angle(np.arctan2(d[:, 1], d[:, 0]) - self.pose[:, 2])

    @classmethod
    def of(cls, obs: Observation) -> BatchObservation:
        """``obs`` as a batch of one (what :meth:`BatchController.act` hands to ``act_batch``):
        every per-robot field gets a leading axis of 1; a missing speed or steering is 0, a
        missing obstacle distance ``inf`` at bearing 0."""
        def one(value, default):
            return np.array([default if value is None else value], dtype=float)

        def row(value):
            return None if value is None else np.asarray(value, dtype=float)[None, :]

        return cls(t=obs.t, dt=obs.dt, pose=row(obs.pose), speed=one(obs.speed, 0.0), steering=one(obs.steering, 0.0),
                   target=row(obs.target), ranges=row(obs.ranges), sensor_angles=obs.sensor_angles,
                   max_range=obs.max_range, obstacle_distance=one(obs.obstacle_distance, np.inf),
                   obstacle_bearing=one(obs.obstacle_bearing, 0.0), active=np.ones(1, dtype=bool), path=obs.path,
                   waypoint_index=np.array([obs.waypoint_index]), target_velocity=row(obs.target_velocity),
                   extras=obs.extras)

    def single(self, i: int) -> Observation:
        """The :class:`Observation` of robot ``i``."""
        return Observation(
            t=self.t,
            dt=self.dt,
            pose=self.pose[i],
            speed=float(self.speed[i]),
            steering=float(self.steering[i]),
            target=self.target[i],
            ranges=self.ranges[i],
            sensor_angles=self.sensor_angles,
            max_range=self.max_range,
            obstacle_distance=float(self.obstacle_distance[i]),
            obstacle_bearing=float(self.obstacle_bearing[i]),
            path=self.path,
            waypoint_index=int(self.waypoint_index[i]) if self.waypoint_index is not None else 0,
            target_velocity=self.target_velocity[i] if self.target_velocity is not None else None,
            extras=self.extras,
        )


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

    ``act_batch`` takes a :class:`BatchObservation` — arrays with a leading robot axis — and
    returns ``(steering (N,), speed (N,), behaviours (N,))``. :meth:`act` hands it the single
    observation as a batch of one (:meth:`BatchObservation.of`) and returns the first command.
    """

    @abstractmethod
    def act_batch(self, obs):
        """``(steering (N,), speed (N,), behaviours (N,))`` for a batch observation."""

    def act(self, obs: Observation) -> Command:
        steering, speed, labels = self.act_batch(BatchObservation.of(obs))
        return Command(float(steering[0]), float(speed[0]), str(labels[0]))
