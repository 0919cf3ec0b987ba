"""What hybrid A* costs and adds in ``astar-pp``: planning time per world against the grid A* it
replaced, and the same tracker on either path.

For every world of each suite (a folder of scenario files, or a generated family ``name:count``
with ``--seed``), plans as ``astar-pp`` does in ``prepare`` (uncached) and, interleaved on the
same world, the peer: the grid A* path with the same inflation and clearance cost. Prints per
suite the median and maximum wall time of each, the median ratio hybrid / grid, and how many
worlds fell back to grid A* (hybrid A* found no path within its node budget) or had no path.
The first plan (numba compilation, or loading its cache) is not timed.

``--episodes`` also runs ``astar-pp`` (``planner="hybrid"``, the default) and ``astar-pp`` with
``planner="grid"`` (grid A* only, heading ignored), one episode each with seed ``--seed``, and
prints their outcome counts, median time of the successes and smallest clearance.

    python benchmarks/astar_planners.py SUITE... [--seed 0] [--episodes] [--json]
"""

from __future__ import annotations

import json
import statistics
import time
from collections import Counter

from fuzzynav.bench.suites import parse_suite
from fuzzynav.cli import Parser
from fuzzynav.control.classic.astar_pp import AStarPurePursuit, plan_path
from fuzzynav.sim import metrics, run_episode

PLANNERS = ("hybrid", "grid")


def _timed(scenario, navigator: AStarPurePursuit, hybrid: bool) -> tuple[str, float]:
    started = time.perf_counter()
    planner = plan_path(scenario, navigator.body, navigator.inflation, navigator.search, hybrid)[0]
    return planner, time.perf_counter() - started


def _episodes(scenario, seed: int) -> dict:
    results = {}
    for name in PLANNERS:
        trace = run_episode(scenario, AStarPurePursuit(planner=name), seed=seed)
        results[name] = (trace.outcome, metrics(trace, scenario))
    return results


def measure(spec: str, seed: int, episodes: bool) -> dict:
    """Planning times and planner counts (and episode outcomes) of one suite."""
    suite = parse_suite(spec)
    navigator = AStarPurePursuit()
    times = {name: [] for name in PLANNERS}
    planners = Counter()
    outcomes = {name: Counter() for name in PLANNERS}
    durations, clearances = {name: [] for name in PLANNERS}, {name: [] for name in PLANNERS}
    for index in range(suite.size):
        scenario = suite.scenario(index, seed)
        for name in PLANNERS:
            planner, seconds = _timed(scenario, navigator, name == "hybrid")
            times[name].append(seconds)
            if name == "hybrid":
                planners[planner] += 1
        for name, (outcome, numbers) in (_episodes(scenario, seed) if episodes else {}).items():
            outcomes[name][outcome] += 1
            clearances[name].append(numbers["min_clearance_m"])
            if outcome == "reached":
                durations[name].append(numbers["time_s"])
    result = {"suite": suite.name, "worlds": suite.size, "planners": dict(planners),
              "ratio_median": statistics.median(h / g for h, g in zip(times["hybrid"], times["grid"]))}
    for name in PLANNERS:
        result[name] = {"plan_median_s": statistics.median(times[name]), "plan_max_s": max(times[name])}
        if episodes:
            result[name].update(outcomes=dict(outcomes[name]), min_clearance_m=min(clearances[name]),
                                median_time_s=statistics.median(durations[name]) if durations[name] else None)
    return result


def main() -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("suites", nargs="+")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--episodes", action="store_true", help="also run an episode with each planner")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    _timed(parse_suite(args.suites[0]).scenario(0, args.seed), AStarPurePursuit(), True)  # compile once
    results = [measure(spec, args.seed, args.episodes) for spec in args.suites]
    if args.json:
        print(json.dumps(results, indent=1))
        return
    for r in results:
        print(f"{r['suite']} ({r['worlds']} worlds): planners {r['planners']}, hybrid/grid planning time "
              f"median ratio {r['ratio_median']:.2f}")
        for name in PLANNERS:
            numbers = r[name]
            line = f"  {name} A*: planning median {numbers['plan_median_s']:.3f} s, max {numbers['plan_max_s']:.3f} s"
            if args.episodes:
                line += (f"; episodes {numbers['outcomes']}, median time {numbers['median_time_s']} s, "
                         f"smallest clearance {numbers['min_clearance_m']:.3f} m")
            print(line)


if __name__ == "__main__":
    main()
