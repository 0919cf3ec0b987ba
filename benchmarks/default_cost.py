"""CPU cost of the default navigator ``fuzzy-5b``: where ``fuzzynav evaluate`` spends its time,
and its rate of robot-steps in ``benchmarks/sim_core.py``'s world.

``--parts``: one process times, in order, the imports of ``fuzzynav evaluate``, the first world
generated (numba's first load of a cached kernel imports its registries), ``--n`` worlds of
``mixed`` seed 0, and one ``fuzzy-5b`` episode on each (CPU seconds; µs a step). ``--robots``:
for each count, ``fuzzy-5b`` with the 271-beam lidar from ``sim_core.start_poses`` steps
``--steps`` times after 3 of warm-up (robot-steps per CPU second, finished episodes restarted;
the loop of ``benchmarks/navigator_profile.py``). CPU time, so that figures taken on a busy
machine compare; run two checkouts alternately to compare them. Run:

    python benchmarks/default_cost.py --parts [--n 100]
    python benchmarks/default_cost.py --robots 1 64 1024 [--steps 1500]
"""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path

from fuzzynav.cli import Parser


def parts(n: int) -> dict:
    """CPU seconds of each part of an ``evaluate`` run of ``fuzzy-5b`` on ``n`` ``mixed`` worlds."""
    clock = time.process_time
    t0 = clock()
    import fuzzynav.bench.evaluate  # noqa: F401
    import fuzzynav.cli  # noqa: F401
    from fuzzynav.world.generate import generate_worlds

    t1 = clock()
    generate_worlds("mixed", 1, 0)
    t2 = clock()
    worlds = generate_worlds("mixed", n, 0)
    t3 = clock()
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim import run_episode

    steps = sum(len(run_episode(world, make_controller("fuzzy-5b"), seed=0).t) - 1 for world in worlds)
    t4 = clock()
    return {"imports_s": round(t1 - t0, 3), "first_world_s": round(t2 - t1, 3), "worlds_s": round(t3 - t2, 3),
            "episodes_s": round(t4 - t3, 3), "steps": steps, "us_per_step": round(1e6 * (t4 - t3) / steps, 1)}


def rate(n: int, steps: int) -> float:
    """Robot-steps of ``fuzzy-5b`` per CPU second, ``n`` robots (module docstring)."""
    import numpy as np

    sys.path.insert(0, str(Path(__file__).parent))
    from sim_core import start_poses, world_of_15

    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.robot.sensors import named_ring
    from fuzzynav.sim import BatchSimulator

    scenario = world_of_15()
    starts = start_poses(scenario, n, clearance=3.0 if n == 1 else 0.5)
    sim = BatchSimulator(scenario, make_controller("fuzzy-5b"), starts=starts, record=False,
                         sensors=named_ring("lidar"))
    for _ in range(3):
        sim.step()
    done, spent = 0, 0.0
    for _ in range(steps):
        if sim.done:
            sim.reset()
        running = int(np.count_nonzero(sim.active))
        t0 = time.process_time()
        sim.step()
        spent += time.process_time() - t0
        done += running
    return done / spent


def main(argv=None) -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--parts", action="store_true", help="split an evaluate run's CPU time")
    parser.add_argument("--n", type=int, default=100, help="worlds of --parts")
    parser.add_argument("--robots", type=int, nargs="*", default=[], help="robot counts to rate")
    parser.add_argument("--steps", type=int, default=1500, help="steps of one robot (n robots: / n, at least 8)")
    args = parser.parse_args(argv)
    report: dict = {"benchmark": "default_cost", "controller": "fuzzy-5b"}
    if args.parts:
        report["evaluate_parts"] = parts(args.n)
    report["robot_steps_per_cpu_s"] = {str(n): round(rate(n, max(8, args.steps // n))) for n in args.robots}
    print(json.dumps(report))


if __name__ == "__main__":
    main()
