"""The learning tasks of chapter VI and ``fuzzynav train`` for them (thesis §VI.2, §VI.5).

Each task assembles a :class:`~fuzzynav.learn.envs.RobotEnv` (layout, inputs, actions, reward of
:mod:`fuzzynav.learn.rewards`) and a learner of :mod:`fuzzynav.learn`, trains it resumably with
:func:`~fuzzynav.learn.checkpoint.train_loop`, extracts the controller and writes its model file:

======================  =====================================================================
``q-goal``              tabular Q-learning goal seeking, zones × sectors of (d_rg, θ_rg), 3
                        actions, reward VI.2 (§VI.2, Figs VI.1–VI.4, Table VI.1)
``fql-goal``            FQL, 15 rules × 3 conclusions, steering (VI.2) then speed (VI.14),
                        random starts (§VI.5.1, Figs VI.7–VI.10)
``fql-goal-35``         FQL on the chapter IV partition, 35 rules × 5 conclusions (VI.13–VI.14)
``fql-goal-traces``     ``fql-goal``'s steering with eligibility traces (Figs VI.15–VI.16)
``fql-avoid``           FQL obstacle avoider, 8 rules × 3 over front/right/left distances —
                        × 2 by which side is more open (a deviation, :data:`AVOID_OPEN`) —
                        steering (VI.20) then speed (VI.21), trained inside the goal navigator
                        (§VI.5.2, Figs VI.17–VI.22); model = the navigator of Figs VI.20, VI.24
``fql-wall``            the wall follower of Table VI.2 with 3 interpretations per conclusion
                        learned by FQL, steering (VI.21) then speed (VI.22) (§VI.5.3.2)
======================  =====================================================================

Episodes. B episodes run in parallel (:data:`BATCH` = 50 with random starts, :data:`FIXED_BATCH`
= 10 from a fixed start, :data:`AVOID_BATCH` = 10 for the avoider) and feed one shared rule base
(or Q table) — synchronous data collection; every count of episodes here (``--episodes``,
checkpoints, the learning curve, episodes to converge) counts single episodes, B per batch; a
budget that is not a multiple of B ends with one smaller batch of the remainder
(:func:`batch_plan`). The exploration schedules tick once per batch: B episodes gathered with the
same knowledge are one step of learning. From a fixed start the B episodes of a batch differ
only by exploration, so a small B counts the episodes the learning needs instead of rounding them
up to a few large batches (the thesis' ~180 episodes of Fig VI.8 would be 4 batches of 50). The
avoider's batches are one random world each: with 50 episodes per world its ε reached its floor
only after 850 episodes (17 batches) and its curve settled at 800–1,150 episodes (the thesis:
~250, Fig VI.22); with 10 the same schedules and 10-world windows take a fifth of the episodes
(an episode costs about 3 × the wall time of one in a batch of 50: fewer robots share each
vectorised step).
Its rate :func:`avoid_rate` starts high and decays to the per-correction rate of 50-episode
batches, so the final qualities average as many corrections as before (a constant 0.1 learnt
as fast but flipped 2 of the 14 extracted rules on one seed, 7 collisions in 100 worlds).

Convergence. ``converged_at`` of every phase is :func:`fuzzynav.learn.curves.episodes_to_converge`
on the mean reinforcement per episode, counted at batch ends — budget-independent: training
longer does not move it. Goal seeking (:data:`GOAL_CONVERGENCE`): window 50, hold 500, and the
success gate (≥ 95 % of the episodes of the hold reach the goal). Obstacle avoidance and wall
following (:data:`WORLD_CONVERGENCE`): the episodes of a batch share one random world, whose
obstacles set the level of all their rewards, so the independent samples of the curve are the
batches (``clustered``: the noise band is 3 standard errors of a window's mean of W / B batch
means, σ from the successive differences of the batch means, which a trend does not inflate). With
independent episodes (the goal tasks' standard error) the band was √B times too narrow for the
world-to-world noise and the avoider never settled. So the window and hold are counted in worlds
(:func:`convergence_window`): a window spans 10 worlds, the hold 15 (500 and 750 episodes for the
wall follower's batches of 50, 100 and 150 for the avoider's 10), without success gate (their
training success, exploring among obstacles, stays below 95 %): with 5-world windows the early
batches (ε = 0.3, σ of a batch mean ≈ 0.2 against a travel of ≈ 0.4) made the band so wide that a
curve still on its first level "converged" at its first window on one seed of five. The count
cannot be below one window. ``fql-avoid`` trains 1,000 + 1,000 episodes by default
(:data:`AVOID_EPISODES`). ``--episodes N`` is
the total of a task; a two-phase task (steering, then speed) gives the speed phase the share
:data:`SPEED_SHARE` (the thesis' ~3,000 : ~900 episodes of Fig VI.9; the avoider:
:data:`AVOID_SPEED_SHARE`). A task writes one
checkpoint per phase next to ``--out`` (``OUT.steering.checkpoint.json``, …).

Extraction. Each rule keeps its best conclusion unless its gain over the prior is within the
tolerance (:data:`TOLERANCE`, :data:`AVOID_TOLERANCE`, :data:`WALL_TOLERANCE`) — so that quality differences at the noise
level cannot flip the extracted controller (issue 5). The prior is the middle candidate
(straight ahead / medium speed) for goal seeking, a-priori conclusions for the avoider
(:data:`AVOID_PRIOR`) and the hand-made follower's own values for wall following.

Credit in the navigator (``fql-avoid``). The avoider is trained inside the navigator, where the
chapter IV supervisor hands the robot to goal seeking whenever the goal direction is clear; there
the learner observes "all far" (the free rules, whose candidates are 0), so the avoider's rules
are credited only for the decisions they make. (Crediting them for the goal seeker's decisions
drowned their quality gaps: "front near" rules came out "straight ahead" on some seeds.)

Choices the thesis leaves open (documented where they are made): the constant speeds of the
steering phases, the candidate speeds, d_m / d_s of Fig VI.17, the decision period of the
sensor-based tasks (:data:`AVOID_DECISION`: the learner decides every 0.3 s, so that one choice
moves the next state enough to separate the candidates' qualities), the learning rates.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from fuzzynav.atomic import savefig_atomic
from fuzzynav.control.learned import TabularGoalSeeker, finite_numbers, model_name
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.io.document import to_document
from fuzzynav.fuzzy.membership import Singleton, Trapezoidal, Triangular
from fuzzynav.fuzzy.partition import strong_partition
from fuzzynav.fuzzy.rules import Rule
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.systems import D_MAX_GOAL, goal_seeking
from fuzzynav.fuzzy.variable import Variable
from fuzzynav.learn.checkpoint import train_loop
from fuzzynav.learn.curves import episodes_to_converge
from fuzzynav.learn.envs import FixedGoal, GridPremise, RandomGoal, RandomObstacles, RobotEnv, WallCourse
from fuzzynav.learn.exploration import EpsilonGreedy
from fuzzynav.learn.fql import FuzzyQLearner
from fuzzynav.learn.rewards import (
    AvoidSpeedReward,
    AvoidSteeringReward,
    GoalSpeedReward,
    GoalSteeringReward,
    WallSpeedReward,
    WallSteeringReward,
)
from fuzzynav.learn.schedules import ExponentialDecay, InverseVisits
from fuzzynav.learn.tabular import TabularLearner, ZoneSectorDiscretiser
from fuzzynav.models import save_json_atomic
from fuzzynav.robot.sensors import SensorRing

PI = math.pi
BATCH = 50  # parallel episodes per batch (random starts)
FIXED_BATCH = 10  # parallel episodes per batch from a fixed start (Figs VI.1, VI.8)
SPEED_SHARE = 0.25  # share of a two-phase task's episodes given to the speed phase
TOLERANCE = 0.05  # extraction: minimum quality gain over the prior conclusion
GOAL_TOLERANCE = 0.3  # m, as the scenarios' default
STEERING_SPEED = 1.8  # m/s: the constant speed of the steering phases (M of Fig IV.8)
MAX_STEPS = 300  # 30 s per episode
GOAL_CONVERGENCE = {"window": 50, "hold": 500, "target": 0.95}  # learn.curves.episodes_to_converge
WORLD_CONVERGENCE = {"worlds": 10, "hold_worlds": 15, "target": None, "clustered": True}  # one random world per batch

STEERING3 = {"NG": -PI / 5, "Z": 0.0, "PG": PI / 5}  # eq VI.12
STEERING5 = {"NG": -PI / 5, "NM": -PI / 10, "Z": 0.0, "PM": PI / 10, "PG": PI / 5}  # eq VI.15
SPEED3 = {"F": 1.0, "M": 1.8, "G": 3.0}  # eq VI.13, the F, M, G singletons of Fig IV.8


# -- rule bases ------------------------------------------------------------------------------
def goal_partition_15() -> list[Variable]:
    """Inputs of the 15-rule goal seeker (Figs VI.5–VI.6).

    d_rg: P, M, G with breakpoints 0, 0.3, 1, 3, D_max (P flat to 0.3 m, M peaking at 1 m, G
    flat from 3 m); θ_rg: NG, NM, Z, PM, PG peaking at −π/2, −π/6, 0, π/6, π/2 (shoulders to ±π).
    """
    drg = Variable("drg", (0.0, D_MAX_GOAL), {
        "P": Trapezoidal(0.0, 0.0, 0.3, 1.0),
        "M": Triangular(0.3, 1.0, 3.0),
        "G": Trapezoidal(1.0, 3.0, D_MAX_GOAL, D_MAX_GOAL),
    })
    peaks = (-PI / 2, -PI / 6, 0.0, PI / 6, PI / 2)
    theta = Variable("theta", (-PI, PI), strong_partition(peaks, ("NG", "NM", "Z", "PM", "PG"), (-PI, PI)))
    return [drg, theta]


def goal_partition_35() -> list[Variable]:
    """Inputs of the 35-rule goal seeker: the chapter IV partition (Figs VI.11–VI.12 = IV.5–IV.6)."""
    return list(goal_seeking().inputs)


def output_variable(name: str, values: dict[str, float], universe) -> Variable:
    return Variable(name, universe, {label: Singleton(v) for label, v in values.items()})


def grid_system(inputs, outputs, conclusions, name: str, description: str) -> FuzzySystem:
    """TS0 system over the full term grid of ``inputs`` (first input varying slowest), product
    T-norm, weighted sum (eq IV.4); ``conclusions[o][r]`` is the label of output o for rule r."""
    grids = np.meshgrid(*[np.arange(len(v.terms)) for v in inputs], indexing="ij")
    cells = np.column_stack([g.ravel() for g in grids])
    rules = [Rule(tuple((v.name, v.labels[c]) for v, c in zip(inputs, cell)),
                  tuple((out.name, labels[r]) for out, labels in zip(outputs, conclusions)))
             for r, cell in enumerate(cells)]
    return FuzzySystem(inputs, outputs, rules, method="ts0", tnorm="product", defuzzifier="weighted_sum",
                       name=name, description=description)


# -- running a phase -------------------------------------------------------------------------
@dataclass
class Phase:
    """One learning run: its env, learner, episode budget and checkpoint file."""

    name: str
    env: RobotEnv
    learner: object
    episodes: int
    checkpoint: Path
    convergence: dict = None  # settings of the criterion: GOAL_CONVERGENCE (default) or WORLD_CONVERGENCE


def checkpoint_path(out: Path, phase: str) -> Path:
    return Path(out).with_name(f"{Path(out).name}.{phase}.checkpoint.json")


def batch_plan(episodes: int, batch: int) -> list[tuple[int, int]]:
    """(batches to reach, episodes per batch) of a phase of ``episodes`` single episodes: full
    batches of ``batch``, then one last batch of the remainder (fewer parallel episodes) if any."""
    full, rest = divmod(int(episodes), int(batch))
    return [(n, size) for n, size in ((full, batch), (full + 1, rest)) if n and size]


def episode_curve(curve: dict, field: str) -> np.ndarray:
    """One field of a :func:`~fuzzynav.learn.checkpoint.train_loop` curve, one value per episode
    in order (batches of unequal size: the last one may be smaller, :func:`batch_plan`)."""
    return np.concatenate([np.ravel(np.asarray(row, dtype=float)) for row in curve[field]])


def run_phase(phase: Phase, request, seed_offset: int) -> dict:
    """Train one phase of exactly ``phase.episodes`` episodes resumably; returns its per-episode
    curves and convergence. The last partial batch continues from the checkpoint of the full
    ones (restoring it is exact, so a resumed run equals an uninterrupted one)."""
    batch = phase.env.batch
    every = math.ceil(request.checkpoint_every / batch) if request.checkpoint_every else 0
    rng = np.random.default_rng([int(request.seed), seed_offset])
    resume, continued = request.resume, False
    try:
        for batches, size in batch_plan(phase.episodes, batch):
            phase.env.batch = size
            result = train_loop(phase.env, phase.learner, batches, rng, checkpoint=phase.checkpoint,
                                checkpoint_every=every, resume=resume, progress=request.progress, batch_size=size,
                                desc=phase.name, budget=phase.episodes,
                                extra={"task": request.task, "phase": phase.name, "seed": int(request.seed),
                                       "batch": batch})
            resume, continued = True, continued or result.resumed_from != result.episode
    finally:
        phase.env.batch = batch
    reward, success = episode_curve(result.curve, "mean_reward"), episode_curve(result.curve, "success")
    return {"episodes": int(reward.size), "mean_reward": reward, "success": success, "continued": continued,
            "converged_at": converged_at(reward, success, batch, phase.convergence),
            "window": convergence_window(phase.convergence or GOAL_CONVERGENCE, batch)[0],
            "final_success": float(success[-min(success.size, 5 * batch):].mean())}


def convergence_window(settings: dict, batch: int) -> tuple[int, int]:
    """(window, hold) in episodes of a convergence setting: given in episodes (``window``,
    ``hold``) or, where one batch is one random world, in worlds (``worlds``, ``hold_worlds``)."""
    if "worlds" in settings:
        return settings["worlds"] * batch, settings["hold_worlds"] * batch
    return settings["window"], settings["hold"]


def converged_at(reward, success, batch: int, settings: dict | None = None) -> int:
    """Episodes to converge of one phase (module docstring, :mod:`fuzzynav.learn.curves`)."""
    settings = settings or GOAL_CONVERGENCE
    window, hold = convergence_window(settings, batch)
    return episodes_to_converge(reward, window=window, hold=hold, batch=batch,
                                success=None if settings["target"] is None else success,
                                target=settings["target"] or 0.0, clustered=settings.get("clustered", False))


class PhaseSummary(dict):
    """The train results of one phase: ``episodes``, ``converged_at`` (``None`` when the curve did
    not settle within the budget) and ``final_training_success``; JSON as a plain mapping, and
    printed by ``fuzzynav train`` as one readable line ("not settled" for ``None``)."""

    def __str__(self) -> str:
        converged = "not settled" if self["converged_at"] is None else f"episode {self['converged_at']}"
        return (f"{self['episodes']} episodes, converged: {converged}, "
                f"final training success {self['final_training_success']:.1%}")


def _summary(phases: dict) -> dict:
    """Per phase, :class:`PhaseSummary` (``converged_at`` beyond the curve → ``None``)."""
    return {name: PhaseSummary(episodes=r["episodes"],
                               converged_at=r["converged_at"] if r["converged_at"] <= r["episodes"] else None,
                               final_training_success=round(r["final_success"], 4))
            for name, r in phases.items()}


def _episodes(request, default: int) -> int:
    episodes = default if request.episodes is None else int(request.episodes)
    if episodes < 1:
        raise InputError("must be a positive integer", field="--episodes")
    return episodes


def steering_episodes(episodes: int, speed_share: float) -> int:
    """Episodes of the steering phase when ``episodes`` in total are split with the share
    ``speed_share`` for the speed phase (0: a single phase); each phase gets at least one."""
    if not speed_share:
        return episodes
    if episodes < 2:
        raise InputError(f"a two-phase task (steering, then speed) needs at least 2 episodes, got {episodes}",
                         field="--episodes")
    return episodes - min(episodes - 1, max(1, round(speed_share * episodes)))


def _write_curve(request, phases: dict, title: str) -> None:
    if request.curve is None:
        return
    import matplotlib.pyplot as plt

    from fuzzynav.viz.curves import plot_learning_curve

    figure, axes = plt.subplots(1, len(phases), figsize=(6.4 * len(phases), 4.0), squeeze=False)
    for ax, (name, result) in zip(axes[0], phases.items()):
        plot_learning_curve(result["mean_reward"], ax=ax, window=result["window"], title=f"{title}: {name}",
                            label=name, converged_at=result["converged_at"])
    Path(request.curve).parent.mkdir(parents=True, exist_ok=True)
    savefig_atomic(figure, request.curve, dpi=120, bbox_inches="tight")
    plt.close(figure)


# -- goal seeking, tabular (§VI.2) -----------------------------------------------------------
Q_STEERING = (0.0, -PI / 5, PI / 5)  # forward (α1), right (α2), left (α3)
Q_SPEED = 1.0  # m/s, constant (the tabular goal seeker only steers)


FIXED_EPSILON_FLOOR = 0.0  # from a fixed start ε decays to 0 (greedy in the limit): see q_goal_parts


def q_discretiser(n_states: int = 13) -> ZoneSectorDiscretiser:
    """States of Table VI.1: 1 + 2 × sectors — d_rg zones split at 1 m and 4 m, the inner zone
    (d_rg < 1 m) one state, the two outer zones 4, 5, 6 or 9 sectors of θ_rg each."""
    sectors = {9: 4, 11: 5, 13: 6, 19: 9}
    if n_states not in sectors:
        raise InputError(f"Table VI.1 has 9, 11, 13 or 19 states, got {n_states}", field="n_states")
    return ZoneSectorDiscretiser([1.0, 4.0], sectors[n_states], merge_inner=True)


def batch_size(fixed: bool) -> int:
    """Parallel episodes of a task: :data:`FIXED_BATCH` from a fixed start, else :data:`BATCH`."""
    return FIXED_BATCH if fixed else BATCH


def q_goal_parts(n_states: int = 13, n_actions: int = 3, fixed: bool = False, batch: int | None = None):
    """(env, learner, discretiser, steering values) of tabular goal seeking (§VI.2, Table VI.1).

    ε decays × 0.9 per batch from 0.3 to 0.02 with random starts; from the fixed start of Fig VI.1
    to 0 (:data:`FIXED_EPSILON_FLOOR`, "greedy in the limit"): there the episodes differ only by
    exploration, and with ε kept at 0.02 (about ten random turns in each 500-step episode) the
    greedy route of one training seed in five kept flipping between two near-equal routes (mean
    reinforcement 0.62 ↔ 0.69 per 100 episodes), so its curve settled only at episode 1,310."""
    batch = batch_size(fixed) if batch is None else batch
    disc = q_discretiser(n_states)
    steering = Q_STEERING if n_actions == 3 else (0.0, -PI / 10, PI / 10, -PI / 5, PI / 5)
    actions = np.asarray(steering)
    env = RobotEnv(FixedGoal() if fixed else RandomGoal(), lambda s: disc(s.goal[:, 0], s.goal[:, 1]),
                   lambda a, s: (actions[a], Q_SPEED), GoalSteeringReward(), batch=batch, max_steps=500,
                   tolerance=GOAL_TOLERANCE)
    learner = TabularLearner(disc.n_states, len(steering), gamma=0.9, alpha=InverseVisits(1.0, 0.8, 0.01),
                             policy=EpsilonGreedy(ExponentialDecay(0.3, 0.9, FIXED_EPSILON_FLOOR if fixed else 0.02)))
    return env, learner, disc, steering


def q_goal_controller(learner, disc, steering) -> TabularGoalSeeker:
    return TabularGoalSeeker(disc, learner.greedy()[0], steering, Q_SPEED)


def train_q_goal(request) -> dict:
    """``fuzzynav train q-goal``: 13 states × 3 actions, random starts (Figs VI.3–VI.4)."""
    env, learner, disc, steering = q_goal_parts()
    phases, _ = run_phases([Phase("steering", env, learner, _episodes(request, 3000),
                                  checkpoint_path(request.out, "steering"))], request)
    document = {"kind": "q-goal", "zone_edges": disc.zone_edges.tolist(), "n_sectors": disc.n_sectors,
                "merge_inner": disc.merge_inner, "steering": list(steering), "speed": Q_SPEED,
                "q": learner.q[0].tolist(), "training": {"task": "q-goal", "seed": request.seed, **_summary(phases)}}
    save_json_atomic(request.out, document)
    _write_curve(request, phases, "q-goal")
    return {"model": str(request.out), **_summary(phases)}


def load_q_goal(document: dict, path) -> TabularGoalSeeker:
    """Model loader of kind ``q-goal`` (fuzzynav.models.MODEL_LOADERS): every field checked, a bad
    one is an InputError naming the file and the field."""
    try:
        for name in ("zone_edges", "n_sectors", "merge_inner", "steering", "speed", "q"):
            if name not in document:
                raise InputError("missing field", field=name)
        sectors, merge = document["n_sectors"], document["merge_inner"]
        if not isinstance(sectors, int) or isinstance(sectors, bool):
            raise InputError(f"must be a positive integer, got {sectors!r}", field="n_sectors")
        if not isinstance(merge, bool):
            raise InputError(f"must be true or false, got {merge!r}", field="merge_inner")
        disc = ZoneSectorDiscretiser(finite_numbers(document["zone_edges"], "zone_edges", 1, empty=True), sectors,
                                     merge)
        q = finite_numbers(document["q"], "q", 2)
        steering = finite_numbers(document["steering"], "steering", 1)
        if q.shape != (disc.n_states, steering.size):
            raise InputError(f"Q table of shape {q.shape}, expected {(disc.n_states, steering.size)} "
                             "(states of zone_edges × n_sectors, actions of steering)", field="q")
        return TabularGoalSeeker(disc, np.argmax(q, axis=1), steering, document["speed"], name=model_name(document))
    except InputError as error:
        raise InputError(error.problem, source=str(path), field=error.field) from None


# -- goal seeking, fuzzy Q-learning (§VI.5.1) ------------------------------------------------
@dataclass(frozen=True)
class GoalFQL:
    """Settings of one FQL goal-seeking task."""

    name: str
    inputs: callable
    steering: dict
    lam: float = 0.0
    learn_speed: bool = True
    episodes: int = 3000
    fixed: bool = False


GOAL_TASKS = {
    "fql-goal": GoalFQL("fql-goal", goal_partition_15, STEERING3),
    "fql-goal-35": GoalFQL("fql-goal-35", goal_partition_35, STEERING5, episodes=4000),
    "fql-goal-traces": GoalFQL("fql-goal-traces", goal_partition_15, STEERING3, lam=0.7, learn_speed=False,
                               episodes=1500),
}


def fql_learner(premise, candidates, lam: float = 0.0, batch: int = BATCH, prior=None, alpha=None) -> FuzzyQLearner:
    """The FQL settings of every task: γ = 0.9, β = 1 / (1 + visits) (eq III.24) floored so the
    B parallel corrections stay small, ε-greedy per rule with ε decaying 0.3 → 0.02 (× 0.85 per batch)."""
    alpha = InverseVisits(1.0, 1.0, 0.2 / batch) if alpha is None else alpha
    return FuzzyQLearner(premise, candidates, gamma=0.9, alpha=alpha,
                         policy=EpsilonGreedy(ExponentialDecay(0.3, 0.85, 0.02)), lam=lam,
                         normalise=False, prior=prior)


def goal_fql_phases(task: GoalFQL, out: Path, episodes: int, batch: int | None = None):
    """Yields the phases of an FQL goal task; the speed phase is built from the trained steering."""
    batch = batch_size(task.fixed) if batch is None else batch
    inputs = task.inputs()
    alpha = output_variable("alpha", task.steering, (-PI / 5, PI / 5))
    template = grid_system(inputs, [alpha], [[alpha.labels[0]] * math.prod(len(v.terms) for v in inputs)],
                           task.name, "premise")
    premise = GridPremise(template)
    layout = FixedGoal() if task.fixed else RandomGoal()
    steer_values = np.array(list(task.steering.values()))
    n_steer = steering_episodes(episodes, SPEED_SHARE if task.learn_speed else 0.0)
    steer = fql_learner(premise, steer_values, task.lam, batch)
    env = RobotEnv(layout, lambda s: s.goal, lambda a, s: (a[:, 0], STEERING_SPEED), GoalSteeringReward(),
                   batch=batch, max_steps=MAX_STEPS, tolerance=GOAL_TOLERANCE)
    yield Phase("steering", env, steer, n_steer, checkpoint_path(out, "steering"))
    if task.learn_speed:
        speed_values = np.array(list(SPEED3.values()))
        speed = fql_learner(premise, speed_values, 0.0, batch)
        env = RobotEnv(layout, lambda s: s.goal,
                       lambda a, s: (steer.greedy_action(s.goal, TOLERANCE)[:, 0], a[:, 0]), GoalSpeedReward(),
                       batch=batch, max_steps=MAX_STEPS, tolerance=GOAL_TOLERANCE)
        yield Phase("speed", env, speed, episodes - n_steer, checkpoint_path(out, "speed"))


def goal_system(task: GoalFQL, learners: dict) -> FuzzySystem:
    """The extracted controller: every rule with its best conclusion(s), as a TS0 system."""
    inputs = task.inputs()
    outputs, conclusions = [], []
    for name, values, universe in (("steering", task.steering, (-PI / 5, PI / 5)), ("speed", SPEED3, (0.0, 4.0))):
        if name in learners:
            variable = output_variable("alpha" if name == "steering" else "v", values, universe)
            outputs.append(variable)
            conclusions.append([variable.labels[j] for j in learners[name].greedy_indices(TOLERANCE)[0, 0]])
    rules = math.prod(len(v.terms) for v in inputs)
    return grid_system(inputs, outputs, conclusions, task.name,
                       f"Goal seeking learned by fuzzy Q-learning (thesis §VI.5.1, Algorithm VI.1): {rules} rules, "
                       f"{len(task.steering)} steering conclusions" + (", speed learned" if "speed" in learners else ""))


def run_phases(phases, request) -> tuple[dict, dict]:
    """Run the phases in order; a later phase resumes only if every earlier one was already
    complete in its checkpoint (otherwise it is retrained on the changed earlier result)."""
    results, learners = {}, {}
    for offset, phase in enumerate(phases):
        results[phase.name] = run_phase(phase, request, offset)
        learners[phase.name] = phase.learner
        if results[phase.name].pop("continued"):
            request = replace(request, resume=False)
    return results, learners


def train_goal_fql(task: GoalFQL, request) -> dict:
    phases, learners = run_phases(goal_fql_phases(task, request.out, _episodes(request, task.episodes)), request)
    system = goal_system(task, learners)
    document = {"kind": "fql-goal", **to_document(system), "constant_speed": STEERING_SPEED,
                "training": {"task": task.name, "seed": request.seed, **_summary(phases)}}
    save_json_atomic(request.out, document)
    _write_curve(request, phases, task.name)
    return {"model": str(request.out), **_summary(phases)}


def train_fql_goal(request) -> dict:
    """``fuzzynav train fql-goal``: 15 rules × 3 conclusions, steering then speed (Figs VI.9–VI.10)."""
    return train_goal_fql(GOAL_TASKS["fql-goal"], request)


def train_fql_goal_35(request) -> dict:
    """``fuzzynav train fql-goal-35``: 35 rules × 5 conclusions (Figs VI.13–VI.14)."""
    return train_goal_fql(GOAL_TASKS["fql-goal-35"], request)


def train_fql_goal_traces(request) -> dict:
    """``fuzzynav train fql-goal-traces``: 15 rules × 3, eligibility traces λ = 0.7 (Figs VI.15–VI.16)."""
    return train_goal_fql(GOAL_TASKS["fql-goal-traces"], request)


# -- evaluation in the simulator -------------------------------------------------------------
def _scenario(world, start, goal, name: str, max_time: float):
    from fuzzynav.world.scenario import Goal, Scenario

    return Scenario(name=name, world=world, start=np.asarray(start, dtype=float),
                    goal=Goal(np.asarray(goal, dtype=float), GOAL_TOLERANCE), max_time=max_time)


def evaluate_goal(controller, n: int = 100, seed: int = 12345, goals: int = 10, max_time: float = 60.0) -> dict:
    """Success of a goal seeker in the simulator from ``n`` random starts (≥ 3 m from their goal)
    towards ``goals`` random goals in the empty 20 m × 20 m workspace (Figs VI.3, VI.10, VI.14)."""
    from fuzzynav.sim.simulator import BatchSimulator

    rng = np.random.default_rng(seed)
    layout = RandomGoal()
    outcomes = []
    for g in range(goals):
        world, candidates, targets = layout.sample(rng, 8 * math.ceil(n / goals))
        far = np.hypot(*(candidates[:, :2] - targets[0]).T) >= layout.min_distance
        starts = candidates[far][: n // goals + (g < n % goals)]
        scenario = _scenario(world, starts[0], targets[0], f"random-goal-{g}", max_time)
        outcomes += BatchSimulator(scenario, controller, starts=starts, record=False).run().outcomes()
    outcomes = outcomes[:n]
    return {"runs": len(outcomes), "success": outcomes.count("reached") / len(outcomes),
            "collisions": outcomes.count("collision"), "timeouts": outcomes.count("timeout")}


# -- obstacle avoidance, fuzzy Q-learning (§VI.5.2) ------------------------------------------
D_MAX = 4.0  # m, sensor range (docs/ARCHITECTURE.md)
AVOID_D_MIN, AVOID_D_SAFE = 1.5, 3.0  # d_m, d_s of Fig VI.17 (m): those of fuzzy-5b (Fig IV.18)
AVOID_SPEED = 1.0  # m/s: constant speed of the avoider while its steering is learned
AVOID_STEERING = STEERING3  # eq VI.18: {−π/5, 0, π/5}
AVOID_SPEEDS = {"F": 0.5, "M": 1.0, "G": 1.8}  # candidate speeds of the avoider (m/s)
AVOID_MAX_STEPS = 400
AVOID_BATCH = 10  # parallel episodes (one random world) per batch of the avoider — see the module docstring
AVOID_RATE = 1.0  # β × B of the wall follower: a constant rate that follows the improving policy; the avoider's floor ÷ BATCH
AVOID_RATE_START, AVOID_RATE_DECAY = 0.1, 0.95  # the avoider's β per batch: 0.1, × 0.95 down to AVOID_RATE / BATCH


def avoid_rate() -> ExponentialDecay:
    """β of the avoider's corrections (every robot of a batch adds one): fast while the first
    worlds teach the most, then down to the per-correction rate AVOID_RATE / BATCH (0.02) whose
    qualities average enough corrections for the extraction tolerance to hold."""
    return ExponentialDecay(AVOID_RATE_START, AVOID_RATE_DECAY, AVOID_RATE / BATCH)


AVOID_DECISION = 3  # steps Δt per learning decision (0.3 s)
AVOID_TOLERANCE = 0.05  # extraction tolerance: the avoider's quality gaps at the noise level are a few
# hundredths; extracted with tolerance 0 (plain argmax), 1 training seed of 5 collided in 31 of 100 worlds
# A-priori conclusions (indices of NG, Z, PG) of the 8 rules (front, right, left ∈ P, L; first
# slowest), from the principle of §IV.7: turn away from the nearer side, right when blocked in
# front (Table IV.3, rule R1). A rule keeps its prior unless a learned candidate beats it by more
# than AVOID_TOLERANCE — the "knowledge introduced a priori" of §VI.6.
AVOID_PRIOR = (0, 2, 0, 0, 1, 2, 0, 1)  # PPP PPL PLP PLL LPP LPL LLP LLL
# and the speed prior F (slow) near obstacles, the principle of the VRB (Table IV.6).
# With the openness input (AVOID_OPEN, below) the situations with both sides alike — PPP and PLL —
# turn a priori towards the more open side (open D: right, NG; open G: left, PG).
OPEN_PRIOR = {0: (0, 2), 3: (0, 2)}
# Deviation from the thesis (issue 5): the thesis' 8 rules cannot tell which side is more open when
# front, right and left are all near (a wall or a corner ahead) — in 100 random worlds they collided
# 4–8 times for every training seed. The avoider gets a fourth input, "open" (control.learned.openness,
# the mean reading of the left module minus the right's) with two labels D (right more open) and G
# (left more open), crossing over [0, OPEN_WIDTH]: 16 rules, 14 of them learned. The thesis' 8 rules stay
# available (open_side=False, the study fql-avoid-8 of benchmarks/rl_bench.py).
AVOID_OPEN = True
OPEN_WIDTH = 0.05  # m: |openness| beyond which one side is the more open (narrow: a tie must not cancel the turn)


def distance_variable(name: str, d_min: float, d_safe: float, d_max: float = D_MAX) -> Variable:
    """A distance d_i with P (near) and L (far) defined by d_m, d_s and D_max (Figs IV.18, VI.17)."""
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


def avoid_system(steering_index, speed_index=None, open_side: bool = AVOID_OPEN) -> FuzzySystem:
    """The learned avoider: the rules of Fig VI.17 with an obstacle near (the free rules of
    :func:`free_rules` excluded), conclusions by candidate index (steering, and speed if given)."""
    inputs = avoid_inputs(open_side)
    free = free_rules(open_side)
    outputs = [output_variable("alpha", AVOID_STEERING, (-PI / 5, PI / 5))]
    conclusions = [[outputs[0].labels[j] for j in steering_index]]
    if speed_index is not None:
        outputs.append(output_variable("v", AVOID_SPEEDS, (0.0, 4.0)))
        conclusions.append([outputs[1].labels[j] for j in speed_index])
    full = grid_system(inputs, outputs, [c + [c[0]] * free.size for c in conclusions], "fql-avoid", "")
    extra = " and which side is more open (a deviation: 16 rules instead of 8)" if open_side else ""
    return FuzzySystem(inputs, outputs, full.rules[:free[0]], method="ts0", tnorm="product",
                       defuzzifier="weighted_sum", name="fql-avoid",
                       description="Obstacle avoidance learned by fuzzy Q-learning (thesis §VI.5.2, eqs VI.18-VI.21) "
                                   f"over front, right, left distances{extra}; "
                                   "the situation 'front, right and left far' is goal seeking (Table IV.1)")


def _avoid_candidates(values: dict, open_side: bool) -> np.ndarray:
    """(R, 3) candidates; the free rules' are 0 (their share is goal seeking's, added by the env)."""
    free = free_rules(open_side)
    candidates = np.tile(np.array(list(values.values())), (free[-1] + 1, 1))
    candidates[free] = 0.0
    return candidates


def fql_avoid_phases(out: Path, episodes: int, batch: int = AVOID_BATCH, open_side: bool = AVOID_OPEN):
    """Steering (eq VI.20) then speed (eq VI.21) of the avoider, trained inside the navigator."""
    from fuzzynav.control import supervisor
    from fuzzynav.control.goal_seeking import GuardedGoalSeeking
    from fuzzynav.control.learned import avoidance_inputs, avoidance_supervisor, supervise

    inputs = avoid_inputs(open_side)
    free_rule = free_rules(open_side)
    template = grid_system(inputs, [output_variable("alpha", AVOID_STEERING, (-PI / 5, PI / 5))],
                           [["Z"] * (free_rule[-1] + 1)], "premise", "")
    premise = GridPremise(template)
    gsb = GuardedGoalSeeking()
    params = avoidance_supervisor(template)
    layout = RandomObstacles()
    sensors = SensorRing()

    def observe(s):
        """The avoider's inputs; where the supervisor hands the robot to goal seeking, "all far"
        (the free rules): the avoider does not act there, so its rules get no credit for it."""
        x = avoidance_inputs(s.ranges, open_side)
        seeking = supervisor.select(s.ranges, s.goal[:, 0], -s.goal[:, 1], params) == supervisor.GSB
        x[seeking, :3] = D_MAX
        return x

    def navigate(s, alpha, speed):
        """The navigator of control.learned with the learner's (α, V_r) shares of the avoider."""
        goal = np.column_stack(gsb(s.goal[:, 0], -s.goal[:, 1])[:2])
        free = premise.firing_strengths(observe(s), normalise=False)[:, free_rule].sum(axis=1)
        blended = np.column_stack([alpha + free * goal[:, 0], speed(free) + free * goal[:, 1]])
        return supervise(blended, goal, s.ranges, s.goal[:, 0], -s.goal[:, 1], params)[:2]

    def steer_command(a, s):
        return navigate(s, a[:, 0], lambda free: (1.0 - free) * AVOID_SPEED)

    steer = fql_learner(premise, _avoid_candidates(AVOID_STEERING, open_side), 0.0, batch,
                        prior=avoid_prior(open_side), alpha=avoid_rate())
    n_steer = steering_episodes(episodes, AVOID_SPEED_SHARE)
    env = RobotEnv(layout, observe, steer_command, AvoidSteeringReward(D_MAX), batch=batch,
                   max_steps=AVOID_MAX_STEPS // AVOID_DECISION, tolerance=GOAL_TOLERANCE, sensors=sensors,
                   decision_steps=AVOID_DECISION)
    yield Phase("steering", env, steer, n_steer, checkpoint_path(out, "steering"), WORLD_CONVERGENCE)

    def speed_command(a, s):
        return navigate(s, steer.greedy_action(observe(s), AVOID_TOLERANCE)[:, 0], lambda free: a[:, 0])

    speed = fql_learner(premise, _avoid_candidates(AVOID_SPEEDS, open_side), 0.0, batch, prior=0,
                        alpha=avoid_rate())
    env = RobotEnv(layout, observe, speed_command, AvoidSpeedReward(D_MAX, low=1.0), batch=batch,
                   max_steps=AVOID_MAX_STEPS // AVOID_DECISION, tolerance=GOAL_TOLERANCE, sensors=sensors,
                   decision_steps=AVOID_DECISION)
    yield Phase("speed", env, speed, episodes - n_steer, checkpoint_path(out, "speed"), WORLD_CONVERGENCE)


AVOID_SPEED_SHARE = 0.5  # the thesis: ~250 episodes steering, ~2,000 speed (Fig VI.22)
AVOID_EPISODES = 2000  # default budget: 1,000 per phase (the hold of WORLD_CONVERGENCE needs 250 episodes after k)


def train_fql_avoid(request, open_side: bool = AVOID_OPEN) -> dict:
    """``fuzzynav train fql-avoid``: the avoider over front/right/left distances (Figs VI.17–VI.22)
    and, by default, which side is more open (:data:`AVOID_OPEN`: 16 rules instead of the thesis' 8)."""
    phases, learners = run_phases(
        fql_avoid_phases(request.out, _episodes(request, AVOID_EPISODES), open_side=open_side), request)
    learned = free_rules(open_side)[0]
    system = avoid_system(learners["steering"].greedy_indices(AVOID_TOLERANCE)[0, 0, :learned],
                          learners["speed"].greedy_indices(AVOID_TOLERANCE)[0, 0, :learned], open_side)
    document = {"kind": "fql-avoid", **to_document(system), "constant_speed": AVOID_SPEED,
                "training": {"task": "fql-avoid", "seed": request.seed, **_summary(phases)}}
    save_json_atomic(request.out, document)
    _write_curve(request, phases, "fql-avoid")
    return {"model": str(request.out), **_summary(phases)}


def evaluate_avoid(controller, n: int = 100, seed: int = 54321, max_time: float = 60.0) -> dict:
    """Success and collisions of a navigator in ``n`` random obstacle worlds (one start and goal
    each, drawn as in training but from another seed) — the evaluation of §VI.5.2."""
    from fuzzynav.sim.simulator import BatchSimulator

    rng = np.random.default_rng(seed)
    outcomes = []
    for k in range(n):
        world, starts, goals = RandomObstacles().sample(rng, 1)
        scenario = _scenario(world, starts[0], goals[0], f"random-world-{k}", max_time)
        outcomes += BatchSimulator(scenario, controller, record=False).run().outcomes()
    return {"runs": n, "success": outcomes.count("reached") / n, "collisions": outcomes.count("collision"),
            "timeouts": outcomes.count("timeout")}


# -- wall following optimised by FQL (§VI.5.3.2) -----------------------------------------------
WALL_SPREAD = math.radians(10.0)  # three interpretations per steering label: value − 10°, value, value + 10°
WALL_SPEED_SCALE = (0.7, 1.0, 1.3)  # and per speed label: 0.7, 1, 1.3 × its value
WALL_SUFFIXES = ("_lo", "", "_hi")
WALL_DECISION = 3
WALL_TOLERANCE = 0.02  # extraction tolerance of the wall follower's interpretations
WALL_MAX_STEPS = 300


def wall_parts():
    """The hand-made follower (Table VI.2), its premise, and the candidates of every rule."""
    from fuzzynav.fuzzy.systems_navigation import wall_follower

    handmade = wall_follower()
    values = handmade.compiled.values  # (R, 2): α and V_r of every rule
    alpha = np.clip(values[:, :1] + WALL_SPREAD * np.array([-1.0, 0.0, 1.0]), -PI / 4, PI / 4)
    speed = np.clip(values[:, 1:] * np.array(WALL_SPEED_SCALE), 0.0, 4.0)
    return handmade, GridPremise(handmade), alpha, speed


WALL_COLUMNS = [1, 0, 2]  # (d_d, d_f, d_g) = (right, front, left) of the env's sides (front, right, left)


WALL_SENSING = "rays"  # the hand-made follower's single rays (control.learned.SENSING)
WALL_REWARD_SENSING = "modules"  # the d_i of the rewards VI.21-VI.22: nearest of each module's three sensors


def fql_wall_phases(out: Path, episodes: int, batch: int = BATCH, sensing: str = WALL_SENSING):
    """Steering (eq VI.21) then speed (eq VI.22) interpretations, from the hand-made follower.

    ``sensing`` is how the learner reads d_d, d_f, d_g (:data:`fuzzynav.control.learned.SENSING`):
    by default the single rays at −90°, 0°, +90° of the hand-made follower, so that what learning
    changes is the interpretations only. The rewards' d_i (eqs VI.21–VI.22) are the nearest
    reading of each module's three sensors (:data:`WALL_REWARD_SENSING`): the critic sees the
    corner tip between the rays that the follower does not (Fig VI.28), so the near-corner states
    that end in the collision are punished before it — on the rays alone one training seed of five
    still hit the Fig VI.28 corner.
    """
    from fuzzynav.control.learned import SENSING
    from fuzzynav.fuzzy.systems_navigation import WALL_D_M, WALL_D_S

    handmade, premise, alpha, speed = wall_parts()
    layout, sensors, sides, inputs = WallCourse(), SensorRing(), SENSING[WALL_REWARD_SENSING], SENSING[sensing]

    def observe(s):
        return inputs(s.ranges)[:, WALL_COLUMNS]

    steer = fql_learner(premise, alpha, 0.0, batch, prior=1, alpha=AVOID_RATE / batch)
    n_steer = steering_episodes(episodes, SPEED_SHARE)
    env = RobotEnv(layout, observe, lambda a, s: (a[:, 0], handmade.evaluate(observe(s))[:, 1]),
                   WallSteeringReward(WALL_D_M), batch=batch, max_steps=WALL_MAX_STEPS // WALL_DECISION,
                   sensors=sensors, decision_steps=WALL_DECISION, sides=sides)
    yield Phase("steering", env, steer, n_steer, checkpoint_path(out, "steering"), WORLD_CONVERGENCE)
    fast = fql_learner(premise, speed, 0.0, batch, prior=1, alpha=AVOID_RATE / batch)
    env = RobotEnv(layout, observe, lambda a, s: (steer.greedy_action(observe(s), WALL_TOLERANCE)[:, 0], a[:, 0]),
                   WallSpeedReward(WALL_D_S), batch=batch, max_steps=WALL_MAX_STEPS // WALL_DECISION,
                   sensors=sensors, decision_steps=WALL_DECISION, sides=sides)
    yield Phase("speed", env, fast, episodes - n_steer, checkpoint_path(out, "speed"), WORLD_CONVERGENCE)


def wall_system(handmade, candidates: dict, learners: dict, sensing: str = WALL_SENSING) -> FuzzySystem:
    """The optimised follower: Table VI.2's rules with the chosen interpretation of each label
    (``PG_lo`` / ``PG`` / ``PG_hi`` = value − 10°, value, value + 10°; speeds × 0.7, 1, 1.3)."""
    outputs, conclusions = [], []
    for o, (name, universe) in enumerate((("alpha", (-PI / 4, PI / 4)), ("v", (0.0, 4.0)))):
        chosen = learners["steering" if o == 0 else "speed"].greedy_indices(WALL_TOLERANCE)[0, 0]
        terms, labels = {}, []
        for r, rule in enumerate(handmade.rules):
            label = dict(rule.conclusions)[name] + WALL_SUFFIXES[chosen[r]]
            terms[label] = Singleton(float(candidates[name][r, chosen[r]]))
            labels.append(label)
        outputs.append(Variable(name, universe, terms))
        conclusions.append(labels)
    rules = [Rule(rule.premises, ((outputs[0].name, conclusions[0][r]), (outputs[1].name, conclusions[1][r])))
             for r, rule in enumerate(handmade.rules)]
    return FuzzySystem(handmade.inputs, outputs, rules, method="ts0", tnorm="product", defuzzifier="weighted_sum",
                       name="fql-wall", description="Wall follower of Table VI.2 optimised by fuzzy Q-learning "
                                                    f"(thesis §VI.5.3.2, eqs VI.21-VI.22); sensing: {sensing} "
                                                    f"({WALL_SENSINGS[sensing]})")


WALL_SENSINGS = {"rays": "single rays at -90, 0, +90 degrees, as the hand-made follower",
                 "modules": "nearest of the three sensors of each module"}


def train_fql_wall(request, sensing: str = WALL_SENSING) -> dict:
    """``fuzzynav train fql-wall``: Table VI.2's interpretations learned (Figs VI.29–VI.30) on the
    hand-made follower's single rays (``sensing``: :data:`WALL_SENSINGS`)."""
    handmade, _, alpha, speed = wall_parts()
    phases, learners = run_phases(fql_wall_phases(request.out, _episodes(request, 1500), sensing=sensing), request)
    system = wall_system(handmade, {"alpha": alpha, "v": speed}, learners, sensing)
    document = {"kind": "fql-wall", "sensing": sensing, **to_document(system),
                "training": {"task": "fql-wall", "seed": request.seed, **_summary(phases)}}
    save_json_atomic(request.out, document)
    _write_curve(request, phases, "fql-wall")
    return {"model": str(request.out), **_summary(phases)}


def wall_course_scenario(rng, name: str, max_time: float = 30.0):
    """A random wall course as a scenario. The follower ignores goals: the goal, in a corner of
    the workspace, only gives the episode a task; success is lasting ``max_time`` without collision."""
    world, starts, _ = WallCourse().sample(rng, 1)
    return _scenario(world, starts[0], (0.5, 0.5), name, max_time)


def evaluate_wall(controller, n: int = 20, seed: int = 777, max_time: float = 30.0) -> dict:
    """Collisions of a wall follower on the Fig VI.28 corners and on ``n`` random wall courses."""
    from fuzzynav.sim.simulator import BatchSimulator
    from fuzzynav.world.scenario import load_scenario

    corners = BatchSimulator(load_scenario("fig-VI-28"), controller, record=False).run().outcomes()[0]
    rng = np.random.default_rng(seed)
    outcomes = []
    for k in range(n):
        scenario = wall_course_scenario(rng, f"wall-course-{k}", max_time)
        outcomes += BatchSimulator(scenario, controller, record=False).run().outcomes()
    return {"fig-VI-28": corners, "courses": n, "collisions": outcomes.count("collision")}
