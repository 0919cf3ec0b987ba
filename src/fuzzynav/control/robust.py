"""The chapter IV navigators with layers, ``fuzzy-2b`` (a default) and ``fuzzy-5b-rays`` (the
default five-behaviour navigator before ``fuzzy-5b`` moved to the lidar): the thesis' navigators
on the seven range sensors with a supervisor layer that never lets them freeze, sized to the
scenario's robot. The default ``fuzzy-5b`` (:mod:`fuzzynav.control.through_gaps`) is the same
class round the gap-finding navigator on a lidar, with the route guidance below.

:class:`RobustNavigator` wraps a compiled navigator — a thesis one
(:mod:`fuzzynav.control.five_behaviours`, :mod:`fuzzynav.control.avoidance`) or any other
:class:`~fuzzynav.control.batched.CompiledNavigator` — and adds two behaviours to its supervisor:

- **recovery** (:mod:`fuzzynav.control.recovery`): when the navigator's safety stop has held the
  robot for ``stop_wait`` seconds away from the goal, the robot backs out on an arc and turns the
  other way (``REC-BACK``, ``REC-TURN``), then the navigator drives again;
- **loop escape** (:mod:`fuzzynav.control.escape`): when the robot circles without getting
  nearer the goal, the navigator follows the boundary of what traps it towards a virtual goal
  beside it (``BF``) until the goal is nearer than where following began and its direction is
  free (the Bug algorithms' rule).

A third layer, the **route guidance** (:mod:`fuzzynav.kernels.guidance`, used by the default
``fuzzy-5b``, also named ``fuzzy-5b-gap-robust``, :mod:`fuzzynav.control.through_gaps`), aims the
navigator along the shortest route round the obstacles seen so far; ``fuzzy-2b`` and
``fuzzy-5b-rays`` do not use it.

The thesis navigator runs every step (its hit memory and behaviour switch stay current); a
layer in charge replaces its command. The labels in the trace are the navigator's, or
``REC-BACK``, ``REC-TURN``, ``BF`` (and, with the route guidance's car route, ``CAR-BACK``,
``CAR-FWD`` while the layer drives the planned arcs). The layers are compiled around any compiled navigator
(:mod:`fuzzynav.kernels.robust`), so the simulator runs the whole decision inside its own
compiled step, for one robot or a batch.

**The robot's size and limits** (the scenario's ``robot:`` keys) reach the navigators through
their compiled parameter vector: the simulator calls :meth:`CompiledNavigator.for_robot
<fuzzynav.control.batched.CompiledNavigator.for_robot>` with its robot, which sets the wheelbase
(the anti-orbit guard of goal seeking, the full-lock turn radius), the body radius (turning room
and safety stop) and the top speed; :meth:`RobustNavigator.for_robot` gives the layers the
robot's radius and reverse speed (a one-robot :meth:`~RobustNavigator.act` reads them from
``extras["robot"]`` when there). With the default robot nothing changes. The ``-thesis``
variants (:func:`fuzzy_5b_thesis`, :func:`fuzzy_2b_thesis`) are the compiled navigators with none
of their own optional layers either (:data:`fuzzynav.control.batched.LAYERS`): the tables, switch,
supervisor and VRB as published; the ``-layered`` ones (:func:`fuzzy_5b_layered`,
:func:`fuzzy_2b_layered`) keep those layers, without recovery and loop escape.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np

from fuzzynav.control.base import BatchController, Command
from fuzzynav.control.batched import readings
from fuzzynav.control.escape import FOLLOW, LOOP
from fuzzynav.control.recovery import RECOVERY, recovery_system
from fuzzynav.errors import InputError
from fuzzynav.kernels import layers, row_blocks
from fuzzynav.kernels.motion import ROBOT_FIELDS
from fuzzynav.kernels.records import Clock, Layers, Navigator, Reading, Robot
from fuzzynav.kernels.step import route_of
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.settings import DURATION, ROOM, SHARE, Range, checked

FIRST_SLOTS = 16  # obstacle point slots per robot at the start, in steps of S + 1 (doubled when needed)
BARRIER = Range(0.0, 1.0, hi_open=True)  # the share of the body's gap a back-up step may close
ROUTE_SLOTS = 100  # poses of the car route kept for reuse (arcs of guide_car_step: 20 m at 0.2 m)


class RobustNavigator(BatchController):
    """A compiled navigator (a :class:`~fuzzynav.control.batched.CompiledNavigator`, or anything
    with its ``compiled``, ``labels``, ``reset``, ``for_robot``) with the recovery and
    loop-escape layers (either can be switched off: ``recovery=False``, ``escape=False``;
    ``stop_wait``: seconds of safety stop before a recovery; ``barrier``: the recovery's
    :attr:`~fuzzynav.kernels.layers.Recovery.barrier`, :func:`fuzzynav.kernels.recovery.may_step`;
    ``barrier_within``: :attr:`~fuzzynav.kernels.layers.Recovery.barrier_within`) and, given ``guidance`` (a
    :class:`fuzzynav.kernels.layers.Guidance`, e.g. :data:`fuzzynav.control.through_gaps.GUIDANCE`),
    the route guidance (:mod:`fuzzynav.kernels.guidance`) and, given ``pace`` (a
    :class:`fuzzynav.kernels.layers.Pace`, e.g. :data:`fuzzynav.control.through_gaps.PACE`), the
    speed set by the room ahead (:mod:`fuzzynav.kernels.pace`); with ``compensate=True``, the
    decision at the pose where the command will act once told the robot's actuation latency
    (:meth:`for_latency`, :mod:`fuzzynav.kernels.latency`; for a dense scan, a lidar); with
    ``forget_moving=True``, in a scenario with moving obstacles, the points its scans contradict
    forgotten (:meth:`for_traffic`); with ``goal_share`` > 0, the car route's search ending
    within that share of the goal's tolerance (:meth:`for_goal`); given ``traffic`` (a
    :class:`~fuzzynav.control.yield_layer.YieldLayer`), in a scenario with moving obstacles only,
    that layer adjusts each command after the compiled decision (then made in Python, one call a
    step: :attr:`in_step` is False); ``systems`` of the navigator are its rule bases by role."""

    @checked(stop_wait=DURATION, barrier=BARRIER, barrier_within=ROOM, goal_share=SHARE)
    def __init__(self, navigator, name: str, *, recovery: bool = True, escape: bool = True,
                 stop_wait: float = 1.0, barrier: float = 0.0, barrier_within: float = 0.0, guidance: layers.Guidance | None = None, pace: layers.Pace | None = None,
                 compensate: bool = False, forget_moving: bool = False, traffic=None, goal_share: float = 0.0):
        self.navigator, self.name, self.compensate, self.forget_moving = navigator, name, compensate, forget_moving
        self.goal_share = float(goal_share)
        self._reach = guidance.guide_car_reach if guidance else 0.0
        self.traffic, self._yielding = traffic, False
        self.labels = (*navigator.labels, "REC-BACK", "REC-TURN", "BF", "CAR-BACK", "CAR-FWD")
        supervisor = layers.Supervisor(on=1.0, recovery=float(recovery), escape=float(escape),
                                       stop_wait=float(stop_wait), n_labels=len(navigator.labels))
        places = int(LOOP.horizon / (LOOP.sample_every - 1e-9)) + 3  # never all in use
        slots = layers.Slots(places_slots=places, route_slots=ROUTE_SLOTS if guidance else 0)
        recovering = dataclasses.replace(
            RECOVERY, barrier=float(barrier), barrier_within=float(barrier_within))
        records = (supervisor, recovering, LOOP, FOLLOW, guidance, pace, slots)
        self.params = np.concatenate([layers.pack(*(record for record in records if record is not None)),
                                      _recovery_tables()])
        self._latency = 0.0
        self.for_robot(DEFAULT_PARAMS, navigator=False)
        self.reset()

    def reset(self, rng=None) -> None:
        """Forget the layers' state and the navigator's (a new episode)."""
        self.navigator.reset(rng)
        self._rows = None
        if self.traffic is not None:
            self.traffic.reset()

    @property
    def systems(self) -> dict:
        """The navigator's rule bases by role."""
        return self.navigator.systems

    @property
    def roles(self) -> tuple[str, ...]:
        """The names of the navigator's rule bases."""
        return self.navigator.roles

    @property
    def sensors(self):
        """The ring the navigator reads by default (``None``: the thesis' seven rays)."""
        return getattr(self.navigator, "sensors", None)

    def for_robot(self, robot, navigator: bool = True) -> RobustNavigator:
        """Size the navigator (unless ``navigator`` is False) and the layers for ``robot``
        (:class:`TricycleParams`)."""
        if navigator:
            self.navigator.for_robot(robot)
        if self.traffic is not None:
            self.traffic.for_robot(robot)
        layers.put(self.params, layers.Body(radius=robot.radius, max_reverse_speed=robot.max_reverse_speed,
                                            wheelbase=robot.wheelbase, max_speed=robot.max_speed))
        self.params[layers.PARAM.plant_dt:layers.PARAM.plant_dt + len(ROBOT_FIELDS)] = robot.array()
        return self.for_latency(self._latency)

    def for_latency(self, latency: float) -> RobustNavigator:
        """Compensate an actuation latency of ``latency`` seconds (the scenario's
        ``robot.actuation.latency``; 0: none), in whole steps of the robot's Δt as the robot's
        queue holds them (:mod:`fuzzynav.kernels.latency`); ignored without ``compensate``."""
        self._latency = float(latency) if self.compensate else 0.0
        delay = float(round(self._latency / self.params[layers.PARAM.plant_dt]))
        if delay != self.params[layers.PARAM.delay]:
            self.params[layers.PARAM.delay] = delay
            self._rows = None  # the state rows hold the queue: new ones at the next compiled()
        return self

    def for_goal(self, tolerance: float) -> RobustNavigator:
        """Told the goal's tolerance (the scenario's ``goal.tolerance``): with ``goal_share`` > 0
        the car route's search ends within ``goal_share`` × ``tolerance`` of the goal
        (``guide_car_reach`` at most), inside the disc where the task is done. A route that ends
        outside it (0.5 m against a 0.3 m tolerance) leaves the robot beside its goal and hands it
        to the navigator, which cannot turn that tightly forwards."""
        if self.goal_share > 0.0 and self._reach > 0.0:
            self.params[layers.PARAM.guide_car_reach] = min(self._reach, self.goal_share * float(tolerance))
        return self

    def for_traffic(self, moving: bool) -> RobustNavigator:
        """Told whether the scenario's obstacles move: with ``forget_moving``, the scans then clear
        the remembered points they contradict (:mod:`fuzzynav.kernels.clearing`); a static
        scenario's decisions are unchanged; with a ``traffic`` layer, it runs among moving obstacles."""
        self.params[layers.PARAM.forget] = float(bool(moving) and self.forget_moving)
        self._yielding = bool(moving) and self.traffic is not None
        return self

    @property
    def in_step(self) -> bool:
        """Can the simulator decide inside its compiled step (:class:`~fuzzynav.control.hooks.CompiledAct`)?
        Not while the ``traffic`` layer runs: it is Python, called after the compiled decision."""
        return not self._yielding

    def compiled(self, n: int, sensor_angles):
        """The arguments of :func:`fuzzynav.kernels.step.step` for ``n`` robots with this ring:
        the navigator's, with the layers' parameters and state (:mod:`fuzzynav.kernels.layers`) —
        a new state when the navigator's is new, a wider one when a step has asked for room."""
        kind, params, tables, state, memory, *_ = self.navigator.compiled(n, sensor_angles)
        if self._rows is None or self._inner is not state:
            slots = FIRST_SLOTS * (len(np.atleast_1d(sensor_angles)) + 1)
            self.params[[layers.PARAM.points_slots, layers.PARAM.cell_slots, layers.PARAM.grow]] = (
                slots, _hash_size(slots), 0.0)
            self._inner, self._rows = state, layers.fresh_state(n, self.params)
        elif self.params[layers.PARAM.grow]:
            self._rows = _grown(self.params, self._rows)
        return kind, params, tables, state, memory, self.params, self._rows

    def act_batch(self, obs):
        """``(steering (N,), speed (N,), behaviours (N,))`` for a batch observation."""
        from fuzzynav.kernels import robust

        n = len(obs.speed)
        if obs.ranges is None:
            raise InputError("this controller needs range sensors", field="sensors")
        arguments = self.compiled(n, obs.sensor_angles)
        active = getattr(obs, "active", None)
        out = np.zeros((n, 3))
        kind, params, tables, state, memory, layer_params, rows = arguments
        robust.act(Navigator(kind, params, tables), state, memory, Layers(layer_params, rows),
                   readings(obs, obs.ranges, obs.sensor_angles, active, n), Clock(float(obs.dt), float(obs.t)),
                   route_of(layer_params), out)
        command = out[:, 0], out[:, 1], np.asarray(self.labels)[out[:, 2].astype(int)]
        return self.traffic(obs, *command) if self._yielding else command

    def act(self, obs) -> Command:
        """One robot: the compiled decision, called directly (no batch of one is built; among
        moving obstacles with a ``traffic`` layer, through :meth:`act_batch`)."""
        if self._yielding:
            return super().act(obs)
        if obs.ranges is None or obs.target is None:
            raise InputError("this controller needs range sensors and a target", field="sensors")
        from fuzzynav.kernels import robust

        robot = obs.extras.get("robot")
        if robot is not None:
            self.for_robot(robot, navigator=False)
        angles = np.ascontiguousarray(obs.sensor_angles, dtype=float)
        kind, params, tables, state, memory, layer_params, rows = self.compiled(1, angles)
        x, y, theta = (float(value) for value in obs.pose)
        tx, ty = (float(value) for value in obs.target)
        d_o = math.inf if obs.obstacle_distance is None else float(obs.obstacle_distance)
        b_o = 0.0 if obs.obstacle_bearing is None else float(obs.obstacle_bearing)
        v = 0.0 if obs.speed is None else float(obs.speed)
        steering, speed, code = robust.act_one(
            Navigator(kind, params, tables), state[0], memory[0], Layers(layer_params, rows[0]),
            Robot(x, y, theta, v, tx, ty),
            Reading(np.ascontiguousarray(obs.ranges, dtype=float), angles, float(obs.max_range), d_o, b_o),
            Clock(float(obs.dt), float(obs.t)), route_of(layer_params))
        return Command(float(steering), float(speed), str(self.labels[int(code)]))


@functools.cache
def _recovery_tables() -> np.ndarray:
    """The recovery's rule base packed for the kernels (built once; the kernels only read it)."""
    from fuzzynav.kernels import ts0

    return ts0.pack([recovery_system()], ["recovery"])


def _hash_size(slots: int) -> int:
    """Slots of the hash set of the obstacle points' cells: a power of two ≥ twice ``slots``."""
    return 1 << (2 * slots - 1).bit_length()


def _grown(params: np.ndarray, rows: np.ndarray) -> np.ndarray:
    """The layers' state ``rows`` with twice the obstacle point slots per robot (``params`` updated)."""
    from fuzzynav.kernels import robust

    at = layers.PARAM
    slots = int(params[at.points_slots])
    kept = row_blocks.points_at(params) + 2 * slots  # the state, places, queue, route and points
    params[[at.points_slots, at.cell_slots, at.grow]] = 2 * slots, _hash_size(2 * slots), 0.0
    wider = layers.fresh_state(len(rows), params)
    wider[:, :kept] = rows[:, :kept]
    robust.rehash_all(params, wider)
    return wider


def _five(name: str, **options):
    from fuzzynav.control.five_behaviours import FiveBehaviourNavigator

    navigator = FiveBehaviourNavigator(**options)
    navigator.name = name
    return navigator


def _two(name: str, **options):
    from fuzzynav.control.avoidance import TwoBehaviourNavigator

    navigator = TwoBehaviourNavigator(**options)
    navigator.name = name
    return navigator


def fuzzy_5b(*, recovery: bool = True, escape: bool = True, **options) -> RobustNavigator:
    """``fuzzy-5b-rays``: the five-behaviour navigator of §IV.7 on the seven range sensors with
    recovery and loop escape (``options``, e.g. ``systems=``, go to the navigator)."""
    return RobustNavigator(_five("fuzzy-5b-rays", **options), "fuzzy-5b-rays", recovery=recovery, escape=escape)


def fuzzy_2b(*, recovery: bool = True, escape: bool = True, **options) -> RobustNavigator:
    """``fuzzy-2b``: the two-behaviour navigator of Fig IV.9 with recovery and loop escape
    (``options``, e.g. ``systems=``, go to the navigator)."""
    return RobustNavigator(_two("fuzzy-2b", **options), "fuzzy-2b", recovery=recovery, escape=escape)


def fuzzy_5b_thesis(**options):
    """``fuzzy-5b-thesis``: the five-behaviour navigator of §IV.7 as published — none of the
    layers of :data:`fuzzynav.control.batched.LAYERS` unless ``layers=`` names some."""
    return _five("fuzzy-5b-thesis", **{"layers": (), **options})


def fuzzy_2b_thesis(**options):
    """``fuzzy-2b-thesis``: the two-behaviour navigator of Fig IV.9 as published — none of the
    layers of :data:`fuzzynav.control.batched.LAYERS` unless ``layers=`` names some."""
    return _two("fuzzy-2b-thesis", **{"layers": (), **options})


def fuzzy_5b_layered(**options):
    """``fuzzy-5b-layered``: ``fuzzy-5b-thesis`` with every layer of
    :data:`~fuzzynav.control.batched.LAYERS` (what ``fuzzy-5b-thesis`` ran before it was stripped)."""
    return _five("fuzzy-5b-layered", **options)


def fuzzy_2b_layered(**options):
    """``fuzzy-2b-layered``: ``fuzzy-2b-thesis`` with every layer of :data:`~fuzzynav.control.batched.LAYERS`."""
    return _two("fuzzy-2b-layered", **options)
