"""Controllers built from trained models (thesis chapter VI): learned TS0 rule bases that drive.

After fuzzy Q-learning (Algorithm VI.1) every rule keeps its best conclusion, so a trained model
is an ordinary zero-order Takagi–Sugeno system (:class:`~fuzzynav.fuzzy.FuzzySystem`). A model
file is the system's ``fuzzynav-fis`` document (readable by the fuzzy library, printable as a rule
table) plus a ``kind`` that says how the controller reads its inputs:

- ``fql-goal`` — goal seeking (§VI.5.1, Figs VI.7–VI.16): inputs ``drg`` (d_rg, eq IV.6) and
  ``theta`` (θ_r − θ_d, fed through :func:`~fuzzynav.control.base.thesis_angle_error` so a
  learned table reads like Table IV.1); outputs ``alpha`` and optionally ``v`` (else the model's
  ``constant_speed``) — :class:`FuzzyGoalSeeker`;
- ``fql-avoid`` — the learned obstacle avoider of §VI.5.2 (Figs VI.17–VI.22) as a complete
  navigator (Figs VI.20, VI.24) — :class:`LearnedAvoidanceNavigator`;
- ``fql-wall`` — the FQL-optimised wall follower of §VI.5.3 (Figs VI.29–VI.30) —
  :class:`LearnedWallFollower`.

The tabular Q-learning goal seeker (§VI.2, Figs VI.1–VI.4) is :class:`TabularGoalSeeker`; its
model (kind ``q-goal``) holds a Q table. Each model kind is written and read by its training task
(one module per task family under ``fuzzynav/learn/tasks``), which owns its document.

The input features — :func:`goal_inputs`, :func:`side_distances`, :func:`openness` — are defined here once and
used by the training environments too (:mod:`fuzzynav.learn.envs`), so a controller sees exactly
what its learner saw.
"""

from __future__ import annotations

import numpy as np

from fuzzynav import validation
from fuzzynav.control.base import BatchController
from fuzzynav.errors import InputError
from fuzzynav.kernels.records import Shares

# Sensor groups of the seven-sensor ring C1…C7 at 0°, −30°, +30°, −60°, +60°, −90°, +90°
# (fuzzynav.robot.sensors), as the modules of §IV.7: front = C1, C2, C3 (FOA); right = C2, C4,
# C6 (ROA); left = C3, C5, C7 (LOA). A single ray ahead would miss a post ±15° off the axis.
FRONT, RIGHT, LEFT = (0, 1, 2), (1, 3, 5), (2, 4, 6)
RAYS = (0, 5, 6)  # the single rays C1 (0°), C6 (−90°), C7 (+90°) of the hand-made wall follower
N_SENSORS = 7


def goal_inputs(pose, target) -> np.ndarray:
    """(d_rg, θ_r − θ_d) of robots ``pose`` (B, 3) towards ``target`` (B, 2) → (B, 2).

    d_rg is eq IV.6; the angle is the thesis' table input (eq IV.8 with the sign of :func:`~fuzzynav.control.base.thesis_angle_error` that
    makes its tables steer towards the goal): negative when the goal is on the left.
    """
    import fuzzynav.kernels.learned as learned  # numba, imported when first needed

    pose = np.asarray(pose, dtype=float).reshape(-1, 3)
    rel = np.asarray(target, dtype=float).reshape(-1, 2) - pose[:, :2]
    out = np.empty((len(rel), 2))
    # NumPy's vectorised arctan2 (it may differ from libm's in the last bit; the models were trained with it)
    direction = np.arctan2(rel[:, 1], rel[:, 0])
    heading = pose[:, 2] if len(pose) == len(rel) else np.broadcast_to(pose[:, 2], direction.shape)
    learned.goal_inputs(rel, direction, heading, out)
    return out


def side_distances(ranges) -> np.ndarray:
    """Front, right and left distances (B, 3) from the seven range readings (B, 7) (§VI.5.2).

    The thesis' FQL avoider and wall follower read "the distances in three directions" (Fig VI.17);
    with the ring of §IV.7 each direction is the nearest reading of its module's three sensors.
    """
    return _module_inputs(ranges, False)


def single_rays(ranges) -> np.ndarray:
    """Front, right and left distances (B, 3) as the single rays at 0°, −90°, +90° (B, 7) → (B, 3):
    the sensing of the hand-made wall follower (:mod:`fuzzynav.control.wall_following`)."""
    return _readings(ranges)[:, list(RAYS)]


def _readings(ranges) -> np.ndarray:
    """``ranges`` as a contiguous float (B, 7) array, else InputError."""
    ranges = np.ascontiguousarray(ranges, dtype=float)
    if ranges.ndim != 2 or ranges.shape[1] != N_SENSORS:  # a lidar's 271 (`--sensors lidar`): say so
        raise InputError(f"this controller reads the {N_SENSORS} range sensors of the thesis' ring (sensors thesis or "
                         f"beam), not {ranges.shape[-1] if ranges.ndim == 2 else ranges.shape} readings", field="sensors")
    return ranges


GROUPS = np.array([FRONT, RIGHT, LEFT])


def as_column(values, n: int) -> np.ndarray:
    """``values`` (a scalar or (n,)) as an (n,) float array for the kernels (no copy when it is one)."""
    values = np.asarray(values, dtype=float)
    if values.shape == (n,):
        return values
    return np.full(n, values) if values.ndim == 0 else np.broadcast_to(values, (n,))


def _module_inputs(ranges, open_side: bool) -> np.ndarray:
    """(B, 3) front, right, left distances [and (B, 4) openness] by :func:`fuzzynav.kernels.learned.module_inputs`."""
    import fuzzynav.kernels.learned as learned  # numba, imported when first needed

    ranges = _readings(ranges)
    out = np.empty((len(ranges), 4 if open_side else 3))
    learned.module_inputs(ranges, GROUPS, open_side, out)
    return out


def openness(ranges) -> np.ndarray:
    """Which side is more open (B,): the mean reading of the left module (C3, C5, C7) minus that
    of the right module (C2, C4, C6), in m — positive when the left is more open.

    Not an input of the thesis' avoider (its 8 rules read front, right and left only, Fig VI.17):
    with the nearest reading of each module, "front, right and left near" (a robot facing a wall
    or a corner) cannot tell which way to turn; the means of the modules can.
    """
    return _module_inputs(ranges, True)[:, 3]


AVOID_INPUTS = ["front", "right", "left"]  # the thesis' avoider (Fig VI.17)
AVOID_OPEN_INPUTS = AVOID_INPUTS + ["open"]  # plus which side is more open (:func:`openness`)


def avoidance_inputs(ranges, open_side: bool) -> np.ndarray:
    """The learned avoider's inputs (B, 3) or, with ``open_side``, (B, 4): front, right and left
    distances (:func:`side_distances`) [and :func:`openness`]."""
    return _module_inputs(ranges, open_side)


SENSING = {"rays": single_rays, "modules": side_distances}  # how a model reads d_f, d_d, d_g
MAX_SPEED = 4.0  # m/s: the robot's limit (fuzzynav.robot.tricycle), the TG singleton of Table IV.1


def check_speed(value, field: str) -> float:
    """A model's constant speed: a number in [0, :data:`MAX_SPEED`] m/s (else InputError)."""
    if not isinstance(value, (int, float)) or isinstance(value, bool) or not 0 <= value <= MAX_SPEED:
        raise InputError(f"must be a speed in [0, {MAX_SPEED:g}] m/s, got {value!r}", field=field)
    return float(value)


def _batch(obs):
    """(pose (B, 3), target (B, 2) or None, ranges (B, S) or None) of an Observation or a batch."""
    pose = np.asarray(obs.pose, dtype=float).reshape(-1, 3)
    target = None if obs.target is None else np.asarray(obs.target, dtype=float).reshape(-1, 2)
    ranges = None if obs.ranges is None else np.asarray(obs.ranges, dtype=float).reshape(pose.shape[0], -1)
    return pose, target, ranges


def _outputs(system, names: tuple[str, ...]) -> list[int]:
    found = [system.output_names.index(n) if n in system.output_names else -1 for n in names]
    if found[0] < 0:
        raise InputError(f"the rule base has no output {names[0]!r} (outputs: {system.output_names})",
                         field="outputs")
    return found


class FuzzyGoalSeeker(BatchController):
    """Learned TS0 goal seeker (§VI.5.1): system(drg, theta) → α [, V_r]; Figs VI.10, VI.14, VI.15."""

    def __init__(self, system, constant_speed: float = 1.0, name: str = "fql-goal"):
        if system.input_names != ["drg", "theta"]:
            raise InputError(f"a goal seeker reads inputs ['drg', 'theta'], got {system.input_names}",
                             field="inputs")
        self.system = system
        self.alpha_index, self.speed_index = _outputs(system, ("alpha", "v"))
        self.constant_speed = float(constant_speed)
        self.name = name

    def act_batch(self, obs):
        pose, target, _ = _batch(obs)
        if target is None:
            raise InputError("goal seeking needs a goal (a goal task)", field="target")
        out = self.system.evaluate(goal_inputs(pose, target))
        speed = out[:, self.speed_index] if self.speed_index >= 0 else np.full(len(out), self.constant_speed)
        return out[:, self.alpha_index], speed, ["goal seeking"] * len(out)


class TabularGoalSeeker(BatchController):
    """Greedy policy of a Q table over (d_rg, θ_rg) states (§VI.2, Figs VI.2–VI.3).

    ``state_of(d_rg, angle) -> state indices`` is the discretiser the table was learned on,
    ``greedy`` the best action of every state and ``steering`` the value of each action
    (forward, right, left, …) applied at the constant ``speed``.
    """

    def __init__(self, state_of, greedy, steering, speed: float, name: str = "q-goal"):
        self.state_of = state_of
        self.greedy = np.asarray(greedy, dtype=int)
        self.steering = validation.finite_array(steering, field="steering", ndim=1, empty=False)
        if np.abs(self.steering).max() >= np.pi / 2:  # as a robot's max_steering (robot.tricycle)
            raise InputError(f"steering angles must lie in (-π/2, π/2) rad, got {self.steering.tolist()}",
                             field="steering")
        if self.greedy.size == 0 or self.greedy.min() < 0 or self.greedy.max() >= self.steering.size:
            raise InputError("greedy actions outside the action set", field="greedy")
        self.speed = check_speed(speed, "speed")
        self.name = name

    def act_batch(self, obs):
        pose, target, _ = _batch(obs)
        x = goal_inputs(pose, target)
        actions = self.greedy[self.state_of(x[:, 0], x[:, 1])]
        return self.steering[actions], np.full(len(x), self.speed), ["goal seeking"] * len(x)


def avoidance_supervisor(avoidance):
    """The chapter IV supervisor (:mod:`fuzzynav.control.supervisor`, Fig IV.16) with the learned
    avoider's own thresholds: d_m and d_s are the breakpoints of its ``front`` P set (Fig VI.17),
    as ``fuzzy-5b-thesis`` uses d_m and d_s of Fig IV.18 (detection d_s, front and keep d_m, clear d_s)."""
    from fuzzynav.control.supervisor import SupervisorParams

    d_m, d_s = avoidance.inputs[0].terms["P"].breakpoints()[-2:]
    return SupervisorParams(detection=d_s, front=d_m, keep=d_m, clear=d_s)


def supervisor_array(params) -> np.ndarray:
    """The supervisor's thresholds as the kernels read them: detection, front, keep, clear, vision."""
    return np.array([params.detection, params.front, params.keep, params.clear, params.vision])


def with_goal_seeking(alpha, speed, free, goal_command):
    """(α, V_r) (B,) of the learned navigator: the avoider's shares ``alpha``, ``speed`` plus
    w_free = ``free`` times the goal seeker's command ``goal_command`` (B, 2) — the blend of
    :class:`LearnedAvoidanceNavigator`, also what the avoider's training drives."""
    return alpha + free * goal_command[:, 0], speed + free * goal_command[:, 1]


GUARD_MARGIN = 0.5  # m: room the guard keeps for the full-lock half turn (as fuzzy-5b-thesis' room_margin)
GUARD_SPEED = 0.3  # m/s: speed of the guard's turn (fuzzy-5b-thesis' v_floor)


class LearnedAvoidanceNavigator(BatchController):
    """Goal seeking plus the learned obstacle avoider: the navigator of Figs VI.20 and VI.24.

    ``avoidance`` is the learned TS0 system over (``front``, ``right``, ``left``) distances —
    and optionally ``open``, which side is more open (:func:`openness`) — with the rules of every
    situation in which an obstacle is near (7 of the 8 rules of Fig VI.17; 14 of 16 with
    ``open``). The remaining situation — all three distances far — is goal seeking (``goal``: the guarded
    chapter IV behaviour of Table IV.1 by default, :mod:`fuzzynav.control.goal_seeking`): with
    w_free = 1 − Σ w_i the share of that situation,

        α = Σ_i w_i α_i + w_free · α_GS,     V_r = Σ_i w_i V_i + w_free · V_GS.

    When nothing is near (w_free = 1) this is the goal-seeking behaviour alone and when an
    obstacle is close (w_free = 0) the avoider alone — the switch of Fig IV.9, made continuous by
    the fuzzy partition of Fig VI.17. The chapter IV supervisor (:meth:`drive`) hands the
    robot to goal seeking alone whenever the goal direction is clear, as in ``fuzzy-5b-thesis``: without
    it the blend keeps pulling away from obstacles beside a clear path and the robot circles
    goals placed near obstacles.

    ``turn_guard`` adds the turning-room guard of ``fuzzy-5b-thesis``
    (:class:`~fuzzynav.control.turning_room.TurnGuard`, thesis §IV.4: no reverse gear, tightest
    turn R = 0.69 m): when the lane ahead is blocked within d_m and the better full-lock half turn
    is about to close, the robot turns at full lock (±π/5) to the roomier side at
    :data:`GUARD_SPEED`, labelled ``"turn guard"``. It is off by default: the learned avoider is
    what avoids; the guard is a safety layer whose share of the steps the trace shows, and the
    benchmark reports the navigator with and without it.
    """

    def __init__(self, avoidance, goal=None, constant_speed: float = 1.0, name: str = "fql-avoid",
                 turn_guard: bool = False):
        if avoidance.input_names not in (AVOID_INPUTS, AVOID_OPEN_INPUTS):
            raise InputError(f"the avoider reads {AVOID_INPUTS} or {AVOID_OPEN_INPUTS}, got "
                             f"{avoidance.input_names}", field="inputs")
        self.open_side = avoidance.input_names == AVOID_OPEN_INPUTS
        if goal is None:
            from fuzzynav.control.goal_seeking import GuardedGoalSeeking

            goal = GuardedGoalSeeking()
        self.avoidance = avoidance
        self.goal = goal  # a GuardedGoalSeeking (its rule table and wheelbase run compiled in drive)
        self.alpha_index, self.speed_index = _outputs(avoidance, ("alpha", "v"))
        self.constant_speed = float(constant_speed)
        self.params = avoidance_supervisor(avoidance)
        self.supervisor = supervisor_array(self.params)
        self.name = name
        self.guard = None
        if turn_guard:
            from fuzzynav.control.turning_room import TurnGuard

            self.guard = TurnGuard(lane=self.params.front, margin=GUARD_MARGIN)
        self.reset()

    def reset(self, rng=None) -> None:
        """A new episode: the guard forgets its hits and turns."""
        self._turning = None
        if self.guard is not None:
            self.guard.reset()

    def free_share(self, distances) -> np.ndarray:
        """w_free = 1 − Σ_i w_i (B,): the share of "all three distances far" (``distances``: the
        avoider's inputs, :func:`avoidance_inputs`)."""
        covered = self.avoidance.firing_strengths(distances, normalise=False).sum(axis=1)
        return np.clip(1.0 - covered, 0.0, 1.0)

    def blend(self, distances, goal_command):
        """(α, V_r, w_free) from the avoider's inputs (B, 3 or 4) and the goal seeker's (α, V_r) (B, 2)."""
        alpha, speed, free = self.avoider_shares(distances)
        return (*with_goal_seeking(alpha, speed, free, goal_command), free)

    def avoider_shares(self, distances):
        """(Σ_i w_i α_i, Σ_i w_i V_i, w_free) (B,) of the learned rules for the avoider's inputs."""
        out = self.avoidance.evaluate(distances)
        free = self.free_share(distances)
        speed = out[:, self.speed_index] if self.speed_index >= 0 else (1.0 - free) * self.constant_speed
        return out[:, self.alpha_index], speed, free

    def drive(self, alpha, speed, free, ranges, goal):
        """(α, V_r, goal seeking?) (B,): the avoider's shares ``alpha``, ``speed`` blended by ``free``
        with the goal seeker's command for ``goal`` (d_rg, θ_r − θ_d) (B, 2) (:func:`goal_inputs`;
        :func:`with_goal_seeking`), in one call of :func:`fuzzynav.kernels.learned.drive`.

        As in ``fuzzy-5b-thesis``: goal seeking alone when the supervisor (Fig IV.16) finds nothing sensed
        or the goal direction clear — at a speed no higher than the avoider's while something is
        sensed (the VRB principle, Table IV.6); the blend otherwise. The avoider's training drives
        the robot through this method with the learner's shares in place of the rules'."""
        import fuzzynav.kernels.learned as learned  # numba, imported when first needed

        ranges = _readings(ranges)
        n = len(ranges)
        out = np.empty((n, 3))
        learned.drive(Shares(as_column(alpha, n), as_column(speed, n), as_column(free, n)), ranges,
                      np.ascontiguousarray(goal, dtype=float), self.goal.tables, self.goal.wheelbase, self.supervisor,
                      out)
        return out[:, 0], out[:, 1], out[:, 2] != 0.0

    def act_batch(self, obs):
        pose, target, ranges = _batch(obs)
        if target is None or ranges is None:
            raise InputError("the navigator needs a goal and the range readings", field="observation")
        x = goal_inputs(pose, target)
        steering, speed, goal = self.drive(*self.avoider_shares(avoidance_inputs(ranges, self.open_side)), ranges, x)
        labels = np.where(goal, "goal seeking", "obstacle avoidance")
        if self.guard is not None:
            steering, speed, labels = self._guarded(obs, steering, speed, labels, -x[:, 1])
        return steering, speed, labels.tolist()

    def _guarded(self, obs, steering, speed, labels, bearing):
        """The turning-room guard over the navigator's commands (class docstring)."""
        from fuzzynav.control.turning_room import ALPHA_MAX

        if self._turning is None or self._turning.size != steering.size:
            self._turning = np.zeros(steering.size, dtype=bool)
        turn, side = self.guard(obs, self._turning, bearing)
        self._turning = turn
        return (np.where(turn, side * ALPHA_MAX, steering), np.where(turn, GUARD_SPEED, speed),
                np.where(turn, "turn guard", labels))


class LearnedWallFollower(BatchController):
    """The FQL-optimised wall follower (§VI.5.3.2): system(dd, df, dg) → α, V_r (Figs VI.29–VI.30).

    The rules of the hand-made follower (:mod:`fuzzynav.control.wall_following`, Table VI.2) with
    learned numeric interpretations of their conclusions. ``sensing`` says how it reads d_d
    (right), d_f (front), d_g (left): ``"rays"`` — the single rays at −90°, 0°, +90° of the
    hand-made follower (:func:`single_rays`), the thesis' comparison — or ``"modules"`` — the
    nearest reading of each module's three sensors (:func:`side_distances`), a richer sensing
    with which the hand-made rules pass the corners of Fig VI.28 too.
    """

    def __init__(self, system, sensing: str = "rays", name: str = "fql-wall"):
        if system.input_names != ["dd", "df", "dg"]:
            raise InputError(f"a wall follower reads ['dd', 'df', 'dg'], got {system.input_names}", field="inputs")
        if sensing not in SENSING:
            raise InputError(f"unknown sensing {sensing!r}; known: {', '.join(SENSING)}", field="sensing")
        self.system = system
        self.alpha_index, self.speed_index = _outputs(system, ("alpha", "v"))
        if self.speed_index < 0:
            raise InputError("a wall follower concludes on both 'alpha' and 'v'", field="outputs")
        self.sensing = sensing
        self.name = name

    def act_batch(self, obs):
        _, _, ranges = _batch(obs)
        if ranges is None:
            raise InputError("wall following needs the range readings", field="ranges")
        front, right, left = SENSING[self.sensing](ranges).T
        out = self.system.evaluate(np.column_stack([right, front, left]))
        return out[:, self.alpha_index], out[:, self.speed_index], ["wall following"] * len(out)


def model_name(document: dict) -> str:
    """The name of a learned model's controller: its training task (``fql-goal-35``, ``q-goal``…,
    ``training.task`` as ``fuzzynav train`` writes it), else its kind — one scheme for every model."""
    training = validation.mapping(document.get("training", {}), field="training")
    task = training.get("task", document.get("kind"))
    if not isinstance(task, str) or not task:
        raise InputError(f"must be the name of the training task, got {task!r}", field="training.task")
    return task
