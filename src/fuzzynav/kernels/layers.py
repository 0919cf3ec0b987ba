"""Array layout of the recovery and loop-escape layers of the default navigators, the route guidance and the pace
of ``fuzzy-5b`` (kernels :mod:`~fuzzynav.kernels.recovery`, :mod:`~fuzzynav.kernels.escape`,
:mod:`~fuzzynav.kernels.guidance`, :mod:`~fuzzynav.kernels.pace`, :mod:`~fuzzynav.kernels.robust`; controller
:mod:`fuzzynav.control.robust`), generated from one dataclass per layer.

The layers travel as two float arrays (two arguments of the compiled step; each costs time at a call):

- ``params``: the fields of :data:`PARAMETERS` — :class:`Supervisor`, :class:`Body`, :class:`Recovery`, :class:`Loop`,
  :class:`Follow`, :class:`Guidance`, :class:`Pace`, :class:`Latency`, :class:`Slots`, in that order (a layer not
  given is off: all its fields 0) —, then from :data:`TABLES_AT` the recovery's rule base
  (:func:`fuzzynav.kernels.ts0.pack`). :func:`pack` writes them;
- ``state`` (N, …), one row per robot: the fields of :class:`RobotState` (a new episode's values:
  :data:`NEW_EPISODE`), then the loop detector's ring buffer of sampled places (``places_slots`` ×
  (t, x, y)), the commands sent and not yet applied (``delay`` × (α, V), the latency
  compensation's), the car route kept for reuse (``route_slots`` × (x, y, θ, primitive)), the
  obstacle points seen (``points_slots`` × (x, y)) and the hash set of their cells
  (``cell_slots``, :mod:`fuzzynav.kernels.sightings`) — views of the row by :mod:`fuzzynav.kernels.row_blocks`.

The kernels read a field by name at its position, ``params[PARAM.v_back]``, ``row[STATE.phase]``: :data:`PARAM` and
:data:`STATE` are named tuples of those positions, which numba reads as compile-time constants. A field's docstring
gives its unit. A compiled navigator without layers passes :func:`none` (``params[PARAM.on]`` = 0).
"""

from __future__ import annotations

import math
from collections import namedtuple
from dataclasses import dataclass, fields
from typing import Any

import numpy as np


@dataclass(frozen=True, kw_only=True)
class Supervisor:
    """Which layers run (1.0: on) round the navigator (:mod:`fuzzynav.kernels.robust`)."""

    on: float
    """1: the layers run (0: a navigator without layers, :func:`none`)"""
    recovery: float
    """1: the recovery manoeuvre runs"""
    escape: float
    """1: the loop escape runs"""
    stop_wait: float
    """s: the safety stop holding the robot away from its goal this long starts a recovery"""
    n_labels: float
    """the count of the navigator's own behaviour labels (the layers' labels follow them)"""
    forget: float = 0.0
    """1: the scans clear the remembered points they contradict (moving obstacles: kernels.clearing)"""


@dataclass(frozen=True, kw_only=True)
class Body:
    """The robot's size and limits the layers read (the scenario's ``robot:``, set by ``for_robot``)."""

    radius: float
    """m: the body's radius"""
    max_reverse_speed: float
    """m/s: the reverse speed limit (0: the robot cannot back up)"""
    wheelbase: float
    """m: the tricycle's wheelbase l (eq IV.1)"""
    max_speed: float
    """m/s: the top speed"""


@dataclass(frozen=True, kw_only=True)
class Recovery:
    """The recovery manoeuvre (:mod:`fuzzynav.kernels.recovery`, :mod:`fuzzynav.control.recovery`)."""

    v_back: float
    """m/s: the backing speed"""
    back_distance: float
    """m: the longest back-up"""
    margin: float
    """m: the room kept from every remembered obstacle point"""
    v_turn: float
    """m/s: the speed of the turn at full lock"""
    turn_angle: float
    """rad: the turn ends after this change of heading (or with the lane free)"""
    lane: float
    """m: the rays within ±31° reading this much free end the turn"""
    recovery_time: float
    """s: the longest manoeuvre"""
    barrier: float = 0.0
    """share of the body's gap to the nearest point a step within ``margin`` may close (0: none)"""
    barrier_within: float = 0.0
    """m: the barrier holds only while a back-up has covered less than this, not in the turn (0: throughout)"""


@dataclass(frozen=True, kw_only=True)
class Loop:
    """The loop detector of the loop escape (:mod:`fuzzynav.kernels.escape`, :mod:`fuzzynav.control.escape`)."""

    revisit: float
    """m: back this near a place passed before counts as a lap"""
    min_lap: float
    """s: the least time since that place for a lap"""
    patience: float
    """s: a lap counts as a loop when the goal distance has not improved for this long"""
    loop_gain: float
    """m: the improvement of the best goal distance that counts"""
    sample_every: float
    """s: the period of the places sampled"""
    horizon: float
    """s: the places kept (the most that long ago)"""


@dataclass(frozen=True, kw_only=True)
class Follow:
    """Boundary following, the escape mode ``BF`` (:mod:`fuzzynav.kernels.escape`)."""

    offset: float
    """rad: the virtual goal's angle to the side of the heading, without a route"""
    search: float
    """rad: that angle while no obstacle is near"""
    near: float
    """m: an obstacle nearer than this is near"""
    reach: float
    """m: the virtual goal's distance ahead"""
    leave_gain: float
    """m: the goal nearer than the hit distance by this much ends the mode (with the way free)"""
    free: float
    """m: the range ray nearest the goal reading this much (or up to the goal) counts free"""
    follow_time: float
    """s: the longest following"""
    room: float
    """m: the room the route keeps from the obstacle points"""
    tight: float
    """m: the least room the route may keep where the wider one gives none"""
    ahead: float
    """m: the virtual goal's distance along the route"""
    replan: float
    """s: the period of the route's re-planning"""


@dataclass(frozen=True, kw_only=True)
class Guidance:
    """The route guidance and its car route (:mod:`fuzzynav.kernels.guidance`,
    :mod:`fuzzynav.kernels.car_route`; :func:`fuzzynav.kernels.guidance.search_settings` gives the
    car route's search its ``guide_car_…`` settings by name); the grid route tries the rooms
    ``guide_room``, ``guide_narrow``, ``guide_bare`` in that order (widest first)."""

    guide: float
    """1: the layer runs"""
    guide_cell: float
    """m: the grid route's cell"""
    guide_ahead: float
    """m: the route point's distance along the route"""
    guide_replan: float
    """s: the period of the planning"""
    guide_direct: float
    """m: a straight line to the target free for this long needs no route (:data:`guide_off_heading`)"""
    guide_room: float
    """m: the room beyond the radius the grid route keeps"""
    guide_narrow: float
    """m: that room where the first gives no route"""
    guide_bare: float
    """m: that room where neither gives one"""
    guide_car: float
    """1: the car route is tried before the grid route"""
    guide_car_room: float
    """m: the room beyond the radius the car route keeps"""
    guide_car_step: float
    """m: the length of an arc of the search"""
    guide_car_node: float
    """m: the cell of a search node"""
    guide_car_headings: float
    """the heading bins of a search node"""
    guide_car_weight: float
    """the weight of the clearance cost"""
    guide_car_comfort: float
    """m: clearance beyond which an arc costs no more"""
    guide_car_turn: float
    """the cost of an arc at full lock"""
    guide_car_switch: float
    """m: the cost of a change of steering"""
    guide_car_reach: float
    """m: the search ends this near the goal"""
    guide_car_budget: float
    """the search nodes before it gives up (then the grid route)"""
    guide_car_reverse: float
    """the cost factor of a backward arc (0: forward arcs only)"""
    guide_car_gear: float
    """m: the cost of a change of direction"""
    guide_car_cell: float
    """m: the clearance grid's cell"""
    guide_car_steerings: float
    """the steering values of the arcs, spread over ± ``guide_car_steering``"""
    guide_car_steering: float
    """rad: the largest steering of an arc"""
    guide_car_ahead: float
    """m: the route point's distance along the car route"""
    guide_car_tight: float
    """m: clearance beyond the radius below which the layer drives the arcs itself"""
    guide_car_speed: float
    """m/s: its forward speed then"""
    guide_car_reuse: float = 0.0
    """s: the longest a car route is kept and reused instead of searched again (0: searched at every plan)"""
    guide_car_keep: float = 0.0
    """m: room beyond the route's radius that a newly seen point must keep from the rest of a reused route"""
    guide_car_stray: float = 0.0
    """m: the robot's farthest from a reused route"""
    guide_car_swerve: float = 0.0
    """rad: its heading's farthest from the route's there"""
    guide_car_chain: float = 0.0
    """1: a backward arc of the layer ends with the next plan in the same step (0: the navigator drives that step)"""
    guide_off_heading: float = 0.0
    """rad: a target farther off the heading than this gets a route though the line to it is free (0: never)"""
    guide_car_shot: float = 0.0
    """expanded nodes (whole) between two analytic expansions of a search off the heading (0: none)"""


@dataclass(frozen=True, kw_only=True)
class Pace:
    """The speed set by the room ahead (:mod:`fuzzynav.kernels.pace`)."""

    pace: float
    """1: the layer runs"""
    pace_room: float
    """m: the room beyond the radius kept on the arc ahead"""
    pace_horizon: float
    """s: the travel left before that room"""
    pace_goal: float
    """s: the least time to the target"""
    pace_car: float
    """1: the car route's forward arcs (``CAR-FWD``) paced too, at least ``guide_car_speed``"""


@dataclass(frozen=True, kw_only=True)
class Latency:
    """The latency compensated (:mod:`~fuzzynav.kernels.latency`): the robot's array (ROBOT_FIELDS), the delay."""

    plant_dt: float
    """s: the step Δt"""
    plant_wheelbase: float
    """m: the wheelbase l"""
    plant_radius: float
    """m: the body's radius"""
    plant_max_steering: float
    """rad: the steering limit"""
    plant_lowest_speed: float
    """m/s: the lowest speed (negative: reverse)"""
    plant_max_speed: float
    """m/s: the top speed"""
    plant_arc: float
    """1: the exact arc, 0: Euler (eq IV.1–IV.2)"""
    delay: float = 0.0
    """steps: round(latency / Δt), the commands on their way to the wheels (0: none), the queue's slots"""


@dataclass(frozen=True, kw_only=True)
class Slots:
    """The sizes of the per-robot blocks of ``state``, and the flag asking for more point slots (set
    by a step after which a robot could run out: the controller's ``compiled()`` then adds some)."""

    places_slots: float
    """the loop detector's sampled places"""
    route_slots: float = 0.0
    """the poses of the car route kept for reuse"""
    points_slots: float = 0.0
    """the obstacle points remembered"""
    cell_slots: float = 0.0
    """the hash set of their cells (a power of two)"""
    grow: float = 0.0
    """1: a step asks for more point slots"""


@dataclass(frozen=True, kw_only=True)
class RobotState:
    """A robot's row of ``state`` (a new episode's values: :data:`NEW_EPISODE`)."""

    stopped: float
    """s: the time the navigator's safety stop has held the robot"""
    count: float
    """the obstacle points remembered"""
    phase: float
    """the recovery's phase: :data:`NO_PHASE`, :data:`BACK`, :data:`TURN`"""
    t_recovery: float
    """s: when the recovery began"""
    start_x: float
    """m: the pose it began at"""
    start_y: float
    """m"""
    back_steering: float
    """rad: the back-up command's steering"""
    back_speed: float
    """m/s: its speed"""
    heading: float
    """rad: the heading the turn began at"""
    flip: float
    """1: the turn's steering is flipped"""
    last_x: float
    """m: the place of the last recovery"""
    last_y: float
    """m"""
    best: float
    """m: the loop detector's best goal distance"""
    t_best: float
    """s: when it was reached"""
    first: float
    """the first sampled place in the ring buffer"""
    places: float
    """the places kept"""
    active: float
    """1: boundary following is on"""
    side: float
    """its side (+1 left, −1 right)"""
    failed: float
    """the side that failed last"""
    hit: float
    """m: the hit distance"""
    t_follow: float
    """s: when following began"""
    route_x: float
    """m: its route point"""
    route_y: float
    """m"""
    planned: float
    """s: when that route was planned"""
    guide_x: float
    """m: the route guidance's route point (NaN: the target itself)"""
    guide_y: float
    """m"""
    guide_planned: float
    """s: when it was planned"""
    guide_gear: float
    """the car route's manoeuvre: −1 / +1 while the layer drives an arc, else 0"""
    guide_kappa: float
    """1/m: that arc's curvature"""
    guide_run: float
    """m: its length"""
    guide_driven: float
    """m: the distance driven on it"""
    sent: float
    """the commands sent (the latency queue's next slot is ``sent % delay``)"""
    guide_poses: float
    """the poses of the car route kept (0: none)"""
    guide_at: float
    """the kept pose the robot was nearest at the last plan"""
    guide_tx: float
    """m: the target the kept route leads to"""
    guide_ty: float
    """m"""
    guide_seen: float
    """the remembered points the kept route has been checked against"""
    guide_made: float
    """s: when the kept route was searched"""
    guide_keep: float
    """m: the radius it keeps from the points"""
    guide_whole: float
    """1: the kept poses reach the route's end (0: the route was longer than the slots)"""


# a new episode's state row: 0 but these (NaN: none yet)
NEW_EPISODE = {"last_x": math.nan, "last_y": math.nan, "best": math.inf, "t_best": math.nan, "route_x": math.nan,
               "route_y": math.nan, "planned": -math.inf, "guide_x": math.nan, "guide_y": math.nan,
               "guide_planned": -math.inf, "guide_made": -math.inf}

PARAMETERS = (Supervisor, Body, Recovery, Loop, Follow, Guidance, Pace, Latency, Slots)
PARAM_NAMES = tuple(field.name for record in PARAMETERS for field in fields(record))
STATE_NAMES = tuple(field.name for field in fields(RobotState))
# the positions by name (their fields are generated, so typed Any for the checker)
PARAM: Any = namedtuple("ParamAt", PARAM_NAMES)(*range(len(PARAM_NAMES)))
STATE: Any = namedtuple("StateAt", STATE_NAMES)(*range(len(STATE_NAMES)))
TABLES_AT, PLACES_AT = len(PARAM_NAMES), len(STATE_NAMES)
ON, GROW = PARAM.on, PARAM.grow  # read by the simulator's step (kernels.step) and the simulator
NO_PHASE, BACK, TURN = 0, 1, 2  # recovery phases; labels after the navigator's: REC-BACK, REC-TURN, BF
_FRESH = np.array([NEW_EPISODE.get(name, 0.0) for name in STATE_NAMES])


def put(params: np.ndarray, record) -> np.ndarray:
    """Write the fields of ``record`` (a layer's dataclass) into ``params`` at their positions."""
    for field in fields(record):
        params[getattr(PARAM, field.name)] = getattr(record, field.name)
    return params


def pack(*records) -> np.ndarray:
    """``params`` without the tables: the fields of ``records`` (one per layer; a layer not
    given is all 0, off)."""
    params = np.zeros(TABLES_AT)
    for record in records:
        put(params, record)
    return params


def fresh_state(n: int, params: np.ndarray) -> np.ndarray:
    """The ``state`` of ``n`` robots at the start of an episode, sized by ``params``
    (:mod:`fuzzynav.kernels.row_blocks`: the blocks after the fields)."""
    blocks = (3 * int(params[PARAM.places_slots]) + 2 * int(params[PARAM.delay]) + 4 * int(params[PARAM.route_slots])
              + 2 * int(params[PARAM.points_slots]) + int(params[PARAM.cell_slots]))
    state = np.zeros((n, PLACES_AT + blocks))
    state[:, :PLACES_AT] = _FRESH
    return state


def none() -> tuple[np.ndarray, np.ndarray]:
    """``(params, state)`` of a navigator without layers."""
    params = np.zeros(TABLES_AT + 1)
    return params, fresh_state(1, params)
