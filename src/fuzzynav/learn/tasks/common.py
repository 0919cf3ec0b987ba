"""What the learning tasks share: the request, phases and their budgets, convergence, curves, model files.

A reinforcement-learning task (one module of this package per task family) assembles, for each of
its *phases* (steering, then speed), a :class:`~fuzzynav.learn.envs.RobotEnv` (layout, inputs,
actions, a reward of :mod:`fuzzynav.learn.rewards`) and a learner of :mod:`fuzzynav.learn`; it trains
them resumably with :func:`run_phases` (:func:`~fuzzynav.learn.checkpoint.train_loop` underneath,
one checkpoint per phase next to ``--out``), extracts the controller and writes its model file with
:func:`save_model`.

Two protocols (:func:`robots`). By default the *thesis'* (§VI.2, §VI.5, Algorithm VI.1): one robot,
one episode after another, every q[i, j] = 0 at start (eq VI.9), ε-greedy exploration, β = 1 / (1 +
visits) (eq III.24) and, after learning, each rule's conclusion of best quality ("le robot choisit
pour chaque règle la conclusion avec la meilleure fonction qualité", §VI.5.1) — settings in
:data:`THESIS`. ``fuzzynav train … --parallel N`` runs N robots per *batch* sharing one rule base
(:data:`BATCH`, :data:`FIXED_BATCH` are the tasks' usual N), a faster learner whose curves count
episodes in batches of N. Every count of episodes (``--episodes``, checkpoints, curves, episodes
to converge) counts single episodes. ``converged_at`` of a phase is :func:`fuzzynav.learn.curves.episodes_to_converge` under
the task's criterion (:data:`GOAL_CONVERGENCE`, or :data:`WORLD_CONVERGENCE` where every batch, or
the single robot's every episode, is one random world: :func:`criterion`). The reasons for these settings, with what was measured, are in docs/training.md.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from fuzzynav import validation
from fuzzynav.control.learned import check_speed, model_name
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.constants import STEERING_SINGLETONS
from fuzzynav.fuzzy.coverage import check_covered, check_rules_cover
from fuzzynav.fuzzy.io.document import TOP_KEYS, from_document
from fuzzynav.fuzzy.membership import Singleton
from fuzzynav.fuzzy.rules import Rule
from fuzzynav.fuzzy.system import FuzzySystem
from fuzzynav.fuzzy.variable import Variable
from fuzzynav.learn.checkpoint import check_resumable, episodes_done, train_loop
from fuzzynav.learn.curves import episodes_to_converge
from fuzzynav.learn.exploration import EpsilonGreedy
from fuzzynav.learn.fql import FuzzyQLearner
from fuzzynav.learn.schedules import ExponentialDecay, InverseVisits
from fuzzynav.learn.tasks.plan import batch_plan, checkpoint_progress
from fuzzynav.storage import save_document, savefig_atomic
from fuzzynav.world.scenario import DEFAULT_GOAL_TOLERANCE

if TYPE_CHECKING:
    from fuzzynav.learn.envs import RobotEnv

PI = math.pi
BATCH = 50  # parallel episodes per batch (random starts)
FIXED_BATCH = 10  # parallel episodes per batch from a fixed start (Figs VI.1, VI.8)
SPEED_SHARE = 0.25  # share of a two-phase task's episodes given to the speed phase
TOLERANCE = 0.05  # extraction: minimum quality gain over the prior conclusion
GOAL_TOLERANCE = DEFAULT_GOAL_TOLERANCE  # m: the scenarios' default
STEERING_SPEED = 1.8  # m/s: the constant speed of the steering phases (M of Fig IV.8)
MAX_STEPS = 300  # 30 s per episode
GOAL_CONVERGENCE = {"window": 50, "hold": 500, "target": 0.95}  # learn.curves.episodes_to_converge
WORLD_CONVERGENCE = {"worlds": 10, "hold_worlds": 15, "target": None, "clustered": True,  # one random world per batch
                     "one_robot": {"window": 100, "hold": 500, "noise": 2.0, "target": None}}
# "one_robot": the thesis' protocol; its reading of its curves, "à partir de l'épisode 180, la valeur moyenne
# des renforcements est constante" (§VI.5.1, Fig VI.8), made a test that the first window can fail

STEERING3 = {label: STEERING_SINGLETONS[label] for label in ("NG", "Z", "PG")}  # eq VI.12
STEERING5 = {label: STEERING_SINGLETONS[label] for label in ("NG", "NM", "Z", "PM", "PG")}  # eq VI.15
SPEED3 = {"S": 0.1, "L": 0.5, "F": 1.0, "M": 1.8, "G": 3.0}  # the candidate speeds' labels (m/s): F, M, G
# of Fig IV.8 and, to stop (Table IV.1 concludes Z = 0 at the goal), a creeping S and a low L
SPEED_CANDIDATES = (("S", "L", "F"), ("L", "F", "M"), ("F", "M", "G"))  # eq VI.13's V_i1..3 of a rule whose
# d_rg is its partition's first term, its second, any farther one. The thesis indexes the candidates by
# rule (V_ij) without their values; a rule near the goal may creep, one far away may not (with one set for
# every rule, eq VI.14 — −1 for speeding up, +1 only on arriving slowly — lets a creeping speed that never
# arrives win everywhere: docs/results/chapter-vi.md).


@dataclass(frozen=True)
class TrainRequest:
    """What the user asked of one training run (defaults are each task's own when ``None``)."""

    out: Path
    task: str = ""  # the TASK name, recorded in checkpoints (a resume of another task is refused)
    episodes: int | None = None
    seed: int = 0
    resume: bool = False
    checkpoint_every: int | None = None
    curve: Path | None = None  # learning-curve plot to write, if any
    progress: bool = True
    parallel: int | None = None  # robots per batch (--parallel); None: the thesis' one robot at a time
    prior: str | None = None  # fql-avoid's initial table (--prior none | thesis); None: the task's default
    on_resume: Callable[[list], None] | None = None  # told what a resumed run goes on from (check_resume)


def save_model(request: TrainRequest, document: dict) -> None:
    """Write a task's model document to ``request.out`` (atomically, in the format of its extension)."""
    save_document(request.out, document)


def finish(request: TrainRequest, document: dict, phases: dict, title: str) -> dict:
    """Write the model and (if asked) the learning curves; the results ``fuzzynav train`` prints."""
    save_model(request, document)
    write_curve(request, phases, title)
    return {"model": str(request.out), **summarise(phases)}


def load_fuzzy_model(document: dict, path, build, keys=("constant_speed",), free: tuple[dict, ...] = ()):
    """The controller of a learned fuzzy model file, ``build(system, constant_speed, name)``, every
    error naming the file. The system is the file's ``fuzzynav-fis`` document: its terms cover their
    universes and its rules every combination of terms but the ``free`` ones (:mod:`~fuzzynav.fuzzy.coverage`).
    Its keys are the system's, ``kind``, ``training`` and the model's ``keys``: a typo is refused."""
    if "inputs" not in document:  # another kind of model relabelled (it is already run with --model)
        raise InputError(f"missing (a {document['kind']!r} model holds a fuzzy system)", source=str(path),
                         field="inputs")
    validation.known_keys(document, (*TOP_KEYS, "kind", "training", *keys), str(path))
    system = from_document(document, source=str(path))
    check_covered(system, str(path))
    check_rules_cover(system, str(path), free)
    try:
        return build(system, check_speed(document.get("constant_speed", 1.0), "constant_speed"), model_name(document))
    except InputError as error:
        raise InputError(error.problem, source=str(path), field=error.field) from None


# -- rule bases ------------------------------------------------------------------------------
def output_variable(name: str, values: dict[str, float], universe) -> Variable:
    """An output variable of singletons ``label -> value`` (the candidates of a learned conclusion)."""
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


PHASES = ("steering", "speed")  # the phases' names, in their order


def checkpoint_path(out: Path, phase: str) -> Path:
    return Path(out).with_name(f"{Path(out).name}.{phase}.checkpoint.json")


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
        for batches, size in batch_plan(phase.episodes, batch, checkpoint_progress(phase.checkpoint, resume)):
            phase.env.batch = size
            result = train_loop(phase.env, phase.learner, batches, rng, checkpoint=phase.checkpoint,
                                checkpoint_every=every, resume=resume, progress=request.progress, batch_size=size,
                                desc=phase.name, budget=phase.episodes, extra=run_settings(request, phase.name, batch))
            resume, continued = True, continued or result.resumed_from != result.episode
    finally:
        phase.env.batch = batch
    reward, success = episode_curve(result.curve, "mean_reward"), episode_curve(result.curve, "success")
    return {"episodes": int(reward.size), "mean_reward": reward, "success": success, "continued": continued,
            "converged_at": converged_at(reward, success, batch, phase.convergence),
            "window": convergence_window(phase.convergence or GOAL_CONVERGENCE, batch)[0],
            "final_success": float(success[-min(success.size, 5 * batch):].mean())}


def run_settings(request, phase: str, batch: int) -> dict:
    """What a phase's checkpoint records of its run, which a resumed run must share."""
    return {"task": request.task, "phase": phase, "seed": int(request.seed), "batch": batch}


def check_resume(first: Phase, request) -> None:
    """Before a resumed run trains anything, the checkpoints it will go on from must be its own:
    the first phase's in full, the later ones' in the run's settings (their learners are built
    when the phases before them have trained), each while the one before it is complete (else it
    is retrained); then ``request.on_resume`` is told [(phase, checkpoint, episodes done)]."""
    found = []
    for name in PHASES[PHASES.index(first.name):]:
        path, settings = checkpoint_path(request.out, name), run_settings(request, name, first.env.batch)
        if not path.exists():
            break
        own = (first.episodes, first.learner) if name == first.name else ()  # a later phase's: its settings
        found.append((name, path, episodes_done(check_resumable(path, settings, *own)["curve"])))
        if own and found[-1][2] < first.episodes:
            break
    if request.on_resume is not None:
        request.on_resume(found)


def criterion(settings: dict, batch: int) -> dict:
    """The convergence settings that apply to a run of ``batch`` robots per batch.

    Where one batch is one random world (``worlds``), the batch learner counts its window and
    hold in worlds; the thesis' single robot meets a new world every episode, so its episodes
    are independent samples and its settings are ``one_robot``'s, in episodes: a window of 100
    (its noise band, 2 standard errors of a window's mean, ≈ 0.05 for the avoider's σ ≈ 0.25 per
    episode, is narrower than the ≈ 0.12 its curve rises; counting 5-episode "worlds" with a
    3-standard-error band and a 75-episode hold made the first window always qualify) and a
    hold of 500 episodes, as the goal tasks'."""
    if "worlds" not in settings:
        return settings
    if thesis_protocol(batch):
        return settings["one_robot"]
    return {"window": settings["worlds"] * batch, "hold": settings["hold_worlds"] * batch,
            "target": settings["target"], "clustered": settings["clustered"]}


def convergence_window(settings: dict, batch: int) -> tuple[int, int]:
    """(window, hold) in episodes of a convergence setting for ``batch`` robots per batch (:func:`criterion`)."""
    settings = criterion(settings, batch)
    return settings["window"], settings["hold"]


def converged_at(reward, success, batch: int, settings: dict | None = None) -> int:
    """Episodes to converge of one phase (module docstring, :mod:`fuzzynav.learn.curves`)."""
    settings = criterion(settings or GOAL_CONVERGENCE, batch)
    options = {"noise": settings["noise"]} if "noise" in settings else {}
    return episodes_to_converge(reward, window=settings["window"], hold=settings["hold"], batch=batch,
                                success=None if settings["target"] is None else success,
                                target=settings["target"] or 0.0, clustered=settings.get("clustered", False),
                                **options)


class PhaseSummary(dict):
    """The train results of one phase: ``episodes``, ``converged_at`` (``None`` when the curve did
    not settle within the budget) and ``final_training_success``; JSON as a plain mapping, and
    printed by ``fuzzynav train`` as one readable line ("not converged within N episodes" for
    ``None``), whose words ``fuzzynav.cli.train.PHASE_NOTE`` explains."""

    def __str__(self) -> str:
        episodes = f"{self['episodes']} episode{'s' * (self['episodes'] != 1)}"
        converged = f"not converged within {episodes}" if self["converged_at"] is None else \
            f"converged at episode {self['converged_at']}"
        return (f"{episodes}, {converged}; success in the last training episodes "
                f"{self['final_training_success']:.1%}")


def summarise(phases: dict) -> dict:
    """Per phase, :class:`PhaseSummary` (``converged_at`` beyond the curve → ``None``)."""
    return {name: PhaseSummary(episodes=r["episodes"],
                               converged_at=r["converged_at"] if r["converged_at"] <= r["episodes"] else None,
                               final_training_success=round(r["final_success"], 4))
            for name, r in phases.items()}


def episode_budget(request, default: int) -> int:
    """The task's total episodes: ``--episodes``, else its ``default``; at least one."""
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


def write_curve(request, phases: dict, title: str) -> None:
    """The learning curve of every phase, side by side, into ``request.curve`` (if given)."""
    if request.curve is None:
        return
    import matplotlib.pyplot as plt

    from fuzzynav.viz.curves import plot_learning_curve

    figure, axes = plt.subplots(1, len(phases), figsize=(6.4 * len(phases), 4.0), squeeze=False)
    for ax, (name, result) in zip(axes[0], phases.items()):
        plot_learning_curve(result["mean_reward"], ax=ax, window=result["window"], title=f"{title}: {name}",
                            label=name, converged_at=result["converged_at"])
    savefig_atomic(figure, request.curve, dpi=120, bbox_inches="tight")
    plt.close(figure)


def run_phases(phases, request) -> tuple[dict, dict]:
    """Run the phases in order; a later phase resumes only if every earlier one was already
    complete in its checkpoint (otherwise it is retrained on the changed earlier result); a resumed
    run checks first what it goes on from (:func:`check_resume`)."""
    results, learners = {}, {}
    for offset, phase in enumerate(phases):
        if offset == 0 and request.resume:
            check_resume(phase, request)
        results[phase.name] = run_phase(phase, request, offset)
        learners[phase.name] = phase.learner
        if results[phase.name].pop("continued"):
            request = replace(request, resume=False)
    return results, learners


def batch_size(fixed: bool) -> int:
    """Parallel episodes of a task: :data:`FIXED_BATCH` from a fixed start, else :data:`BATCH`."""
    return FIXED_BATCH if fixed else BATCH


# The thesis' protocol (module docstring). The thesis gives neither ε, β nor γ: ε-greedy is its
# example policy (§VI.4, "ε-gloutonne par exemple"), β = 1 / (1 + visits) its eq III.24 (floored at
# 0.01 so that late corrections still count: at 0.05 the avoider's qualities stayed too noisy to rank
# its candidates, docs/results/chapter-vi.md), γ = 0.9. ε decays per episode 0.3 → 0.02 (the floor after
# ~900 episodes: the same pace per episode as the parallel learner's × 0.85 per batch of 50).
THESIS = {"robots": 1, "gamma": 0.9, "epsilon": (0.3, 0.85 ** (1 / BATCH), 0.02), "rate_floor": 0.01,
          "tolerance": 0.0, "initial_q": 0.0}


def robots(request) -> int:
    """Robots per batch of a run: ``--parallel N``, else the thesis' single robot."""
    return int(request.parallel) if request.parallel else THESIS["robots"]


def thesis_protocol(batch: int) -> bool:
    """One robot, one episode after another: the thesis' protocol (module docstring)."""
    return batch == THESIS["robots"]


def extraction_tolerance(batch: int, parallel_tolerance: float) -> float:
    """Quality gain over the prior a conclusion needs to be extracted: none in the thesis'
    protocol (the conclusion of best quality), ``parallel_tolerance`` for the batch learner."""
    return THESIS["tolerance"] if thesis_protocol(batch) else parallel_tolerance


def thesis_schedules() -> tuple[InverseVisits, EpsilonGreedy]:
    """(β, ε-greedy policy) of the thesis' protocol (:data:`THESIS`), for every learner that follows it."""
    return InverseVisits(1.0, 1.0, THESIS["rate_floor"]), EpsilonGreedy(ExponentialDecay(*THESIS["epsilon"]))


def batch_schedules(batch: int) -> tuple[InverseVisits, ExponentialDecay]:
    """(β, ε) of the batch learner of ``batch`` robots: β = 1 / (1 + visits) floored at 0.2 / B, so
    the B parallel corrections stay small, and ε decaying 0.3 → 0.02, × 0.85 per batch."""
    return InverseVisits(1.0, 1.0, 0.2 / batch), ExponentialDecay(0.3, 0.85, 0.02)


def fql_learner(premise, candidates, lam: float = 0.0, batch: int = BATCH, prior=None, alpha=None) -> FuzzyQLearner:
    """The FQL settings of every task: γ = 0.9, q = 0 at start (eq VI.9), ε-greedy per rule.

    Thesis protocol (``batch`` 1, :data:`THESIS`): β = 1 / (1 + visits) (eq III.24) down to
    0.01, ε = 0.3 · 0.9967^episode down to 0.02, and the step that ends an episode bootstrapped
    like any other (Algorithm VI.1 computes V*(s') and updates q before its test "jusqu'à
    s_t ∈ F", §VI.4: :class:`~fuzzynav.learn.fql.FuzzyQLearner`'s ``terminal_bootstrap``). Batch
    learner: β = 1 / (1 + visits) floored so the B parallel corrections stay small (``alpha``
    replaces it when given), ε decaying 0.3 → 0.02 (× 0.85 per batch), no bootstrap at the end."""
    if thesis_protocol(batch):
        alpha, policy = thesis_schedules()
    else:
        rate, epsilon = batch_schedules(batch)
        alpha, policy = rate if alpha is None else alpha, EpsilonGreedy(epsilon)
    return FuzzyQLearner(premise, candidates, gamma=THESIS["gamma"], alpha=alpha, policy=policy, lam=lam,
                         normalise=False, prior=prior, initial_q=THESIS["initial_q"],
                         terminal_bootstrap=thesis_protocol(batch))


def protocol_record(batch: int, prior: str) -> dict:
    """How a model was trained, for its file: the protocol (``thesis``: one robot; else
    ``parallel`` with its robots per batch, whose episodes were counted in batches) and the
    initial table (``prior``)."""
    if thesis_protocol(batch):
        return {"protocol": "thesis", "prior": prior}
    return {"protocol": "parallel", "robots_per_batch": int(batch), "prior": prior}


def rules_changed(learners, tolerance: float, rules: int | None = None) -> int:
    """How many rules the extraction changed from the initial table: rules (the first ``rules``,
    default all) whose extracted conclusion of any learner differs from that learner's prior —
    its initial table, which the extraction keeps when learning found nothing better."""
    changed = np.zeros(learners[0].prior.shape[1], dtype=bool)
    for learner in learners:
        changed |= (learner.greedy_indices(tolerance)[0] != learner.prior).any(axis=0)
    return int(changed[:rules].sum())

