"""GA, PSO and ant colony against fuzzy Q-learning, same episodes, every seed (the experiment
``cmp-VI-tuning`` of :mod:`fuzzynav.experiments.tuning`, with the number of seeds and episodes
chosen here), printing the table and the rule grids of docs/tuning.md::

    python benchmarks/tuning_compare.py --tasks avoid goal --seeds 5 --episodes 3000 --out tuning_compare

writes ``OUT.json`` (every seed's numbers; the tuned files and FQL models in ``OUT/``).
"""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import numpy as np

from fuzzynav.experiments.tuning import TASKS, cmp_vi_tuning


def table(results: dict) -> str:
    lines = ["| task | method | held-out success (mean; per seed) | collisions (per seed) | mean time to goal, s | "
             "episodes to beat the start (FQL: to converge, steering/speed) | wall s |", "|---|---|---|---|---|---|---|"]
    for name, task in results.items():
        for method, seeds in task["rows"].items():
            success = [s["success"] for s in seeds]
            times = [s["mean_time_s"] for s in seeds if s["mean_time_s"] is not None]
            beaten = [s.get("episodes_to_beat_start") or "/".join(str(v) for v in s.get("converged_at", {}).values())
                      or None for s in seeds]
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
        parser.error("--seeds and --episodes must be >= 1")
    results = cmp_vi_tuning(args.out, tasks=args.tasks, seeds=args.seeds, episodes=args.episodes)["tasks"]
    Path(f"{args.out}.json").write_text(json.dumps(results, indent=1, default=str))
    print(table(results))
    for name, task in results.items():
        for label, grid in task["tables"].items():
            print(f"\n{name}, {label}:\n" + "\n".join(grid))


if __name__ == "__main__":
    main()
