"""Cost of ``fuzzynav bench`` beyond the episodes themselves, and a campaign's wall time.

The peer, measured in the same run and interleaved with the runner, is the bare loop a user
would write: draw each world, build the controller, ``run_episode``, ``metrics``. The runner
(:func:`fuzzynav.bench.campaign.run_campaign`, local backend, one worker, no reports) adds the
shortest path of each world (computed once, cached), the extra measures, the rows written to
runs.csv / runs.jsonl and the final rewrite. Each repetition runs both on the same worlds
(family ``--family``, ``--worlds`` of them, new worlds each repetition) with ``--controllers``;
CPU time of this process (steadier than wall time on a shared machine) and wall time are
reported, per run, with the runner/peer ratio (median over repetitions).

``--campaign N`` also times a real campaign of N worlds × the controllers with ``--workers``
processes (wall time, the one that matters for a 10,000-run campaign), into a temporary folder.

    python benchmarks/bench_overhead.py [--family mixed] [--worlds 20] [--controllers fuzzy-5b-rays,dwa]
                                        [--repeats 3] [--campaign 0] [--workers 2] [--json]
"""

from __future__ import annotations

import json
import statistics
import tempfile
import time
from pathlib import Path

from fuzzynav.bench.campaign import Plan, run_campaign
from fuzzynav.bench.suites import parse_suite
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.cli import Parser
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.sim import metrics, run_episode
from fuzzynav.world.generate import generate_world


def _clock():
    return time.process_time(), time.perf_counter()


def peer(family: str, count: int, seed: int, controllers: list[str]) -> tuple[float, float]:
    cpu, wall = _clock()
    for i in range(count):
        scenario = generate_world(family, seed, i)
        for name in controllers:
            metrics(run_episode(scenario, make_controller(name), seed=0), scenario)
    return time.process_time() - cpu, time.perf_counter() - wall


def runner(family: str, count: int, seed: int, controllers: list[str], workers: int = 1) -> tuple[float, float]:
    plan = Plan((parse_suite(f"{family}:{count}:{seed}"),), tuple((c, c) for c in controllers), 1,
                DEFAULT_PARAMS.radius)
    with tempfile.TemporaryDirectory() as folder:
        cpu, wall = _clock()
        run_campaign(plan, Path(folder), workers=workers, progress=False)
        return time.process_time() - cpu, time.perf_counter() - wall


def main() -> None:
    parser = Parser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--family", default="mixed")
    parser.add_argument("--worlds", type=int, default=20)
    parser.add_argument("--controllers", default="fuzzy-5b-rays,dwa")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--campaign", type=int, default=0, metavar="N")
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    controllers = args.controllers.split(",")
    runs = args.worlds * len(controllers)
    peer_cpu, runner_cpu, peer_wall, runner_wall = [], [], [], []
    for repeat in range(args.repeats):
        seed = 1000 + repeat  # fresh worlds: no cache carried over between repetitions
        c, w = peer(args.family, args.worlds, seed, controllers)
        peer_cpu.append(c / runs)
        peer_wall.append(w / runs)
        c, w = runner(args.family, args.worlds, seed, controllers)
        runner_cpu.append(c / runs)
        runner_wall.append(w / runs)
    result = {
        "family": args.family, "worlds": args.worlds, "controllers": controllers, "repeats": args.repeats,
        "peer_cpu_s_per_run": statistics.median(peer_cpu), "runner_cpu_s_per_run": statistics.median(runner_cpu),
        "peer_wall_s_per_run": statistics.median(peer_wall), "runner_wall_s_per_run": statistics.median(runner_wall),
        "cpu_ratio": statistics.median(r / p for r, p in zip(runner_cpu, peer_cpu)),
        "overhead_cpu_ms_per_run": 1000 * statistics.median(r - p for r, p in zip(runner_cpu, peer_cpu)),
    }
    if args.campaign:
        _, wall = runner(args.family, args.campaign, 2000, controllers, args.workers)
        n = args.campaign * len(controllers)
        result.update({"campaign_runs": n, "campaign_workers": args.workers, "campaign_wall_s": wall,
                       "campaign_runs_per_s": n / wall, "extrapolated_10000_runs_min": 10000 / (n / wall) / 60})
    if args.json:
        print(json.dumps(result))
        return
    for key, value in result.items():
        print(f"{key:32s} {value:.4g}" if isinstance(value, float) else f"{key:32s} {value}")


if __name__ == "__main__":
    main()
