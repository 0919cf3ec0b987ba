"""Closed-loop step rate of the five-behaviour navigator (issue 3, benchmarks).

One step = sense (7 range rays against every obstacle, nearest obstacle) → ``fuzzy-5b``
(supervisor, GSB, FOA/ROA/LOA, VRB: five TS0 systems, ``act_batch``) → clip → kinematics → stop
tests, in the 15-obstacle mixed world of ``benchmarks/sim_core.py``, goal at (19, 19):

- one robot: simulation steps per second;
- 1, 64 and 1,024 robots stepped together in one vectorised batch: robot-steps per second
  (only robots still running count; a batch whose robots have all finished is reset);
- IR-SIM's headless step rate for one robot in the same world, measured in the same run by
  ``benchmarks/irsim_peer.py`` in its own virtualenv (IR-SIM gets a constant command: its number
  is the simulator alone, ours includes the fuzzy navigator).

Rates are medians of 5 timed chunks, wall clock and CPU time of this process. Run:

    python benchmarks/sim_bench.py [--json] [--irsim-python /work/venv-irsim/bin/python]
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from sim_core import DEFAULT_IRSIM_PYTHON, measure_irsim, start_poses, world_of_15  # noqa: E402

from fuzzynav.control.registry import make_controller  # noqa: E402
from fuzzynav.sim import BatchSimulator  # noqa: E402

COUNTS = ((1, 300), (64, 60), (1024, 8))  # robots, steps per timed chunk


def measure(scenario, starts, steps: int, chunks: int = 5) -> tuple[float, float]:
    """Median running-robot steps per second over ``chunks``: (wall clock, CPU time)."""
    sim = BatchSimulator(scenario, make_controller("fuzzy-5b"), starts=starts, record=False)
    for _ in range(3):
        sim.step()
    wall, cpu = [], []
    for _ in range(chunks):
        count, busy_wall, busy_cpu = 0, 0.0, 0.0
        for _ in range(steps):
            if sim.done:
                sim.reset()
            running = int(sim.active.sum())
            w0, c0 = time.perf_counter(), time.process_time()
            sim.step()
            busy_wall += time.perf_counter() - w0
            busy_cpu += time.process_time() - c0
            count += running
        wall.append(count / busy_wall)
        cpu.append(count / max(busy_cpu, 1e-9))
    return statistics.median(wall), statistics.median(cpu)


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true", help="print only one JSON object")
    parser.add_argument("--irsim-python", default=DEFAULT_IRSIM_PYTHON,
                        help="Python of a venv with ir-sim installed ('' to skip)")
    args = parser.parse_args(argv)
    scenario = world_of_15()
    one = start_poses(scenario, 1, clearance=2.5)
    results = {n: measure(scenario, one if n == 1 else start_poses(scenario, n), steps) for n, steps in COUNTS}
    irsim = measure_irsim(args.irsim_python, one[0])
    report = {
        "benchmark": "sim_bench", "controller": "fuzzy-5b", "obstacles": len(scenario.world.obstacles), "sensors": 7,
        "robot_steps_per_s_wall": {str(n): round(w) for n, (w, _) in results.items()},
        "robot_steps_per_s_cpu": {str(n): round(c) for n, (_, c) in results.items()},
        "irsim": None,
    }
    if irsim is not None:
        report["irsim"] = {
            "version": irsim["version"], "beams": irsim["beams"],
            "steps_per_s_wall": round(irsim["steps_per_s_wall"]), "steps_per_s_cpu": round(irsim["steps_per_s_cpu"]),
            "ratio_1_robot_wall": round(results[1][0] / irsim["steps_per_s_wall"], 1),
            "ratio_1_robot_cpu": round(results[1][1] / irsim["steps_per_s_cpu"], 1),
            "ratio_1024_robots_cpu": round(results[1024][1] / irsim["steps_per_s_cpu"], 1),
        }
    if args.json:
        print(json.dumps(report))
        return
    print(f"fuzzy-5b closed loop, {report['obstacles']} obstacles, 7 sensors")
    print(f"{'robots':>7} {'robot-steps/s (wall)':>21} {'robot-steps/s (CPU)':>20}")
    for n, (wall, cpu) in results.items():
        print(f"{n:7d} {wall:21,.0f} {cpu:20,.0f}")
    if irsim is None:
        print("IR-SIM: unavailable (see --irsim-python)")
    else:
        r = report["irsim"]
        print(f"IR-SIM {r['version']} (1 robot, {r['beams']} beams, headless, no controller): "
              f"{r['steps_per_s_wall']:,} steps/s wall, {r['steps_per_s_cpu']:,} CPU; fuzzynav fuzzy-5b / IR-SIM: "
              f"{r['ratio_1_robot_wall']}x wall, {r['ratio_1_robot_cpu']}x CPU (1 robot), "
              f"{r['ratio_1024_robots_cpu']}x CPU (1,024 robots)")


if __name__ == "__main__":
    main()
