"""Planning time of the map-aware ``astar-pp`` per world: hybrid A* against the grid A* it replaced.

For every world of each suite (a folder of scenario files, or a generated family ``name:count``
with ``--seed``), plans as ``astar-pp`` does in ``prepare`` (uncached) and, interleaved on the
same world, the peer: the grid A* path with the same inflation and clearance cost
(:func:`fuzzynav.world.planning.shortest_path`). Prints per suite the median and maximum wall
time of each, the median ratio hybrid / grid, and how many worlds fell back to grid A* (hybrid A*
found no path within its node budget) or had no path at all. The first plan (numba compilation,
or loading its cache) is not timed.

    python benchmarks/plan_time.py SUITE... [--seed 0] [--json]
"""

from __future__ import annotations

import argparse
import json
import statistics
import time
from collections import Counter

from fuzzynav.bench.suites import parse_suite
from fuzzynav.control.classic.astar_pp import AStarPurePursuit, plan_path
from fuzzynav.world.planning import shortest_path


def measure(spec: str, seed: int) -> dict:
    """Timings and planner counts of one suite."""
    suite = parse_suite(spec)
    navigator = AStarPurePursuit()
    radius = navigator.body.radius + navigator.inflation
    hybrid, grid, planners = [], [], Counter()
    for index in range(suite.size):
        scenario = suite.scenario(index, seed)
        started = time.perf_counter()
        planner, _, _ = plan_path(scenario, navigator.body, navigator.inflation, navigator.search)
        hybrid.append(time.perf_counter() - started)
        planners[planner] += 1
        started = time.perf_counter()
        shortest_path(scenario.world, scenario.start, scenario.goal.position, radius,
                      weight=navigator.search.weight, comfort=navigator.search.comfort)
        grid.append(time.perf_counter() - started)
    ratios = [h / g for h, g in zip(hybrid, grid)]
    return {"suite": suite.name, "worlds": suite.size, "hybrid_median_s": statistics.median(hybrid),
            "hybrid_max_s": max(hybrid), "grid_median_s": statistics.median(grid), "grid_max_s": max(grid),
            "ratio_median": statistics.median(ratios), "planners": dict(planners)}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("suites", nargs="+")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    first = parse_suite(args.suites[0]).scenario(0, args.seed)  # compile (or load) the search once
    navigator = AStarPurePursuit()
    plan_path(first, navigator.body, navigator.inflation, navigator.search)
    results = [measure(spec, args.seed) for spec in args.suites]
    if args.json:
        print(json.dumps(results, indent=1))
        return
    for r in results:
        print(f"{r['suite']}: {r['worlds']} worlds, hybrid A* median {r['hybrid_median_s']:.3f} s, "
              f"max {r['hybrid_max_s']:.3f} s; grid A* median {r['grid_median_s']:.3f} s, max "
              f"{r['grid_max_s']:.3f} s; hybrid/grid median ratio {r['ratio_median']:.2f}; planners {r['planners']}")


if __name__ == "__main__":
    main()
