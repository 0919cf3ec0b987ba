"""What many robots see at one step, as arrays: :class:`BatchObservation`.

The batch counterpart of :class:`fuzzynav.control.base.Observation` (same fields, one leading
robot axis). A controller with ``act_batch(batch_obs)`` reads it directly; others get one
:class:`Observation` per robot from :meth:`BatchObservation.single`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from fuzzynav.control.base import Observation
from fuzzynav.kernels.angles import wrap_angle


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
