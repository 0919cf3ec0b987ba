"""The named records the compiled navigators and the step take instead of long argument lists.

Each is a ``typing.NamedTuple``: numba compiles a kernel taking one as a struct whose fields it
reads by name (``robot.theta``, ``seen.ranges``), at no cost over separate arguments, and built
inside a kernel or in Python alike. A field's comment gives its unit.

- :class:`Navigator` — which navigator and its constants (shared by the robots);
- :class:`Pose` — where a robot is;
- :class:`Robot` — one robot this step: pose, speed and the point it aims at;
- :class:`Reading` — what one robot's sensors read this step;
- :class:`Readings` — the same, and the robots' poses, speeds and targets, for a batch;
- :class:`Layers` — the recovery / loop-escape / guidance layers of one robot
  (:mod:`fuzzynav.kernels.layers`);
- :class:`Sightings` — the obstacle points a robot remembers (:mod:`fuzzynav.kernels.sightings`);
- :class:`CarSearch` — the settings of the hybrid A* search (:mod:`fuzzynav.kernels.car_search`)
  of the car route and of :mod:`fuzzynav.world.hybrid_astar`;
- :class:`Wavefront` — the car route's cost-to-go, settled on demand (:func:`fuzzynav.kernels.car_search.wavefront`);
- :class:`TurnRoom` — the turning-room guard's distances (:func:`fuzzynav.kernels.guard.turn_wanted`);
- :class:`Thresholds` — the behaviour selection's distances (:func:`fuzzynav.kernels.guard.select`);
- :class:`Shares` — the learned avoider's shares of a batch (:func:`fuzzynav.kernels.learned.drive`);
- :class:`StepNavigator`, :class:`Traffic`, :class:`Robots` — the arguments of the simulator's step
  (:func:`fuzzynav.kernels.step.step`);
- :class:`Tracks`, :class:`Scans`, :class:`ThreatSettings` — the moving obstacles a batch of
  robots tracks, its scan before and the yield layer's settings (:mod:`fuzzynav.kernels.scan_tracks`,
  :mod:`fuzzynav.kernels.threats`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np


class Navigator(NamedTuple):
    """A compiled navigator (:mod:`fuzzynav.kernels.navigators`)."""

    kind: int  # navigators.GOAL_SEEKING, TWO_BEHAVIOURS, FIVE_BEHAVIOURS, WALL_FOLLOWER or CONSTANT
    params: np.ndarray  # (P,) its constants at the indices of kernels.navigators
    tables: np.ndarray  # its rule bases (kernels.ts0.pack), in the order of its roles


class Pose(NamedTuple):
    """Where a robot is."""

    x: float  # m
    y: float  # m
    theta: float  # rad, heading


class Robot(NamedTuple):
    """One robot this step."""

    x: float  # m
    y: float  # m
    theta: float  # rad, heading
    v: float  # m/s, speed
    tx: float  # m, the point it aims at (goal, waypoint or target)
    ty: float  # m


class Reading(NamedTuple):
    """What one robot's sensors read this step."""

    ranges: np.ndarray  # (S,) m, one per ray
    angles: np.ndarray  # (S,) rad, the rays' directions from the heading
    max_range: float  # m
    d_o: float  # m, D_ro: the nearest obstacle (inf: none)
    b_o: float  # rad, θ_o: its bearing from the heading


class Readings(NamedTuple):
    """What a batch of N robots knows this step (one row each)."""

    poses: np.ndarray  # (N, 3) m, m, rad
    speeds: np.ndarray  # (N,) m/s
    targets: np.ndarray  # (N, 2) m, the points they aim at
    ranges: np.ndarray  # (N, S) m
    angles: np.ndarray  # (S,) rad
    max_range: float  # m
    obstacle: np.ndarray  # (N, 2) D_ro (m), θ_o (rad)
    active: np.ndarray  # (N,) bool: the robots to act for


class Layers(NamedTuple):
    """The layers around a navigator, for one robot (:mod:`fuzzynav.kernels.layers`)."""

    params: np.ndarray  # layers.PARAM_NAMES, then the recovery's rule base
    state: np.ndarray  # the robot's row: layers.STATE_NAMES, then its places, points and cells


class Clock(NamedTuple):
    """When a robot decides: the step's period and the time of the decision (s)."""

    dt: float
    t: float


class Sightings(NamedTuple):
    """The obstacle points a robot remembers."""

    points: np.ndarray  # (P, 2) m, world frame; the first ``count`` are filled
    count: int


class CarSearch(NamedTuple):
    """The settings of the hybrid A* search for a car (:func:`fuzzynav.kernels.car_search.search`;
    :mod:`fuzzynav.world.hybrid_astar` tells their meaning)."""

    curvatures: np.ndarray  # (K,) 1/m: primitive a is the arc of curvatures[a % K], backwards when a >= K
    cell: float  # m, the clearance grid's cell
    step: float  # m, the length of an arc
    node_cell: float  # m, the cell of a search node
    headings: int  # the heading bins of a search node
    weight: float  # the weight of the clearance cost
    comfort: float  # m, the clearance beyond which an arc costs no more
    turn_cost: float  # the cost per metre of an arc at full lock
    switch_cost: float  # m, the cost of a change of steering
    reach: float  # m, the search ends this near the goal
    budget: int  # the search nodes before it gives up
    reverse: float  # the cost factor of a backward arc (0: forward arcs only)
    gear: float  # m, the cost of a change of direction
    shot: int  # expanded nodes between two analytic expansions (0: none; kernels.car_search)


class SearchNodes(NamedTuple):
    """The nodes of a hybrid A* search (:func:`fuzzynav.kernels.car_search.search`), one entry each."""

    xs: np.ndarray  # (budget,) m, the pose reached
    ys: np.ndarray
    ths: np.ndarray  # rad
    parents: np.ndarray  # (budget,) int: the node it was reached from (−1: the start)
    primitives: np.ndarray  # (budget,) int: the arc that reached it (−1: the start)


class Wavefront(NamedTuple):
    """A wavefront from the goal over a clearance grid, run as far as asked
    (:func:`fuzzynav.kernels.car_search.settle`): an A* towards the search's start cell, or
    Dijkstra without one."""

    clearance: np.ndarray  # (ny, nx) m, each cell's clearance
    cell: float  # m, the grid's cell
    radius: float  # m, a cell of less clearance is blocked
    weight: float  # the weight of the clearance cost
    comfort: float  # m, the clearance beyond which a move costs no more
    cost: np.ndarray  # (ny · nx,) the cost-to-go of each cell (final where ``done``)
    done: np.ndarray  # (ny · nx,) bool: settled
    heap_f: np.ndarray  # the open cells' keys (a binary heap)
    heap_n: np.ndarray  # their cells
    size: np.ndarray  # (1,) int: the heap's entries
    toward_row: int  # the cell the A* heads for (the search's start; < 0: none, Dijkstra)
    toward_col: int


class TurnRoom(NamedTuple):
    """The distances of the turning-room guard."""

    lane: float  # m, the lane ahead that must be free
    margin: float  # m, the room the better half turn must keep
    body: float  # m, the body's radius
    radius: float  # m, the full-lock turn's radius


class Thresholds(NamedTuple):
    """The distances of the behaviour selection (Fig IV.16)."""

    detection: float  # m, an obstacle nearer than this is avoided
    front: float  # m, the front avoider (FOA) while the front reading is below this
    keep: float  # m, no reading below this for the goal direction to count clear
    clear: float  # m, the rays towards the goal read at least min(d_rg, clear) to count clear
    vision: float  # rad, the rays within this of the goal bearing are those looked at


class Shares(NamedTuple):
    """The learned avoider's shares of a batch of N rows."""

    alpha: np.ndarray  # (N,) rad, its steering share
    speed: np.ndarray  # (N,) m/s, its speed share
    free: np.ndarray  # (N,) the goal seeker's weight w_free


class StepNavigator(NamedTuple):
    """The navigator of the simulator's step, but for the two parameter arrays the step takes
    apart (a ``None`` there prunes the code that reads them at compile time)."""

    kind: int  # a navigators code, or step.NO_NAVIGATOR (commands given)
    tables: np.ndarray  # its rule bases
    state: np.ndarray  # (N, 4) ints: navigators.MODE, HELD, SIDE, COUNT
    memory: np.ndarray  # (N, steps, S + 1, 3) the hit memory of kernels.guard
    layer_state: np.ndarray | None  # (N, …) the layers' rows (None without layers: lean_arguments)
    route: np.ndarray | None  # the layers' params when their route guidance or pace is on, else None (step.route_of)


class Traffic(NamedTuple):
    """The world the step moves the robots in (:mod:`fuzzynav.kernels.traffic`)."""

    base: np.ndarray  # the static scene's rows of the moving obstacles
    movers: np.ndarray  # (M, 4) ints: which scene rows each moving obstacle owns
    offsets: np.ndarray  # (M, 2) m, where the moving obstacles are at this step
    scene: np.ndarray  # the scene array (kernels.scene), written with the movers in place


class Robots(NamedTuple):
    """The per-robot arrays the step updates in place."""

    state: np.ndarray  # (N, step.STATE_FIELDS) floats
    ranges: np.ndarray  # (N, S) m
    status: np.ndarray  # (N, 3) ints: outcome, steps taken, waypoint index
    moves: bool  # False: the step only acts and clips; another plant moves them (sim.plants)


class Tracks(NamedTuple):
    """The moving obstacles N robots track (:mod:`fuzzynav.kernels.scan_tracks`): robot i's are
    its slots 0 … count[i] − 1, oldest first; a track's sightings are oldest first."""

    times: np.ndarray  # (N, T, W) s, each track's last sightings
    centres: np.ndarray  # (N, T, W, 2) m, where it was seen then
    sightings: np.ndarray  # (N, T) ints: how many of its W rows hold
    radius: np.ndarray  # (N, T) m
    velocity: np.ndarray  # (N, T, 2) m/s, fitted over its sightings
    count: np.ndarray  # (N,) ints: tracks in use


class Scans(NamedTuple):
    """One range scan of N robots in the world frame (:mod:`fuzzynav.kernels.threats`)."""

    points: np.ndarray  # (N, B, 2) m, each beam's echo (or its reach)
    valid: np.ndarray  # (N, B) bool: an echo, not the reach
    here: np.ndarray  # (N, 2) m, where each robot was


class ThreatSettings(NamedTuple):
    """The yield layer's settings and the step's time (:func:`fuzzynav.kernels.threats.threats`)."""

    t: float  # s, this step's time
    dt: float  # s, since the scan before
    max_range: float  # m, the lidar's reach
    mover_speed: float  # m/s: an echo that moved slower stands still
    horizon: float  # m: the two-scan cue reads echoes this near
    track_range: float  # m: the tracker reads echoes this near
    tracked_beyond: float  # rad: a track counts this far off the heading and farther
    radius: float  # m, the robot's
    tracks: bool  # track the moving obstacles
