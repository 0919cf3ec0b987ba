"""Recovery manoeuvre of the default chapter IV navigators: back out of a dead end, then turn.

The thesis' robot has no reverse gear (§IV.4) and its navigators, kept as published for
``fuzzy-5b-thesis`` / ``fuzzy-2b-thesis``, stop for good when no forward turn is free (the
safety stop of :mod:`fuzzynav.control.five_behaviours`). A car-like robot that can reverse
makes a K-turn instead, and this module is that behaviour of the supervisor
(:mod:`fuzzynav.control.robust`):

1. **Back** (``REC-BACK``): reverse at ``v_back`` along a circular arc whose steering comes
   from a small zero-order Takagi–Sugeno rule base in the thesis' style (strong partitions,
   product T-norm, weighted sum, the steering singletons of Fig IV.7), Table ``TABLE_RECOVERY``:
   inputs ``room`` — the room on the left minus the room on the right (m) — and ``theta`` — the
   goal bearing (rad, > 0 on the left). Reversing with α > 0 swings the nose to the right
   (eq IV.1: θ̇ = V tan α / l with V < 0), so the rules swing it towards the roomier side, or
   the goal's side when both are alike, and back straight when the goal is ahead and both
   sides are alike. Every reverse step is checked against the remembered obstacle points
   (:class:`ObstacleMemory`: the ring's hits and the nearest obstacle point, D_ro / θ_o,
   which the observation gives all round, so obstacles behind the robot are known without
   rear sensors); the back-up ends after ``back_distance`` or when the next step would bring
   the body within ``margin`` of a point.
2. **Turn** (``REC-TURN``): forward at full lock the other way — the turn direction changed —
   until the heading has turned ``turn_angle`` or the lane ahead is free, each step checked
   the same way; then the navigator takes the robot back. A second recovery started near
   the place of the last one swings the other way.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.fuzzy.membership import Singleton
from fuzzynav.fuzzy.partition import strong_partition
from fuzzynav.fuzzy.rules import rules_from_grid
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.variable import Variable

ALPHA_TURN = math.pi / 5  # the largest steering singleton of Fig IV.7
CELL = 0.05  # m: obstacle points closer than this on a grid are remembered once

# Reverse steering, rows room (N: the right roomier, Z: alike, P: the left roomier), columns
# the goal bearing (N: right, Z: ahead, P: left); cells are Fig IV.7's singletons. α > 0
# while reversing swings the nose right, α < 0 left.
ROOM_LABELS, GOAL_LABELS = ("N", "Z", "P"), ("N", "Z", "P")
TABLE_RECOVERY = (
    "PG PG PM",  # the right roomier: swing the nose right (less if the goal is on the left)
    "PG Z  NG",  # alike: swing towards the goal; back straight with the goal ahead
    "NM NG NG",  # the left roomier: swing the nose left
)


def recovery_system() -> FuzzySystem:
    """The rule base of the back-up arc, ``TABLE_RECOVERY`` (9 rules, TS0, product, weighted sum).

    Inputs ``room`` (m: N, Z, P peaking at −1, 0, 1) and ``theta`` (rad: N, Z, P peaking at
    −π/4, 0, π/4); output ``alpha`` (the Fig IV.7 singletons NG −π/5 … PG π/5 in use)."""
    room = Variable("room", (-4.0, 4.0), strong_partition((-1.0, 0.0, 1.0), ROOM_LABELS, (-4.0, 4.0)))
    theta = Variable("theta", (-math.pi, math.pi),
                     strong_partition((-math.pi / 4, 0.0, math.pi / 4), GOAL_LABELS, (-math.pi, math.pi)))
    values = {"NG": -ALPHA_TURN, "NM": -ALPHA_TURN / 2, "Z": 0.0, "PM": ALPHA_TURN / 2, "PG": ALPHA_TURN}
    alpha = Variable("alpha", (-ALPHA_TURN, ALPHA_TURN), {k: Singleton(v) for k, v in values.items()})
    rules = rules_from_grid("room", "theta", ROOM_LABELS, GOAL_LABELS, TABLE_RECOVERY, ("alpha",),
                            columns_first=False, source="TABLE_RECOVERY")
    return FuzzySystem([room, theta], [alpha], rules, method="ts0", tnorm="product", defuzzifier="weighted_sum",
                       name="recovery", description="Back-up arc of the recovery manoeuvre (TS0, product, weighted sum)")


class ObstacleMemory:
    """Obstacle points seen during the episode, in the world frame, one per ``CELL`` grid cell."""

    def __init__(self):
        self.reset()

    def reset(self) -> None:
        """Forget every point (a new episode)."""
        self._cells: set[tuple[int, int]] = set()
        self._points: list[tuple[float, float]] = []
        self._array = np.zeros((0, 2))  # the points as an array, built when asked for (None: stale)

    def add(self, obs) -> None:
        """Store the hits of the ring (readings below the range) and the nearest obstacle point."""
        x, y, theta = (float(v) for v in obs.pose)
        seen = []
        if obs.ranges is not None:
            for r, a in zip(np.asarray(obs.ranges, dtype=float).tolist(), np.asarray(obs.sensor_angles).tolist()):
                if math.isfinite(r) and r < obs.max_range - 1e-9:
                    seen.append((x + r * math.cos(theta + a), y + r * math.sin(theta + a)))
        if obs.obstacle_distance is not None and math.isfinite(obs.obstacle_distance):
            d, b = max(float(obs.obstacle_distance), 0.0), theta + float(obs.obstacle_bearing)
            seen.append((x + d * math.cos(b), y + d * math.sin(b)))
        for px, py in seen:
            cell = (math.floor(px / CELL), math.floor(py / CELL))
            if cell not in self._cells:
                self._cells.add(cell)
                self._points.append((px, py))
                self._array = None

    @property
    def points(self) -> np.ndarray:
        """Every remembered point, ``(P, 2)`` world frame."""
        if self._array is None:
            self._array = np.array(self._points).reshape(-1, 2)
        return self._array

    def clearance(self, x: float, y: float) -> float:
        """Distance from (x, y) to the nearest remembered point (``inf`` with none)."""
        points = self.points
        if not len(points):
            return math.inf
        return float(np.min(np.hypot(points[:, 0] - x, points[:, 1] - y)))

    def side_room(self, pose, cap: float) -> tuple[float, float]:
        """``(left, right)``: distance to the nearest point on each side of the heading (ahead of
        the rear of the body), capped at ``cap``."""
        points = self.points
        if not len(points):
            return cap, cap
        x, y, theta = (float(v) for v in pose)
        rx, ry = points[:, 0] - x, points[:, 1] - y
        ahead = math.cos(theta) * rx + math.sin(theta) * ry
        lateral = math.cos(theta) * ry - math.sin(theta) * rx
        dist = np.hypot(rx, ry)
        near = ahead > -0.3
        left = dist[near & (lateral > 0)]
        right = dist[near & (lateral <= 0)]
        return (min(float(left.min()) if len(left) else cap, cap), min(float(right.min()) if len(right) else cap, cap))


class Recovery:
    """The K-turn of the module docstring for one robot: :meth:`start`, then :meth:`command`
    each step until it returns ``None`` (the navigator takes over)."""

    def __init__(self, v_back: float = 0.3, back_distance: float = 0.8, margin: float = 0.05,
                 v_turn: float = 0.3, turn_angle: float = math.pi / 3, lane: float = 1.5, max_time: float = 6.0):
        self.system = recovery_system()
        self.v_back, self.back_distance, self.margin = float(v_back), float(back_distance), float(margin)
        self.v_turn, self.turn_angle, self.lane, self.max_time = float(v_turn), float(turn_angle), float(lane), float(max_time)
        self.reset()

    def reset(self) -> None:
        """No manoeuvre under way, none remembered."""
        self.phase = None
        self._last_place = None
        self._flip = False

    def start(self, obs, memory: ObstacleMemory, robot) -> None:
        """Begin a manoeuvre here (``robot``: the robot's :class:`TricycleParams`)."""
        pose = np.asarray(obs.pose, dtype=float)
        left, right = memory.side_room(pose, obs.max_range)
        steering = self.system.evaluate_one(left - right, obs.target_bearing)[0]
        again = self._last_place is not None and math.hypot(*(pose[:2] - self._last_place)) < 1.0
        self._flip = (not self._flip) if again else False
        if self._flip:
            steering = -steering if abs(steering) > 1e-9 else ALPHA_TURN * (1 if obs.target_bearing >= 0 else -1)
        self._last_place = pose[:2].copy()
        self.phase, self._start_pose, self._t0 = "REC-BACK", pose.copy(), obs.t
        self._steering = float(steering)
        self._speed = -min(self.v_back, robot.max_reverse_speed)

    def command(self, obs, memory: ObstacleMemory, robot) -> tuple[float, float, str] | None:
        """``(α, V, label)`` of this step of the manoeuvre, or ``None`` when it has ended."""
        x, y, theta = (float(v) for v in obs.pose)
        if obs.t - self._t0 > self.max_time:
            self.phase = None
        if self.phase == "REC-BACK":
            backed = math.hypot(x - self._start_pose[0], y - self._start_pose[1])
            if backed < self.back_distance:
                for steering in (self._steering, 0.0):  # the rule base's arc, else straight back
                    if self._safe(memory, robot, obs.pose, steering, self._speed, obs.dt):
                        return steering, self._speed, "REC-BACK"
            self.phase = "REC-TURN" if abs(self._steering) > ALPHA_TURN / 4 else None
            self._heading = theta
        if self.phase == "REC-TURN":
            turned = abs(math.remainder(theta - self._heading, math.tau))
            steering = -math.copysign(ALPHA_TURN, self._steering)
            ahead = np.asarray(obs.ranges, dtype=float)[np.abs(np.asarray(obs.sensor_angles)) <= math.radians(31)]
            if (turned < self.turn_angle and not (ahead >= self.lane).all()
                    and self._safe(memory, robot, obs.pose, steering, self.v_turn, obs.dt)):
                return steering, self.v_turn, "REC-TURN"
            self.phase = None
        return None

    def _safe(self, memory: ObstacleMemory, robot, pose, steering: float, speed: float, dt: float) -> bool:
        """True when one step of (α, V) (eq IV.2) leaves the body ``margin`` from every remembered
        point, or at least no nearer to them than now (and clear of them)."""
        x, y, theta = (float(v) for v in pose)
        now = memory.clearance(x, y)
        after = memory.clearance(x + speed * dt * math.cos(theta), y + speed * dt * math.sin(theta))
        return after >= robot.radius + self.margin or (after >= now and after > robot.radius + 0.01)
