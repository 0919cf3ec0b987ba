"""Robot-steps per second of a large batch stepped on one thread and on one thread per core
(:mod:`fuzzynav.sim.blocks`), in the world of ``benchmarks/sim_core.py`` (15 mixed obstacles,
robots spread over the free space; only robots still running count). The two settings run the
same batch from the same starts in alternating chunks of ``--steps`` steps, ``--chunks`` times
each; the ratio is the median of the per-chunk ratios, so both see the same machine load. The
states after every pair of chunks are checked equal.

    python benchmarks/batch_threads.py --controller fuzzy-5b --robots 64 1024 [--steps 10] [--chunks 5] [--json]
"""

from __future__ import annotations

import json
import statistics
import sys
import time
from pathlib import Path

import numpy as np

from fuzzynav.cli import Parser

sys.path.insert(0, str(Path(__file__).parent))

from sim_core import start_poses, world_of_15  # noqa: E402

from fuzzynav import threads  # noqa: E402
from fuzzynav.catalog.controllers import make_controller  # noqa: E402
from fuzzynav.sim import BatchSimulator  # noqa: E402


def chunk(sim: BatchSimulator, count: int, steps: int) -> tuple[float, float]:
    """(running robot-steps per second of wall clock, of this process' CPU time) over ``steps``
    steps on ``count`` threads."""
    threads.set_count(count)
    done, wall, cpu = 0, 0.0, 0.0
    for _ in range(steps):
        running = int(np.count_nonzero(sim.active))
        if not running:
            break
        started, used = time.perf_counter(), time.process_time()
        sim.step()
        wall += time.perf_counter() - started
        cpu += time.process_time() - used
        done += running
    return done / max(wall, 1e-9), done / max(cpu, 1e-9)


def main(argv=None) -> None:
    parser = Parser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--controller", default="fuzzy-5b")
    parser.add_argument("--robots", type=int, nargs="+", default=[64, 1024])
    parser.add_argument("--steps", type=int, default=10, help="steps per timed chunk")
    parser.add_argument("--chunks", type=int, default=5)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)
    scenario, cores = world_of_15(), threads.cores()
    report = {"benchmark": "batch_threads", "controller": args.controller, "cores": cores, "robots": {}}
    for n in args.robots:
        starts = start_poses(scenario, n)
        sims = {count: BatchSimulator(scenario, make_controller(args.controller), starts=starts, record=False)
                for count in (1, cores)}
        for count, sim in sims.items():
            chunk(sim, count, 1)  # kernels loaded, first plans made
        rates: dict[int, list] = {1: [], cores: []}
        same = True
        for _ in range(args.chunks):
            for count, sim in sims.items():
                rates[count].append(chunk(sim, count, args.steps))
            same &= bool(np.array_equal(sims[1]._state, sims[cores]._state, equal_nan=True))
        row = {str(count): {"wall": round(statistics.median(r[0] for r in rate)),
                            "cpu": round(statistics.median(r[1] for r in rate))} for count, rate in rates.items()}
        row["ratio_wall"] = round(statistics.median(b[0] / a[0] for a, b in zip(rates[1], rates[cores])), 2)
        row["same_states"] = same
        report["robots"][str(n)] = row
        if not args.json:
            print(f"{args.controller}, {n} robots: 1 thread {row['1']['wall']:,} robot-steps/s, {cores} threads "
                  f"{row[str(cores)]['wall']:,} (x{row['ratio_wall']} wall, median of {args.chunks} chunks); "
                  f"same states: {same}")
    threads.set_count(None)
    if args.json:
        print(json.dumps(report))


if __name__ == "__main__":
    main()
