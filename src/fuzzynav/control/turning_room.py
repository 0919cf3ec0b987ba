"""Turning room of a tricycle from its range readings (used by the supervisor of the five-behaviour navigators).

The thesis' robot (§IV.4) has no reverse gear and a bounded steering angle: its tightest turn,
at the largest steering singleton α_max = π/5 of Fig IV.7, has radius R = l / tan(π/5)
(0.69 m for l = 0.5 m, eq IV.1), and slowing down does not shrink it. So an obstacle must be
turned away from while a full-lock turn is still free. (Turning at the robot's steering limit
π/4 instead, R = 0.5 m, was tried: on 100 mixed worlds it avoided half of the collisions, but it
sent the robot of Fig IV.22a round an extra loop, out of its time.) This module measures that room:

- the hit memory keeps, per robot, the points where the range rays of the last ``steps``
  steps hit something, in the world frame (the pose comes from the robot's odometry, §IV.4), and
  returns them in the current robot frame. The ring C1…C7 is 30° apart, so a thin wall end or a
  corner can lie between two rays at one step; the rays swept over the last second fill part of
  the gaps. The rest is a modelling matter: the simulator's rays are lines, but the thesis'
  sensors are ultrasonic (§IV.7), and a sonar returns the nearest echo within its cone (about
  30° wide). The cone echo stands for those cones: the nearest obstacle point (D_ro, θ_o of
  the observation) counts as a hit when it lies within the ring's coverage, the 7 directions
  ±15°. A robot driving straight at a wall end that sits between the 0° and ±30° rays, inside
  its own lane, would otherwise see it only when it is already too late to turn.
- the step clearance is the last resort: the gap between the body after the next step and
  the remembered hits (below a few centimetres the navigator stops, :mod:`five_behaviours`).
- the turning room gives, for the half-turn at full lock to the left and to the right, the
  smallest gap between the swept body (a disc of radius ``body`` whose centre runs on the circle
  of radius R through the robot, centre at (0, ±R) in the robot frame) and those points, and the
  free length of the straight lane ahead (points within ``body`` of the heading line).

Robot frame: x ahead, y to the left (α > 0 turns left, docs/thesis.md). All of it is compiled
(:mod:`fuzzynav.kernels.guard`) and runs inside the navigators' ``act``; :class:`TurnGuard` offers
it to other controllers.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.fuzzy.constants import ALPHA_MAX
from fuzzynav.kernels.records import Readings
from fuzzynav.robot.tricycle import DEFAULT_PARAMS

TURN_RADIUS = DEFAULT_PARAMS.wheelbase / math.tan(ALPHA_MAX)  # R = l / tan(π/5), eq IV.1 (m)


class TurnGuard:
    """When a robot must start its full-lock turn, and to which side (thesis §IV.4: no reverse).

    The turn is wanted when the straight lane ahead is blocked within ``lane`` (m) and the
    better full-lock half turn keeps less than ``margin`` (m) from every remembered hit — both
    after one more step at the current speed; a turn under way goes on until lane and room
    exceed those thresholds by 0.5 m and 0.2 m. The side is the roomier one (within 0.1 m, the
    goal's side), chosen when the turn starts and kept until it ends. Hits: the range ring plus
    the sonar-cone echo of the nearest obstacle point, over ``memory`` steps; :meth:`stop` measures
    the next step against them.
    """

    def __init__(self, lane: float, margin: float, memory: int = 10):
        from fuzzynav.control.batched import navigator_params

        self.lane, self.margin, self.steps = float(lane), float(margin), int(memory)
        # this object is the turning-room layer (and its stop): both switched on in the kernel's params
        self.params = navigator_params(lane=lane, room_margin=margin, turn_radius=TURN_RADIUS,
                                       body=DEFAULT_PARAMS.radius, half_cone=math.radians(15.0), turning_room=1.0,
                                       safety_stop=1.0)
        self.reset()

    def reset(self) -> None:
        """Forget the hits and the sides (a new episode)."""
        self._state = self._memory = self._pose = None

    def __call__(self, obs, turning, bearing) -> tuple[np.ndarray, np.ndarray]:
        """``(wanted (N,) bool, side (N,) ±1)`` for a batch observation; ``turning`` marks the
        robots already in their turn, ``bearing`` is the goal bearing (N,)."""
        from fuzzynav.kernels import navigators

        ranges = np.ascontiguousarray(obs.ranges, dtype=float)
        n, s = ranges.shape
        if self._memory is None or self._memory.shape[:1] + self._memory.shape[2:3] != (n, s + 1):
            self._state, self._memory = np.zeros((n, 4), dtype=np.int64), np.zeros((n, self.steps, s + 1, 3))
        self._pose = np.ascontiguousarray(obs.pose, dtype=float)
        out = np.empty((n, 2))
        from fuzzynav.control.supervisor import column

        seen = Readings(self._pose, column(obs.speed, n), np.zeros((n, 2)), ranges,
                        np.ascontiguousarray(obs.sensor_angles, dtype=float), float(obs.max_range),
                        np.column_stack([column(obs.obstacle_distance, n), column(obs.obstacle_bearing, n)]),
                        np.ones(n, dtype=np.bool_))
        navigators.guard_all(self.params, self._state, self._memory, seen, float(obs.dt), column(bearing, n),
                             column(turning, n, np.bool_), out)
        return out[:, 0] != 0.0, out[:, 1]

    def stop(self, speed, dt: float, margin: float) -> np.ndarray:
        """The safety stop: ``speed`` ``(N,)`` with 0 where the next step would bring the body
        within ``margin`` (m) of a hit remembered at the last call."""
        from fuzzynav.kernels import navigators

        params = self.params.copy()
        params[navigators.STOP_MARGIN] = margin
        out = np.empty(len(self._pose))
        navigators.stop_all(params, self._memory, self._pose, np.ascontiguousarray(speed, dtype=float), float(dt), out)
        return out
