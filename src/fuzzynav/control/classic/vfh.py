"""``vfh``: VFH+ (I. Ulrich, J. Borenstein, *VFH+: reliable obstacle avoidance for fast mobile
robots*, ICRA 1998) on the tricycle's remembered range hits, in the robot frame.

1. **Primary polar histogram** (§2): sectors of ``sector`` degrees; every hit at distance d
   within the active window ``window`` adds m = a − b d² (certainty 1, a − b·window² = 0,
   a = 1) to each sector within the enlargement angle γ = asin(r_{r+s} / d) of its direction,
   r_{r+s} the body radius plus the safety distance ``safety``.
2. **Binary histogram** (§3): sector blocked above τ_high, free below τ_low, else as at the
   previous step (hysteresis).
3. **Masked histogram** (§4): the robot turns no tighter than R = l / tan(α_max) (eq IV.1);
   a hit inside the left (right) trajectory circle enlarged by r_{r+s} blocks every direction
   to its left (right), and directions behind the robot are out of reach.
4. **Direction** (§5): for each free opening, its centre when it is narrow (< ``s_max``
   sectors), else its two edges moved ``s_max``/2 sectors inwards and the goal direction when
   it lies inside; the candidate of least cost μ1 Δ(c, goal) + μ2 Δ(c, heading) + μ3 Δ(c,
   previous choice), μ = 5, 2, 2 (the paper's values for goal-oriented behaviour).
5. **Steering and speed**: the arc through the point ``lookahead`` metres in that direction
   (α = atan(2 l sin φ / L), Coulter 1992); V = V_max · max(0.2, 1 − h_c / h_m) · max(cos φ, 0.2)
   with h_c the primary histogram in the chosen direction (§6 slows down in dense regions).

No free direction left: the robot stops (no reverse gear) and the episode times out.

``vfh-tracks`` (``tracks=True``, after the VFH of J. Borenstein, Y. Koren, *The vector field
histogram — fast obstacle avoidance for mobile robots*, IEEE Trans. Robotics and Automation 7(3),
1991, which VFH+ refines) reads the lidar and predicts the moving obstacles as
``fuzzy-5b-yield-tracks`` does (:class:`~fuzzynav.control.classic.local_map.TrackedMap`: tracks
from successive scans, constant velocity): the primary histogram of step 1 also holds each
tracked obstacle at its predicted centres over the next ``prediction`` s (every
``prediction_step`` s), its enlargement angle grown by the obstacle's radius — the sectors it
will sweep are blocked or costly before it gets there. The masked histogram (step 3) keeps the
echoes of this step: where the robot can turn is a matter of what stands round it now.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.control.base import Command, Controller
from fuzzynav.control.classic.local_map import Body, LocalMap, TrackedMap
from fuzzynav.control.sighting_tracks import tracked_variant
from fuzzynav.robot.sensors import named_ring
from fuzzynav.settings import BODY, LENGTH, MEMORY, PREDICTION, RATE, ROOM, WEIGHT, Range, checked


class VectorFieldHistogram(Controller):
    """VFH+ (module docstring). Options: robot ``radius``/``wheelbase``/``max_steering``/``max_speed``,
    ``sector`` (°), ``window``, ``safety``, ``lookahead`` (m), ``tau_low``/``tau_high``, ``s_max``
    (sectors), ``h_m``, ``memory`` (steps); ``tracks``: add the predicted tracks of moving obstacles, on
    the lidar, over ``prediction`` s every ``prediction_step`` s."""

    name = "vfh"

    @checked(**BODY, sector=Range(0.1, 180.0), window=LENGTH, safety=ROOM, lookahead=LENGTH, tau_low=WEIGHT, tau_high=WEIGHT,
             s_max=Range(1, 3600), h_m=RATE, memory=MEMORY, prediction=PREDICTION, prediction_step=Range(0.01, 60.0))
    def __init__(self, *, radius: float = Body.radius, wheelbase: float = Body.wheelbase,
                 max_steering: float = Body.max_steering, max_speed: float = Body.max_speed,
                 sector: float = 5.0, window: float = 3.0, safety: float = 0.15, lookahead: float = 1.0,
                 tau_low: float = 0.4, tau_high: float = 0.8, s_max: int = 16, h_m: float = 3.0, memory: int = 10,
                 tracks: bool = False, prediction: float = 1.5, prediction_step: float = 0.25):
        self.body = Body(radius, wheelbase, max_steering, max_speed)
        self.n = int(round(360.0 / sector))
        self.width = 2 * math.pi / self.n
        self.window, self.safety, self.lookahead, self.h_m = float(window), float(safety), float(lookahead), float(h_m)
        self.tau_low, self.tau_high, self.s_max = float(tau_low), float(tau_high), int(s_max)
        self.directions = np.angle(np.exp(1j * np.arange(self.n) * self.width))  # sector k ↦ k·width, wrapped
        self.map = TrackedMap(memory) if tracks else LocalMap(memory)
        self.sensors = named_ring("lidar") if tracks else None  # None: the thesis' seven rays
        self.ahead = np.arange(0.0, prediction + 1e-9, prediction_step)
        self.reset()

    def reset(self, rng=None) -> None:
        self.map.reset()
        self._binary = np.zeros(self.n, dtype=bool)
        self._previous = 0.0  # last chosen direction, world frame

    def _primary(self, points, grown=0.0) -> np.ndarray:
        """Step 1 over ``points`` (P, 2), each enlarged by the body and ``grown`` (m, scalar or (P,))."""
        d = np.hypot(points[:, 0], points[:, 1])
        keep = d < self.window
        d, beta = d[keep], np.arctan2(points[keep, 1], points[keep, 0])
        enlarged = self.body.radius + self.safety + np.broadcast_to(grown, keep.shape)[keep]
        gamma = np.arcsin(np.clip(enlarged / np.maximum(d, 1e-6), 0.0, 1.0))
        magnitude = 1.0 - (d / self.window) ** 2
        offset = np.abs(np.angle(np.exp(1j * (self.directions[None, :] - beta[:, None]))))
        return (magnitude[:, None] * (offset <= gamma[:, None])).sum(axis=0)

    def _masked(self, points, binary) -> np.ndarray:
        """Blocked sectors of the masked histogram (step 3)."""
        radius, enlarged = self.body.turn_radius, self.body.radius + self.safety
        x, y = points[:, 0], points[:, 1]
        beta = np.arctan2(y, x)
        left_limit, right_limit = math.pi, -math.pi
        left = (y > 0) & (np.hypot(x, y - radius) < radius + enlarged)
        right = (y <= 0) & (np.hypot(x, y + radius) < radius + enlarged)
        if left.any():
            left_limit = float(beta[left].min())
        if right.any():
            right_limit = float(beta[right].max())
        reachable = (self.directions < left_limit) & (self.directions > right_limit)
        return binary | ~reachable

    def _candidates(self, blocked, goal_sector) -> list[int]:
        if blocked.all():
            return []
        start = int(np.argmax(blocked))  # walk the circle from a blocked sector
        order = (start + np.arange(1, self.n + 1)) % self.n
        candidates, run = [], []
        for k in order:
            if not blocked[k]:
                run.append(int(k))
                continue
            if run:
                candidates += self._from_opening(run, goal_sector)
                run = []
        if run:
            candidates += self._from_opening(run, goal_sector)
        return candidates

    def _from_opening(self, run, goal_sector) -> list[int]:
        if len(run) < self.s_max:
            return [run[len(run) // 2]]
        half = self.s_max // 2
        found = [run[half], run[-1 - half]]
        return found + ([goal_sector] if goal_sector in run else [])

    def act(self, obs) -> Command:
        points = self.map.points(obs)
        primary = self._primary(points) if len(points) else np.zeros(self.n)
        if isinstance(self.map, TrackedMap):
            where, radii = self.map.predicted(obs, self.ahead)  # (M, T, 2), (M,)
            if len(radii):
                primary = primary + self._primary(where.reshape(-1, 2), np.repeat(radii, len(self.ahead)))
        binary = np.where(primary > self.tau_high, True, np.where(primary < self.tau_low, False, self._binary))
        self._binary = binary
        blocked = self._masked(points, binary) if len(points) else np.zeros(self.n, dtype=bool)
        goal = obs.target_bearing
        goal_sector = int(round(goal / self.width)) % self.n
        candidates = self._candidates(blocked, goal_sector)
        if not candidates:
            return Command(0.0, 0.0, "VFH-stop")
        heading = float(obs.pose[2])
        previous = math.remainder(self._previous - heading, math.tau)
        angles = self.directions[candidates]
        gap = lambda a, b: np.abs(np.angle(np.exp(1j * (a - b))))
        cost = 5.0 * gap(angles, goal) + 2.0 * gap(angles, 0.0) + 2.0 * gap(angles, previous)
        best = int(np.argmin(cost))
        phi = float(angles[best])
        self._previous = heading + phi
        density = float(primary[candidates[best]])
        speed = self.body.max_speed * max(0.2, 1.0 - min(density, self.h_m) / self.h_m) * max(math.cos(phi), 0.2)
        return Command(self.body.steer_towards(phi, self.lookahead), speed, "VFH+")


def make(**options) -> VectorFieldHistogram:
    """Factory of ``vfh`` (options: see :class:`VectorFieldHistogram`)."""
    return VectorFieldHistogram(**options)


make_tracked = tracked_variant(VectorFieldHistogram, "vfh-tracks")
