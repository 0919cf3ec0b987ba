"""``dwa``: the Dynamic Window Approach (D. Fox, W. Burgard, S. Thrun, *The dynamic window
approach to collision avoidance*, IEEE Robotics & Automation Magazine 4(1), 1997) for the tricycle.

Fox et al. search velocities (v, ω) of a synchro-drive robot; for a car-like robot the same
search runs over its own controls (α, V), since each pair fixes a circular arc of curvature
tan α / l (eq IV.1). At every step:

1. **Candidates**: ``n_steering`` steering angles over [−α_max, α_max] (the steering is set
   directly, as for every navigator here) and ``n_speeds`` speeds in the *dynamic window*
   [V − a Δt, V + a Δt] ∩ [0, V_max] around the current speed, ``a`` the acceleration limit.
2. **Forward simulation**: each arc is driven in the robot frame (:func:`local_map.arcs`) against
   the remembered range hits; dist(α) is the free arc length before the footprint disc (radius +
   ``margin``, less when a hit is already inside the margin) touches one (capped at ``horizon``).
3. **Admissible** pairs (Fox et al. §4.2): V ≤ √(2 b dist), the robot can still stop before the
   obstacle with the braking deceleration ``b``.
4. **Objective** (§4.3): G = σ(w_h · heading + w_d · dist + w_v · velocity), each term
   normalised to [0, 1] over the admissible pairs; heading = 1 − |angle to the goal| / π seen
   from the pose reached after ``lookahead`` seconds on the arc, velocity = V / V_max. Weights
   1, 1, 0.2 here: Fox et al.'s 2, 0.2, 0.2 (§5) suit a robot that turns on the spot; a car
   that may not reverse, sent at the goal that eagerly, ends nose-to-obstacle with no arc left
   (8 of 20 mixed worlds reached, against 19 with 1, 1, 0.2; see docs/benchmarks.md).

With no admissible pair the robot brakes (V = 0) steering along the freest arc: with no reverse
gear it stays there until the episode ends — the classic local minimum of reactive methods.

``dwa-tracks`` (``tracks=True``) reads the lidar and predicts the moving obstacles as
``fuzzy-5b-yield-tracks`` does (:class:`~fuzzynav.control.classic.local_map.TrackedMap`: tracks
from successive scans, constant velocity): dist(α, V) of step 2 is also cut where the arc, driven
at V, meets a tracked obstacle moved along its track to the time the robot gets there (within
``prediction`` s), so admissibility and the clearance term weigh where the obstacles will be, not
where they were — the time-parameterised collision check of velocity obstacles (P. Fiorini,
Z. Shiller, IJRR 17(7), 1998) on Fox et al.'s arcs.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.control.base import Command, Controller
from fuzzynav.control.classic.local_map import Body, LocalMap, TrackedMap, arcs, free_length, moving_free_length
from fuzzynav.control.sighting_tracks import tracked_variant
from fuzzynav.kernels.angles import wrap_angle
from fuzzynav.robot.sensors import named_ring
from fuzzynav.settings import BODY, LENGTH, MEMORY, PREDICTION, RATE, ROOM, SAMPLES, WEIGHT, checked


class DynamicWindow(Controller):
    """DWA (module docstring). Options: robot ``radius``/``wheelbase``/``max_steering``/``max_speed``,
    ``acceleration``, ``braking`` (m/s²), ``margin``, ``horizon`` (m), ``lookahead`` (s), weights
    ``heading``, ``clearance``, ``velocity``, sample counts ``n_steering``, ``n_speeds``; ``tracks``:
    plan against the predicted tracks of moving obstacles, on the lidar, ``prediction`` s ahead."""

    name = "dwa"

    @checked(**BODY, acceleration=RATE, braking=RATE, margin=ROOM, horizon=LENGTH, lookahead=PREDICTION,
             heading=WEIGHT, clearance=WEIGHT, velocity=WEIGHT, n_steering=SAMPLES, n_speeds=SAMPLES, memory=MEMORY,
             prediction=PREDICTION)
    def __init__(self, *, radius: float = Body.radius, wheelbase: float = Body.wheelbase,
                 max_steering: float = Body.max_steering, max_speed: float = Body.max_speed,
                 acceleration: float = 2.0, braking: float = 2.0, margin: float = 0.1, horizon: float = 3.0,
                 lookahead: float = 1.0, heading: float = 1.0, clearance: float = 1.0, velocity: float = 0.2,
                 n_steering: int = 15, n_speeds: int = 5, memory: int = 10, tracks: bool = False,
                 prediction: float = 3.0):
        self.body = Body(radius, wheelbase, max_steering, max_speed)
        self.acceleration, self.braking = float(acceleration), float(braking)
        self.margin, self.horizon, self.lookahead = float(margin), float(horizon), float(lookahead)
        self.weights = np.array([float(heading), float(clearance), float(velocity)])
        self.steering = np.linspace(-max_steering, max_steering, int(n_steering))
        self.n_speeds = int(n_speeds)
        self.map = TrackedMap(memory) if tracks else LocalMap(memory)
        self.sensors = named_ring("lidar") if tracks else None  # None: the thesis' seven rays
        self.prediction = float(prediction)

    def reset(self, rng=None) -> None:
        self.map.reset()

    def act(self, obs) -> Command:
        body = self.body
        points = self.map.points(obs)
        curvature = np.tan(self.steering) / body.wheelbase
        # inside the margin already (sensed late): only the body itself (+ 2 cm) must not touch,
        # so the arcs leading away stay admissible
        nearest = float(np.hypot(points[:, 0], points[:, 1]).min()) if len(points) else math.inf
        contact = max(body.radius + 0.02, min(body.radius + self.margin, nearest - 0.05))
        reach = self.acceleration * obs.dt
        speeds = np.linspace(max(0.0, obs.speed - reach), min(body.max_speed, obs.speed + reach), self.n_speeds)
        dist = np.broadcast_to(free_length(curvature, points, contact, self.horizon)[:, None], (len(curvature), len(speeds)))
        if isinstance(self.map, TrackedMap):
            tracked = self.map
            dist = np.minimum(dist, moving_free_length(curvature, speeds, lambda times: tracked.predicted(obs, times),
                                                       contact, self.horizon, self.prediction))
        a, v = np.meshgrid(np.arange(len(self.steering)), speeds, indexing="ij")
        admissible = (v <= np.sqrt(2.0 * self.braking * dist)) & (v > 0)
        if not admissible.any():
            return Command(float(self.steering[int(np.argmax(dist.max(axis=1)))]), 0.0, "DWA-stop")
        # heading term: the goal's angle seen from the pose reached after `lookahead` seconds
        travelled = np.maximum(v * self.lookahead, 0.3)
        end = arcs(curvature, np.unique(travelled))  # (A, U, 2)
        which = np.searchsorted(np.unique(travelled), travelled)
        end_xy = end[a, which]
        end_theta = curvature[a] * travelled
        c, s = math.cos(obs.pose[2]), math.sin(obs.pose[2])
        goal = np.array([c * (obs.target[0] - obs.pose[0]) + s * (obs.target[1] - obs.pose[1]),
                         -s * (obs.target[0] - obs.pose[0]) + c * (obs.target[1] - obs.pose[1])])
        to_goal = np.arctan2(goal[1] - end_xy[..., 1], goal[0] - end_xy[..., 0])
        heading = 1.0 - np.abs(wrap_angle(to_goal - end_theta)) / math.pi
        terms = np.stack([heading, dist, v / body.max_speed])
        top = np.where(admissible, terms, 0.0).reshape(3, -1).max(axis=1)
        score = np.tensordot(self.weights / np.maximum(top, 1e-9), terms, axes=1)
        best = np.unravel_index(np.argmax(np.where(admissible, score, -np.inf)), v.shape)
        return Command(float(self.steering[best[0]]), float(v[best]), "DWA")


def make(**options) -> DynamicWindow:
    """Factory of ``dwa`` (options: see :class:`DynamicWindow`)."""
    return DynamicWindow(**options)


make_tracked = tracked_variant(DynamicWindow, "dwa-tracks")
