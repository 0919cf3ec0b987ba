"""Goal-seeking behaviour GSB (thesis §IV.5.1, Figs IV.4–IV.8, Table IV.1) and the ``goal-seeking``
controller (Figs IV.12–IV.14).

The table reads d_rg (eq IV.6) and θ_rg; the sign problem of the angle error (docs/thesis.md) is solved by
:func:`~fuzzynav.control.base.thesis_angle_error`, which feeds it θ_r − θ_d.

**Orbiting** (thesis §IV.5.1). Table IV.1 alone can circle a goal it comes close to: near the goal
its steering is small (PM, PP in the Z column: turning radii of 1.5 m and more) while the speed
F = 1 m/s of the P column never falls enough, so the robot passes beside the goal and circles it.
A goal at distance d and bearing β is hit by the forward arc of steering
α_arc = atan(2 l sin β / d) (eq IV.1: radius r = d / (2 |sin β|) = l / tan |α|).
:class:`GuardedGoalSeeking` keeps the table's command unless it steers less than that arc: then it
steers α_arc; and when even the tightest turn α_max = π/5 is too wide (the goal inside the
turning circle, r < l / tan(π/5) = 0.69 m for l = 0.5 m) it drives straight (α = 0, the table's
speed) until the goal leaves the circle. Every navigator of this package uses this guarded GSB.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.control.base import thesis_angle_error
from fuzzynav.control.batched import BatchedController, evaluate
from fuzzynav.fuzzy.systems import goal_seeking
from fuzzynav.robot.tricycle import DEFAULT_PARAMS

ALPHA_MAX = math.pi / 5  # largest steering singleton of Fig IV.7


class GuardedGoalSeeking:
    """Table IV.1 on a batch, with the anti-orbit guard of the module docstring."""

    def __init__(self, wheelbase: float = DEFAULT_PARAMS.wheelbase):
        self.system = goal_seeking()
        self.wheelbase = float(wheelbase)

    def __call__(self, distance, bearing):
        """``(α (N,), V (N,), guard (N,) int)`` for goal distances and bearings (N,).

        ``guard`` is 0 where the table's steering is used, 1 where it was raised to the arc
        through the goal, 2 where the robot drives straight out of its turning circle.
        """
        distance = np.asarray(distance, dtype=float)
        bearing = np.asarray(bearing, dtype=float)
        if len(distance) == 1:  # one robot: the same formulas on floats (np.arctan keeps its rounding)
            d, b = float(distance[0]), float(bearing[0])
            table, speed = self.system.evaluate_one(d, thesis_angle_error(b))
            arc = float(np.arctan(2.0 * self.wheelbase * math.sin(b) / max(d, 1e-9)))
            guard = 2 if abs(arc) > ALPHA_MAX else (1 if abs(table) < abs(arc) else 0)
            return np.array([(table, arc, 0.0)[guard]]), np.array([speed]), np.array([guard])
        out = evaluate(self.system, np.column_stack([distance, thesis_angle_error(bearing)]))
        table = out[:, 0]
        arc = np.arctan(2.0 * self.wheelbase * np.sin(bearing) / np.maximum(distance, 1e-9))
        guard = np.where(np.abs(arc) > ALPHA_MAX, 2, np.where(np.abs(table) < np.abs(arc), 1, 0))
        steering = np.choose(guard, [table, arc, np.zeros_like(arc)])
        return steering, out[:, 1], guard


class GoalSeekingController(BatchedController):
    """``goal-seeking``: the GSB alone (Figs IV.12–IV.14); blind to obstacles."""

    name = "goal-seeking"

    def __init__(self, wheelbase: float = DEFAULT_PARAMS.wheelbase):
        self.gsb = GuardedGoalSeeking(wheelbase)

    def act_batch(self, obs):
        steering, speed, _ = self.gsb(obs.target_distance, obs.target_bearing)
        return steering, speed, np.full(len(steering), "GSB")


def make(**options) -> GoalSeekingController:
    """Factory of the ``goal-seeking`` entry of :data:`fuzzynav.control.registry.CONTROLLERS`."""
    return GoalSeekingController(**options)
