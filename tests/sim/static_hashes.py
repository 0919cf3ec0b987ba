"""Hashes of closed-loop traces in static worlds, to show that moving obstacles changed nothing
where nothing moves: ``python -m tests.sim.static_hashes OUT.json`` records them with the
checkout on ``PYTHONPATH``; ``tests/sim/static_hashes.json`` holds those of the code before
moving obstacles were added, and ``tests/sim/test_moving_obstacles.py`` compares."""

from __future__ import annotations

import hashlib
import json
import sys

import numpy as np

# (built-in scenario, controller): compiled and Python navigators, path and target trackers
# (fuzzy-2b-layered is the fuzzy-2b-thesis of the recorded code, whose layers are optional since)
RUNS = (
    ("fig-IV-15a", "fuzzy-5b"), ("fig-IV-22b", "fuzzy-5b"), ("fig-IV-23", "fuzzy-2b-layered"),
    ("example-goal", "dwa"), ("fig-IV-22a", "vfh"), ("example-path", "fuzzy-tracker"),
    ("example-target", "pure-pursuit"),
)
# the default as it was recorded: without the pace, the plan reuse, the chained arcs, the car
# route ended inside the goal's tolerance, its arcs driven wherever it passes within 2 m and the
# route to a target off the heading, which came later
OPTIONS = {"fuzzy-5b": {"paced": False, "goal_share": 0.0,
                        "guidance": {"guide_car_reuse": 0.0, "guide_car_chain": 0.0, "guide_car_tight": 0.5,
                                     "guide_off_heading": 0.0}}}


def trace_hash(scenario: str, controller: str) -> str:
    """SHA-256 of the outcome, poses, commands and ranges of one seeded run."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim.simulator import run_episode
    from fuzzynav.world.scenario import load_scenario

    trace = run_episode(load_scenario(scenario), make_controller(controller, **OPTIONS.get(controller, {})), seed=0)
    return trace_digest(trace)


def trace_digest(trace) -> str:
    """SHA-256 of a trace's outcome, poses, commands and ranges."""
    digest = hashlib.sha256(trace.outcome.encode())
    for array in (trace.pose, trace.steering, trace.speed, trace.ranges, trace.target):
        digest.update(np.ascontiguousarray(array, dtype=float).tobytes())
    return digest.hexdigest()


def all_hashes() -> dict[str, str]:
    return {f"{scenario}/{controller}": trace_hash(scenario, controller) for scenario, controller in RUNS}


if __name__ == "__main__":
    hashes = all_hashes()
    with open(sys.argv[1], "w") as out:
        json.dump(hashes, out, indent=1)
