"""The MuJoCo plant against the kinematic model (docs/results/physics-plant.md).

``manoeuvres``: constant commands (α, V) held for 12.6 s in an open world on both plants (the
kinematic one integrating eq IV.1 exactly, the arc); for each, the distance driven, the radius
of the circle fitted to the last three quarters of the path (turns only) and the largest
distance between the two paths at equal times.

``compare --kinematic DIR… --mujoco DIR…``: ``fuzzynav bench`` folders of the same worlds and
controllers, one plant each (a plant's worlds may be split over several folders), paired run by
run (world, seed, controller): outcomes of each, the worlds whose outcome differs, and the median of the
per-world ratio of the times of the runs both reached.

``cost SCENARIO…``: wall time per control step of the default navigator on each plant (each
episode run twice, the second timed: compiled kernels and the MuJoCo model warm).

Usage::

    python benchmarks/physics_plant.py manoeuvres
    python benchmarks/physics_plant.py compare --kinematic DIR [DIR ...] --mujoco DIR [DIR ...]
    python benchmarks/physics_plant.py cost SCENARIO [SCENARIO ...]
"""

from __future__ import annotations

import csv
import math
import statistics
import time
from collections import Counter
from pathlib import Path

import numpy as np

from fuzzynav.cli import Parser

MANOEUVRES = ((0.0, 0.5), (0.0, 2.0), (0.2, 0.5), (0.2, 1.0), (0.2, 2.0), (math.pi / 4, 0.25), (math.pi / 4, 0.5),
              (math.pi / 4, 1.0), (math.pi / 4, 2.0))


def circle_radius(points: np.ndarray) -> float:
    """Radius of the least-squares circle through ``points`` (M, 2)."""
    a = np.column_stack([2 * points, np.ones(len(points))])
    cx, cy, c = np.linalg.lstsq(a, (points ** 2).sum(axis=1), rcond=None)[0]
    return math.sqrt(c + cx * cx + cy * cy)


def manoeuvres() -> None:
    from fuzzynav.control.batched import ConstantCommand
    from fuzzynav.robot.tricycle import TricycleParams
    from fuzzynav.sim.simulator import run_episode
    from fuzzynav.world.scenario import scenario_from_dict

    world = scenario_from_dict({"robot": {"x": 5, "y": 20, "theta": 0}, "goal": {"x": 39, "y": 39},
                                "world": {"width": 40, "height": 40}, "max_time": 12.6}, source="open")
    print("| α (rad) | V (m/s) | distance kinematic / MuJoCo (m) | radius kinematic / MuJoCo (m) | largest gap (m) |")
    print("|---|---|---|---|---|")
    for steering, speed in MANOEUVRES:
        paths = [run_episode(world, ConstantCommand(steering, speed), robot_params=TricycleParams(integrator="arc"),
                             plant=plant).pose for plant in ("kinematic", "mujoco")]
        driven = [float(np.hypot(*np.diff(p[:, :2], axis=0).T).sum()) for p in paths]
        radii = ([circle_radius(p[len(p) // 4:, :2]) for p in paths] if steering else None)
        n = min(len(p) for p in paths)  # a run that meets the world's edge stops early
        gap = float(np.hypot(*(paths[0][:n, :2] - paths[1][:n, :2]).T).max())
        radius = f"{radii[0]:.3f} / {radii[1]:.3f}" if radii else "–"
        print(f"| {steering:.3f} | {speed:.2f} | {driven[0]:.2f} / {driven[1]:.2f} | {radius} | {gap:.3f} |")


def read_runs(folders: list[Path]) -> dict[tuple, dict]:
    """The rows of the ``runs.csv`` of ``folders`` by (world, seed, controller)."""
    return {(r["world"], r["seed"], r["controller"]): r for folder in folders
            for r in csv.DictReader(open(folder / "runs.csv", encoding="utf-8"))}


def compare(kinematic: list[Path], mujoco: list[Path]) -> None:
    a, b = read_runs(kinematic), read_runs(mujoco)
    number = lambda k: int(k[0].rpartition("_")[2]) if k[0][-1].isdigit() else 0  # noqa: E731
    both = sorted(set(a) & set(b), key=lambda k: (number(k), k))
    for name, rows in (("kinematic", a), ("mujoco", b)):
        counts = Counter(rows[k]["outcome"] for k in both)
        print(f"{name}: {len(both)} paired runs, " + ", ".join(f"{o} {counts[o]} ({100 * counts[o] / len(both):.1f} %)"
                                                             for o in ("reached", "collision", "timeout")))
    for k in both:
        if a[k]["outcome"] != b[k]["outcome"]:
            print(f"  {k[0]}: kinematic {a[k]['outcome']} {a[k]['time_s']} s, mujoco {b[k]['outcome']} {b[k]['time_s']} s")
    reached = [k for k in both if a[k]["outcome"] == b[k]["outcome"] == "reached"]
    if reached:
        ratios = [float(b[k]["time_s"]) / float(a[k]["time_s"]) for k in reached]
        clear = [(float(a[k]["min_clearance_m"]), float(b[k]["min_clearance_m"])) for k in reached]
        print(f"both reached: {len(reached)}; time MuJoCo / kinematic: median {statistics.median(ratios):.3f}, "
              f"range {min(ratios):.2f}–{max(ratios):.2f}; median smallest clearance kinematic "
              f"{statistics.median(c[0] for c in clear):.3f} m, MuJoCo {statistics.median(c[1] for c in clear):.3f} m")


def cost(scenarios: list[str]) -> None:
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.sim.simulator import run_episode
    from fuzzynav.world.scenario_file import open_scenario

    for name in scenarios:
        scenario = open_scenario(name)
        for plant in ("kinematic", "mujoco"):
            for _ in range(2):
                start = time.perf_counter()
                trace = run_episode(scenario, make_controller("fuzzy-5b"), seed=0, plant=plant)
                seconds = time.perf_counter() - start
            steps = len(trace.t) - 1
            print(f"{scenario.name} {plant}: {trace.outcome} in {steps} steps, {1000 * seconds / steps:.2f} ms per step")


def main() -> None:
    parser = Parser(description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    commands.add_parser("manoeuvres", help="constant commands on both plants")
    pair = commands.add_parser("compare", help="two bench folders, paired run by run")
    pair.add_argument("--kinematic", type=Path, nargs="+", required=True)
    pair.add_argument("--mujoco", type=Path, nargs="+", required=True)
    timed = commands.add_parser("cost", help="wall time per step of fuzzy-5b on each plant")
    timed.add_argument("scenarios", nargs="+")
    args = parser.parse_args()
    if args.command == "manoeuvres":
        manoeuvres()
    elif args.command == "compare":
        compare(args.kinematic, args.mujoco)
    else:
        cost(args.scenarios)


if __name__ == "__main__":
    main()
