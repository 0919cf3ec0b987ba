"""``astar-pp`` on dead-end starts: corridors whose start faces the closed end, so the way out
begins backwards (:mod:`fuzzynav.world.dead_ends`: width 1.0–2.4 m, depth 4–9 m, any orientation).
Reports outcomes, the planner used and the median time to the goal. Run:

    python benchmarks/astar_backing.py [--n 40] [--seed 0] [--json]
"""

from __future__ import annotations

import json
import statistics
from collections import Counter

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.cli import Parser
from fuzzynav.sim import metrics, run_episode
from fuzzynav.world.dead_ends import dead_ends


def main(argv=None) -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=40)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--controller", default="astar-pp")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)
    outcomes, planners, times, clearances = Counter(), Counter(), [], []
    for scenario in dead_ends(args.n, args.seed):
        controller = make_controller(args.controller)
        trace = run_episode(scenario, controller, seed=0)
        outcomes[trace.outcome] += 1
        planners[getattr(controller, "planner", "-")] += 1
        clearances.append(metrics(trace, scenario)["min_clearance_m"])
        if trace.outcome == "reached":
            times.append(float(trace.t[-1]))
        if not args.json:
            print(f"{scenario.name}: {trace.outcome} ({getattr(controller, 'planner', '-')})", flush=True)
    report = {"benchmark": "astar_backing", "controller": args.controller, "worlds": args.n, "seed": args.seed,
              "outcomes": dict(outcomes), "success": round(outcomes["reached"] / args.n, 3),
              "planners": dict(planners), "median_time_s": round(statistics.median(times), 1) if times else None,
              "min_clearance_m": round(min(clearances), 3)}
    print(json.dumps(report))


if __name__ == "__main__":
    main()
