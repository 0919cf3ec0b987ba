"""Array layout of the recovery and loop-escape layers of the default navigators, and of the
route guidance that ``fuzzy-5b`` (the default) adds (the kernels: :mod:`~fuzzynav.kernels.recovery`,
:mod:`~fuzzynav.kernels.escape`, :mod:`~fuzzynav.kernels.guidance`, :mod:`~fuzzynav.kernels.robust`;
the controller: :mod:`fuzzynav.control.robust`).

The layers travel as two float arrays (two arguments of the compiled step, whose every array
argument costs time at each call):

- ``params``: :data:`PARAM_NAMES` — switches, the robot's size, the constants, the sizes of the
  per-robot blocks below and the ``grow`` flag (set by a step after which a robot could run out
  of obstacle point slots: the controller's ``compiled()`` then makes them larger before the
  next step) —, then from :data:`TABLES_AT` the recovery's rule base
  (:func:`fuzzynav.kernels.ts0.pack`);
- ``state`` (N, …), one row per robot: :data:`STATE_NAMES` (NaN: none yet), then the loop
  detector's ring buffer of sampled places (``places_slots`` × (t, x, y)), the obstacle points
  seen (``points_slots`` × (x, y)) and the hash set of their cells (``cell_slots``,
  :mod:`fuzzynav.kernels.sightings`) — views of the row by :func:`places_of`, :func:`points_of`,
  :func:`cells_of`.

A compiled navigator without layers passes :func:`none` (``params[ON]`` = 0).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.jit import jit

PARAM_NAMES = (
    "on", "recovery", "escape", "stop_wait", "radius", "max_reverse_speed", "n_labels",
    # the recovery manoeuvre (kernels.recovery)
    "v_back", "back_distance", "margin", "v_turn", "turn_angle", "lane", "recovery_time",
    # the loop detector (kernels.escape)
    "revisit", "min_lap", "patience", "loop_gain", "sample_every", "horizon",
    # boundary following (kernels.escape)
    "offset", "search", "near", "reach", "leave_gain", "free", "follow_time", "room", "tight", "ahead", "replan",
    # the route guidance (kernels.guidance; off unless ``guide``): grid cell, look-ahead, re-plan
    # period, straight-line reach, and the room kept, widest first (contiguous)
    "guide", "guide_cell", "guide_ahead", "guide_replan", "guide_direct", "guide_room", "guide_narrow", "guide_bare",
    # the car route of the guidance (kernels.car_route; off unless ``guide_car``): the room kept, then
    # the search's numbers in the order of kernels.car_search.search (contiguous), its grid cell,
    # steering values and limit, look-ahead; the robot's wheelbase
    "guide_car", "guide_car_room", "guide_car_step", "guide_car_node", "guide_car_headings", "guide_car_weight",
    "guide_car_comfort", "guide_car_turn", "guide_car_switch", "guide_car_reach", "guide_car_budget",
    "guide_car_reverse", "guide_car_gear", "guide_car_cell", "guide_car_steerings", "guide_car_steering",
    "guide_car_ahead", "guide_car_tight", "guide_car_speed", "wheelbase",
    # the pace (kernels.pace; off unless ``pace``): room kept on the arc ahead (m), seconds of travel
    # left before it, seconds to the target; the robot's top speed
    "pace", "pace_room", "pace_horizon", "pace_goal", "max_speed",
    # sizes of the per-robot blocks of ``state``, and the flag asking for more point slots
    "places_slots", "points_slots", "cell_slots", "grow",
)
(ON, RECOVERY, ESCAPE, STOP_WAIT, RADIUS, MAX_REVERSE_SPEED, N_LABELS,
 V_BACK, BACK_DISTANCE, MARGIN, V_TURN, TURN_ANGLE, LANE, RECOVERY_TIME,
 REVISIT, MIN_LAP, PATIENCE, LOOP_GAIN, SAMPLE_EVERY, HORIZON,
 OFFSET, SEARCH, NEAR, REACH, LEAVE_GAIN, FREE, FOLLOW_TIME, ROOM, TIGHT, AHEAD, REPLAN,
 GUIDE, GUIDE_CELL, GUIDE_AHEAD, GUIDE_REPLAN, GUIDE_DIRECT, GUIDE_ROOM, GUIDE_NARROW, GUIDE_BARE,
 GUIDE_CAR, GUIDE_CAR_ROOM, GUIDE_CAR_STEP, GUIDE_CAR_NODE, GUIDE_CAR_HEADINGS, GUIDE_CAR_WEIGHT,
 GUIDE_CAR_COMFORT, GUIDE_CAR_TURN, GUIDE_CAR_SWITCH, GUIDE_CAR_REACH, GUIDE_CAR_BUDGET,
 GUIDE_CAR_REVERSE, GUIDE_CAR_GEAR, GUIDE_CAR_CELL, GUIDE_CAR_STEERINGS, GUIDE_CAR_STEERING,
 GUIDE_CAR_AHEAD, GUIDE_CAR_TIGHT, GUIDE_CAR_SPEED, WHEELBASE, PACE, PACE_ROOM, PACE_HORIZON, PACE_GOAL, MAX_SPEED,
 PLACES_SLOTS, POINTS_SLOTS, CELL_SLOTS, GROW) = range(len(PARAM_NAMES))
TABLES_AT = len(PARAM_NAMES)
STATE_NAMES = (
    "stopped", "count",  # seconds the navigator has held the robot, obstacle points remembered
    # recovery: phase, its start (time, pose), the back-up command, the heading the turn began at,
    # whether the steering is flipped, the place of the last recovery
    "phase", "t_recovery", "start_x", "start_y", "back_steering", "back_speed", "heading", "flip", "last_x", "last_y",
    # loop detector: best goal distance and when, first sampled place in the ring buffer, places kept
    "best", "t_best", "first", "places",
    # boundary following: on, side, side that failed, hit distance, start, route point, when planned
    "active", "side", "failed", "hit", "t_follow", "route_x", "route_y", "planned",
    # route guidance: the route point given (NaN: the goal itself), when planned; the car route's
    # manoeuvre (gear −1 / +1 while the layer drives it, else 0): its arc's curvature and length, the
    # distance driven on it
    "guide_x", "guide_y", "guide_planned", "guide_gear", "guide_kappa", "guide_run", "guide_driven",
)
(STOPPED, COUNT, PHASE, T_RECOVERY, START_X, START_Y, BACK_STEERING, BACK_SPEED, HEADING, FLIP, LAST_X, LAST_Y,
 BEST, T_BEST, FIRST, PLACES_KEPT, ACTIVE, SIDE, FAILED, HIT, T_FOLLOW, ROUTE_X, ROUTE_Y,
 PLANNED, GUIDE_X, GUIDE_Y, GUIDE_PLANNED, GUIDE_GEAR, GUIDE_KAPPA, GUIDE_RUN,
 GUIDE_DRIVEN) = range(len(STATE_NAMES))
PLACES_AT = len(STATE_NAMES)
NO_PHASE, BACK, TURN = 0, 1, 2  # recovery phases; labels after the navigator's: REC-BACK, REC-TURN, BF


@jit
def places_of(params, row):
    """The loop detector's ring buffer (places_slots, 3) in a robot's ``state`` row."""
    size = int(params[PLACES_SLOTS])
    return row[PLACES_AT:PLACES_AT + 3 * size].reshape(size, 3)


@jit
def points_of(params, row):
    """The obstacle points (points_slots, 2) in a robot's ``state`` row."""
    at, size = PLACES_AT + 3 * int(params[PLACES_SLOTS]), int(params[POINTS_SLOTS])
    return row[at:at + 2 * size].reshape(size, 2)


@jit
def cells_of(params, row):
    """The hash set of the points' cells (cell_slots,) in a robot's ``state`` row."""
    at = PLACES_AT + 3 * int(params[PLACES_SLOTS]) + 2 * int(params[POINTS_SLOTS])
    return row[at:at + int(params[CELL_SLOTS])]


def fresh_state(n: int, params: np.ndarray) -> np.ndarray:
    """The ``state`` of ``n`` robots at the start of an episode, sized by ``params``."""
    width = PLACES_AT + 3 * int(params[PLACES_SLOTS]) + 2 * int(params[POINTS_SLOTS]) + int(params[CELL_SLOTS])
    state = np.zeros((n, width))
    state[:, [LAST_X, LAST_Y, T_BEST, ROUTE_X, ROUTE_Y, GUIDE_X, GUIDE_Y]] = np.nan
    state[:, BEST], state[:, [PLANNED, GUIDE_PLANNED]] = np.inf, -np.inf
    return state


def none() -> tuple[np.ndarray, np.ndarray]:
    """``(params, state)`` of a navigator without layers."""
    params = np.zeros(TABLES_AT + 1)
    return params, fresh_state(1, params)
