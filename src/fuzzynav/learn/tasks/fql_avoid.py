"""Obstacle avoidance by fuzzy Q-learning, ``fuzzynav train fql-avoid`` (thesis §VI.5.2, Figs VI.17–VI.22).

An avoider of 8 rules × 3 conclusions over the front, right and left distances (Fig VI.17) — × 2
by which side is more open, a deviation from the thesis (:data:`AVOID_OPEN`) — learns its steering
(reward VI.20) then its speed (VI.21) inside the goal navigator of Figs VI.20 and VI.24, the
:class:`~fuzzynav.control.learned.LearnedAvoidanceNavigator` that the model file (kind
``fql-avoid``) runs (:func:`load_model`): training drives the robot through that navigator's own
:meth:`~fuzzynav.control.learned.LearnedAvoidanceNavigator.drive`, the learner's action in place
of the extracted rules' shares.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from fuzzynav.control.learned import LearnedAvoidanceNavigator, avoidance_inputs
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.constants import ALPHA_MAX
from fuzzynav.fuzzy.io.document import to_document
from fuzzynav.fuzzy.membership import Trapezoidal
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.systems_navigation import D_MAX
from fuzzynav.fuzzy.variable import Variable
from fuzzynav.learn.envs import GridPremise, RandomObstacles, RobotEnv
from fuzzynav.learn.extraction import rule_table
from fuzzynav.learn.rewards import AvoidSpeedReward, AvoidSteeringReward
from fuzzynav.learn.schedules import ExponentialDecay
from fuzzynav.learn.tasks import common
from fuzzynav.robot.sensors import SensorRing

AVOID_D_MIN, AVOID_D_SAFE = 1.5, 3.0  # d_m, d_s of Fig VI.17 (m): those of fuzzy-5b-thesis (Fig IV.18)
AVOID_SPEED = 1.0  # m/s: constant speed of the avoider while its steering is learned
AVOID_STEERING = common.STEERING3  # eq VI.18: {−π/5, 0, π/5}
AVOID_SPEEDS = {"F": 0.5, "M": 1.0, "G": 1.8}  # candidate speeds of the avoider (m/s)
AVOID_MAX_STEPS = 400
AVOID_BATCH = 10  # parallel episodes (one random world) per batch of the avoider — see docs/training.md
AVOID_RATE = 1.0  # β × B of the wall follower: a constant rate that follows the improving policy; the avoider's floor ÷ BATCH
AVOID_RATE_START, AVOID_RATE_DECAY = 0.1, 0.95  # the avoider's β per batch: 0.1, × 0.95 down to AVOID_RATE / BATCH


def avoid_rate() -> ExponentialDecay:
    """β of the avoider's corrections (every robot of a batch adds one): fast while the first
    worlds teach the most, then down to the per-correction rate AVOID_RATE / BATCH (0.02) whose
    qualities average enough corrections for the extraction tolerance to hold."""
    return ExponentialDecay(AVOID_RATE_START, AVOID_RATE_DECAY, AVOID_RATE / common.BATCH)


AVOID_DECISION = 3  # steps Δt per learning decision (0.3 s)
AVOID_TOLERANCE = 0.05  # extraction tolerance: the avoider's quality gaps at the noise level are a few
# hundredths (docs/training.md, "Obstacle avoidance")
# A-priori conclusions (indices of NG, Z, PG) of the 8 rules (front, right, left ∈ P, L; first
# slowest), from the principle of §IV.7: turn away from the nearer side, right when blocked in
# front (Table IV.3, rule R1). A rule keeps its prior unless a learned candidate beats it by more
# than AVOID_TOLERANCE — the "knowledge introduced a priori" of §VI.6.
AVOID_PRIOR = (0, 2, 0, 0, 1, 2, 0, 1)  # PPP PPL PLP PLL LPP LPL LLP LLL
# and the speed prior F (slow) near obstacles, the principle of the VRB (Table IV.6).
# With the openness input (AVOID_OPEN, below) the situations with both sides alike — PPP and PLL —
# turn a priori towards the more open side (open D: right, NG; open G: left, PG).
OPEN_PRIOR = {0: (0, 2), 3: (0, 2)}
# Deviation from the thesis (docs/thesis.md, chapter VI): the thesis' 8 rules cannot tell which side is more open when
# front, right and left are all near (a wall or a corner ahead; docs/training.md, "Obstacle avoidance").
# The avoider gets a fourth input, "open" (control.learned.openness,
# the mean reading of the left module minus the right's) with two labels D (right more open) and G
# (left more open), crossing over [0, OPEN_WIDTH]: 16 rules, 14 of them learned. The thesis' 8 rules stay
# available (open_side=False, the study fql-avoid-8 of benchmarks/rl_bench.py).
AVOID_OPEN = True
OPEN_WIDTH = 0.05  # m: |openness| beyond which one side is the more open (narrow: a tie must not cancel the turn)


def distance_variable(name: str, d_min: float, d_safe: float, d_max: float = D_MAX) -> Variable:
    """A distance d_i with P (near) and L (far) defined by d_m, d_s and D_max (Figs IV.18, VI.17): the
    partition of :func:`fuzzynav.fuzzy.systems_navigation.distance_variable`, written as trapezoids
    bounded by D_max — the form the avoider's model documents store."""
    return Variable(name, (0.0, d_max), {"P": Trapezoidal(0.0, 0.0, d_min, d_safe),
                                        "L": Trapezoidal(d_min, d_safe, d_max, d_max)})


def open_variable(width: float = OPEN_WIDTH, d_max: float = D_MAX) -> Variable:
    """Which side is more open (:func:`fuzzynav.control.learned.openness`): D (right, ≤ 0) and
    G (left, ≥ ``width``), a strong partition crossing over [0, width]. A tie (openness 0: e.g. a
    thin post seen by C1 alone) is D, so that it turns right as rule R1 of Table IV.3 does — a
    partition symmetric about 0 would blend the two opposite turns of a tie into going straight."""
    return Variable("open", (-d_max, d_max), {"D": Trapezoidal(-d_max, -d_max, 0.0, width),
                                            "G": Trapezoidal(0.0, width, d_max, d_max)})


def avoid_inputs(open_side: bool = AVOID_OPEN) -> list[Variable]:
    """front, right, left distances (Fig VI.17) [and which side is more open, :func:`open_variable`]."""
    distances = [distance_variable(n, AVOID_D_MIN, AVOID_D_SAFE) for n in ("front", "right", "left")]
    return distances + [open_variable()] if open_side else distances


FREE = {"front": "L", "right": "L", "left": "L"}  # the situation without rules: goal seeking (free_rules)


def free_rules(open_side: bool = AVOID_OPEN) -> np.ndarray:
    """Indices of the "front, right and left far" rules in the grid (front slowest): the last
    one, or the last two with the openness input — goal seeking in the navigator (Table IV.1)."""
    n = 2 if open_side else 1
    return np.arange(8 * n - n, 8 * n)


def avoid_prior(open_side: bool = AVOID_OPEN) -> tuple:
    """A-priori steering conclusions of every rule of the grid (:data:`AVOID_PRIOR`, :data:`OPEN_PRIOR`)."""
    if not open_side:
        return AVOID_PRIOR
    return tuple(j for r, p in enumerate(AVOID_PRIOR) for j in OPEN_PRIOR.get(r, (p, p)))


def avoid_template(open_side: bool = AVOID_OPEN) -> FuzzySystem:
    """The avoider's premise: the rules of its whole input grid, the free rules included (every
    conclusion Z until learned)."""
    return common.grid_system(avoid_inputs(open_side),
                              [common.output_variable("alpha", AVOID_STEERING, (-ALPHA_MAX, ALPHA_MAX))],
                              [["Z"] * (free_rules(open_side)[-1] + 1)], "premise", "")


def avoid_system(steering_index, speed_index=None, open_side: bool = AVOID_OPEN) -> FuzzySystem:
    """The learned avoider: the rules of Fig VI.17 with an obstacle near (the free rules of
    :func:`free_rules` excluded), conclusions by candidate index (steering, and speed if given),
    built by the one extractor :func:`~fuzzynav.learn.extraction.rule_table`."""
    outputs = [(common.output_variable("alpha", AVOID_STEERING, (-ALPHA_MAX, ALPHA_MAX)),
                _avoid_candidates(AVOID_STEERING, open_side), steering_index)]
    if speed_index is not None:
        outputs.append((common.output_variable("v", AVOID_SPEEDS, (0.0, 4.0)),
                        _avoid_candidates(AVOID_SPEEDS, open_side), speed_index))
    extra = " and which side is more open (a deviation: 16 rules instead of 8)" if open_side else ""
    return rule_table(avoid_template(open_side), outputs, rules=free_rules(open_side)[0], name="fql-avoid",
                      description="Obstacle avoidance learned by fuzzy Q-learning (thesis §VI.5.2, eqs VI.18-VI.21) "
                                  f"over front, right, left distances{extra}; "
                                  "the situation 'front, right and left far' is goal seeking (Table IV.1)")


def _avoid_candidates(values: dict, open_side: bool) -> np.ndarray:
    """(R, 3) candidates; the free rules' are 0 (their share is goal seeking's, added by the env)."""
    free = free_rules(open_side)
    candidates = np.tile(np.array(list(values.values())), (free[-1] + 1, 1))
    candidates[free] = 0.0
    return candidates


PRIORS = ("none", "thesis")


def initial_tables(prior: str, open_side: bool = AVOID_OPEN) -> tuple[tuple, int]:
    """(steering indices of every rule, speed index) the avoider starts from (``--prior``):

    - ``none``: nothing chosen — every q[i, j] = 0 (eq VI.9); the neutral candidates (Z, and the
      middle speed) only break exact ties of rules never fired; the extraction takes each rule's
      conclusion of best quality (§VI.5.2: "les conclusions des règles avec les meilleures
      qualités sont choisies"). This is the thesis' protocol: its a-priori knowledge is in the
      rules' premises and candidates, not in pre-chosen conclusions.
    - ``thesis``: the a-priori table of §IV.7's principle (:data:`AVOID_PRIOR`, :data:`OPEN_PRIOR`,
      speed F), kept unless a learned conclusion beats it by more than :data:`AVOID_TOLERANCE`.
    """
    if prior == "none":
        return (1,) * (free_rules(open_side)[-1] + 1), 1
    if prior == "thesis":
        return avoid_prior(open_side), 0
    raise InputError(f"must be one of {', '.join(PRIORS)}, got {prior!r}", field="--prior")


def prior_tolerance(prior: str, batch: int) -> float:
    """Extraction tolerance for a prior: the best quality (none), else :data:`AVOID_TOLERANCE`."""
    return common.extraction_tolerance(batch, AVOID_TOLERANCE) if prior == "none" else AVOID_TOLERANCE


def fql_avoid_phases(out: Path, episodes: int, batch: int = AVOID_BATCH, open_side: bool = AVOID_OPEN,
                     prior: str = "thesis"):
    """Steering (eq VI.20) then speed (eq VI.21) of the avoider, trained inside the navigator,
    from the initial table ``prior`` (:func:`initial_tables`); ``batch`` robots per batch (1:
    the thesis' protocol)."""
    from fuzzynav.kernels import learned as learned_kernels

    free_rule = free_rules(open_side)
    template = avoid_template(open_side)
    premise = GridPremise(template)
    navigator = LearnedAvoidanceNavigator(template)  # the navigator a fql-avoid model file runs
    layout = RandomObstacles()
    sensors = SensorRing()

    def observe(s):
        """The avoider's inputs; where the supervisor hands the robot to goal seeking, "all far"
        (the free rules): the avoider does not act there, so its rules get no credit for it."""
        x = avoidance_inputs(s.ranges, open_side)
        learned_kernels.seeking_far(s.ranges, s.goal, navigator.supervisor, D_MAX, x)
        return x

    def navigate(s, alpha, speed):
        """The navigator's commands with the learner's (α, V_r) shares of the avoider."""
        free = premise.firing_strengths(observe(s), normalise=False)[:, free_rule].sum(axis=1)
        return navigator.drive(alpha, speed(free), free, s.ranges, s.goal)[:2]

    def steer_command(a, s):
        return navigate(s, a[:, 0], lambda free: (1.0 - free) * AVOID_SPEED)

    steering_prior, speed_prior = initial_tables(prior, open_side)
    tolerance = prior_tolerance(prior, batch)
    steer = common.fql_learner(premise, _avoid_candidates(AVOID_STEERING, open_side), 0.0, batch,
                        prior=steering_prior, alpha=avoid_rate())
    n_steer = common.steering_episodes(episodes, AVOID_SPEED_SHARE)
    env = RobotEnv(layout, observe, steer_command, AvoidSteeringReward(D_MAX), batch=batch,
                   max_steps=AVOID_MAX_STEPS // AVOID_DECISION, tolerance=common.GOAL_TOLERANCE, sensors=sensors,
                   decision_steps=AVOID_DECISION)
    yield common.Phase("steering", env, steer, n_steer, common.checkpoint_path(out, "steering"),
                       common.WORLD_CONVERGENCE)

    steering_rules = steer.greedy_indices(tolerance)  # the extracted steering, frozen from here on

    def speed_command(a, s):
        return navigate(s, steer.action(observe(s), steering_rules)[:, 0], lambda free: a[:, 0])

    speed = common.fql_learner(premise, _avoid_candidates(AVOID_SPEEDS, open_side), 0.0, batch, prior=speed_prior,
                        alpha=avoid_rate())
    env = RobotEnv(layout, observe, speed_command, AvoidSpeedReward(D_MAX, low=1.0), batch=batch,
                   max_steps=AVOID_MAX_STEPS // AVOID_DECISION, tolerance=common.GOAL_TOLERANCE, sensors=sensors,
                   decision_steps=AVOID_DECISION)
    yield common.Phase("speed", env, speed, episodes - n_steer, common.checkpoint_path(out, "speed"),
                       common.WORLD_CONVERGENCE)


AVOID_SPEED_SHARE = 0.5  # the thesis: ~250 episodes steering, ~2,000 speed (Fig VI.22)
AVOID_EPISODES = 6000  # default budget: 3,000 per phase (the thesis plots 450 steering and 2,000 speed episodes;
# it gives no budget: with 1,500 per phase the tight-spot rules stayed unsettled, docs/results/chapter-vi.md)


def train_fql_avoid(request, open_side: bool = AVOID_OPEN, watch=None) -> dict:
    """``fuzzynav train fql-avoid [--prior none|thesis]``: the avoider over front/right/left
    distances (Figs VI.17–VI.22) and, by default, which side is more open (:data:`AVOID_OPEN`: 16
    rules instead of the thesis' 8). The model's ``training`` records the protocol, the prior and
    ``rules_changed``: how many learned rules conclude otherwise than the initial table.
    ``watch(phase)``, if given, sees each phase before it runs (e.g. to record its episodes)."""
    prior, batch = request.prior or "none", common.robots(request)
    phases = fql_avoid_phases(request.out, common.episode_budget(request, AVOID_EPISODES), batch, open_side, prior)
    if watch is not None:
        phases = (watch(phase) or phase for phase in phases)
    phases, learners = common.run_phases(phases, request)
    learned, tolerance = free_rules(open_side)[0], prior_tolerance(prior, batch)
    system = avoid_system(learners["steering"].greedy_indices(tolerance)[0, 0, :learned],
                          learners["speed"].greedy_indices(tolerance)[0, 0, :learned], open_side)
    changed = common.rules_changed([learners["steering"], learners["speed"]], tolerance, rules=learned)
    document = {"kind": "fql-avoid", **to_document(system), "constant_speed": AVOID_SPEED,
                "training": {"task": "fql-avoid", "seed": request.seed, **common.protocol_record(batch, prior),
                             "rules_changed": changed, "rules_learned": int(learned), **common.summarise(phases)}}
    return common.finish(request, document, phases, "fql-avoid")


def load_model(document: dict, path) -> LearnedAvoidanceNavigator:
    """Model loader of kind ``fql-avoid``: the learned avoider in the goal navigator (``turn_guard``
    optional, default false)."""

    def build(system, speed, name):
        guard = document.get("turn_guard", False)
        if not isinstance(guard, bool):
            raise InputError(f"must be true or false, got {guard!r}", field="turn_guard")
        return LearnedAvoidanceNavigator(system, constant_speed=speed, name=name, turn_guard=guard)

    return common.load_fuzzy_model(document, path, build, keys=("constant_speed", "turn_guard"), free=(FREE,))
