"""``cmp-VI-tuning``: GA, PSO and ant colony (``fuzzynav tune``) against fuzzy Q-learning (``fuzzynav
train``) with the same budget of simulated episodes, every seed — the comparison of the thesis'
conclusion ("la comparaison des méthodes développées avec d'autres algorithmes stochastiques tels
que les algorithmes génétiques", "l'optimisation des contrôleurs flous par les algorithmes de
colonies de fourmis").

Tasks (each method gets the same number of episodes per seed):

- ``avoid`` — obstacle avoidance: the tuners tune ``fuzzy-2b:oab`` (Table IV.2; GA and PSO its
  breakpoints and conclusions, the ant colony its conclusions) on ``mixed:40``; FQL trains
  ``fql-avoid`` (§VI.5.2, the avoider inside its goal navigator). Held out: ``mixed:40:1000``.
- ``goal`` — goal seeking: the tuners tune ``goal-seeking:gsb`` (Table IV.1) on 40 empty-workspace
  worlds written as scenario files (random start pose, goal ≥ 10 m away); FQL trains ``fql-goal``
  (§VI.5.1). Held out: 40 other such worlds.

Under ``fuzzynav reproduce cmp-VI-tuning --fis ROLE=FILE`` the replaced tables
(:mod:`fuzzynav.experiments.rule_bases`) stand in for the hand-made ones of the tuned controller —
its held-out row, the tuners' start and the roles they keep fixed — so the comparison can be run
from an edited table. FQL learns from q = 0 and reads none of them (the ``fql-avoid`` navigator
keeps its own guarded Table IV.1 goal seeking, :class:`fuzzynav.control.learned.LearnedAvoidanceNavigator`).

Every controller — the hand-made start, each tuned system (``--fis ROLE=FILE``), each FQL model
(``--model``) — is then run on the held-out worlds by the ordinary simulator
(:func:`fuzzynav.sim.run_episode`), not by the tuner's compiled loop. Reported per method and
seed: held-out success, collisions and mean time to the goal, the episodes spent before beating
the start on the training worlds (tuners: the first generation whose best training cost is below
the start's; FQL: its phases' ``converged_at``), and the rule tables side by side. ``wall`` — wall following: ``wall-follow:wall`` (Table VI.2) on 40
wall courses by the wall cost of :mod:`fuzzynav.tune.fitness`, FQL trains ``fql-wall``; held out
on 40 other courses by :func:`held_out_wall`.
"""

from __future__ import annotations

import math
import time
from pathlib import Path

import numpy as np

from fuzzynav.catalog.roles import default_system, make_with_systems, systems_from_options
from fuzzynav.catalog.tasks import load_controller, trainer
from fuzzynav.errors import InputError
from fuzzynav.experiments import rule_bases
from fuzzynav.fuzzy.io import load, save
from fuzzynav.learn.tasks.common import TrainRequest
from fuzzynav.sim import metrics, run_episode
from fuzzynav.tune.session import TuneRequest, tune
from fuzzynav.world.scenario import scenario_from_dict
from fuzzynav.world.scenario_file import save_scenario

TASKS = {
    "avoid": {"target": "fuzzy-2b:oab", "fql": "fql-avoid", "train": "mixed:40", "holdout": "mixed:40:1000",
              "methods": {"ga": "both", "pso": "both", "aco": "rules"}},
    "goal": {"target": "goal-seeking:gsb", "fql": "fql-goal", "train": "empty-train", "holdout": "empty-holdout",
             "methods": {"ga": "both", "pso": "both", "aco": "rules"}},
    "wall": {"target": "wall-follow:wall", "fql": "fql-wall", "train": "walls-train", "holdout": "walls-holdout",
             "methods": {"ga": "both", "pso": "both", "aco": "rules"}},
}
EMPTY_WORLDS, EMPTY_SEEDS = 40, {"empty-train": 0, "empty-holdout": 1000}
WALL_SEEDS = {"walls-train": 0, "walls-holdout": 1000}
METHODS = ("ga", "pso", "aco", "fql")


def empty_worlds(folder: Path, seed: int, n: int = EMPTY_WORLDS) -> Path:
    """``n`` goal scenarios in the empty 20 m × 20 m workspace: start 2.5 m from the walls with a
    uniform heading, goal ≥ 10 m away (the rule of the generated families), written as files."""
    folder.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(seed)
    for i in range(n):
        while True:
            start, goal = rng.uniform(2.5, 17.5, 2), rng.uniform(2.5, 17.5, 2)
            if np.hypot(*(goal - start)) >= 10.0:
                break
        scenario = scenario_from_dict({
            "name": f"empty-{seed}-{i:03d}", "world": {"width": 20.0, "height": 20.0},
            "robot": {"x": float(start[0]), "y": float(start[1]), "theta": float(rng.uniform(-math.pi, math.pi))},
            "goal": {"x": float(goal[0]), "y": float(goal[1]), "tolerance": 0.3}, "max_time": 60})
        save_scenario(scenario, folder / f"empty-{seed}-{i:03d}.yaml")
    return folder


def wall_worlds(folder: Path, seed: int, n: int = EMPTY_WORLDS) -> Path:
    """``n`` random wall courses (:func:`~fuzzynav.experiments.evaluation.wall_course_scenario`:
    the layout of the FQL wall follower's training, 30 s each) written as scenario files; a
    course whose start the scenario checks refuse (the body touching a wall) is drawn again."""
    from fuzzynav.experiments.evaluation import wall_course_scenario
    from fuzzynav.world.scenario_file import open_scenario

    folder.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(seed)
    for i in range(n):
        path = folder / f"walls-{seed}-{i:03d}.yaml"
        while True:
            save_scenario(wall_course_scenario(rng, path.stem), path)
            try:
                open_scenario(path)
                break
            except InputError:
                continue
    return folder


def held_out(scenarios, build) -> dict:
    """Success, collisions, mean time to the goal of a controller built by ``build()`` on ``scenarios``."""
    runs = [metrics(run_episode(s, build(), seed=0), s) for s in scenarios]
    reached = [r["time_s"] for r in runs if r["outcome"] == "reached"]
    return {"success": len(reached) / len(runs), "collisions": sum(r["outcome"] == "collision" for r in runs),
            "mean_time_s": float(np.mean(reached)) if reached else None}


def held_out_wall(scenarios, system) -> dict:
    """A wall-follower rule base (Table VI.2's inputs and outputs) on ``scenarios`` by the tuner's
    compiled loop (the simulator's own step, checked against it in the tests): success — the
    share followed (lasted without collision at a mean speed of at least half of P) — the share
    lasted, collisions and the wall measures of :func:`fuzzynav.tune.fitness.summary`."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.tune.fitness import Fitness

    fitness = Fitness(make_controller("wall-follow"), "wall", None, scenarios, wall=True)
    jobs = np.column_stack([np.zeros(len(scenarios), dtype=np.int64), np.arange(len(scenarios))])
    numbers = fitness.summary(fitness.worlds.run(fitness.tables(system)[None], jobs))
    return {"success": numbers["followed_rate"], "lasted": numbers["success_rate"], **numbers}


def task_suite(spec: str, work: Path) -> tuple[str, list]:
    """(the SUITE argument, its scenarios) of a task's worlds (the empty ones written under ``work``)."""
    from fuzzynav.bench.suites import parse_suite

    if spec in EMPTY_SEEDS:
        text = str(empty_worlds(work / spec, EMPTY_SEEDS[spec]))
    elif spec in WALL_SEEDS:
        text = str(wall_worlds(work / spec, WALL_SEEDS[spec]))
    else:
        text = spec
    suite = parse_suite(text)
    return text, [suite.scenario(i, 0) for i in range(suite.size)]


def starts(controller: str, role: str) -> tuple[dict, object]:
    """(``{role: system}`` of ``controller`` replaced by ``--fis``, the start of the tuned ``role``):
    the replacement, else the hand-made table."""
    replaced = rule_bases.systems_for(controller)
    return replaced, replaced[role] if role in replaced else default_system(controller, role)


def run_task(name: str, seeds, episodes: int, out: Path, methods=METHODS) -> dict:
    """One task: the hand-made start, each tuner and FQL of ``methods`` for every seed of ``seeds``,
    on its held-out worlds."""
    task = TASKS[name]
    controller, role = task["target"].split(":")
    replaced, start = starts(controller, role)
    worlds, _ = task_suite(task["train"], out)
    holdout_spec, holdout = task_suite(task["holdout"], out)
    wall = name == "wall"
    if wall:
        rows = {"hand-made": [held_out_wall(holdout, start)]}
    else:
        rows = {"hand-made": [held_out(holdout, lambda: make_with_systems(controller, replaced))]}
    for method, what in task["methods"].items():
        if method not in methods:
            continue
        rows[method] = []
        for seed in seeds:
            path = out / f"{name}-{method}-{seed}.yaml"
            started = time.perf_counter()
            result = tune(TuneRequest(target=task["target"], worlds=worlds, holdout=holdout_spec, what=what,
                                      method=method, budget=episodes, seed=seed, out=str(path), progress=False,
                                      systems=replaced))
            seconds = time.perf_counter() - started
            save(result["system"], path)
            systems = {**replaced, **systems_from_options(controller, [f"{role}={path}"])}
            start_cost = result["start"]["training"]["cost"]
            beaten = next((n for n, cost in result["curve"] if cost < start_cost), None)
            tested = held_out_wall(holdout, systems[role]) if wall else held_out(
                holdout, lambda systems=systems: make_with_systems(controller, systems))
            rows[method].append({"seed": seed, **tested,
                                 "episodes_to_beat_start": beaten, "wall_s": seconds, "file": str(path),
                                 "training": result["tuned"]["training"]})
    if "fql" in methods:
        rows["fql"] = []
    for seed in seeds if "fql" in methods else ():
        path = out / f"{name}-fql-{seed}.json"
        started = time.perf_counter()
        trained = trainer(task["fql"])(TrainRequest(out=path, task=task["fql"], episodes=episodes, seed=seed,
                                                    resume=False, checkpoint_every=None, curve=None, progress=False))
        seconds = time.perf_counter() - started
        model = load_controller(path)
        if wall and model.sensing != "rays":
            raise InputError("the wall comparison runs followers reading the single rays", source=str(path),
                             field="sensing")
        tested = held_out_wall(holdout, model.system) if wall else held_out(holdout, lambda model=model: model)
        rows["fql"].append({"seed": seed, **tested, "wall_s": seconds, "file": str(path),
                            "episodes_to_beat_start": None,
                            "converged_at": {k: v.get("converged_at") for k, v in trained.items() if isinstance(v, dict)}})
    return {"target": task["target"], "fql": task["fql"], "train": task["train"], "holdout": task["holdout"],
            "episodes": episodes, "rows": rows, "tables": _tables(start, rows)}


def _tables(start, rows: dict) -> dict:
    """The rule grid (first input across, second down; cells joined by '/') of the hand-made
    system (or its ``--fis`` replacement) and of each tuner's seed-0 file."""
    systems = {"hand-made": start}
    systems.update({method: load(seeds[0]["file"]) for method, seeds in rows.items()
                    if method not in ("hand-made", "fql") and seeds})
    return {label: _grid(system) for label, system in systems.items()}


def _grid(system) -> list[str]:
    """Two inputs: the grid; more (the wall follower's three distances): one line per rule."""
    if len(system.inputs) != 2:
        return [" ".join(f"{v}={t}" for v, t in rule.premises) + " -> " + "/".join(t for _, t in rule.conclusions)
                for rule in system.rules]
    first, second = system.inputs[0], system.inputs[1]
    cells = {frozenset(rule.premises): "/".join(t for _, t in rule.conclusions) for rule in system.rules}
    lines = [f"{second.name:>8s} | " + " ".join(f"{label:>6s}" for label in first.labels)]
    for label in second.labels:  # a cell by its (input, term) pairs, whatever order the rule names them in
        lines.append(f"{label:>8s} | " + " ".join(
            f"{cells.get(frozenset({(first.name, c), (second.name, label)}), '?'):>6s}" for c in first.labels))
    return lines


def cmp_vi_tuning(out_dir, quick: bool = False, seed: int = 0, tasks=tuple(TASKS), seeds: int | None = None,
                  episodes: int | None = None, methods=METHODS) -> dict:
    """Every task × method × seed (``quick``: one seed, 800 episodes; else 5 seeds, 3,000 episodes,
    seeds ``seed`` … ``seed + 4``; ``methods``: a subset of :data:`METHODS`, the others left out);
    writes the tuned files and models under ``out_dir`` and ``cmp-VI-tuning.png`` (held-out success
    and time per method)."""
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    seeds = seeds or (1 if quick else 5)
    episodes = episodes or (800 if quick else 3000)
    results = {name: run_task(name, range(seed, seed + seeds), episodes, out, methods) for name in tasks}
    _plot(results, out / "cmp-VI-tuning.png")
    return {"episodes": episodes, "seeds": seeds, "tasks": results}


def _plot(results: dict, path: Path) -> None:
    from matplotlib.figure import Figure

    from fuzzynav.storage import savefig_atomic

    figure = Figure(figsize=(5.5 * len(results), 4.0), layout="constrained")
    for ax, (name, task) in zip(np.atleast_1d(figure.subplots(1, len(results))), results.items()):
        methods = list(task["rows"])
        for k, method in enumerate(methods):
            seeds = task["rows"][method]
            ax.scatter([k] * len(seeds), [s["success"] for s in seeds], marker="o", color="C0")
        ax.set_xticks(range(len(methods)), methods)
        ax.set_ylabel("held-out success")
        ax.set_ylim(0, 1.05)
        ax.set_title(f"{name}: {task['target']} vs {task['fql']} ({task['episodes']} episodes)")
    savefig_atomic(figure, path, dpi=120)
