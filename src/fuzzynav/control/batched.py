"""The compiled navigators: one decision over many robots, compiled.

The chapter IV navigators are :class:`CompiledNavigator` s (a
:class:`~fuzzynav.control.base.BatchController`): their decision — with
per-robot memory where they have one (the behaviour switch, the recent range hits), kept in
arrays over the robot axis — is compiled (:mod:`fuzzynav.kernels.navigators`), and the simulator
runs it inside its own compiled step.
"""

from __future__ import annotations

import math

import numpy as np

from fuzzynav.control.base import BatchController, Command, Observation
from fuzzynav.errors import InputError
from fuzzynav.kernels.angles import wrap_angle
from fuzzynav.kernels.records import Navigator, Reading, Readings, Robot
from fuzzynav.robot.sensors import THESIS_SENSOR_ANGLES, named_ring
from fuzzynav.robot.tricycle import DEFAULT_PARAMS

GAP_MARGIN = 0.05  # m kept between the body and a post when aiming through a gap (then half, a quarter)
GAP_LOOK = 2.0  # m: hits nearer than this shape the gaps
GAP_FIELD = np.pi / 2  # directions searched: within ±90° of the heading
# The layers this package adds to the thesis' navigators, each optional (the published ones run
# without: ``goal-seeking``, ``fuzzy-2b-thesis``, ``fuzzy-5b-thesis``):
LAYERS = {
    "orbit_guard": "anti-orbit guard of goal seeking (fuzzynav.control.goal_seeking)",
    "turning_room": "full-lock turn when the turning room runs out (fuzzynav.control.turning_room)",
    "safety_stop": "V = 0 when the next step would touch a remembered hit (fuzzynav.control.five_behaviours)",
    "hysteresis": "the behaviour switch held for a dwell, relaxed thresholds to keep goal seeking "
                  "(fuzzynav.control.supervisor)",
}


class CompiledNavigator(BatchController):
    """A navigator whose decision is compiled (:func:`fuzzynav.kernels.navigators.act`).

    Subclasses set ``kind`` (a :mod:`fuzzynav.kernels.navigators` code), ``labels`` (behaviour
    label of each mode code), ``roles`` (the names of their rule bases, in the kernel's order),
    ``sensors_deg`` (the ring directions they read, or ``None``), ``gap_aware`` (steer through
    gaps of a scan, :mod:`fuzzynav.kernels.gaps`), ``sensors`` (the ring the simulator gives
    them by default, ``None``: the thesis' seven rays) and ``memory`` (steps of hit
    memory, 0 for none), and call :meth:`_build` with their rule bases and parameters. The
    state of each robot (mode, hold count, turn side, hits) lives in arrays; the simulator steps
    the navigator inside its own compiled step (:meth:`compiled`).
    """

    kind: int
    gap_aware, sensors = False, None
    labels: tuple[str, ...]
    roles: tuple[str, ...]
    sensors_deg: tuple[float, ...] | None = None
    memory: int = 0

    def _build(self, systems, defaults, params: np.ndarray) -> None:
        """Pack the rule bases (``systems`` by role, missing roles from ``defaults()``) and keep
        ``params`` (the kernel's parameter vector, sensor columns filled in on first use)."""
        unknown = set(systems or {}) - set(self.roles)
        if unknown:
            raise InputError(f"unknown role(s) {', '.join(sorted(unknown))}; {self.name} has "
                             f"{', '.join(self.roles)}", field="systems")
        chosen = {**defaults(), **dict(systems or {})}
        self.systems = {role: chosen[role] for role in self.roles}
        from fuzzynav.kernels import layers, ts0

        self.tables = ts0.pack(list(self.systems.values()), [f"{self.name} {role}" for role in self.roles]) \
            if self.roles else np.zeros(1)
        self.params = params
        self._angles, self._no_layers = None, layers.none()
        self.reset()

    def reset(self, rng=None) -> None:
        """Forget the modes, turns and hits (a new episode)."""
        self._state = None

    def for_robot(self, robot) -> CompiledNavigator:
        """Size the navigator for ``robot`` (a :class:`~fuzzynav.robot.tricycle.TricycleParams`, the
        scenario's): its wheelbase (and with it the full-lock turn radius R = l / tan(π/5)), its
        body radius and, for the five-behaviour navigators, a top speed no higher than the robot's. The default
        robot leaves the parameters as built."""
        from fuzzynav.kernels import navigators

        if not hasattr(self, "_as_built"):
            self._as_built = self.params.copy()
        built, params = self._as_built, self.params
        if self.kind in (navigators.CONSTANT, navigators.WALL_FOLLOWER) or built[navigators.WHEELBASE] <= 0:
            return self
        params[navigators.WHEELBASE] = robot.wheelbase
        params[navigators.TURN_RADIUS] = built[navigators.TURN_RADIUS] * (robot.wheelbase / built[navigators.WHEELBASE])
        params[navigators.BODY] = robot.radius
        if self.kind == navigators.FIVE_BEHAVIOURS:
            params[navigators.V_MAX] = min(built[navigators.V_MAX], robot.max_speed)
        if self.gap_aware:  # the same margin around this body
            params[navigators.GAP_CLEARANCE] = robot.radius + built[navigators.GAP_CLEARANCE] - built[navigators.BODY]
        return self

    def compiled(self, n: int, sensor_angles):
        """The arguments of :func:`fuzzynav.kernels.step.step` for ``n`` robots with this ring:
        ``(kind, params, tables, state, memory, layer params, layer state)``; the state is this
        navigator's own (kept across calls, cleared by :meth:`reset`); no layers
        (:func:`fuzzynav.kernels.layers.none`)."""
        angles = np.asarray(sensor_angles, dtype=float).reshape(-1)
        if self._angles is None or not np.array_equal(angles, self._angles):
            if self.sensors_deg is not None:
                columns = sensor_columns(angles, self.sensors_deg)
                from fuzzynav.kernels import navigators

                at = navigators.COLUMNS if self.kind == navigators.FIVE_BEHAVIOURS else navigators.WALL_COLUMNS
                self.params[at:at + len(columns)] = columns
            self._scan_options(angles)
            self._angles, self._state = angles.copy(), None
        if self._state is None or len(self._state) != n:
            self._state = np.zeros((n, 4), dtype=np.int64)
            self._state[:, 0] = -1  # no mode yet
            self._memory = np.zeros((n, max(self.memory, 1), len(angles) + 1, 3))
        return (self.kind, self.params, self.tables, self._state, self._memory, *self._no_layers)

    def act(self, obs: Observation) -> Command:
        """One robot: the compiled decision of :meth:`act_batch`'s row, called directly (no batch
        of one is built, the cost of a navigator wrapped per robot)."""
        if obs.ranges is None or obs.target is None:
            return super().act(obs)
        from fuzzynav.kernels import navigators

        angles = np.ascontiguousarray(obs.sensor_angles, dtype=float)
        kind, params, tables, state, memory, *_ = self.compiled(1, angles)
        d_o = math.inf if obs.obstacle_distance is None else float(obs.obstacle_distance)
        b_o = 0.0 if obs.obstacle_bearing is None else float(obs.obstacle_bearing)
        x, y, theta = (float(value) for value in obs.pose)
        tx, ty = (float(value) for value in obs.target)
        v = 0.0 if obs.speed is None else float(obs.speed)
        steering, speed, code = navigators.act_one(
            Navigator(kind, params, tables), state[0], memory[0], Robot(x, y, theta, v, tx, ty),
            Reading(np.ascontiguousarray(obs.ranges, dtype=float), self._angles, float(obs.max_range), d_o, b_o),
            float(obs.dt))
        return Command(float(steering), float(speed), str(self.labels[int(code)]))

    def _variant(self, gap: bool, gap_margin: float, gap_look: float) -> dict:
        """The published navigator (the seven rays, no gap finding) or, with ``gap``, the
        gap-aware ``<name>-gap`` (the lidar ring); returns the gap entries of the parameter vector."""
        if gap:
            self.name = f"{type(self).name}-gap"
            self.gap_aware, self.sensors = True, named_ring("lidar")
        return {"gap_clearance": DEFAULT_PARAMS.radius + gap_margin, "gap_look": gap_look, "gap_field": GAP_FIELD}

    def _scan_options(self, angles) -> None:
        """Readings by 30° sector and gap finding on for a gap-aware navigator reading a scan
        (more rays than the thesis' seven), off otherwise (:mod:`fuzzynav.kernels.gaps`)."""
        from fuzzynav.kernels import navigators

        scan = self.gap_aware and len(angles) > len(THESIS_SENSOR_ANGLES)
        self.params[navigators.READING_HALF] = np.deg2rad(15.0) if scan else 0.0
        self.params[navigators.GAP] = float(scan)

    def act_batch(self, obs):
        """``(steering (N,), speed (N,), behaviours (N,))`` for a batch observation."""
        from fuzzynav.kernels import navigators

        n = len(obs.speed)
        if obs.ranges is None and self.sensors_deg is not None:
            raise InputError("this controller needs range sensors", field="sensors")
        angles = obs.sensor_angles if obs.ranges is not None else np.zeros(0)
        kind, params, tables, state, memory, *_ = self.compiled(n, angles)
        ranges = np.zeros((n, 0)) if obs.ranges is None else obs.ranges
        active = getattr(obs, "active", None)
        out = np.zeros((n, 3))
        navigators.act(Navigator(kind, params, tables), state, memory, readings(obs, ranges, angles, active, n),
                       float(obs.dt), out)
        return out[:, 0], out[:, 1], np.asarray(self.labels)[out[:, 2].astype(int)]


def layer_flags(layers) -> dict:
    """The ``navigator_params`` entries that switch on the named ``layers`` (keys of :data:`LAYERS`)
    and off the others; an unknown name is an :class:`InputError`."""
    layers = tuple(layers)
    unknown = sorted(set(layers) - set(LAYERS))
    if unknown:
        raise InputError(f"unknown layer(s) {', '.join(unknown)}; known: {', '.join(LAYERS)}", field="layers")
    return {name: float(name in layers) for name in LAYERS}


def readings(obs, ranges, angles, active, n: int) -> Readings:
    """The :class:`~fuzzynav.kernels.records.Readings` of a batch observation of ``n`` robots
    (``ranges``, ``angles`` and ``active`` given; every robot active when ``active`` is None)."""
    return Readings(*(np.ascontiguousarray(v, dtype=float) for v in (obs.pose, obs.speed, obs.target, ranges, angles)),
                    float(obs.max_range),
                    np.ascontiguousarray(np.column_stack([obs.obstacle_distance, obs.obstacle_bearing]), dtype=float),
                    np.ones(n, dtype=np.bool_) if active is None else np.ascontiguousarray(active, dtype=np.bool_))


def navigator_params(**values) -> np.ndarray:
    """The parameter vector of :mod:`fuzzynav.kernels.navigators` with the named entries set
    (names are its index constants in lower case)."""
    from fuzzynav.kernels import navigators

    params = np.zeros(navigators.N_PARAMS)
    for name, value in values.items():
        params[getattr(navigators, name.upper())] = value
    return params


class ConstantCommand(CompiledNavigator):
    """The same command (α, V) at every step (open loop): a reference for timing the simulator
    itself, and a scripted drive. Label: ``constant``."""

    name = "constant"
    labels, roles = ("constant",), ()

    def __init__(self, steering: float = 0.0, speed: float = 1.0):
        from fuzzynav.kernels import navigators

        self.kind = navigators.CONSTANT
        self._build({}, dict, navigator_params(steering=steering, speed=speed))


def sensor_columns(angles, wanted_deg, source: str = "sensors") -> np.ndarray:
    """Indices of the readings pointing at ``wanted_deg`` (degrees, CCW from the heading).

    The navigators address the thesis' sensors C1…C7 by direction (thesis §IV.7), so any ring that
    contains those directions works; a missing one raises :class:`InputError`.
    """
    if angles is None:
        raise InputError("this controller needs range sensors", field=source)
    angles = np.asarray(angles, dtype=float)
    wanted = np.deg2rad(np.asarray(wanted_deg, dtype=float))
    gap = np.abs(wrap_angle(angles[None, :] - wanted[:, None]))
    idx = np.argmin(gap, axis=1)
    missing = gap[np.arange(len(wanted)), idx] > np.deg2rad(5.0)
    if missing.any():
        raise InputError(f"needs sensors at {', '.join(f'{w:g}°' for w in np.asarray(wanted_deg)[missing])} "
                         f"(ring has {', '.join(f'{a:.0f}°' for a in np.rad2deg(angles))})", field=source)
    return idx
