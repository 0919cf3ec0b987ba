"""``fuzzy-2b``: goal seeking + obstacle avoidance by distance and angle (thesis §IV.5.2.1,
Figs IV.9–IV.11, Table IV.2), the two-behaviour navigator of Fig IV.15.

Inputs of the avoider: D_ro, the clearance from the robot centre to the nearest obstacle surface
(:attr:`Observation.obstacle_distance`), and θ_o, the angle between the robot axis and that
point, fed to the table through :func:`~fuzzynav.control.base.thesis_angle_error` like θ_rg
(with the thesis' sign the table turns left when the obstacle is on the right, and steers right
with an obstacle dead ahead — rule R1 of §IV.5.2.1).

The thesis treats the robot as a point and puts a risk zone around each circular obstacle
(§IV.5.2, Fig IV.3); here D_ro is the clearance minus ``risk`` (default 0.3 m, the robot's
footprint radius), i.e. the gap between the robot's body and the obstacle, so the P set of
Fig IV.10 (fully near below 0.5 m) leaves room to turn. The workspace's boundary walls are
obstacles too: :attr:`Observation.obstacle_distance` leaves them out, so when the range ring
reads a wall nearer than D_ro, that reading and its sensor direction stand for D_ro and θ_o.

The switch of Fig IV.9 activates the avoider when an obstacle is detected "in front, on the
right or on the left" (§IV.6.2) and stands in the way: D_ro below ``detection`` (default 2 m),
the goal farther than the obstacle, and the obstacle either within ``front`` (default 45°) of
the heading, or within ``sector`` (default 90°) of the heading and of the goal direction. An
obstacle beside or behind the robot on the side away from the goal leaves the goal-seeking
behaviour of :mod:`fuzzynav.control.goal_seeking` in charge (it turns away from
such an obstacle anyway). Behaviour labels: ``GSB``, ``OA``.

**Layers** (this package's, each optional: ``layers=`` names those on, keys of
:data:`fuzzynav.control.batched.LAYERS`; all by default, none in ``fuzzy-2b-thesis``): the
anti-orbit guard of goal seeking, the hysteresis, the full-lock turn and the safety stop below.

**Hysteresis** (layer ``hysteresis``; Fig IV.9 states the switch only in words). Taken step by step that test
chatters at its edges — avoiding turns the obstacle out of the sector, goal seeking turns it
back in — and the steering jumps between the two tables every step. The switch is therefore
held by the switch of :mod:`fuzzynav.control.supervisor`: OA is taken at once, GSB only after OA
has driven ``dwell`` steps (default 10, 1 s), and OA, once active, stays wanted while D_ro is
below ``detection`` + ``release`` (default 0.5 m) and the obstacle within ``sector`` + 15° of
the heading. With the layers ``turning_room`` and ``safety_stop``, like the five-behaviour
navigators, it turns at full lock (α = ±π/5, the extreme
singletons of Table IV.2) and low speed ``v_turn`` when its turning room runs out
(:class:`fuzzynav.control.turning_room.TurnGuard`; this turn is labelled ``OA``), and it has the
same safety stop (V = 0 when the next step would bring the body within ``stop_margin`` of a
remembered hit, :mod:`fuzzynav.control.five_behaviours`). The state is one
mode per robot plus the guard's memory; :meth:`reset` clears it. The decision is compiled
(:func:`fuzzynav.kernels.navigators.two_behaviours`).

**Through the gaps** (this package's, opt-in as ``fuzzy-2b-gap``, ``gap=True``; as
``fuzzy-5b-gap``). The navigator reads the ``lidar`` ring, and when the avoider would take over and a
passage that fits the body and can be turned to exists (:mod:`fuzzynav.kernels.gaps`), the mode
``GAP`` steers by Table IV.1 towards the passage's direction at Table IV.2's speed, without the
full-lock turn.

Rule bases by role (``systems=``): ``"gsb"`` (d_rg, θ_r − θ_d) → (α, V_r) [Table IV.1] and
``"oab"`` (D_ro, θ_o) → (α, V_r) [Table IV.2, the obstacle-avoidance behaviour of Fig IV.9].
"""

from __future__ import annotations

import functools
import math
from collections.abc import Mapping

from fuzzynav.control.batched import GAP_LOOK, GAP_MARGIN, LAYERS, CompiledNavigator, layer_flags, navigator_params
from fuzzynav.control.turning_room import TURN_RADIUS
from fuzzynav.fuzzy.systems import goal_seeking, obstacle_avoidance
from fuzzynav.kernels.navigators import TWO_BEHAVIOURS
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.settings import LENGTH, ROOM, SPEED, SPREAD, STEPS, checked


@functools.lru_cache(maxsize=1)
def default_systems() -> dict:
    """Tables IV.1 and IV.2 by role (built once, shared by the navigators)."""
    return {"gsb": goal_seeking(), "oab": obstacle_avoidance()}


class TwoBehaviourNavigator(CompiledNavigator):
    """GSB (Table IV.1) and OA (Table IV.2) with the switch of Fig IV.9; roles ``"gsb"``, ``"oab"``."""

    name = "fuzzy-2b"
    kind, labels, roles, memory = TWO_BEHAVIOURS, ("GSB", "OA", "OA", "GAP"), ("gsb", "oab"), 10

    @checked(detection=LENGTH, sector=SPREAD, front=SPREAD, risk=ROOM, wheelbase=LENGTH, dwell=STEPS, release=ROOM,
             lane=ROOM, room_margin=ROOM, v_turn=SPEED, stop_margin=ROOM, gap_margin=ROOM, gap_look=LENGTH)
    def __init__(self, detection: float = 2.0, sector: float = math.pi / 2, front: float = math.pi / 4,
                 risk: float = 0.3, wheelbase: float = DEFAULT_PARAMS.wheelbase, dwell: int = 10,
                 release: float = 0.5, lane: float = 1.5, room_margin: float = 0.5, v_turn: float = 0.3,
                 stop_margin: float = 0.02, systems: Mapping | None = None, gap: bool = False,
                 gap_margin: float = GAP_MARGIN, gap_look: float = GAP_LOOK, layers=tuple(LAYERS)):
        gaps = self._variant(gap, gap_margin, gap_look)
        self._build(systems, default_systems, navigator_params(**layer_flags(layers),
            wheelbase=wheelbase, dwell=dwell, lane=lane, room_margin=room_margin, stop_margin=stop_margin,
            v_turn=v_turn, turn_radius=TURN_RADIUS, body=DEFAULT_PARAMS.radius, half_cone=math.radians(15.0),
            detection=detection, sector=sector, front=front, risk=risk, release=release,
            **gaps))


def make(**options) -> TwoBehaviourNavigator:
    """Factory of the ``fuzzy-2b`` entry of :data:`fuzzynav.catalog.controllers.CONTROLLERS`."""
    return TwoBehaviourNavigator(**options)


def make_gap(**options) -> TwoBehaviourNavigator:
    """Factory of ``fuzzy-2b-gap``: the lidar ring, gap finding on (opt-in: it regresses on mixed worlds)."""
    return TwoBehaviourNavigator(gap=True, **options)
