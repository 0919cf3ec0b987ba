"""One tuning run: checked options, the generations, the checkpoint, the result and its held-out test.

:func:`check` validates every option before any work (an :class:`InputError` naming the option);
:func:`tune` runs generations of ask → simulate (:class:`~fuzzynav.tune.fitness.Fitness`) →
tell until the budget is spent, keeping the best candidate ever
evaluated (the start is evaluated first, so the result is never worse than the start on the
training worlds). With validation worlds (``validation``; for a generated family by default its
worlds with seed + :data:`VALIDATION_OFFSET`), the last episodes of the budget run the start and
the :data:`VALIDATED` best distinct candidates on them, and the result is the one of lowest
validation cost — the start when none beats it: model selection on worlds the search never saw
(early stopping by a validation set; Hastie, Tibshirani & Friedman, *The Elements of Statistical
Learning*, 2009, §7.2), since a candidate that fixes the training worlds' few failures often
fails others (docs/tuning.md measures it). After each generation the checkpoint (:mod:`~fuzzynav.tune.checkpoint`; ``.npz``: the options and every
population with its objective values) is rewritten atomically; ``resume`` replays the stored
generations through a new optimiser — same seed, same populations, same values, no
simulation — checks that each replayed population is the one stored, and goes on, so a killed
and resumed run ends exactly where an uninterrupted one does.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.tune import checkpoint
from fuzzynav.tune.fitness import OBJECTIVES, Fitness
from fuzzynav.tune.optimisers import METHODS, check_available
from fuzzynav.tune.space import WHAT

MAX_BUDGET = 10_000_000
HOLDOUT_OFFSET = 1000  # a generated family's held-out worlds: world seed + this (worlds never tuned on)
VALIDATION_OFFSET = 500  # its validation worlds: world seed + this (chosen on, never searched on)
VALIDATED = 3  # best distinct candidates run on the validation worlds beside the start


@dataclass(frozen=True)
class TuneRequest:
    """The options of ``fuzzynav tune`` (:mod:`fuzzynav.cli.tune`)."""

    target: str  # CONTROLLER:ROLE
    worlds: str  # a SUITE of ``fuzzynav bench``
    what: str = "both"
    method: str = "ga"
    budget: int = 3000  # simulated episodes (one candidate on one training world each)
    seed: int = 0
    population: int = 10
    objectives: tuple[str, ...] = ()
    holdout: str | None = None  # default: the family's worlds with seed + HOLDOUT_OFFSET
    # validation worlds: None (none), "auto" (a family's worlds with seed + VALIDATION_OFFSET; none
    # for a folder) or a SUITE; their episodes are part of the budget
    validation: str | None = None
    out: str | None = None
    resume: bool = False
    curve: str | None = None
    progress: bool = True
    # the controller's rule bases by role in place of its built-in ones: the tuned role's start and
    # the fixed others (``fuzzynav reproduce cmp-VI-tuning --fis ROLE=FILE`` passes them)
    systems: Mapping[str, Any] = field(default_factory=dict)
    on_start: Callable[[], None] | None = None  # called once every check has passed, before the first generation

    @property
    def controller(self) -> str:
        return self.target.partition(":")[0]

    @property
    def role(self) -> str:
        return self.target.partition(":")[2]

    def replayed(self) -> dict:
        """The options a checkpoint must share with the run resuming it."""
        keys = ("target", "worlds", "what", "method", "seed", "population", "objectives", "validation")
        return {key: list(value) if isinstance(value, tuple) else value
                for key, value in ((key, getattr(self, key)) for key in keys)}


def check(request: TuneRequest):
    """Every option checked before any work; returns (controller, start system, suite, held-out suite)."""
    from fuzzynav.bench.suites import parse_suite
    from fuzzynav.catalog.controllers import spec_of
    from fuzzynav.catalog.roles import ROLES, default_system, make_with_systems, roles_of
    from fuzzynav.tune.space import SearchSpace

    controller, sep, role = request.target.partition(":")
    if not sep or not controller or not role:
        raise InputError(f"expected CONTROLLER:ROLE (e.g. fuzzy-2b:oab), got {request.target!r}",
                         field="CONTROLLER:ROLE")
    try:
        system = default_system(controller, role)
    except InputError as error:
        raise InputError(error.problem, field="CONTROLLER:ROLE") from None
    foreign = sorted(set(request.systems) - set(roles_of(controller)))
    if foreign:
        raise InputError(f"{controller} has no role {', '.join(foreign)} (its roles: {', '.join(roles_of(controller))})",
                         field="--fis")
    system = request.systems[role] if role in request.systems else system
    validation.choice(request.what, WHAT, field="--what")
    validation.choice(request.method, METHODS, field="--method")
    check_available(request.method)
    validation.integer(request.population, field="--population", lo=2, hi=10_000)
    validation.integer(request.budget, field="--budget", lo=1, hi=MAX_BUDGET)
    validation.integer(request.seed, field="--seed", lo=0, hi=validation.MAX_SMALL_SEED)
    if request.objectives and request.method != "nsga2":
        raise InputError("--objectives needs --method nsga2 (the other methods minimise one cost)", field="--objectives")
    if request.method == "nsga2":
        if len(request.objectives) < 2:
            raise InputError(f"nsga2 needs two or more of {', '.join(OBJECTIVES)}", field="--objectives")
        for name in request.objectives:
            validation.choice(name, OBJECTIVES, field="--objectives")
        if len(set(request.objectives)) != len(request.objectives):
            raise InputError("an objective is named twice", field="--objectives")
    if request.objectives and not spec_of(controller).goal_directed:
        raise InputError(f"{controller} has no goal: its tuning minimises the wall-following cost, not "
                         f"{', '.join(OBJECTIVES)}", field="--objectives")
    if request.method == "aco" and request.what != "rules":
        raise InputError("the ant colony walks rule conclusions only: use --what rules", field="--method")
    if request.out is not None:
        from fuzzynav.fuzzy.io import format_of

        try:
            format_of(request.out)
        except InputError as error:
            raise InputError(error.problem, source=request.out, field="--out") from None
    if request.resume and request.out is None:
        raise InputError("--resume needs --out (the checkpoint lives beside it)", field="--resume")
    SearchSpace(system, request.what)  # a system with nothing to tune fails here
    suite = _suite(request.worlds, "--worlds")
    chooser = validation_suite(request, suite)
    reserve = 0 if chooser is None else (VALIDATED + 1) * chooser.size
    if request.budget < request.population * suite.size + reserve:
        raise InputError(f"{request.budget} episodes do not cover one generation: {request.population} candidates × "
                         f"{suite.size} worlds{f' + {reserve} validation episodes' if reserve else ''} = "
                         f"{request.population * suite.size + reserve} episodes at least", field="--budget")
    given = None if request.holdout is None else _suite(request.holdout, "--holdout")
    if given is not None and _shared(suite, given):
        example = (f" (e.g. {suite.family}:{suite.count}:{suite.seed + HOLDOUT_OFFSET}, the default)"
                   if suite.family else "")
        raise InputError(f"shares {_worlds(_shared(suite, given))} with --worlds {request.worlds}: held-out worlds are "
                         f"worlds the tuner never saw{example}", field="--holdout")
    holdout = given if given is not None else (
        parse_suite(f"{suite.family}:{suite.count}:{suite.seed + HOLDOUT_OFFSET}") if suite.family else None)
    for option, other, why in (("--worlds", suite, "the result would be chosen on the worlds it was tuned on"),
                               ("--holdout" if given is not None else "the default --holdout", holdout,
                                "the held-out numbers would be on worlds the choice saw")):
        if chooser is not None and other is not None and _shared(chooser, other):
            if request.validation == "auto":  # the option given is the other one: it is what to change
                raise InputError(f"shares {_worlds(_shared(chooser, other))} with the default --validation "
                                 f"{chooser.name}: {why}", field=option)
            raise InputError(f"shares {_worlds(_shared(chooser, other))} with {option} {other.name}: {why}",
                             field="--validation")
    made = make_with_systems(controller, dict(request.systems))
    if not callable(getattr(made, "compiled", None)):
        tunable = [name for name in sorted(ROLES) if callable(getattr(make_with_systems(name, {}), "compiled", None))]
        raise InputError(f"{controller} has no compiled step, and tune simulates each generation in one compiled "
                         f"call; tunable: {', '.join(tunable)}", field="CONTROLLER:ROLE")
    return made, system, suite, holdout


def _worlds(n: int) -> str:
    return f"{n} world{'s' * (n != 1)}"


def _shared(a, b) -> int:
    """How many worlds suites ``a`` and ``b`` both hold: a family's worlds are numbered from 0 for
    each seed; a folder's are its files, compared by content (a copy is the same world), and a file
    of a folder is a family's world when it is one as ``fuzzynav worlds generate`` writes it."""
    if a.family is not None and b.family is not None:
        return min(a.count, b.count) if (a.family, a.seed) == (b.family, b.seed) else 0
    if a.family is None and b.family is None:
        return len({Path(f).read_bytes() for f in a.files} & {Path(f).read_bytes() for f in b.files})
    from fuzzynav.world.scenario_file import scenario_yaml

    family, folder = (a, b) if a.family is not None else (b, a)
    index = {family.world_name(i, 0): i for i in range(family.count)}  # its file names: circles-0-007
    named = [(Path(f), index[Path(f).stem]) for f in folder.files if Path(f).stem in index]
    return sum(path.read_bytes() == scenario_yaml(family.scenario(i, 0)).encode() for path, i in named)


def validation_suite(request: TuneRequest, suite):
    """The validation worlds of ``request`` (training ``suite``), or None (:class:`TuneRequest`)."""
    from fuzzynav.bench.suites import parse_suite

    if request.validation in (None, "none"):
        return None
    if request.validation == "auto":
        return parse_suite(f"{suite.family}:{suite.count}:{suite.seed + VALIDATION_OFFSET}") if suite.family else None
    return _suite(request.validation, "--validation")


def _suite(spec: str, option: str):
    """The suite ``spec`` names, its errors naming ``option``."""
    from fuzzynav.bench.suites import parse_suite

    try:
        return parse_suite(spec)
    except InputError as error:
        raise InputError(error.problem, source=error.source, field=option) from None


def _columns(request: TuneRequest) -> list[int]:
    """Columns of :meth:`Fitness.objectives` the optimiser minimises."""
    return [1 + OBJECTIVES.index(name) for name in request.objectives] if request.objectives else [0]


def tune(request: TuneRequest) -> dict:
    """Run ``request``; returns the result (module docstring): the tuned system under ``system``,
    the start's and the result's training and held-out summaries, the learning curve, the speed."""
    from fuzzynav import progress
    from fuzzynav.catalog.controllers import spec_of
    from fuzzynav.tune.optimisers import make_optimiser
    from fuzzynav.tune.space import SearchSpace

    controller, system, suite, holdout = check(request)
    chooser = validation_suite(request, suite)
    space = SearchSpace(system, request.what)
    path = checkpoint.path_for(request)
    resumed = request.resume and path is not None and path.is_file()
    fitness = Fitness(controller, request.role, space, [suite.scenario(i, 0) for i in range(suite.size)],
                      wall=not spec_of(request.controller).goal_directed)
    stored = checkpoint.load(path, request, fitness) if resumed else []
    optimiser = make_optimiser(request.method, space, request.population, request.seed,
                               n_obj=len(_columns(request)))
    generations, spent, columns, n_worlds = [], 0, _columns(request), len(fitness.worlds)
    reserve = 0 if chooser is None else (VALIDATED + 1) * chooser.size
    _check_stored_fit(path, stored, n_worlds, request.budget, reserve)
    if request.on_start is not None:
        request.on_start()
    best_x, best = space.start, math.inf
    curve = []  # (episodes, best cost so far)
    with progress.bar(total=request.budget, desc=f"tune {request.target} ({request.method})", unit="episode") as bar:
        while spent + n_worlds <= request.budget - reserve:
            population = optimiser.ask()
            asked = len(population)
            population = population[:(request.budget - reserve - spent) // n_worlds]
            values = np.zeros((0, 1 + len(OBJECTIVES)))
            if len(generations) < len(stored):  # replayed: the stored values, none simulated
                x, values = stored[len(generations)]
                known = min(len(x), len(population))
                if x.shape[1:] != population.shape[1:] or not np.array_equal(x[:known], population[:known]):
                    raise InputError(f"generation {len(generations)} replays differently from the checkpoint "
                                     "(another version of the optimiser?)", source=str(path))
                values = values[:known]
            if len(population) > len(values):  # new candidates (or the rest of a generation cut short)
                values = np.concatenate([values, fitness.objectives(population[len(values):])])
            spent += len(population) * n_worlds
            i = int(np.argmin(values[:, 0]))
            if values[i, 0] < best:
                best_x, best = population[i].copy(), float(values[i, 0])
            curve.append((spent, best))
            generations.append((population, values))
            if len(population) == asked:  # a population cut short by the budget ends the run untold
                optimiser.tell(population, values[:, columns])
            if path is not None:
                checkpoint.save(path, request, generations, fitness)
            bar.update(len(population) * n_worlds)
            bar.set_postfix(best=f"{best:.4f}")
        chosen = None
        if chooser is not None:
            chosen = _validate(request, space, controller, chooser, generations, fitness.wall)
            best_x = chosen["genes"]
            bar.update(chosen["episodes"])
    result = _result(request, space, fitness, controller, holdout, generations, best_x, curve)
    if chosen is not None:
        result["validation"] = {key: value for key, value in chosen.items() if key != "genes"}
        result["evaluations"] += chosen["evaluations"]
        result["episodes"] += chosen["episodes"]
    return result


def _check_stored_fit(path, stored, n_worlds: int, budget: int, reserve: int) -> None:
    """Refuse a checkpoint holding more training episodes than ``budget`` leaves for training
    (after the ``reserve`` of validation episodes): replaying it would cut its generations short
    and rewrite both the checkpoint and the result of the longer run."""
    held = sum(len(x) for x, _ in stored) * n_worlds
    if held > budget - reserve:
        asked = f"{budget - reserve} training episodes ({reserve} of --budget {budget} validate)" if reserve \
            else f"{budget}"
        raise InputError(f"the checkpoint already holds {held} episodes, more than the {asked} this run asks "
                         "for: resume with at least as large a --budget, or tune afresh without --resume",
                         source=str(path), field="--budget")


def _validate(request, space, controller, suite, generations, wall: bool) -> dict:
    """The start and the :data:`VALIDATED` best distinct candidates of ``generations`` (by
    training cost) on the ``validation`` worlds; the lowest validation cost wins, the start on a tie."""
    x = np.concatenate([g for g, _ in generations])
    cost = np.concatenate([v[:, 0] for _, v in generations])
    start = space.start
    picked: list[np.ndarray] = []
    for i in np.argsort(cost, kind="stable"):
        if len(picked) == VALIDATED:
            break
        if not any(np.array_equal(x[i], p) for p in [start, *picked]):
            picked.append(x[i])
    candidates = [start, *picked]
    held = Fitness(controller, request.role, space,
                   [suite.scenario(i, 0) for i in range(suite.size)], wall)
    rows = held.simulate(np.stack(candidates))
    summaries = [held.summary(r) for r in rows]
    k = int(np.argmin([s["cost"] for s in summaries]))  # argmin: the first (the start) on a tie
    return {"worlds": suite.name, "start": summaries[0], "candidates": summaries[1:],
            "kept": "start" if k == 0 else f"candidate {k}", "genes": candidates[k],
            "evaluations": held.evaluations, "episodes": held.episodes}


def _result(request, space, fitness, controller, holdout, generations, best_x, curve) -> dict:
    """The tuned system and the numbers of a finished run."""
    tuned = space.decode(best_x, description=f"{space.system.description}; tuned by fuzzynav tune {request.target} "
                                             f"--what {request.what} --method {request.method} --budget "
                                             f"{request.budget} --worlds {request.worlds} --seed {request.seed}")
    both = fitness.simulate(np.stack([space.start, best_x]))
    result = {
        "target": request.target, "what": request.what, "method": request.method, "budget": request.budget,
        "worlds": request.worlds, "seed": request.seed, "population": request.population,
        "genes": space.size, "evaluations": int(sum(len(x) for x, _ in generations)),
        "episodes": int(sum(len(x) for x, _ in generations)) * len(fitness.worlds),
        "evaluations_per_s": fitness.rate, "episodes_per_s": fitness.rate * len(fitness.worlds),
        "simulation_s": fitness.seconds,
        "task": "wall" if fitness.wall else "goal",
        "start": {"training": fitness.summary(both[0])},
        "tuned": {"training": fitness.summary(both[1])},
        "changed": bool(space.decode(best_x) != space.decode(space.start)),
        "curve": [[int(n), float(c)] for n, c in curve],
        "system": tuned,
    }
    if request.method == "nsga2":
        result["front"] = _front(generations, _columns(request), request.objectives)
        for k, member in enumerate(result["front"]):
            member["system"] = space.decode(member["genes"], description=f"{tuned.description}; Pareto front "
                                                                         f"member {k}: {member['objectives']}")
    if holdout is not None:
        held = Fitness(controller, request.role, space, [holdout.scenario(i, 0) for i in range(holdout.size)],
                       fitness.wall)
        rows = held.simulate(np.stack([space.start, best_x]))
        result["holdout_worlds"] = holdout.name
        result["start"]["holdout"] = held.summary(rows[0])
        result["tuned"]["holdout"] = held.summary(rows[1])
    return result


def _front(generations, columns, names) -> list[dict]:
    """The non-dominated candidates of every evaluated one, on the chosen objectives (shown as the
    success rate, the mean time in s and the mean least clearance in m)."""
    x = np.concatenate([g for g, _ in generations])
    f = np.concatenate([v for _, v in generations])
    chosen = f[:, columns]
    keep = [i for i in range(len(chosen))
            if not np.any(np.all(chosen <= chosen[i], axis=1) & np.any(chosen < chosen[i], axis=1))]
    _, unique = np.unique(chosen[keep], axis=0, return_index=True)
    keep = [keep[k] for k in sorted(unique)]
    shown = {"success": lambda v: 1.0 - v, "time": lambda v: v, "clearance": lambda v: -v}  # back to their units
    return [{"genes": x[i], "objectives": {name: shown[name](float(v)) for name, v in zip(names, chosen[i])},
             "cost": float(f[i, 0])} for i in keep]
