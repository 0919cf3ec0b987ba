"""Trajectory trackers of chapter V: fuzzy (CF), neural (CN) and neuro-fuzzy ANFIS (CNF) (§V.3).

The robot aims at a point — the current waypoint of a path (the simulator switches waypoints
inside the tolerance zone, §V.2) or a moving target (§V.5) — at constant speed; the only command
is the steering α. With e_x = x_p − x_r, e_y = y_p − y_r, θ_d = atan2(e_y, e_x) (eqs V.1–V.3),
the angular error fed to the thesis' controllers is θ_er = θ_r − θ_d (eq V.4 with the sign of
:func:`~fuzzynav.control.base.thesis_angle_error`).

- :class:`FuzzyTracker` (``fuzzy-tracker``): Table V.1 on (θ_er, dθ_er), dθ_er the change of
  θ_er over one step (§V.3.1, Figs V.3–V.7).
- :class:`ModelTracker` (``neural-tracker``, ``anfis-tracker``): a learned inverse model
  α = f(θ_er) of one input (§V.3.2, §V.3.5); the input is clamped to the range the model was
  trained on, so the command saturates instead of extrapolating.

Corner anticipation (an addition to the thesis; ``corner_radius = 0`` is the thesis' tracker):
the thesis switches to the next waypoint inside a fixed tolerance zone, too late for a sharp
corner (the robot overshoots) and too early for a gentle one (it cuts). With ``corner_radius``
R > 0 the tracker follows the corner-smoothed reference of :func:`fuzzynav.control.reference.
smoothed_path` instead — an outward swing of R·(1 − cos(|φ|/2))/2 and an arc of radius R that
begins R·tan(|φ|/2) before the (shifted) corner of heading change φ — and aims at the point
``lookahead`` metres ahead of the robot's projection on it; θ_er is the angle error to that
point, so the controllers (Table V.1, the learned inverse models) are unchanged. The default R is
the tightest turn of the robot, R_min = l / tan(α_max) = 0.5 m (eq IV.1, l = 0.5 m,
α_max = π/4); the look-ahead, 0.35 m (3.5 steps at 1 m/s) for the learned trackers and 1.5 m
for the gentler Table V.1, was chosen once for all paths on the V, N and trapezoid paths of the
comparison (benchmarks/tracking_bench.py). The simulator still switches waypoints in its
tolerance zone, or once the robot has passed the corner (``path_switching: passed``, the default,
:mod:`fuzzynav.sim.tasks`); with the thesis' zone alone (``path_switching: zone``) the zone must
contain the swing's closest approach to the corner (at most ``APPROACH`` = 0.4 m).
"""

from __future__ import annotations

from abc import abstractmethod

import numpy as np

from fuzzynav import validation
from fuzzynav.control.base import BatchController, thesis_angle_error
from fuzzynav.control.reference import STEP, WINDOW, advance, smoothed_path
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.systems import tracking
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.settings import LENGTH, ROOM, SPEED, STEERING, checked
from fuzzynav.world.geometry import wrap_angle

DEFAULT_SPEED = 1.0  # m/s, the constant tracking speed of the chapter V comparison
DEFAULT_CORNER_RADIUS = DEFAULT_PARAMS.wheelbase / np.tan(DEFAULT_PARAMS.max_steering)  # R_min = 0.5 m
DEFAULT_LOOKAHEAD = 0.35  # m, see the module docstring
FUZZY_LOOKAHEAD = 1.5  # m, the fuzzy tracker's (Table V.1 steers gently: π/8 at θ_er = π/6)


class AngleErrorTracker(BatchController):
    """Base of the chapter V trackers: θ_er (and its change) → α, constant ``speed``.

    Subclasses implement :meth:`steering` on arrays. Works on batches (``act_batch``) and on one
    robot (``act``); the state is the previous θ_er of every robot and, with corner
    anticipation, the reference of the path and every robot's index on it.
    """

    label = "track"

    @checked(speed=SPEED, corner_radius=ROOM, lookahead=LENGTH)
    def __init__(self, speed: float = DEFAULT_SPEED, corner_radius: float = DEFAULT_CORNER_RADIUS,
                 lookahead: float = DEFAULT_LOOKAHEAD):
        self.speed = float(speed)
        self.corner_radius = float(corner_radius)
        self.lookahead = float(lookahead)
        self.reset()

    def reset(self, rng: np.random.Generator | None = None) -> None:
        self._previous = None
        self._index = None
        self._path = None
        self.reference_ = None

    @abstractmethod
    def steering(self, theta_er: np.ndarray, dtheta_er: np.ndarray) -> np.ndarray:
        """Steering α ``(N,)`` (rad, > 0 left) from θ_er and dθ_er ``(N,)`` (thesis sign)."""

    def aim_points(self, obs) -> np.ndarray:
        """Point ``(N, 2)`` aimed at: ``obs.target``, or with corner anticipation on a path the
        reference sample ``lookahead`` ahead of each robot's projection (module docstring)."""
        target = np.atleast_2d(obs.target)
        if obs.path is None or self.corner_radius == 0:
            return target
        xy = np.atleast_2d(obs.pose)[:, :2]
        if self._path is None or not np.array_equal(self._path, obs.path):
            self._path = np.array(obs.path, dtype=float)
            self.reference_ = smoothed_path(self._path, self.corner_radius)
            self._index = None
        fresh = self._index is None or len(self._index) != len(xy)
        if fresh:
            self._index = np.zeros(len(xy), dtype=int)
        window = len(self.reference_) if fresh else int(WINDOW / STEP)  # the first projection: whole path
        self._index = advance(self.reference_, xy, self._index, window)
        ahead = np.minimum(self._index + int(round(self.lookahead / STEP)), len(self.reference_) - 1)
        return self.reference_[ahead]

    def act_batch(self, obs):
        pose = np.atleast_2d(obs.pose)
        d = self.aim_points(obs) - pose[:, :2]
        theta_er = thesis_angle_error(np.arctan2(d[:, 1], d[:, 0]) - pose[:, 2])
        fresh = self._previous is None or len(self._previous) != len(theta_er)
        dtheta_er = np.zeros_like(theta_er) if fresh else wrap_angle(theta_er - self._previous)
        self._previous = theta_er
        alpha = self.steering(theta_er, dtheta_er)
        return alpha, np.full(len(alpha), self.speed), [self.label] * len(alpha)


class FuzzyTracker(AngleErrorTracker):
    """Fuzzy tracker CF, §V.3.1: Table V.1 (25 rules, TS0, product, weighted sum) on (θ_er, dθ_er).

    ``system`` defaults to :func:`fuzzynav.fuzzy.systems.tracking` (Figs V.4–V.6); any system
    with inputs (θ_er, dθ_er) and output α can be passed (e.g. an edited rule table).
    """

    name = "fuzzy-tracker"
    roles = ("tracker",)  # its rule base by role: Table V.1

    def __init__(self, speed: float = DEFAULT_SPEED, corner_radius: float = DEFAULT_CORNER_RADIUS,
                 lookahead: float = FUZZY_LOOKAHEAD, system=None):
        super().__init__(speed, corner_radius, lookahead)
        self.system = system if system is not None else tracking()

    def steering(self, theta_er, dtheta_er):
        return self.system.evaluate(np.column_stack([theta_er, dtheta_er]))[:, 0]


class ModelTracker(AngleErrorTracker):
    """A learned inverse model α = f(θ_er) (neural CN §V.3.2, ANFIS CNF §V.3.5).

    ``model`` maps an array ``(N, 1)`` of θ_er to α ``(N,)`` (an estimator's ``predict``);
    θ_er is clamped to ``input_range`` (the span of the training data) before prediction, and α
    to ±``max_steering``.
    """

    @checked(speed=SPEED, corner_radius=ROOM, lookahead=LENGTH, max_steering=STEERING)
    def __init__(self, model, input_range, *, name: str, speed: float = DEFAULT_SPEED,
                 corner_radius: float = DEFAULT_CORNER_RADIUS, lookahead: float = DEFAULT_LOOKAHEAD,
                 max_steering: float = np.pi / 4):
        super().__init__(speed, corner_radius, lookahead)
        lo, hi = (float(v) for v in input_range)
        if not lo < hi:
            raise InputError(f"must be an increasing pair, got {input_range!r}", field="input_range")
        self.model = model
        self.input_range = (lo, hi)
        self.max_steering = float(max_steering)
        self.name = name

    def steering(self, theta_er, dtheta_er):
        x = np.clip(theta_er, *self.input_range).reshape(-1, 1)
        alpha = np.asarray(self.model.predict(x), dtype=float).reshape(-1)
        return np.clip(alpha, -self.max_steering, self.max_steering)


def fuzzy_tracker(systems=None, **options) -> FuzzyTracker:
    """Factory of ``fuzzy-tracker`` (options: ``speed``, ``corner_radius``, ``lookahead``, ``system``;
    ``systems={"tracker": system}``, its rule base by role, replaces Table V.1)."""
    unknown = set(validation.mapping(systems, field="systems") if systems is not None else {}) - {"tracker"}
    if unknown:
        raise InputError(f"unknown role(s) {', '.join(sorted(unknown))}; fuzzy-tracker has tracker", field="systems")
    if systems:
        options["system"] = systems["tracker"]
    return FuzzyTracker(**options)
