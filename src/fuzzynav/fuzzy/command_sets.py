"""The command singletons of chapter IV, shared by the goal-seeking and range-sensor systems.

α of Fig IV.7 (NG … PG = −π/5, −π/10, −π/20, 0, π/20, π/10, π/5 rad) and V_r of Fig IV.8
(Z 0, F 1, M 1.8, G 3, TG 4 m/s). Both :mod:`fuzzynav.fuzzy.systems` and
:mod:`fuzzynav.fuzzy.systems_navigation` build their outputs here, so neither imports the other's
internals.
"""

from __future__ import annotations

import math

from fuzzynav.fuzzy.membership import Singleton
from fuzzynav.fuzzy.variable import Variable

PI = math.pi
ANGLE7_LABELS = ("NG", "NM", "NP", "Z", "PP", "PM", "PG")


def steering() -> Variable:
    """α singletons of Fig IV.7: ±π/5, ±π/10, ±π/20, 0 (rad)."""
    values = (-PI / 5, -PI / 10, -PI / 20, 0.0, PI / 20, PI / 10, PI / 5)
    return Variable("alpha", (-PI / 5, PI / 5), {k: Singleton(v) for k, v in zip(ANGLE7_LABELS, values)})


def speed() -> Variable:
    """V_r singletons of Fig IV.8: Z 0, F 1, M 1.8, G 3, TG 4 (m/s)."""
    values = {"Z": 0.0, "F": 1.0, "M": 1.8, "G": 3.0, "TG": 4.0}
    return Variable("v", (0.0, 4.0), {k: Singleton(v) for k, v in values.items()})
