"""``fuzzy-5b-thesis``: the five-behaviour navigator of thesis §IV.7 (Figs IV.16–IV.23, Tables
IV.1, IV.3–IV.6) on the seven range sensors C1…C7; with ``gap=True`` (``fuzzy-5b-gap``) on a lidar,
the navigator inside the default ``fuzzy-5b`` (:mod:`fuzzynav.control.through_gaps`).

Behaviours: GSB (Table IV.1), FOA / ROA / LOA (Tables IV.3–IV.5, steering only) and VRB
(Table IV.6), coordinated by :mod:`fuzzynav.control.supervisor`:

- GSB alone when nothing is sensed: α and V_r from Table IV.1;
- GSB towards a goal in clear view while obstacles are sensed: α from Table IV.1, V_r the
  smaller of Table IV.1's and VRB's;
- an avoider otherwise: α from FOA, ROA or LOA, V_r from VRB.

VRB implements eq IV.9, V_r(k+1) = V_r(k) + V_adjust(k), with V_r(k) the speed applied at the
previous step (:attr:`Observation.speed`) and D_min the smallest of the seven readings; the
result is kept in [``v_floor``, 4 m/s]. ``v_floor`` (default 0.3 m/s) is this package's: at
V_r = 0 near an obstacle Table IV.6 answers "no change" (AC) and a tricycle that does not move
cannot turn, so the navigator would freeze.

**Layers** (this package's, each optional: ``layers=`` names those on, keys of
:data:`fuzzynav.control.batched.LAYERS`; all by default, none in ``fuzzy-5b-thesis``): the
anti-orbit guard of goal seeking (:mod:`fuzzynav.control.goal_seeking`), the hysteresis of the
switch, the turning room and the safety stop below. Without them the supervisor's choice of
each step drives, goal seeking is Table IV.1 alone, and nothing stops the robot.

**Switching** (the part Fig IV.16 states only in words) is :func:`supervisor.select` on the
readings, with the ``hysteresis`` layer held by the switch of :mod:`~fuzzynav.control.supervisor`: more caution at once when a reading is below
d_m or the full-lock turn is needed, anything else after a dwell of ``dwell`` steps (1 s); goal seeking, once in charge, is kept under the relaxed thresholds of
:func:`supervisor.relaxed`. (Handing the robot back to goal seeking only with the goal within
45° of the heading, a literal reading of Fig IV.23's "vision interval", was tried: on 100 mixed
worlds it turned 4 successes into endless wall following.)

**Turning room** (layer ``turning_room``; the robot has no reverse, §IV.4). Slowing down does not shrink the tightest
turn (R = l / tan(π/5) = 0.69 m), so the navigator watches the room left for it
(:class:`fuzzynav.control.turning_room.TurnGuard`, on the range hits of the last second and the
sonar-cone echo of the nearest obstacle point). When the straight lane ahead is blocked within ``lane`` (default d_m = 1.5 m) and the
better of the two full-lock half turns keeps less than ``room_margin`` (0.5 m) from every hit —
both after one more step at the current speed — the front avoider turns at full lock
(α = ±π/5, the extreme FOA singletons) to that side, at ``v_floor``: on the spot of its radius.
The side is chosen when the turn starts (the roomier one; within 0.1 m, the goal's side) and
kept until the turn ends; the turn ends, after the dwell, when lane and room exceed those
thresholds by 0.5 m and 0.2 m. It is labelled ``FOA+VRB`` like the front avoider.

**Safety stop** (layer ``safety_stop``, this package's; the thesis has none). A thin wall end or a corner can hide
between the rays until the robot is too close for any turn, and in a pocket of obstacles neither
full-lock turn may be free. Then the one step left is to stop: when the body after the next step
(eq IV.2 moves it V Δt straight ahead, whatever the steering) would come within ``stop_margin``
(default 0.02 m) of a remembered hit (:func:`fuzzynav.kernels.guard.step_clearance`), V = 0. With no reverse gear
the robot stays there, and the episode ends in a timeout instead of a collision. On 100 mixed
worlds of each of the seeds 0–4 it stops in 2–3 worlds per seed (13 in all): 11 of them collide
without the stop; the other 2 pass within 1.1 cm of an obstacle and reach the goal without it, and
time out with it (README, "Measured results"). While stopped the label stays the mode's.

The state (modes, hold counts, turn sides, hits) is kept per robot in arrays, and the decision
is compiled (:func:`fuzzynav.kernels.navigators.five_behaviours`), so one robot and a batch
run the same code; :meth:`reset` clears the state.
Behaviour labels: ``GSB``, ``FOA+VRB``, ``ROA+VRB``, ``LOA+VRB``, ``GSB+VRB`` (goal seeking with
obstacles sensed, speed capped by VRB).

**Through the gaps** (this package's: ``fuzzy-5b-gap``, ``gap=True``, and inside the layers and
route guidance of the default ``fuzzy-5b``; without it the navigator is the one published, on the
seven single rays). The navigator reads the ``lidar`` ring
(:func:`fuzzynav.robot.sensors.named_ring`): d1…d7 are the nearest readings of each sensor's 30°
sector, so the supervisor and the avoiders see 15 cm posts that the seven rays miss, and the whole
scan is searched for the passage that fits the body plus ``gap_margin`` (0.05 m; where none does,
half and then a quarter of it) within ``gap_look`` (2 m) and can be turned to
(:mod:`fuzzynav.kernels.gaps`: VFH+'s enlarged obstacles and masked directions, follow-the-gap's
choice of the free direction nearest to the goal). When the supervisor would hand over to an
avoider or cap goal seeking by VRB and such a passage exists, the mode ``GAP+VRB`` takes over at
once: Table IV.1 with the passage's direction in place of the goal's bearing (the goal's distance
kept), at the speed of VRB and at most 1.5 /s × the body's clearance to the nearest reading (never
below ``v_floor``); the full-lock turn is not needed. With no passage, the thesis' avoiders, turn
and safety stop act as above.

Rule bases by role (``systems=``, defaults in brackets): ``"gsb"`` (d_rg, θ_r − θ_d) → (α, V_r)
[Table IV.1]; ``"foa"`` (d1, d2, d3) → α [Table IV.3]; ``"roa"`` (d2, d4, d6) → α [Table IV.4];
``"loa"`` (d3, d5, d7) → α [Table IV.5]; ``"vrb"`` (V_r, D_min) → V_adjust [Table IV.6].
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping

from fuzzynav.control import supervisor
from fuzzynav.control.batched import GAP_LOOK, GAP_MARGIN, LAYERS, CompiledNavigator, layer_flags, navigator_params
from fuzzynav.control.turning_room import TURN_RADIUS
from fuzzynav.fuzzy import systems_navigation as nav
from fuzzynav.fuzzy.systems import goal_seeking
from fuzzynav.kernels.navigators import FIVE_BEHAVIOURS
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.settings import LENGTH, MEMORY, ROOM, SLOW, SPEED, STEPS, checked

LABELS = ("GSB", "FOA+VRB", "ROA+VRB", "LOA+VRB", "GSB+VRB", "FOA+VRB", "GAP+VRB")  # of the mode codes (full lock: FOA)


@functools.lru_cache(maxsize=4)
def default_systems(d_m: float, d_s: float, d_max: float) -> dict:
    """Tables IV.1, IV.3–IV.6 for these distances by role (built once, shared by the navigators)."""
    return {"gsb": goal_seeking(), "foa": nav.front_avoider(d_m, d_s, d_max), "roa": nav.right_avoider(d_m, d_s, d_max),
            "loa": nav.left_avoider(d_m, d_s, d_max), "vrb": nav.velocity_reducer(d1=d_m, d2=d_s, d_max=d_max)}


class FiveBehaviourNavigator(CompiledNavigator):
    """GSB, FOA, ROA, LOA and VRB with the supervisor of Fig IV.16; roles ``"gsb"``, ``"foa"``,
    ``"roa"``, ``"loa"``, ``"vrb"`` (module docstring)."""

    name = "fuzzy-5b"
    kind, labels, roles = FIVE_BEHAVIOURS, LABELS, ("gsb", "foa", "roa", "loa", "vrb")
    sensors_deg = supervisor.THESIS_ANGLES_DEG

    @checked(d_m=LENGTH, d_s=LENGTH, d_max=LENGTH, v_floor=SLOW, v_max=SPEED, wheelbase=LENGTH, dwell=STEPS, lane=ROOM,
             room_margin=ROOM, memory=MEMORY, stop_margin=ROOM, gap_margin=ROOM, gap_look=LENGTH)
    def __init__(self, d_m: float = nav.D_M, d_s: float = nav.D_S, d_max: float = nav.D_MAX,
                 v_floor: float = 0.3, v_max: float = DEFAULT_PARAMS.max_speed,
                 params: supervisor.SupervisorParams | None = None, wheelbase: float = DEFAULT_PARAMS.wheelbase,
                 dwell: int = 10, lane: float = nav.D_M, room_margin: float = 0.5, memory: int = 10,
                 stop_margin: float = 0.02, systems: Mapping | None = None, gap: bool = False,
                 gap_margin: float = GAP_MARGIN, gap_look: float = GAP_LOOK, layers=tuple(LAYERS)):
        gaps = self._variant(gap, gap_margin, gap_look)
        self.supervisor = params or supervisor.SupervisorParams(detection=d_s, front=d_m, keep=d_m, clear=d_s)
        kept = supervisor.relaxed(self.supervisor)
        self.memory = int(memory)
        p = self.supervisor
        self._build(systems, lambda: default_systems(d_m, d_s, d_max), navigator_params(
            **layer_flags(layers), wheelbase=wheelbase, dwell=dwell, lane=lane, room_margin=room_margin, stop_margin=stop_margin,
            v_turn=v_floor, turn_radius=TURN_RADIUS, body=DEFAULT_PARAMS.radius, half_cone=math.radians(15.0),
            v_max=v_max, sensed=p.detection, front_5b=p.front, keep=p.keep, clear=p.clear, vision=p.vision,
            kept_detection=kept.detection, kept_keep=kept.keep, kept_clear=kept.clear,
            **gaps))


def make(**options) -> FiveBehaviourNavigator:
    """The navigator of Fig IV.16 as published (``fuzzy-5b-thesis`` builds it by :func:`fuzzynav.control.robust.fuzzy_5b_thesis`)."""
    return FiveBehaviourNavigator(**options)


def make_gap(**options) -> FiveBehaviourNavigator:
    """Factory of ``fuzzy-5b-gap``: the lidar ring, gap finding on (alone it regresses on mixed worlds;
    the default ``fuzzy-5b`` adds the layers and route guidance)."""
    return FiveBehaviourNavigator(gap=True, **options)
