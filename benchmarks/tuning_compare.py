"""GA, PSO and ant colony (``fuzzynav tune``) against fuzzy Q-learning (``fuzzynav train``), same budget
of simulated episodes, every seed: the comparison the thesis' conclusion asks for.

Tasks (each method gets ``--episodes`` episodes per seed):

- ``avoid`` — obstacle avoidance: the tuners tune ``fuzzy-2b:oab`` (Table IV.2; GA and PSO its
  breakpoints and conclusions, the ant colony its conclusions) on ``mixed:40``; FQL trains
  ``fql-avoid`` (§VI.5.2, the avoider inside its goal navigator). Held out: ``mixed:40:1000``.
- ``goal`` — goal seeking: the tuners tune ``goal-seeking:gsb`` (Table IV.1) on 40 empty-workspace
  worlds written as scenario files (random start pose, goal ≥ 10 m away); FQL trains ``fql-goal``
  (§VI.5.1). Held out: 40 other such worlds.

Every controller — the hand-made start, each tuned file (``--fis ROLE=FILE``), each FQL model
(``--model``) — is then run on the held-out worlds by the ordinary simulator
(:func:`fuzzynav.sim.run_episode`), not by the tuner's compiled loop. Reported per method: held-out
success, collisions and mean time to the goal (mean and every seed), and the episodes the method
spent before beating the start on its training worlds (tuners: the first generation whose best
training cost is below the start's; FQL: its phases' ``converged_at``, null when not converged).
Wall following is not compared: ``fuzzynav tune`` scores goal and path episodes, and the wall
follower has no goal (its FQL task measures distance kept to a wall).

    python benchmarks/tuning_compare.py --tasks avoid goal --seeds 5 --episodes 3000 --out tuning_compare

writes ``OUT.json`` (every seed's numbers, the tuned files beside it in ``OUT/``) and prints the
table of docs/tuning.md.
"""

from __future__ import annotations

import argparse
import json
import math
import time
from pathlib import Path

import numpy as np

from fuzzynav.catalog.roles import make_with_systems, systems_from_options
from fuzzynav.catalog.tasks import load_controller, trainer
from fuzzynav.errors import InputError
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
}
EMPTY_WORLDS, EMPTY_SEEDS = 40, {"empty-train": 0, "empty-holdout": 1000}


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


def held_out(scenarios, build) -> dict:
    """Success, collisions, mean time to the goal of a controller built by ``build()`` on ``scenarios``."""
    runs = [metrics(run_episode(s, build(), seed=0), s) for s in scenarios]
    reached = [r["time_s"] for r in runs if r["outcome"] == "reached"]
    return {"success": len(reached) / len(runs), "collisions": sum(r["outcome"] == "collision" for r in runs),
            "mean_time_s": float(np.mean(reached)) if reached else None}


def _suite(spec: str, work: Path) -> tuple[str, list]:
    """(the SUITE argument, its scenarios) of a task's worlds (the empty ones written under ``work``)."""
    from fuzzynav.bench.suites import parse_suite

    text = str(empty_worlds(work / spec, EMPTY_SEEDS[spec])) if spec in EMPTY_SEEDS else spec
    suite = parse_suite(text)
    return text, [suite.scenario(i, 0) for i in range(suite.size)]


def run_task(name: str, seeds: int, episodes: int, out: Path) -> dict:
    task = TASKS[name]
    controller, role = task["target"].split(":")
    worlds, _ = _suite(task["train"], out)
    holdout_spec, holdout = _suite(task["holdout"], out)
    rows = {"hand-made": [held_out(holdout, lambda: make_with_systems(controller, {}))]}
    for method, what in task["methods"].items():
        rows[method] = []
        for seed in range(seeds):
            path = out / f"{name}-{method}-{seed}.yaml"
            started = time.perf_counter()
            result = tune(TuneRequest(target=task["target"], worlds=worlds, holdout=holdout_spec, what=what,
                                      method=method, budget=episodes, seed=seed, out=str(path), progress=False))
            seconds = time.perf_counter() - started
            save(result["system"], path)
            systems = systems_from_options(controller, [f"{role}={path}"])
            start_cost = result["start"]["training"]["cost"]
            beaten = next((n for n, cost in result["curve"] if cost < start_cost), None)
            rows[method].append({"seed": seed, **held_out(holdout, lambda: make_with_systems(controller, systems)),
                                 "episodes_to_beat_start": beaten, "wall_s": seconds, "file": str(path),
                                 "training": result["tuned"]["training"]})
            print(name, method, seed, rows[method][-1], flush=True)
    rows["fql"] = []
    for seed in range(seeds):
        path = out / f"{name}-fql-{seed}.json"
        started = time.perf_counter()
        trained = trainer(task["fql"])(TrainRequest(out=path, task=task["fql"], episodes=episodes, seed=seed,
                                                    resume=False, checkpoint_every=None, curve=None, progress=False))
        seconds = time.perf_counter() - started
        model = load_controller(path)
        rows["fql"].append({"seed": seed, **held_out(holdout, lambda: model), "wall_s": seconds, "file": str(path),
                            "episodes_to_beat_start": None,
                            "converged_at": {k: v.get("converged_at") for k, v in trained.items() if isinstance(v, dict)}})
        print(name, "fql", seed, rows["fql"][-1], flush=True)
    return {"target": task["target"], "fql": task["fql"], "train": task["train"], "holdout": task["holdout"],
            "episodes": episodes, "rows": rows, "tables": _tables(controller, role, rows)}


def _tables(controller: str, role: str, rows: dict) -> dict:
    """The rule grid (first input across, second down; cells joined by '/') of the hand-made
    system and of each tuner's seed-0 file."""
    from fuzzynav.catalog.roles import default_system

    systems = {"hand-made": default_system(controller, role)}
    systems.update({method: load(seeds[0]["file"]) for method, seeds in rows.items()
                    if method not in ("hand-made", "fql") and seeds})
    return {label: _grid(system) for label, system in systems.items()}


def _grid(system) -> list[str]:
    first, second = system.inputs[0], system.inputs[1]
    cells = {tuple(t for _, t in rule.premises): "/".join(t for _, t in rule.conclusions) for rule in system.rules}
    lines = [f"{second.name:>8s} | " + " ".join(f"{label:>6s}" for label in first.labels)]
    for label in second.labels:
        lines.append(f"{label:>8s} | " + " ".join(f"{cells.get((c, label), cells.get((label, c), '?')):>6s}"
                                                 for c in first.labels))
    return lines


def table(results: dict) -> str:
    lines = ["| task | method | held-out success (mean; per seed) | collisions (per seed) | mean time to goal, s | "
             "episodes to beat the start | wall s |", "|---|---|---|---|---|---|---|"]
    for name, task in results.items():
        for method, seeds in task["rows"].items():
            success = [s["success"] for s in seeds]
            times = [s["mean_time_s"] for s in seeds if s["mean_time_s"] is not None]
            beaten = [s.get("episodes_to_beat_start") for s in seeds]
            lines.append(f"| {name} | {method} | {np.mean(success):.3f}; {', '.join(f'{v:.3f}' for v in success)} | "
                         f"{', '.join(str(s['collisions']) for s in seeds)} | "
                         f"{np.mean(times):.2f}; {', '.join(f'{t:.2f}' for t in times)} | "
                         f"{', '.join('-' if b is None else str(b) for b in beaten)} | "
                         f"{', '.join(format(s['wall_s'], '.0f') for s in seeds if 'wall_s' in s)} |")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tasks", nargs="+", default=list(TASKS), choices=list(TASKS))
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--episodes", type=int, default=3000)
    parser.add_argument("--out", default="tuning_compare")
    args = parser.parse_args()
    if args.seeds < 1 or args.episodes < 1:
        raise InputError("must be >= 1", field="--seeds/--episodes")
    folder = Path(args.out)
    folder.mkdir(parents=True, exist_ok=True)
    results = {name: run_task(name, args.seeds, args.episodes, folder) for name in args.tasks}
    Path(f"{args.out}.json").write_text(json.dumps(results, indent=1, default=str))
    print(table(results))
    for name, task in results.items():
        for label, grid in task["tables"].items():
            print(f"\n{name}, {label}:\n" + "\n".join(grid))


if __name__ == "__main__":
    main()
