"""Simulator-core step rate (issue 3, benchmarks): sensing (7 rays), nearest obstacle (D_ro, θ_o),
kinematics, task and stop tests, for 1, 64 and 1,024 robots (spread over the free space) stepped
together in a world of 15 mixed obstacles — and IR-SIM's headless step rate in the same world,
measured in the same run (``benchmarks/irsim_peer.py`` in a subprocess).

The controller is a trivial vectorised law (``act_batch``: constant speed and steering, the
robots drive circles), so the numbers measure the simulator, not a fuzzy controller; IR-SIM gets
the same command. Rates are medians of 5 timed chunks, wall clock and this process's CPU time
(the latter is steadier on a busy machine). Run:

    python benchmarks/sim_core.py [--json] [--irsim-python /work/venv-irsim/bin/python]

``--json`` prints only one JSON object. Without a usable IR-SIM interpreter (or with
``--irsim-python ''``) the IR-SIM column is reported as unavailable.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from fuzzynav.robot.tricycle import DEFAULT_PARAMS
from fuzzynav.sim import BatchSimulator
from fuzzynav.world.geometry import wrap_angle
from fuzzynav.world.scenario import scenario_from_dict

COMMAND = (0.5, 0.4)  # V (m/s), α (rad): circles of radius l / tan α ≈ 1.2 m
COUNTS = ((1, 400), (64, 100), (1024, 10))  # robots, steps per timed chunk
DEFAULT_IRSIM_PYTHON = "/work/venv-irsim/bin/python"


class Circling:
    """Constant command for every robot (they drive circles until they hit something)."""

    name = "circling"

    def reset(self, rng=None):
        pass

    def act_batch(self, obs):
        return np.full(obs.n, COMMAND[1]), np.full(obs.n, COMMAND[0])


def obstacles_of_15(seed: int = 0) -> list[dict]:
    """15 obstacles in scenario-file form, cycling circle, triangle, wall, ellipse."""
    rng = np.random.default_rng(seed)
    shapes = []
    for i in range(15):
        x, y = (float(v) for v in rng.uniform(3, 17, 2))
        shapes.append([
            {"circle": {"center": [x, y], "radius": 0.6}},
            {"polygon": {"points": [[x - 0.5, y - 0.5], [x + 0.5, y - 0.5], [x, y + 0.5]]}},
            {"wall": {"start": [x, y], "end": [x + 1.5, y], "thickness": 0.2}},
            {"ellipse": {"center": [x, y], "radii": [0.8, 0.4], "angle": 0.5}},
        ][i % 4])
    return shapes


def world_of_15(seed: int = 0):
    return scenario_from_dict({"name": "bench-15", "robot": {"x": 1, "y": 1}, "goal": {"x": 19, "y": 19},
                               "obstacles": obstacles_of_15(seed), "max_time": 1e9}, source="benchmark")


def start_poses(scenario, n: int, clearance: float = 0.5) -> np.ndarray:
    """``n`` seeded start poses with at least ``clearance`` (m) to every obstacle and wall."""
    rng = np.random.default_rng(1)
    free = rng.uniform(0.5, 19.5, (40 * n + 400, 2))
    free = free[scenario.world.clearance(free) > clearance][:n]
    return np.column_stack([free, wrap_angle(rng.uniform(-4, 4, n))])


def measure(scenario, starts, steps: int, chunks: int = 5) -> tuple[float, float]:
    """Median robot-steps per second over ``chunks``: (wall clock, CPU time of this process)."""
    n = len(starts)
    sim = BatchSimulator(scenario, Circling(), starts=starts, record=False)
    for _ in range(3):
        sim.step()
    wall, cpu = [], []
    for _ in range(chunks):
        w0, c0 = time.perf_counter(), time.process_time()
        for _ in range(steps):
            sim.step()
        wall.append(n * steps / (time.perf_counter() - w0))
        cpu.append(n * steps / max(time.process_time() - c0, 1e-9))
    return statistics.median(wall), statistics.median(cpu)


def measure_irsim(python: str, start, steps: int = 200, chunks: int = 5) -> dict | None:
    """IR-SIM's headless rate for one robot in the same world, or None when it cannot run."""
    if not python or not os.path.exists(python):
        return None
    job = {"obstacles": obstacles_of_15(), "start": [float(v) for v in start], "command": list(COMMAND),
           "steps": steps, "chunks": chunks, "dt": DEFAULT_PARAMS.dt, "max_range": 4.0,
           "wheelbase": DEFAULT_PARAMS.wheelbase}
    peer = Path(__file__).with_name("irsim_peer.py")
    done = subprocess.run([python, str(peer)], input=json.dumps(job), capture_output=True, text=True,
                          timeout=600, env={**os.environ, "MPLBACKEND": "Agg"})
    if done.returncode != 0:
        print(f"IR-SIM run failed:\n{done.stderr[-2000:]}", file=sys.stderr)
        return None
    return json.loads(done.stdout.strip().splitlines()[-1])


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", action="store_true", help="print only one JSON object")
    parser.add_argument("--irsim-python", default=DEFAULT_IRSIM_PYTHON,
                        help="Python of a venv with ir-sim installed ('' to skip)")
    args = parser.parse_args(argv)
    scenario = world_of_15()
    one = start_poses(scenario, 1, clearance=2.5)  # room for the 1.2 m circle
    results = {n: measure(scenario, one if n == 1 else start_poses(scenario, n), steps) for n, steps in COUNTS}
    irsim = measure_irsim(args.irsim_python, one[0])
    report = {
        "benchmark": "sim_core", "obstacles": 15, "sensors": 7,
        "robot_steps_per_s_wall": {str(n): round(w) for n, (w, _) in results.items()},
        "robot_steps_per_s_cpu": {str(n): round(c) for n, (_, c) in results.items()},
        "irsim": None,
    }
    if irsim is not None:
        report["irsim"] = {
            "version": irsim["version"], "beams": irsim["beams"],
            "steps_per_s_wall": round(irsim["steps_per_s_wall"]),
            "steps_per_s_cpu": round(irsim["steps_per_s_cpu"]),
            "ratio_1_robot_wall": round(results[1][0] / irsim["steps_per_s_wall"], 1),
            "ratio_1_robot_cpu": round(results[1][1] / irsim["steps_per_s_cpu"], 1),
            "ratio_1024_robots_cpu": round(results[1024][1] / irsim["steps_per_s_cpu"], 1),
        }
    if args.json:
        print(json.dumps(report))
        return
    print(f"{'robots':>7} {'robot-steps/s (wall)':>21} {'robot-steps/s (CPU)':>20} {'steps/s (wall)':>15}")
    for n, (wall, cpu) in results.items():
        print(f"{n:7d} {wall:21,.0f} {cpu:20,.0f} {wall / n:15,.0f}")
    if irsim is None:
        print("IR-SIM: unavailable (see --irsim-python)")
    else:
        r = report["irsim"]
        print(f"IR-SIM {r['version']} (1 robot, {r['beams']} beams, headless): {r['steps_per_s_wall']:,} steps/s wall, "
              f"{r['steps_per_s_cpu']:,} CPU; fuzzynav / IR-SIM: {r['ratio_1_robot_wall']}x wall, "
              f"{r['ratio_1_robot_cpu']}x CPU (1 robot), {r['ratio_1024_robots_cpu']}x CPU (1,024 robots)")
    print(json.dumps(report))


if __name__ == "__main__":
    main()
