"""Chapter VI learning tasks end to end: wall time, episodes to converge, success of every seed.

For each task (``fuzzynav train TASK``) and each of the seeds it trains a model with the task's
default episode budget (or ``--episodes``), then evaluates the extracted controller in the
simulator: goal seekers from 100 random starts in the empty workspace, the avoidance navigator in
100 random obstacle worlds, the wall follower on the corners of Fig VI.28 (scenario fig-VI-28) and
20 random wall courses (the evaluation seeds differ from the training ones). It reports, per
seed (not the best one), the training wall time, the episodes to converge of every phase
(criterion of fuzzynav.learn.curves, moving mean over 250 episodes) and the success, collision and
timeout counts; then, per task, the medians next to the thesis' episode counts. The speed target
of issue 5 — 3,000 FQL episodes in under 30 s — is the wall time of ``fql-goal`` with 3,000
episodes (median over the seeds).

Run:  python benchmarks/rl_bench.py [--tasks fql-goal,fql-avoid] [--seeds 5] [--episodes N] [--json]
"""

from __future__ import annotations

import argparse
import json
import statistics
import tempfile
import time
from pathlib import Path

from fuzzynav.experiments import train_rl
from fuzzynav.models import load_controller
from fuzzynav.training import TrainRequest, trainer

# the thesis' episodes to converge (Table VI.1, Figs VI.1, VI.8, VI.9, VI.13, VI.16, VI.22)
THESIS = {
    "q-goal": {"steering": 6200},  # 13 states × 3 actions, Table VI.1
    "fql-goal": {"steering": 3000, "speed": 900},  # random starts, Fig VI.9
    "fql-goal-35": {"steering": 5000},  # Fig VI.13
    "fql-goal-traces": {"steering": 1400},  # Fig VI.16
    "fql-avoid": {"steering": 250, "speed": 2000},  # Fig VI.22
    "fql-wall": {},  # not given
}


def _wall(controller) -> dict:
    """Wall follower: the Fig VI.28 corners and 20 random courses; success = no collision."""
    result = train_rl.evaluate_wall(controller)
    return {**result, "success": 1 - result["collisions"] / result["courses"], "timeouts": 0}


EVALUATE = {"fql-avoid": train_rl.evaluate_avoid, "fql-wall": _wall}


def run_task(task: str, seed: int, episodes: int | None, folder: Path) -> dict:
    out = folder / f"{task}-{seed}.json"
    start = time.perf_counter()
    result = trainer(task)(TrainRequest(out=out, episodes=episodes, seed=seed, progress=False))
    wall = time.perf_counter() - start
    evaluation = EVALUATE.get(task, train_rl.evaluate_goal)(load_controller(out))
    phases = {k: v for k, v in result.items() if isinstance(v, dict)}
    return {"task": task, "seed": seed, "wall_s": round(wall, 2),
            "episodes": {k: v["episodes"] for k, v in phases.items()},
            "converged_at": {k: v["converged_at"] for k, v in phases.items()}, **evaluation}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tasks", default=",".join(THESIS), help="comma-separated task names")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--episodes", type=int, default=None, help="episodes per task (default: the task's)")
    parser.add_argument("--json", action="store_true", help="print one JSON object only")
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for task in args.tasks.split(","):
            for seed in range(args.seeds):
                rows.append(run_task(task, seed, args.episodes, Path(folder)))
                if not args.json:
                    r = rows[-1]
                    print(f"{task:16s} seed {seed}: {r['wall_s']:6.1f} s  converged {r['converged_at']}  "
                          f"success {r['success']:.0%}  collisions {r['collisions']}  timeouts {r['timeouts']}")
    summary = {}
    for task in dict.fromkeys(r["task"] for r in rows):
        mine = [r for r in rows if r["task"] == task]
        summary[task] = {
            "wall_s_median": statistics.median(r["wall_s"] for r in mine),
            "success_per_seed": [r["success"] for r in mine],
            "collisions_per_seed": [r["collisions"] for r in mine],
            **({"fig_VI_28_per_seed": [r["fig-VI-28"] for r in mine]} if "fig-VI-28" in mine[0] else {}),
            "converged_at_median": {p: statistics.median(r["converged_at"][p] for r in mine) for p in mine[0]["converged_at"]},
            "thesis_episodes": THESIS.get(task, {}),
        }
    if not args.json:
        for task, s in summary.items():
            print(f"{task:16s} median wall {s['wall_s_median']:.1f} s; converged (median) {s['converged_at_median']} "
                  f"vs thesis {s['thesis_episodes']}; success per seed {s['success_per_seed']}")
    print(json.dumps({"runs": rows, "summary": summary}))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
