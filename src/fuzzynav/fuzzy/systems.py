"""The thesis' fuzzy systems, ready-made (thesis §IV.5.1, §IV.5.2.1, §V.3.1).

All three are zero-order Takagi–Sugeno systems with strong triangular/trapezoidal input
partitions, product T-norm (eq IV.5) and weighted-sum output (eq IV.4). The rule grids below are
typed cell by cell as printed (rows × columns); the sign problem of the angle error (docs/thesis.md) is *not* solved
here but in :func:`fuzzynav.control.base.thesis_angle_error`, which feeds the tables
θ_r − θ_d.

Universes (the thesis gives peaks, not always the axis ends):

- angles (θ_rg, θ_o, θ_er, dθ_er): (−π, π), the range of a wrapped angle. Fig IV.6 draws the
  θ_rg axis only to ±1.6 rad, but NG/PG are shoulders, flat beyond ±1.5, so clamping to ±1.6 or
  to ±π gives identical outputs; ±π is used because the input is a wrapped angle.
- d_rg: (0, D_max) with D_max = 20√2 m, the diagonal of the 20 m × 20 m workspace (Fig IV.5
  marks "Dmax" at the end of the TG shoulder without a value).
- D_ro: (0, 4) m, the sensor range (docs/ARCHITECTURE.md); G is flat beyond 4 m anyway.
"""

from __future__ import annotations

import math

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.command_sets import ANGLE7_LABELS, speed, steering
from fuzzynav.fuzzy.membership import Singleton, Trapezoidal
from fuzzynav.fuzzy.partition import strong_partition
from fuzzynav.fuzzy.rules import rules_from_grid
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.systems_navigation import SYSTEMS as _NAVIGATION_SYSTEMS
from fuzzynav.fuzzy.variable import Variable

PI = math.pi
D_MAX_GOAL = 20.0 * math.sqrt(2.0)
ANGLE_UNIVERSE = (-PI, PI)

# Figs IV.6, IV.11: θ_rg and θ_o, seven sets (labels as the α singletons of Fig IV.7)
ANGLE7_PEAKS = (-1.5, -0.75, -0.25, 0.0, 0.25, 0.75, 1.5)


def _angle7(name: str) -> Variable:
    return Variable(name, ANGLE_UNIVERSE, strong_partition(ANGLE7_PEAKS, ANGLE7_LABELS, ANGLE_UNIVERSE))


# Table IV.1 — rows θ_rg (NG … PG), columns d_rg (Z P M G TG), cells α / V_r, as printed.
TABLE_IV_1 = (
    "PM/Z PG/F PM/F PM/F PM/F",  # NG
    "PP/Z PG/F PM/F PP/M PM/M",  # NM
    "Z/Z  PM/F PP/M PP/G PP/G",  # NP
    "Z/Z  Z/F  Z/M  Z/G  Z/TG",  # Z
    "Z/Z  NM/F NM/M NP/G NP/G",  # PP
    "NP/Z NG/F NG/F NP/M NM/M",  # PM
    "NM/Z NG/F NG/F NM/F NM/F",  # PG
)


def goal_seeking() -> FuzzySystem:
    """Goal-seeking behaviour (GSB), §IV.5.1, Figs IV.4–IV.8, Table IV.1 (35 rules), eqs IV.3–IV.5.

    Inputs ``drg`` (d_rg, m: Z P M G TG peaking at 0.1, 3.5, 8, 13, 18, Fig IV.5) and ``theta``
    (θ_rg, rad: seven sets peaking at ±1.5, ±0.75, ±0.25, 0, Fig IV.6); outputs ``alpha``
    (steering, Fig IV.7) and ``v`` (speed, Fig IV.8).
    """
    drg_labels = ("Z", "P", "M", "G", "TG")
    drg = Variable("drg", (0.0, D_MAX_GOAL), strong_partition((0.1, 3.5, 8.0, 13.0, 18.0), drg_labels,
                                                               (0.0, D_MAX_GOAL)))
    theta = _angle7("theta")
    rules = rules_from_grid("theta", "drg", ANGLE7_LABELS, drg_labels, TABLE_IV_1, ("alpha", "v"),
                            source="Table IV.1")
    return FuzzySystem([drg, theta], [steering(), speed()], rules, method="ts0", tnorm="product",
                       defuzzifier="weighted_sum", name="goal-seeking",
                       description="Goal seeking, thesis §IV.5.1, Table IV.1 (TS0, product, weighted sum)")


# Table IV.2 — rows θ_o (NG … PG), columns D_ro (P M G), cells α / V_r. The extraction scrambled
# the printed table; this is the mirror-symmetric reconstruction of thesis §IV.5.2.1, which keeps the
# surviving rows NG and NM verbatim and matches the scrambled fragments of rows NP…PG.
TABLE_IV_2 = (
    "NM/F NP/M Z/M",  # NG
    "NM/F NM/M Z/M",  # NM
    "NG/F NM/M Z/M",  # NP
    "NG/F NG/M Z/M",  # Z
    "PG/F PM/M Z/M",  # PP
    "PM/F PM/M Z/M",  # PM
    "PM/F PP/M Z/M",  # PG
)


def obstacle_avoidance() -> FuzzySystem:
    """Obstacle avoidance by distance and angle, §IV.5.2.1, Figs IV.9–IV.11, Table IV.2 (21 rules).

    Inputs ``dro`` (D_ro, m: P = [0, 0, 0.5, 1], M = [0.5, 1, 2.8, 4], G = [2.8, 4, ∞), Fig IV.10)
    and ``theta_o`` (θ_o, rad: the seven sets of Fig IV.6, Fig IV.11); outputs ``alpha`` and ``v``
    as for goal seeking. Table IV.2 is the reconstruction of §IV.5.2.1 (see ``TABLE_IV_2``).
    """
    dro = Variable("dro", (0.0, 4.0), {
        "P": Trapezoidal(0.0, 0.0, 0.5, 1.0),
        "M": Trapezoidal(0.5, 1.0, 2.8, 4.0),
        "G": Trapezoidal(2.8, 4.0, math.inf, math.inf),
    })
    theta_o = _angle7("theta_o")
    rules = rules_from_grid("theta_o", "dro", ANGLE7_LABELS, ("P", "M", "G"), TABLE_IV_2, ("alpha", "v"),
                            source="Table IV.2")
    return FuzzySystem([dro, theta_o], [steering(), speed()], rules, method="ts0", tnorm="product",
                       defuzzifier="weighted_sum", name="obstacle-avoidance",
                       description="Obstacle avoidance by distance and angle, thesis §IV.5.2.1, "
                                   "Table IV.2 as reconstructed (TS0, product, weighted sum)")


# Table V.1 — rows θ_er (NG NM Z PM PG), columns dθ_er (NG NM Z PM PG), cells α, as printed.
TABLE_V_1 = (
    "PG PG PG PM Z",  # NG
    "PG PG PM Z NM",  # NM
    "PG PM Z NM NG",  # Z
    "PM Z NM NG NG",  # PM
    "Z NM NG NG NG",  # PG
)


def tracking() -> FuzzySystem:
    """Fuzzy trajectory tracker, §V.3.1, Figs V.3–V.7, Table V.1 (25 rules).

    Inputs ``theta_er`` (θ_er, Fig V.4) and ``dtheta_er`` (its change per step, Fig V.5), each
    NG NM Z PM PG peaking at −π/2, −π/6, 0, π/6, π/2 with shoulders to ±π; output ``alpha``
    singletons NG −π/4, NM −π/8, Z 0, PM π/8, PG π/4 (Fig V.6). Fig V.7 is its control surface.
    """
    labels = ("NG", "NM", "Z", "PM", "PG")
    peaks = (-PI / 2, -PI / 6, 0.0, PI / 6, PI / 2)
    theta_er = Variable("theta_er", ANGLE_UNIVERSE, strong_partition(peaks, labels, ANGLE_UNIVERSE))
    dtheta_er = Variable("dtheta_er", ANGLE_UNIVERSE, strong_partition(peaks, labels, ANGLE_UNIVERSE))
    alpha = Variable("alpha", (-PI / 4, PI / 4),
                     {k: Singleton(v) for k, v in zip(labels, (-PI / 4, -PI / 8, 0.0, PI / 8, PI / 4))})
    rules = rules_from_grid("theta_er", "dtheta_er", labels, labels, TABLE_V_1, ("alpha",),
                            columns_first=False, source="Table V.1")
    return FuzzySystem([theta_er, dtheta_er], [alpha], rules, method="ts0", tnorm="product",
                       defuzzifier="weighted_sum", name="tracking",
                       description="Fuzzy trajectory tracker, thesis §V.3.1, Table V.1 (TS0, product, weighted sum)")


SYSTEMS = {
    "goal-seeking": goal_seeking,
    "obstacle-avoidance": obstacle_avoidance,
    "tracking": tracking,
}

# The range-sensor systems of §IV.7 and §VI.5.3.1 (FOA, ROA, LOA, VRB, wall follower) live in
# their own module; registered here so every built-in system is found by name.
SYSTEMS.update(_NAVIGATION_SYSTEMS)


def get_system(name: str) -> FuzzySystem:
    """A new instance of the built-in system ``name`` (one of :data:`SYSTEMS`)."""
    try:
        return SYSTEMS[name]()
    except KeyError:
        raise InputError(f"unknown fuzzy system {name!r} (built-in: {', '.join(SYSTEMS)})", field="name") from None
