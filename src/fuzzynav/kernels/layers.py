"""Array layout of the recovery and loop-escape layers of the default navigators (the kernels:
:mod:`~fuzzynav.kernels.recovery`, :mod:`~fuzzynav.kernels.escape`, :mod:`~fuzzynav.kernels.robust`;
the controller: :mod:`fuzzynav.control.robust`).

The layers travel as one tuple ``layers`` of arrays (indices :data:`PARAMS` … :data:`GROW`):

- ``params`` (floats, :data:`PARAM_NAMES` order): switches, the robot's size, the constants;
- ``tables``: the recovery's rule base (:func:`fuzzynav.kernels.ts0.pack`);
- ``state`` (N, :data:`STATE_NAMES`) floats per robot (NaN: none yet);
- ``points`` (N, P, 2), ``cells`` (N, H): the obstacle points each robot has seen
  (:mod:`fuzzynav.kernels.sightings`);
- ``places`` (N, L, 3): the loop detector's ring buffer of sampled places (t, x, y);
- ``grow`` (1,) int: set by a step after which a robot could run out of point slots — the
  controller's ``compiled()`` then makes them larger before the next step.

A compiled navigator without layers passes :func:`none` (``params[ON]`` = 0).
"""

from __future__ import annotations

import numpy as np

PARAMS, TABLES, STATE, POINTS, CELLS, PLACES, GROW = range(7)
PARAM_NAMES = (
    "on", "recovery", "escape", "stop_wait", "radius", "max_reverse_speed", "n_labels",
    # the recovery manoeuvre (kernels.recovery)
    "v_back", "back_distance", "margin", "v_turn", "turn_angle", "lane", "recovery_time",
    # the loop detector (kernels.escape)
    "revisit", "min_lap", "patience", "loop_gain", "sample_every", "horizon",
    # boundary following (kernels.escape)
    "offset", "search", "near", "reach", "leave_gain", "free", "follow_time", "room", "tight", "ahead", "replan",
)
(ON, RECOVERY, ESCAPE, STOP_WAIT, RADIUS, MAX_REVERSE_SPEED, N_LABELS,
 V_BACK, BACK_DISTANCE, MARGIN, V_TURN, TURN_ANGLE, LANE, RECOVERY_TIME,
 REVISIT, MIN_LAP, PATIENCE, LOOP_GAIN, SAMPLE_EVERY, HORIZON,
 OFFSET, SEARCH, NEAR, REACH, LEAVE_GAIN, FREE, FOLLOW_TIME, ROOM, TIGHT, AHEAD, REPLAN) = range(len(PARAM_NAMES))
STATE_NAMES = (
    "stopped", "count",  # seconds the navigator has held the robot, obstacle points remembered
    # recovery: phase, its start (time, pose), the back-up command, the heading the turn began at,
    # whether the steering is flipped, the place of the last recovery
    "phase", "t_recovery", "start_x", "start_y", "back_steering", "back_speed", "heading", "flip", "last_x", "last_y",
    # loop detector: best goal distance and when, first sampled place in the ring buffer, places kept
    "best", "t_best", "first", "places",
    # boundary following: on, side, side that failed, hit distance, start, route point, when planned
    "active", "side", "failed", "hit", "t_follow", "route_x", "route_y", "planned",
)
(STOPPED, COUNT, PHASE, T_RECOVERY, START_X, START_Y, BACK_STEERING, BACK_SPEED, HEADING, FLIP, LAST_X, LAST_Y,
 BEST, T_BEST, FIRST, PLACES_KEPT, ACTIVE, SIDE, FAILED, HIT, T_FOLLOW, ROUTE_X, ROUTE_Y,
 PLANNED) = range(len(STATE_NAMES))
NO_PHASE, BACK, TURN = 0, 1, 2  # recovery phases; labels after the navigator's: REC-BACK, REC-TURN, BF


def fresh_state(n: int) -> np.ndarray:
    """The ``state`` of ``n`` robots at the start of an episode."""
    state = np.zeros((n, len(STATE_NAMES)))
    state[:, [LAST_X, LAST_Y, T_BEST, ROUTE_X, ROUTE_Y]] = np.nan
    state[:, BEST], state[:, PLANNED] = np.inf, -np.inf
    return state


def none() -> tuple:
    """The ``layers`` argument of a navigator without layers."""
    return (np.zeros(len(PARAM_NAMES)), np.zeros(1), fresh_state(1), np.zeros((1, 1, 2)),
            np.zeros((1, 2), dtype=np.int64), np.zeros((1, 1, 3)), np.zeros(1, dtype=np.int64))
