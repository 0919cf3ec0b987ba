"""Recovery manoeuvre of the default chapter IV navigators: back out of a dead end, then turn.

The thesis' robot has no reverse gear (§IV.4) and its navigators, kept as published for
``fuzzy-5b-thesis`` / ``fuzzy-2b-thesis``, stop for good when no forward turn is free (the
safety stop of :mod:`fuzzynav.control.five_behaviours`). A car-like robot that can reverse
makes a K-turn instead, and this is that behaviour of the supervisor
(:mod:`fuzzynav.control.robust`), compiled in :mod:`fuzzynav.kernels.recovery` (this module
holds its rule base and constants):

1. **Back** (``REC-BACK``): reverse at ``v_back`` along a circular arc whose steering comes
   from a small zero-order Takagi–Sugeno rule base in the thesis' style (strong partitions,
   product T-norm, weighted sum, the steering singletons of Fig IV.7), Table ``TABLE_RECOVERY``:
   inputs ``room`` — the room on the left minus the room on the right (m) — and ``theta`` — the
   goal bearing (rad, > 0 on the left). Reversing with α > 0 swings the nose to the right
   (eq IV.1: θ̇ = V tan α / l with V < 0), so the rules swing it towards the roomier side, or
   the goal's side when both are alike, and back straight when the goal is ahead and both
   sides are alike. Every reverse step is checked against the remembered obstacle points
   (:mod:`fuzzynav.kernels.sightings`: the ring's hits and the nearest obstacle point, D_ro /
   θ_o, which the observation gives all round, so obstacles behind the robot are known without
   rear sensors); the back-up ends after ``back_distance``
   or when the next step would bring the body within ``margin`` of a point.
2. **Turn** (``REC-TURN``): forward at full lock the other way — the turn direction changed —
   until the heading has turned ``turn_angle`` or the lane ahead is free, each step checked
   the same way; then the navigator takes the robot back. A second recovery started near
   the place of the last one swings the other way.
"""

from __future__ import annotations

import math

from fuzzynav.fuzzy.constants import ALPHA_MAX
from fuzzynav.fuzzy.membership import Singleton
from fuzzynav.fuzzy.partition import strong_partition
from fuzzynav.fuzzy.rules import rules_from_grid
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.variable import Variable
from fuzzynav.kernels.layers import Recovery

# the manoeuvre's constants (their units and meaning: kernels.layers.Recovery)
RECOVERY = Recovery(v_back=0.3, back_distance=0.8, margin=0.05, v_turn=0.3, turn_angle=math.pi / 3, lane=1.5,
                    recovery_time=6.0)

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
    values = {"NG": -ALPHA_MAX, "NM": -ALPHA_MAX / 2, "Z": 0.0, "PM": ALPHA_MAX / 2, "PG": ALPHA_MAX}
    alpha = Variable("alpha", (-ALPHA_MAX, ALPHA_MAX), {k: Singleton(v) for k, v in values.items()})
    rules = rules_from_grid("room", "theta", ROOM_LABELS, GOAL_LABELS, TABLE_RECOVERY, ("alpha",),
                            columns_first=False, source="TABLE_RECOVERY")
    return FuzzySystem([room, theta], [alpha], rules, method="ts0", tnorm="product", defuzzifier="weighted_sum",
                       name="recovery", description="Back-up arc of the recovery manoeuvre (TS0, product, weighted sum)")
