"""GA, PSO and ant colony against fuzzy Q-learning, same episodes, every seed (the experiment
``cmp-VI-tuning`` of :mod:`fuzzynav.experiments.tuning`, with the seeds and episodes chosen here),
printing the tables and the rule grids of docs/tuning.md::

    python benchmarks/tuning_compare.py --tasks avoid goal --seeds 5 --episodes 3000 --out tuning_compare
    python benchmarks/tuning_compare.py --tasks wall --first-seed 2 --seeds 1 --episodes 1000 --out wall-2
    python benchmarks/tuning_compare.py --tasks wall --first-seed 2 --seeds 1 --methods fql --out wall-fql-2
    python benchmarks/tuning_compare.py --table wall-0.json wall-1.json ...   # one table of several runs
    python benchmarks/tuning_compare.py --table wall-0.json ... --rescore     # held out again, today's measures

writes ``OUT.json`` (every seed's numbers; the tuned files and FQL models in ``OUT/``). ``--table``
prints the tables of earlier ``OUT.json`` files, their seeds side by side (the hand-made row once).
"""

from __future__ import annotations

import json
import tempfile
from pathlib import Path

import numpy as np

from fuzzynav.cli import Parser
from fuzzynav.experiments.tuning import METHODS, TASKS, cmp_vi_tuning, held_out_wall, task_suite


def _per_seed(values, fmt: str) -> str:
    """``mean; v0, v1, …`` of ``values`` (None shown as '-', left out of the mean)."""
    known = [v for v in values if v is not None]
    mean = format(float(np.mean(known)), fmt) if known else "-"
    return f"{mean}; " + ", ".join("-" if v is None else format(v, fmt) for v in values)


def _goal_table(name: str, task: dict) -> list[str]:
    lines = ["| task | method | held-out success: mean; per seed | collisions per seed | mean time to goal, s: "
             "mean; per seed | episodes to beat the start (FQL: to converge, steering/speed) | wall s per seed |",
             "|---|---|---|---|---|---|---|"]
    for method, seeds in task["rows"].items():
        beaten = [s.get("episodes_to_beat_start") or "/".join(str(v) for v in s.get("converged_at", {}).values())
                  or None for s in seeds]
        lines.append(f"| {name} | {method} | {_per_seed([s['success'] for s in seeds], '.3f')} | "
                     f"{', '.join(str(s['collisions']) for s in seeds)} | "
                     f"{_per_seed([s['mean_time_s'] for s in seeds], '.2f')} | "
                     f"{', '.join('-' if b is None else str(b) for b in beaten)} | "
                     f"{', '.join(format(s['wall_s'], '.0f') for s in seeds if 'wall_s' in s) or '-'} |")
    return lines


def _wall_table(name: str, task: dict) -> list[str]:
    """Wall following has no goal: lasted (the time limit without collision), collisions and the
    wall measures of :func:`fuzzynav.tune.fitness.summary`, per seed."""
    lines = ["| task | method | followed (lasted at ≥ P/2): mean; per seed | lasted: mean; per seed | "
             "collisions per seed | closer than d_m: mean; per seed | "
             "outside band, m: mean; per seed | speed, m/s: mean; per seed | wall s per seed |",
             "|---|---|---|---|---|---|---|---|---|"]
    for method, seeds in task["rows"].items():
        lines.append(f"| {name} | {method} | {_per_seed([s['success'] for s in seeds], '.3f')} | "
                     f"{_per_seed([s['lasted'] for s in seeds], '.3f')} | "
                     f"{', '.join(str(s['collisions']) for s in seeds)} | "
                     f"{_per_seed([s['too_close_share'] for s in seeds], '.3f')} | "
                     f"{_per_seed([s['off_band_m'] for s in seeds], '.3f')} | "
                     f"{_per_seed([s['mean_speed_mps'] for s in seeds], '.2f')} | "
                     f"{', '.join(format(s['wall_s'], '.0f') for s in seeds if 'wall_s' in s) or '-'} |")
    return lines


def table(results: dict) -> str:
    """One markdown table per task of ``results`` (``cmp_vi_tuning(...)["tasks"]``)."""
    return "\n\n".join("\n".join((_wall_table if name == "wall" else _goal_table)(name, task))
                       for name, task in results.items())


def merged(files) -> dict:
    """The tasks of several ``OUT.json`` files as one: each method's seeds in file order, the
    hand-made row (the same in every run) once, the rule grids of the first file."""
    results: dict = {}
    for path in files:
        for name, task in json.loads(Path(path).read_text()).items():
            if name not in results:
                results[name] = {**task, "rows": {method: list(seeds) for method, seeds in task["rows"].items()}}
                continue
            for method, seeds in task["rows"].items():
                if method != "hand-made":
                    results[name]["rows"].setdefault(method, []).extend(seeds)
    return results


def rescored(results: dict) -> dict:
    """``results`` with the wall task's held-out numbers measured again by today's
    :func:`~fuzzynav.experiments.tuning.held_out_wall` from the files the runs wrote (the hand-made
    row from Table VI.2): numbers of runs made before a measure was added."""
    from fuzzynav.catalog.roles import default_system
    from fuzzynav.catalog.tasks import load_controller
    from fuzzynav.fuzzy.io import load

    if "wall" not in results:
        return results
    task = results["wall"]
    with tempfile.TemporaryDirectory() as work:
        _, holdout = task_suite(task["holdout"], Path(work))
    rows = {"hand-made": [held_out_wall(holdout, default_system(*task["target"].split(":")))]}
    for method, seeds in task["rows"].items():
        if method != "hand-made":
            rows[method] = [{**s, **held_out_wall(holdout, load(s["file"]) if method != "fql"
                                                   else load_controller(s["file"]).system)} for s in seeds]
    return {**results, "wall": {**task, "rows": rows}}


def main() -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--tasks", nargs="+", default=list(TASKS), choices=list(TASKS))
    parser.add_argument("--seeds", type=int, default=5, help="how many seeds (default 5)")
    parser.add_argument("--first-seed", type=int, default=0, help="the first seed (default 0)")
    parser.add_argument("--episodes", type=int, default=3000)
    parser.add_argument("--methods", nargs="+", default=list(METHODS), choices=list(METHODS),
                        help="the methods to run (default all; the hand-made row always)")
    parser.add_argument("--out", default="tuning_compare")
    parser.add_argument("--table", nargs="+", metavar="JSON", help="print the tables of earlier OUT.json files")
    parser.add_argument("--rescore", action="store_true",
                        help="with --table: measure the wall task's held-out numbers again from the files written")
    args = parser.parse_args()
    if args.table:
        results = merged(args.table)
        print(table(rescored(results) if args.rescore else results))
        return
    if args.seeds < 1 or args.episodes < 1 or args.first_seed < 0:
        parser.error("--seeds and --episodes must be >= 1, --first-seed >= 0")
    results = cmp_vi_tuning(args.out, tasks=args.tasks, seed=args.first_seed, seeds=args.seeds,
                            episodes=args.episodes, methods=args.methods)["tasks"]
    Path(f"{args.out}.json").write_text(json.dumps(results, indent=1, default=str))
    print(table(results))
    for name, task in results.items():
        for label, grid in task["tables"].items():
            print(f"\n{name}, {label}:\n" + "\n".join(grid))


if __name__ == "__main__":
    main()
