"""What hybrid A* adds to ``astar-pp``: the same tracker on the hybrid A* path and on the grid A* path.

Runs ``astar-pp`` (``planner="hybrid"``, the default) and ``astar-pp`` with ``planner="grid"``
(grid A* on the same inflated map, heading ignored), interleaved world by world, on every world
of each suite (a folder of scenario files, or a generated family ``name:count`` with ``--seed``),
one episode each with the campaign's seed; prints success / collision / timeout counts, the
median time of the successes and the smallest clearance of each.

    python benchmarks/astar_planners.py SUITE... [--seed 0] [--json]
"""

from __future__ import annotations

import argparse
import json
import statistics
from collections import Counter

from fuzzynav.bench.suites import parse_suite
from fuzzynav.control.classic.astar_pp import AStarPurePursuit
from fuzzynav.sim import metrics, run_episode

PLANNERS = ("hybrid", "grid")


def measure(spec: str, seed: int) -> dict:
    """Outcome counts, median time and smallest clearance per planner on one suite."""
    suite = parse_suite(spec)
    outcomes = {name: Counter() for name in PLANNERS}
    times, clearances = {name: [] for name in PLANNERS}, {name: [] for name in PLANNERS}
    for index in range(suite.size):
        scenario = suite.scenario(index, seed)
        for name in PLANNERS:
            trace = run_episode(scenario, AStarPurePursuit(planner=name), seed=seed)
            numbers = metrics(trace, scenario)
            outcomes[name][trace.outcome] += 1
            clearances[name].append(numbers["min_clearance_m"])
            if trace.outcome == "reached":
                times[name].append(numbers["time_s"])
    return {"suite": suite.name, "worlds": suite.size, **{
        name: {"outcomes": dict(outcomes[name]), "median_time_s": statistics.median(times[name]) if times[name] else None,
               "min_clearance_m": min(clearances[name])} for name in PLANNERS}}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("suites", nargs="+")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    results = [measure(spec, args.seed) for spec in args.suites]
    if args.json:
        print(json.dumps(results, indent=1))
        return
    for r in results:
        for name in PLANNERS:
            print(f"{r['suite']} ({r['worlds']} worlds) {name} A*: {r[name]['outcomes']}, median time "
                  f"{r[name]['median_time_s']} s, smallest clearance {r[name]['min_clearance_m']:.3f} m")


if __name__ == "__main__":
    main()
