"""What the parts of a ``fuzzy-5b`` step cost on the scans it reads, kernel by kernel.

One ``fuzzy-5b`` robot drives ``sim_core.py``'s world of 15 mixed obstacles (an episode that ends
starts again) while its poses and 271-beam scans are recorded; then each part of the default
navigator's step runs over all the recorded steps in one compiled loop (warm first, the median of
``--repeats``), µs per step:

- ``hit memory``: the scan remembered (:func:`fuzzynav.kernels.guard.remember`), the turning room
  and the safety stop's clearance over the last 10 steps' hits (:mod:`fuzzynav.kernels.guard`);
- ``gap finding``: :func:`fuzzynav.kernels.gaps.gap_heading` at the navigator's clearance, and its
  ``blocked directions`` alone (the navigator asks for gaps only off goal seeking, up to three times);
- ``sector readings``: the thesis' seven readings from the scan (:func:`fuzzynav.kernels.gaps.sector_readings`);
- ``pace``: the free run on the arcs of the car route's curvatures (:func:`fuzzynav.kernels.pace.free_run`);
- ``points seen``: the map of the recovery and route layers (:func:`fuzzynav.kernels.sightings.see`).

The parts are timed apart from the simulator, so they are a split of the step, not its sum (the
lidar, the fuzzy systems, the layers' logic and the searches are not in it: ``navigator_profile.py``).
Run:

    python benchmarks/navigator_parts.py [--steps 4000] [--repeats 3] [--json]
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

from fuzzynav.catalog.controllers import make_controller  # noqa: E402
from fuzzynav.jit import jit  # noqa: E402
from fuzzynav.kernels import gaps, guard, guidance, layers, navigators, pace, sightings  # noqa: E402
from fuzzynav.kernels.records import Pose, Reading  # noqa: E402
from fuzzynav.sim import BatchSimulator  # noqa: E402

MEMORY_STEPS = 10  # the hit memory of fuzzy-5b's inner navigator


def recorded(steps: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(poses (T, 3), scans (T, S), beam angles (S,)) of one ``fuzzy-5b`` robot driving ``steps`` steps."""
    scenario = world_of_15()
    sim = BatchSimulator(scenario, make_controller("fuzzy-5b"), starts=start_poses(scenario, 1), record=False)
    poses, scans = [], []
    for _ in range(steps):
        if sim.done:
            sim.reset()
        sim.step()
        poses.append(sim.pose[0].copy())
        scans.append(sim.observation.ranges[0].copy())
    return np.array(poses), np.array(scans), np.asarray(sim.sensors.angles, dtype=float)


@jit
def hit_memory(poses, scans, angles, params, memory):
    total = 0.0
    for i in range(scans.shape[0]):
        x, y, theta = poses[i, 0], poses[i, 1], poses[i, 2]
        guard.remember(memory, i, Pose(x, y, theta), Reading(scans[i], angles, 4.0, 1.0, 0.3),
                       params[navigators.HALF_CONE])
        left, _, _ = guard.turning_room(memory, x, y, theta, params[navigators.BODY], params[navigators.TURN_RADIUS])
        total += left + guard.step_clearance(memory, x, y, theta, 0.05, params[navigators.BODY])
    return total


@jit
def gap_finding(scans, angles, params):
    total = 0.0
    for i in range(scans.shape[0]):
        total += gaps.gap_heading(scans[i], angles, 0.3, params[navigators.GAP_CLEARANCE], params[navigators.GAP_LOOK],
                                  params[navigators.GAP_FIELD], params[navigators.TURN_RADIUS])[1]
    return total


@jit
def blocked(scans, angles, params):
    total = 0
    for i in range(scans.shape[0]):
        clearance, look = params[navigators.GAP_CLEARANCE], params[navigators.GAP_LOOK]
        total += gaps.blocked_directions(scans[i], angles, clearance, look)[0]
    return total


@jit
def sectors(scans, angles, params):
    total = 0.0
    for i in range(scans.shape[0]):
        total += gaps.sector_readings(scans[i], angles, params[navigators.READING_HALF], 4.0)[0]
    return total


@jit
def free_runs(scans, angles, curvatures, room):
    total = 0.0
    for i in range(scans.shape[0]):
        total += pace.free_run(scans[i], angles, 4.0, curvatures[i % curvatures.shape[0]], room)
    return total


@jit
def points_seen(poses, scans, angles, points, cells):
    count = 0
    for i in range(scans.shape[0]):
        count = sightings.see(points, cells, count, Pose(poses[i, 0], poses[i, 1], poses[i, 2]),
                              Reading(scans[i], angles, 4.0, 1.0, 0.3))
    return count


def timed(part, arguments, repeats: int, steps: int) -> float:
    """Median µs per step of ``part(*arguments())`` over ``repeats`` runs, after a warm one, each on
    fresh arguments (empty memories and maps)."""
    part(*arguments())
    spent = []
    for _ in range(repeats):
        given = arguments()
        began = time.perf_counter()
        part(*given)
        spent.append(time.perf_counter() - began)
    return round(1e6 * statistics.median(spent) / steps, 2)


def main(argv=None) -> None:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", type=int, default=4000, help="steps recorded and replayed")
    parser.add_argument("--repeats", type=int, default=3, help="timed runs of each part (the median)")
    parser.add_argument("--json", action="store_true", help="print only one JSON object")
    args = parser.parse_args(argv)
    poses, scans, angles = recorded(args.steps)
    inner = make_controller("fuzzy-5b-gap")
    inner.compiled(1, angles)
    params = inner.params
    layer = make_controller("fuzzy-5b").params  # the pace's room and the car route's arcs, as fuzzy-5b has them
    curvatures = guidance.search_settings(layer, 0).curvatures
    room = layer[layers.PARAM.radius] + layer[layers.PARAM.pace_room]
    parts = {
        "hit memory": (hit_memory, lambda: (poses, scans, angles, params,
                                            np.zeros((MEMORY_STEPS, angles.size + 1, 3)))),
        "gap finding": (gap_finding, lambda: (scans, angles, params)),
        "blocked directions": (blocked, lambda: (scans, angles, params)),
        "sector readings": (sectors, lambda: (scans, angles, params)),
        "pace": (free_runs, lambda: (scans, angles, curvatures, room)),
        "points seen": (points_seen, lambda: (poses, scans, angles, np.zeros((scans.size + 1, 2)),
                                              np.zeros(1 << int(np.ceil(np.log2(2 * scans.size + 2)))))),
    }
    report = {"benchmark": "navigator_parts", "steps": args.steps,
              "hits_per_scan": round(float(np.mean(scans < 4.0 - 1e-9)) * angles.size, 1),
              "us_per_step": {name: timed(part, arguments, args.repeats, args.steps)
                              for name, (part, arguments) in parts.items()}}
    if not args.json:
        for name, us in report["us_per_step"].items():
            print(f"  {name:20s} {us:8.2f} µs a step")
    print(json.dumps(report))


if __name__ == "__main__":
    main()
