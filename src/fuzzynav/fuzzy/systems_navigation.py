"""The thesis' range-sensor fuzzy systems: FOA, ROA, LOA, VRB (§IV.7) and the wall follower (§VI.5.3.1).

All are zero-order Takagi–Sugeno systems with strong input partitions, product T-norm (eq IV.5)
and weighted-sum output (eq IV.4), like those of :mod:`fuzzynav.fuzzy.systems`. The printed
tables (IV.3–IV.6, VI.2) were scrambled by the text extraction; the surviving fragments are
quoted next to each table. Each table below is typed in the printed layout, and every cell that differs
from the fragment is listed next to it with the reason (the principle the thesis states for the
module). Universes and breakpoints the thesis leaves symbolic are fixed here:

- Fig IV.18 (distance d_i, sets P "near" / L "far"): P = 1 up to ``d_m``, falls linearly to 0 at
  ``d_s``; L = 1 − P, up to the sensor range ``d_max``. Defaults d_m = 1.5 m, d_s = 3.0 m,
  d_max = 4.0 m (the sensor range of docs/ARCHITECTURE.md). d_m leaves, beyond the 0.3 m body
  radius, about one tightest-turn radius l / tan(π/5) = 0.69 m plus a margin for the 30° gaps
  between rays; measured on generated worlds, (1.0, 2.0) m and (1.2, 2.4) m collide 2–3 times
  as often and (2.0, 3.5) m starts to time out (tight passages read as blocked).
- Fig IV.19 (current speed V_r: F, M, G): triangles peaking at v1 = 0.5, v2 = 1.0, v3 = 2.0 m/s,
  F a left shoulder, G a right shoulder up to v_max = 4 m/s. Fig IV.20 (D_min: P, L): the
  distance partition above with d1 = d_m, d2 = d_s. With Table IV.6 the speed settles near v1
  with an obstacle near (D_min P) and near v2 with obstacles sensed but far (D_min L).
- Fig VI.17 / VI.25 / VI.26 (wall follower): P / L with d_m = 0.9 m, d_s = 1.6 m, range 4 m;
  speeds Z 0, P v1 = 0.6, M v2 = 1.2 m/s; α the seven singletons of Fig IV.7.
"""

from __future__ import annotations

from fuzzynav.errors import InputError
from fuzzynav.fuzzy.command_sets import steering
from fuzzynav.fuzzy.membership import Singleton
from fuzzynav.fuzzy.partition import strong_partition
from fuzzynav.fuzzy.rules import Rule
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.variable import Variable
from fuzzynav.settings import LENGTH, SPEED, checked

D_M = 1.5  # d_m, Fig IV.18 (m)
D_S = 3.0  # d_s, Fig IV.18 (m)
D_MAX = 4.0  # d_max, the sensor range (m)
V_BREAKS = (0.5, 1.0, 2.0, 4.0)  # v1, v2, v3, v_max of Fig IV.19 (m/s)
WALL_D_M, WALL_D_S = 0.9, 1.6  # d_m, d_s of the wall follower (Fig VI.17), m
WALL_V1, WALL_V2 = 0.6, 1.2  # P and M speed singletons of Fig VI.26 (m/s)

NEAR_FAR = ("P", "L")


def distance_variable(name: str, d_m: float = D_M, d_s: float = D_S, d_max: float = D_MAX) -> Variable:
    """A range reading with P (near) and L (far), Fig IV.18: P = 1 below d_m, 0 beyond d_s."""
    if not 0.0 < d_m < d_s <= d_max:
        raise InputError(f"need 0 < d_m < d_s <= d_max, got {d_m}, {d_s}, {d_max}", field="d_m, d_s, d_max")
    return Variable(name, (0.0, d_max), strong_partition((d_m, d_s), NEAR_FAR, (0.0, d_max)))


def _three_distance_rules(names, table, outputs) -> list[Rule]:
    """Rules of a 2 × 2 × 2 table printed as columns ``names[2]`` = P | L and rows ``names[1]`` ∈
    {P, P, L, L} × ``names[0]`` ∈ {P, L, P, L} (the layout of Tables IV.3–IV.5): ``table`` maps
    the column label to its four cells, top to bottom, one label per output joined by ``/``."""
    first, second, column = names
    rows = [(b, a) for b in NEAR_FAR for a in NEAR_FAR]  # (second, first), top to bottom
    rules = []
    for col_label, cells in table.items():
        for (b, a), cell in zip(rows, cells.split()):
            rules.append(Rule(((first, a), (second, b), (column, col_label)), tuple(zip(outputs, cell.split("/")))))
    return rules


def _avoider(names, table, name, description, d_m, d_s, d_max) -> FuzzySystem:
    inputs = [distance_variable(n, d_m, d_s, d_max) for n in names]
    return FuzzySystem(inputs, [steering()], _three_distance_rules(names, table, ("alpha",)), method="ts0",
                       tnorm="product", defuzzifier="weighted_sum", name=name, description=description)


# Table IV.3 — FOA (module 1: d1 ahead, d2 front-right, d3 front-left). Fragment as extracted:
#   d3 = P: NG NM NG Z      d3 = L: NG NM PG PG
# rows top to bottom (d2, d1) = (P,P) (P,L) (L,P) (L,L). Cells changed from the fragment:
#   (d2 P, d1 L, d3 P): NM -> Z   both front diagonals near, the front free: a corridor, go
#                                 straight (turning right would aim at the right-hand obstacle);
#   (d2 P, d1 P, d3 L): NG -> PG  front and right near, left free: turn left ("turn left if the
#                                 obstacle is on the right", §IV.5.2.1);
#   (d2 P, d1 L, d3 L): NM -> PM  only the front-right near: veer left, mirror of the same
#                                 principle;
#   (d2 L, d1 L, d3 L): PG -> Z   nothing near: no avoidance steering.
# Kept: (P,P,P) NG — blocked all round, hard right as rule R1 of §IV.5.2.1 says; (L,P,P) NG —
# front and left near, turn right; (L,L,P) Z — only the front-left diagonal near, LOA's business;
# (L,P,L) PG — the front alone near, hard left as printed.
TABLE_IV_3 = {"P": "NG Z NG Z", "L": "PG PM PG Z"}

# Table IV.4 — ROA (module 2: d2 at −30°, d4 at −60°, d6 at −90°). Fragment as extracted:
#   d6 = P: PM Z PM Z       d6 = L: PG PM PG PM
# rows (d4, d2) = (P,P) (P,L) (L,P) (L,L). Always ≥ 0: an obstacle on the right turns the robot
# left. Read with this layout, the steering depends on d2 and d6 only: a wall alongside (d6 near,
# d2 far) is followed straight (Z), an obstacle coming up ahead-right (d2 near) turns the robot
# more when the side is still free (PG) than when it already runs along it (PM). One cell changed:
#   (d4 L, d2 L, d6 L): PM -> Z   nothing near: no avoidance steering (as FOA's all-far cell).
TABLE_IV_4 = {"P": "PM Z PM Z", "L": "PG PM PG Z"}

# Table IV.5 — LOA (module 3: d3 at +30°, d5 at +60°, d7 at +90°). The fragment (thesis §IV.7:
# "NM NM NG NM … Z NM", 5 NM, 2 NG, 1 Z among the legible cells) is the mirror of ROA up to one
# cell; the mirror image of Table IV.4 above is used (≤ 0: an obstacle on the left turns the
# robot right), so the left and right avoiders are symmetric.
TABLE_IV_5 = {"P": "NM Z NM Z", "L": "NG NM NG Z"}


def front_avoider(d_m: float = D_M, d_s: float = D_S, d_max: float = D_MAX) -> FuzzySystem:
    """Front obstacle avoider FOA, §IV.7, Figs IV.16–IV.18, Table IV.3 (8 rules).

    Inputs ``d1`` (ahead), ``d2`` (front-right), ``d3`` (front-left), each P / L (Fig IV.18);
    output ``alpha`` (Fig IV.7). See ``TABLE_IV_3`` for the reconstructed cells.
    """
    return _avoider(("d1", "d2", "d3"), TABLE_IV_3, "foa", "Front obstacle avoider, thesis §IV.7, Table IV.3 "
                    "as reconstructed (TS0, product, weighted sum)", d_m, d_s, d_max)


def right_avoider(d_m: float = D_M, d_s: float = D_S, d_max: float = D_MAX) -> FuzzySystem:
    """Right obstacle avoider ROA, §IV.7, Table IV.4 (8 rules): inputs ``d2``, ``d4``, ``d6``."""
    return _avoider(("d2", "d4", "d6"), TABLE_IV_4, "roa", "Right obstacle avoider, thesis §IV.7, Table IV.4 "
                    "(TS0, product, weighted sum)", d_m, d_s, d_max)


def left_avoider(d_m: float = D_M, d_s: float = D_S, d_max: float = D_MAX) -> FuzzySystem:
    """Left obstacle avoider LOA, §IV.7, Table IV.5 (8 rules): inputs ``d3``, ``d5``, ``d7``."""
    return _avoider(("d3", "d5", "d7"), TABLE_IV_5, "loa", "Left obstacle avoider, thesis §IV.7, Table IV.5 "
                    "(mirror of Table IV.4; TS0, product, weighted sum)", d_m, d_s, d_max)


# Table IV.6 — VRB, decoded unambiguously (thesis §IV.7): rows D_min, columns V_r = F M G.
TABLE_IV_6 = {"P": ("AC", "D", "DI"), "L": ("A", "AC", "DI")}


def velocity_reducer(v_breaks=V_BREAKS, d1: float = D_M, d2: float = D_S, d_max: float = D_MAX) -> FuzzySystem:
    """Velocity reducing behaviour VRB, §IV.7, Figs IV.19–IV.21, Table IV.6 (6 rules), eq IV.9.

    Inputs ``v`` (current speed V_r: F, M, G peaking at v1, v2, v3, universe (0, v_max)) and
    ``dmin`` (D_min: P, L with breakpoints d1, d2); output ``v_adjust`` singletons DI −0.8,
    D −0.5, AC 0, A +0.5, AI +0.8 m/s. The navigator applies V_r(k+1) = V_r(k) + V_adjust(k).
    """
    v1, v2, v3, v_max = v_breaks
    speed = Variable("v", (0.0, v_max), strong_partition((v1, v2, v3), ("F", "M", "G"), (0.0, v_max)))
    dmin = distance_variable("dmin", d1, d2, d_max)
    adjust = Variable("v_adjust", (-0.8, 0.8), {k: Singleton(x) for k, x in
                                                 (("DI", -0.8), ("D", -0.5), ("AC", 0.0), ("A", 0.5), ("AI", 0.8))})
    rules = [Rule((("v", v), ("dmin", d)), (("v_adjust", out),))
             for d, row in TABLE_IV_6.items() for v, out in zip(("F", "M", "G"), row)]
    return FuzzySystem([speed, dmin], [adjust], rules, method="ts0", tnorm="product", defuzzifier="weighted_sum",
                       name="vrb", description="Velocity reducing behaviour, thesis §IV.7, Table IV.6, eq IV.9 "
                                               "(TS0, product, weighted sum)")


# Table VI.2 — hand-made wall follower: inputs d_d (right, −90°), d_f (front), d_g (left, +90°).
# Fragment as extracted (thesis §VI.5.3): "NG Z PG Z | NP PG M | Z Z PG M | NM M PP P", read as
# columns d_g = P | L, rows (d_d, d_f) = (P,P) (P,L) (L,P) (L,L), each cell α / V_r:
#   (P,P): NG/Z  PG/Z    (P,L): NP/·  PG/M    (L,P): Z/Z  PG/M    (L,L): NM/M  PP/P
# The last row fixes the followed side — the LEFT wall: too close to it (d_g P) turn right
# (NM), lost (d_g L) turn back left slowly (PP/P). Cells changed or filled:
#   (d_d P, d_f L, d_g P): NP/· -> NP/M  the speed token is missing; M as in the corridor cells;
#   (d_d P, d_f P, d_g P): NG/Z -> NG/P  and (d_d P, d_f P, d_g L): PG/Z -> PG/P — a tricycle
#                          at V = 0 cannot turn, so Z freezes it in front of the wall; P keeps
#                          the printed turn alive at the slow speed;
#   (d_d L, d_f P, d_g P): Z/Z -> NG/P   wall ahead and on the followed side (an inner corner):
#                          turn away from it, slowly ("turn away when the front is near").
# The follower reads only three rays (0°, ±90°), as §VI.5.3.1 says ("distances in the three
# directions"): nothing sees a corner between the rays, which is how it meets the sharp corners
# of Fig VI.28 — the failure the thesis reports and the QLF optimisation later removes.
TABLE_VI_2 = {"P": "NG/P NP/M NG/P NM/M", "L": "PG/P PG/M PG/M PP/P"}


@checked(d_m=LENGTH, d_s=LENGTH, d_max=LENGTH, v1=SPEED, v2=SPEED)
def wall_follower(d_m: float = WALL_D_M, d_s: float = WALL_D_S, d_max: float = D_MAX,
                  v1: float = WALL_V1, v2: float = WALL_V2) -> FuzzySystem:
    """Hand-made fuzzy wall follower, §VI.5.3.1, Figs VI.17, VI.25–VI.26, Table VI.2 (8 rules).

    Inputs ``dd`` (right), ``df`` (front), ``dg`` (left), each P / L; outputs ``alpha`` (seven
    singletons, Fig VI.25) and ``v`` (Z 0, P v1, M v2, Fig VI.26). See ``TABLE_VI_2``.
    """
    inputs = [distance_variable(n, d_m, d_s, d_max) for n in ("dd", "df", "dg")]
    speed = Variable("v", (0.0, v2), {"Z": Singleton(0.0), "P": Singleton(v1), "M": Singleton(v2)})
    rules = _three_distance_rules(("df", "dd", "dg"), TABLE_VI_2, ("alpha", "v"))
    return FuzzySystem(inputs, [steering(), speed], rules, method="ts0", tnorm="product", defuzzifier="weighted_sum",
                       name="wall-follow", description="Hand-made wall follower, thesis §VI.5.3.1, Table VI.2 "
                                                       "as reconstructed (TS0, product, weighted sum)")


SYSTEMS = {
    "foa": front_avoider,
    "roa": right_avoider,
    "loa": left_avoider,
    "vrb": velocity_reducer,
    "wall-follow": wall_follower,
}

__all__ = ["D_M", "D_S", "D_MAX", "SYSTEMS", "distance_variable", "front_avoider", "left_avoider",
           "right_avoider", "velocity_reducer", "wall_follower"]
