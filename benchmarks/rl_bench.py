"""Chapter VI learning tasks end to end: wall time, episodes to converge, success of every seed.

For each task (``fuzzynav train TASK``) and each of the seeds it trains a model with the task's
default episode budget (or ``--episodes``), then evaluates the extracted controller in the
simulator: goal seekers from 100 random starts in the empty workspace (the fixed-start studies
from their fixed start), the avoidance navigator in
100 random obstacle worlds, the wall follower on the corners of Fig VI.28 (scenario fig-VI-28) and
100 random wall courses (the evaluation seeds differ from the training ones). It reports, per
seed (not the best one), the training wall time, the episodes to converge of every phase
(the budget-independent criterion of fuzzynav.learn.curves with the settings of
fuzzynav.learn.tasks) and the success, collision and timeout counts; then, per task, the
medians next to the thesis' episode counts. The speed target — 3,000 FQL episodes in
under 30 s — is the wall time of ``fql-goal`` with 3,000 episodes (median over the seeds).

Besides the ``fuzzynav train`` tasks, the studies of chapter VI that are not tasks of their own:
``q-goal-9``, ``q-goal-11``, ``q-goal-13``, ``q-goal-19x5`` (Table VI.1: states × actions, random
starts, 4,000 episodes), ``q-goal-fixed`` (Fig VI.1, 1,500 episodes) and ``fql-goal-fixed``
(Fig VI.8, 1,000 episodes), ``fql-wall-modules`` (``fql-wall`` reading the nearest of each
module's three sensors instead of the hand-made follower's single rays), ``fql-avoid-8``
(``fql-avoid`` with the thesis' 8 rules, without the openness input). The avoidance navigators
are evaluated as trained and with the turning-room guard of ``fuzzy-5b-thesis`` added (reported apart:
``with_turn_guard``). ``--double`` trains
every run a second time with twice the budget and reports both counts of episodes to converge
(they must agree: the criterion does not depend on the budget).

By default every task trains under the thesis' protocol (one robot, one episode after another), as
``fuzzynav train`` does; ``--parallel N`` trains N robots per batch on one rule base, the fast
option of ``fuzzynav train --parallel N``, whose episodes are counted in batches.

Run:  python benchmarks/rl_bench.py [--tasks fql-goal,q-goal-9] [--seeds 5] [--episodes N] [--double] [--parallel N] [--json]
"""

from __future__ import annotations

import json
import math
import statistics
import tempfile
import time
from dataclasses import replace
from pathlib import Path

from fuzzynav.catalog.tasks import load_controller, trainer
from fuzzynav.cli import Parser
from fuzzynav.experiments import evaluation as evaluations
from fuzzynav.learn import envs
from fuzzynav.learn.tasks import common, fql_avoid, fql_goal, fql_wall, tabular_goal
from fuzzynav.learn.tasks.common import TrainRequest

# the thesis' episodes to converge (Table VI.1, Figs VI.1, VI.8, VI.9, VI.13, VI.16, VI.22)
THESIS = {
    "q-goal": {"steering": 6200},  # 13 states × 3 actions, Table VI.1
    "fql-goal": {"steering": 3000, "speed": 900},  # random starts, Fig VI.9
    "fql-goal-35": {"steering": 5000},  # Fig VI.13
    "fql-goal-traces": {"steering": 1400},  # Fig VI.16
    "fql-avoid": {"steering": 250, "speed": 2000},  # Fig VI.22
    "fql-wall": {},  # not given
    "q-goal-9": {"steering": 3260},  # Table VI.1
    "q-goal-11": {"steering": 4100},
    "q-goal-13": {"steering": 6200},
    "q-goal-19x5": {"steering": 8950},
    "q-goal-fixed": {"steering": 1000},  # Fig VI.1
    "fql-goal-fixed": {"steering": 180},  # Fig VI.8
    "fql-wall-modules": {},  # fql-wall on the richer sensing (nearest of three sensors per direction)
    "fql-avoid-8": {"steering": 250, "speed": 2000},  # fql-avoid with the thesis' 8 rules (no openness input)
}
TASKS = ["q-goal", "fql-goal", "fql-goal-35", "fql-goal-traces", "fql-avoid", "fql-wall"]  # fuzzynav train


def median_count(counts):
    """Median episodes to converge over seeds; a run that never settled (None) counts as
    infinitely many, so the median is None (not settled) when the median run did not settle."""
    median = statistics.median(math.inf if count is None else count for count in counts)
    return None if math.isinf(median) else median


def _tabular(n_states: int, n_actions: int, fixed: bool, default: int):
    """A tabular study: train with tabular_goal.q_goal_parts, return (summary, controller)."""
    def train(request):
        env, learner, disc, steering = tabular_goal.q_goal_parts(n_states, n_actions, fixed,
                                                                 batch=common.robots(request))
        episodes = request.episodes or default
        phases, _ = common.run_phases([common.Phase("steering", env, learner, episodes,
                                                        common.checkpoint_path(request.out, "steering"))], request)
        return common.summarise(phases), tabular_goal.q_goal_controller(learner, disc, steering)
    return train


def _fql_fixed(request):
    """Fig VI.8: fql-goal's steering from the fixed start (1,000 episodes by default)."""
    task = replace(fql_goal.GOAL_TASKS["fql-goal"], fixed=True, learn_speed=False)
    summary = fql_goal.train_goal_fql(task, replace(request, episodes=request.episodes or 1000))
    return summary, load_controller(request.out)


STUDIES = {"q-goal-9": _tabular(9, 3, False, 4000), "q-goal-11": _tabular(11, 3, False, 4000),
           "q-goal-13": _tabular(13, 3, False, 4000), "q-goal-19x5": _tabular(19, 5, False, 4000),
           "q-goal-fixed": _tabular(13, 3, True, 1500), "fql-goal-fixed": _fql_fixed,
           "fql-wall-modules": lambda request: (fql_wall.train_fql_wall(request, "modules"),
                                                load_controller(request.out)),
           "fql-avoid-8": lambda request: (fql_avoid.train_fql_avoid(request, open_side=False),
                                           load_controller(request.out))}


def _train(task: str, request):
    """(summary of the phases, trained controller) of a train task or a study."""
    if task in STUDIES:
        return STUDIES[task](request)
    result = trainer(task)(request)
    return result, load_controller(request.out)


def _wall(controller) -> dict:
    """Wall follower: the Fig VI.28 corners and 100 random courses; success = no collision."""
    result = evaluations.evaluate_wall(controller, 100)
    return {**result, "success": 1 - result["collisions"] / result["courses"], "timeouts": 0}


def _fixed(controller) -> dict:
    """Fixed-start studies (Figs VI.2, VI.7): the one trained trajectory, from the fixed start."""
    from fuzzynav.sim import run_episode

    world, start, goal = envs.FixedGoal().sample(None, 1)
    outcome = run_episode(evaluations.scenario_of(world, start[0], goal[0], "fixed start", 60.0), controller).outcome
    return {"runs": 1, "success": float(outcome == "reached"), "collisions": int(outcome == "collision"),
            "timeouts": int(outcome == "timeout")}


def _avoid(controller) -> dict:
    """Avoidance navigator in 100 random worlds, as trained (the learned avoider alone avoids) and
    with the turning-room guard of fuzzy-5b-thesis added (``turn_guard``: a safety layer, reported apart)."""
    from fuzzynav.control.learned import LearnedAvoidanceNavigator

    guarded = LearnedAvoidanceNavigator(controller.avoidance, constant_speed=controller.constant_speed,
                                        name=controller.name, turn_guard=True)
    return {**evaluations.evaluate_avoid(controller), "with_turn_guard": evaluations.evaluate_avoid(guarded)}


EVALUATE = {"fql-avoid": _avoid, "fql-avoid-8": _avoid, "fql-wall": _wall, "fql-wall-modules": _wall,
            "q-goal-fixed": _fixed, "fql-goal-fixed": _fixed}


def run_task(task: str, seed: int, episodes: int | None, folder: Path, double: bool = False,
             parallel: int | None = None) -> dict:
    """Train ``task`` with ``seed`` (``parallel`` robots per batch, None: the thesis' one robot) and
    evaluate its controller: the row of the report."""
    out = folder / f"{task}-{seed}.json"
    start = time.perf_counter()
    result, controller = _train(task, TrainRequest(out=out, episodes=episodes, seed=seed, progress=False,
                                                   parallel=parallel))
    wall = time.perf_counter() - start
    evaluation = EVALUATE.get(task, evaluations.evaluate_goal)(controller)
    phases = {k: v for k, v in result.items() if isinstance(v, dict)}
    row = {"task": task, "seed": seed, "wall_s": round(wall, 2),
           "episodes": {k: v["episodes"] for k, v in phases.items()},
           "converged_at": {k: v["converged_at"] for k, v in phases.items()}, **evaluation}
    if double:
        budget = 2 * sum(row["episodes"].values())
        again, _ = _train(task, TrainRequest(out=folder / f"{task}-{seed}-x2.json", episodes=budget, seed=seed,
                                             progress=False, parallel=parallel))
        row["converged_at_double_budget"] = {k: v["converged_at"] for k, v in again.items() if isinstance(v, dict)}
    return row


def main() -> int:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--tasks", default=",".join(TASKS), help=f"comma-separated, of {', '.join(THESIS)}")
    parser.add_argument("--seeds", type=int, default=5)
    parser.add_argument("--episodes", type=int, default=None, help="episodes per task (default: the task's)")
    parser.add_argument("--double", action="store_true", help="also train with twice the budget")
    parser.add_argument("--parallel", type=int, default=None, metavar="N",
                        help="train N robots per batch on one rule base, as `fuzzynav train --parallel N` "
                             "(episodes then counted in batches); default: the thesis' one robot")
    parser.add_argument("--json", action="store_true", help="print one JSON object only")
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for task in args.tasks.split(","):
            for seed in range(args.seeds):
                rows.append(run_task(task, seed, args.episodes, Path(folder), args.double, args.parallel))
                if not args.json:
                    r = rows[-1]
                    guard = r.get("with_turn_guard")
                    print(f"{task:16s} seed {seed}: {r['wall_s']:6.1f} s  converged {r['converged_at']} "
                          f"{r.get('converged_at_double_budget', '')}  "
                          f"success {r['success']:.0%}  collisions {r['collisions']}  timeouts {r['timeouts']}"
                          + (f"  [with turn guard: success {guard['success']:.0%}  collisions {guard['collisions']}]"
                             if guard else ""))
    summary = {}
    for task in dict.fromkeys(r["task"] for r in rows):
        mine = [r for r in rows if r["task"] == task]
        summary[task] = {
            "wall_s_median": statistics.median(r["wall_s"] for r in mine),
            "success_per_seed": [r["success"] for r in mine],
            "collisions_per_seed": [r["collisions"] for r in mine],
            **({"fig_VI_28_per_seed": [r["fig-VI-28"] for r in mine]} if "fig-VI-28" in mine[0] else {}),
            **({"with_turn_guard": {"success_per_seed": [r["with_turn_guard"]["success"] for r in mine],
                                    "collisions_per_seed": [r["with_turn_guard"]["collisions"] for r in mine]}}
               if "with_turn_guard" in mine[0] else {}),
            "converged_at_per_seed": {p: [r["converged_at"][p] for r in mine] for p in mine[0]["converged_at"]},
            "converged_at_median": {p: median_count(r["converged_at"][p] for r in mine) for p in mine[0]["converged_at"]},
            "thesis_episodes": THESIS.get(task, {}),
        }
    if not args.json:
        for task, s in summary.items():
            print(f"{task:16s} median wall {s['wall_s_median']:.1f} s; converged (median) {s['converged_at_median']} "
                  f"vs thesis {s['thesis_episodes']}; success per seed {s['success_per_seed']}")
    print(json.dumps({"protocol": f"parallel: {args.parallel} robots per batch" if args.parallel else "thesis: one robot",
                      "runs": rows, "summary": summary}))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
