"""``fuzzy-2b``: goal seeking + obstacle avoidance by distance and angle (thesis §IV.5.2.1,
Figs IV.9–IV.11, Table IV.2), the two-behaviour navigator of Fig IV.15.

Inputs of the avoider: D_ro, the clearance from the robot centre to the nearest obstacle surface
(:attr:`Observation.obstacle_distance`), and θ_o, the angle between the robot axis and that
point, fed to the table through :func:`~fuzzynav.control.base.thesis_angle_error` like θ_rg
(with the thesis' sign the table turns left when the obstacle is on the right, and steers right
with an obstacle dead ahead — rule R1 of §IV.5.2.1).

The thesis treats the robot as a point and puts a risk zone around each circular obstacle
(§IV.5.2, Fig IV.3); here D_ro is the clearance minus ``risk`` (default 0.3 m, the robot's
footprint radius), i.e. the gap between the robot's body and the obstacle, so the P set of
Fig IV.10 (fully near below 0.5 m) leaves room to turn. The workspace's boundary walls are
obstacles too: :attr:`Observation.obstacle_distance` leaves them out, so when the range ring
reads a wall nearer than D_ro, that reading and its sensor direction stand for D_ro and θ_o.

The switch of Fig IV.9 activates the avoider when an obstacle is detected "in front, on the
right or on the left" (§IV.6.2) and stands in the way: D_ro below ``detection`` (default 2 m),
the goal farther than the obstacle, and the obstacle either within ``front`` (default 45°) of
the heading, or within ``sector`` (default 90°) of the heading and of the goal direction. An
obstacle beside or behind the robot on the side away from the goal leaves the guarded
goal-seeking behaviour of :mod:`fuzzynav.control.goal_seeking` in charge (it turns away from
such an obstacle anyway). Behaviour labels: ``GSB``, ``OA``.

**Hysteresis** (Fig IV.9 states the switch only in words). Taken step by step that test
chatters at its edges — avoiding turns the obstacle out of the sector, goal seeking turns it
back in — and the steering jumps between the two tables every step. The switch is therefore
held by :class:`fuzzynav.control.supervisor.Switch`: OA is taken at once, GSB only after OA
has driven ``dwell`` steps (default 10, 1 s), and OA, once active, stays wanted while D_ro is
below ``detection`` + ``release`` (default 0.5 m) and the obstacle within ``sector`` + 15° of
the heading. Like ``fuzzy-5b``, the navigator turns at full lock (α = ±π/5, the extreme
singletons of Table IV.2) and low speed ``v_turn`` when its turning room runs out
(:class:`fuzzynav.control.turning_room.TurnGuard`; this turn is labelled ``OA``), and it has the
same safety stop (V = 0 when the next step would bring the body within ``stop_margin`` of a
remembered hit, :mod:`fuzzynav.control.five_behaviours`). The state is one
mode per robot plus the guard's memory; :meth:`reset` clears it.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.control import supervisor
from fuzzynav.control.base import thesis_angle_error
from fuzzynav.control.batched import BatchedController, evaluate
from fuzzynav.control.goal_seeking import GuardedGoalSeeking
from fuzzynav.control.turning_room import ALPHA_MAX, TurnGuard
from fuzzynav.fuzzy.systems import obstacle_avoidance
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.world.geometry import wrap_angle


class TwoBehaviourNavigator(BatchedController):
    """GSB (Table IV.1) and OA (Table IV.2) with the switch of Fig IV.9."""

    name = "fuzzy-2b"

    def __init__(self, detection: float = 2.0, sector: float = math.pi / 2, front: float = math.pi / 4,
                 risk: float = 0.3, wheelbase: float = DEFAULT_PARAMS.wheelbase, dwell: int = 10,
                 release: float = 0.5, lane: float = 1.5, room_margin: float = 0.5, v_turn: float = 0.3,
                 stop_margin: float = 0.02):
        self.detection = float(detection)
        self.release = float(release)
        self.switch = supervisor.Switch((0, 1, 2), dwell)  # 0 GSB, 1 OA, 2 OA at full lock
        self.guard = TurnGuard(lane, room_margin)
        self.v_turn = float(v_turn)
        self.stop_margin = float(stop_margin)
        self.risk = float(risk)
        self.sector = float(sector)
        self.front = float(front)
        self.gsb = GuardedGoalSeeking(wheelbase)
        self.oa = obstacle_avoidance()

    def reset(self, rng=None) -> None:
        self.switch.reset()
        self.guard.reset()

    def act_batch(self, obs):
        steering, speed, _ = self.gsb(obs.target_distance, obs.target_bearing)
        d_ro = np.asarray(obs.obstacle_distance, dtype=float)
        theta_o = np.asarray(obs.obstacle_bearing, dtype=float)
        if obs.ranges is not None:  # the boundary walls, which D_ro leaves out, as the range ring sees them
            ranges = np.asarray(obs.ranges, dtype=float)
            k = np.argmin(ranges, axis=1)
            nearest = ranges[np.arange(len(k)), k]
            wall = nearest < d_ro
            d_ro = np.where(wall, nearest, d_ro)
            theta_o = np.where(wall, np.asarray(obs.sensor_angles, dtype=float)[k], theta_o)
        d_ro = d_ro - self.risk
        ahead = np.abs(theta_o) <= self.sector
        towards_goal = np.abs(wrap_angle(theta_o - obs.target_bearing)) <= self.sector
        in_front = np.abs(theta_o) <= self.front
        avoid = (d_ro < self.detection) & (in_front | (ahead & towards_goal)) & (obs.target_distance > d_ro)
        before = self.switch.mode if self.switch.mode is not None and len(self.switch.mode) == len(avoid) \
            else np.zeros(len(avoid), dtype=int)
        wide = np.abs(theta_o) <= self.sector + np.radians(15.0)  # OA in charge: a wider test
        avoid = avoid | (before >= 1) & (d_ro < self.detection + self.release) & wide & (obs.target_distance > d_ro)
        turn, side = (self.guard(obs, before == 2, obs.target_bearing) if obs.ranges is not None
                      else (np.zeros(len(avoid), dtype=bool), np.ones(len(avoid))))
        mode = self.switch(np.where(turn, 2, avoid.astype(int)), np.ones(len(avoid), dtype=bool))
        avoid = mode >= 1
        if avoid.any():
            out = evaluate(self.oa, np.column_stack([np.where(np.isfinite(d_ro), d_ro, 1e3),
                                                    thesis_angle_error(theta_o)]))
            steering = np.where(avoid, out[:, 0], steering)
            speed = np.where(avoid, out[:, 1], speed)
        steering = np.where(mode == 2, side * ALPHA_MAX, steering)
        speed = np.where(mode == 2, self.v_turn, speed)
        if obs.ranges is not None:  # the safety stop, on the hits the guard saw this step
            speed = self.guard.stop(speed, obs.dt, self.stop_margin)
        return steering, speed, np.where(avoid, "OA", "GSB")


def make(**options) -> TwoBehaviourNavigator:
    """Factory of the ``fuzzy-2b`` entry of :data:`fuzzynav.control.registry.CONTROLLERS`."""
    return TwoBehaviourNavigator(**options)
