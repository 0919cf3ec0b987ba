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
speed) until the goal leaves the circle. The guard is an optional layer (``orbit_guard`` of
:data:`fuzzynav.control.batched.LAYERS`): the published ``goal-seeking``, ``fuzzy-2b-thesis`` and
``fuzzy-5b-thesis`` run Table IV.1 alone; ``goal-seeking-guarded`` and the other navigators use it.

Rule base by role (``systems=``): ``"gsb"``, a TS0 system (d_rg, θ_r − θ_d) → (α, V_r); the
default is Table IV.1.
"""

from __future__ import annotations

import functools
from collections.abc import Mapping

import numpy as np

from fuzzynav.control.batched import CompiledNavigator, layer_flags, navigator_params
from fuzzynav.fuzzy.systems import goal_seeking
from fuzzynav.kernels.navigators import GOAL_SEEKING
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.settings import LENGTH, checked


@functools.lru_cache(maxsize=1)
def default_systems() -> dict:
    """Table IV.1 by role (built once, shared)."""
    return {"gsb": goal_seeking()}


class GuardedGoalSeeking:
    """Table IV.1 (or ``system``) on a batch, with the anti-orbit guard of the module docstring."""

    @checked(wheelbase=LENGTH)
    def __init__(self, wheelbase: float = DEFAULT_PARAMS.wheelbase, system=None):
        from fuzzynav.kernels import ts0

        self.system = system or default_systems()["gsb"]
        self.tables = ts0.pack([self.system], ["gsb"])
        self.wheelbase = float(wheelbase)

    def __call__(self, distance, bearing):
        """``(α (N,), V (N,), guard (N,) int)`` for goal distances and bearings (N,).

        ``guard`` is 0 where the table's steering is used, 1 where it was raised to the arc
        through the goal, 2 where the robot drives straight out of its turning circle.
        """
        from fuzzynav.kernels import navigators

        distance, bearing = (np.ascontiguousarray(np.asarray(v, dtype=float).reshape(-1)) for v in (distance, bearing))
        out = np.empty((len(distance), 3))
        navigators.goal_seeking_all(self.tables, 0, distance, bearing, self.wheelbase, out)
        return out[:, 0], out[:, 1], out[:, 2].astype(int)


class GoalSeekingController(CompiledNavigator):
    """``goal-seeking``: the GSB alone (Figs IV.12–IV.14); blind to obstacles. Role: ``"gsb"``."""

    name = "goal-seeking"
    kind, labels, roles = GOAL_SEEKING, ("GSB",), ("gsb",)

    @checked(wheelbase=LENGTH)
    def __init__(self, wheelbase: float = DEFAULT_PARAMS.wheelbase, systems: Mapping | None = None,
                 layers=("orbit_guard",)):
        self._build(systems, default_systems, navigator_params(wheelbase=wheelbase, **layer_flags(layers)))


def make(**options) -> GoalSeekingController:
    """Factory of the ``goal-seeking`` entry of :data:`fuzzynav.catalog.controllers.CONTROLLERS`:
    Table IV.1 as published, without the anti-orbit guard (``layers=("orbit_guard",)`` adds it)."""
    return GoalSeekingController(**{"layers": (), **options})


def make_guarded(**options) -> GoalSeekingController:
    """Factory of ``goal-seeking-guarded``: Table IV.1 with the anti-orbit guard."""
    controller = GoalSeekingController(**options)
    controller.name = "goal-seeking-guarded"
    return controller
