"""The command singletons of chapter IV, shared by the goal-seeking and range-sensor systems.

α of Fig IV.7 (NG … PG = −π/5, −π/10, −π/20, 0, π/20, π/10, π/5 rad) and V_r of Fig IV.8
(Z 0, F 1, M 1.8, G 3, TG 4 m/s). Both :mod:`fuzzynav.fuzzy.systems` and
:mod:`fuzzynav.fuzzy.systems_navigation` build their outputs here, so neither imports the other's
internals.
"""

from __future__ import annotations

from fuzzynav.fuzzy.constants import ALPHA_MAX, SPEED_SINGLETONS, STEERING_SINGLETONS
from fuzzynav.fuzzy.membership import Singleton
from fuzzynav.fuzzy.variable import Variable

ANGLE7_LABELS = tuple(STEERING_SINGLETONS)  # NG … PG


def steering() -> Variable:
    """α singletons of Fig IV.7: ±π/5, ±π/10, ±π/20, 0 (rad)."""
    return Variable("alpha", (-ALPHA_MAX, ALPHA_MAX), {k: Singleton(v) for k, v in STEERING_SINGLETONS.items()})


def speed() -> Variable:
    """V_r singletons of Fig IV.8: Z 0, F 1, M 1.8, G 3, TG 4 (m/s)."""
    return Variable("v", (0.0, SPEED_SINGLETONS["TG"]), {k: Singleton(v) for k, v in SPEED_SINGLETONS.items()})
