"""Simulator-core step rate: sensing (7 rays), nearest obstacle, kinematics, task and stop
tests, for 1, 64 and 1,024 robots stepped together in a world of 15 mixed obstacles.

The controller is a trivial vectorised proportional heading law (``act_batch``), so the numbers
measure the simulator, not a fuzzy controller. Prints a table and one JSON line (medians of 5
timed chunks).   Run:  python benchmarks/sim_core.py
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


def measure(scenario, n: int, steps: int, chunks: int = 5) -> float:
    rng = np.random.default_rng(1)
    starts = np.column_stack([rng.uniform(0.5, 2.0, n), rng.uniform(0.5, 19.5, n), wrap_angle(rng.uniform(-4, 4, n))])
    sim = BatchSimulator(scenario, Heading(), starts=starts, record=False)
    for _ in range(3):
        sim.step()
    rates = []
    for _ in range(chunks):
        start = time.perf_counter()
        for _ in range(steps):
            sim.step()
        rates.append(n * steps / (time.perf_counter() - start))
    return statistics.median(rates)


def main() -> None:
    scenario = world_of_15()
    results = {n: measure(scenario, n, steps) for n, steps in ((1, 400), (64, 100), (1024, 10))}
    print(f"{'robots':>7} {'robot-steps/s':>14} {'steps/s':>9}")
    for n, rate in results.items():
        print(f"{n:7d} {rate:14,.0f} {rate / n:9,.0f}")
    print(json.dumps({"benchmark": "sim_core", "obstacles": 15, "sensors": 7,
                      "robot_steps_per_s": {str(n): round(r) for n, r in results.items()}}))


if __name__ == "__main__":
    main()
