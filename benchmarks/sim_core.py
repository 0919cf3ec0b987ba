"""Simulator-core step rate: sensing (7 rays), nearest obstacle, kinematics, task and stop
tests, for 1, 64 and 1,024 robots (spread over the free space) stepped together in a world of 15
mixed obstacles.

The controller is a trivial vectorised proportional heading law (``act_batch``), so the numbers
measure the simulator, not a fuzzy controller. Prints a table and one JSON line (medians of 5
timed chunks, wall clock and this process's CPU time — the latter is steadier on a busy machine).
Run:  python benchmarks/sim_core.py
"""

from __future__ import annotations

import json
import statistics
import time

import numpy as np

from fuzzynav.sim import BatchSimulator
from fuzzynav.world.scenario import scenario_from_dict
from fuzzynav.world.geometry import wrap_angle


class Heading:
    """Steer towards the target, stand still (the robots never finish)."""

    name = "heading"

    def reset(self, rng=None):
        pass

    def act_batch(self, obs):
        return 2.0 * obs.target_bearing, np.zeros(obs.n)


def world_of_15(seed: int = 0):
    rng = np.random.default_rng(seed)
    shapes = []
    for i in range(15):
        x, y = rng.uniform(3, 17, 2)
        shapes.append([
            {"circle": {"center": [x, y], "radius": 0.6}},
            {"polygon": {"points": [[x - 0.5, y - 0.5], [x + 0.5, y - 0.5], [x, y + 0.5]]}},
            {"wall": {"start": [x, y], "end": [x + 1.5, y], "thickness": 0.2}},
            {"ellipse": {"center": [x, y], "radii": [0.8, 0.4], "angle": 0.5}},
        ][i % 4])
    return scenario_from_dict({"name": "bench-15", "robot": {"x": 1, "y": 1}, "goal": {"x": 19, "y": 19},
                               "obstacles": shapes, "max_time": 1e9}, source="benchmark")


def measure(scenario, n: int, steps: int, chunks: int = 5) -> tuple[float, float]:
    """Median robot-steps per second over ``chunks``: (wall clock, CPU time of this process)."""
    rng = np.random.default_rng(1)
    free = rng.uniform(0.5, 19.5, (4 * n + 100, 2))
    free = free[scenario.world.clearance(free) > 0.5][:n]  # robots spread over the free space
    starts = np.column_stack([free, wrap_angle(rng.uniform(-4, 4, n))])
    sim = BatchSimulator(scenario, Heading(), starts=starts, record=False)
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


def main() -> None:
    scenario = world_of_15()
    results = {n: measure(scenario, n, steps) for n, steps in ((1, 400), (64, 100), (1024, 10))}
    print(f"{'robots':>7} {'robot-steps/s (wall)':>21} {'robot-steps/s (CPU)':>20} {'steps/s (wall)':>15}")
    for n, (wall, cpu) in results.items():
        print(f"{n:7d} {wall:21,.0f} {cpu:20,.0f} {wall / n:15,.0f}")
    print(json.dumps({"benchmark": "sim_core", "obstacles": 15, "sensors": 7,
                      "robot_steps_per_s_wall": {str(n): round(w) for n, (w, _) in results.items()},
                      "robot_steps_per_s_cpu": {str(n): round(c) for n, (_, c) in results.items()}}))


if __name__ == "__main__":
    main()
