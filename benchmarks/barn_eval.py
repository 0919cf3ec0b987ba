"""BARN worlds (Perille, Truong, Xiao & Stone, *Benchmarking metric ground navigation*, SSRR 2020;
the ICRA BARN Challenge) run with a navigator: success / collisions / timeouts, median time of the
successes and the challenge's score, for a range of worlds at a scale.

A minimal local conversion (the project's importer, ``fuzzynav import barn``, does the same for
``fuzzynav bench``): every post of ``world_N.world`` becomes a circle; the challenge's ``run.py``
starts the robot at (−2.25, 3) heading +y, the goal 10 m ahead, success within 1 m with no
collision, 100 s limit; score = success × t_opt / clip(t, 2 t_opt, 8 t_opt), t_opt the length
of ``path_N.npy``'s grid path (plus start and goal) at 2 m/s. The post field (x ∈ [−4.5, 0],
y ∈ [0, 9.6]) with 1 m of free space around it is moved to the origin, and everything is
multiplied by ``--scale`` (positions, radii, tolerance, optimal path; the time limit is kept).

Usage (the BARN folder holds ``world_N.world`` and ``path_N.npy``, e.g. a copy of
``jackal_helper/worlds/BARN`` of Daffan/the-barn-challenge with ``path_files/`` flattened)::

    python benchmarks/barn_eval.py --barn DIR --worlds 0-149 --scale 1.0 --controller fuzzy-5b-gap \
        [--sensors thesis|beam|lidar] [--out result.json]
"""

from __future__ import annotations

import argparse
import json
import statistics
import time
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import numpy as np

START = (-2.25, 3.0, 1.57)
GOAL = (-2.25, 13.0)
TOLERANCE, TIME_LIMIT, SPACING = 1.0, 100.0, 0.15
X0, Y0, MARGIN = -4.5, 0.0, 1.0


def posts(world_file: Path) -> list[tuple[float, float, float]]:
    """(x, y, r) of every top-level cylinder model of a BARN world (the ground plane skipped)."""
    world = ElementTree.parse(world_file).getroot().find("world")
    out = []
    for model in world.findall("model"):
        cylinder = model.find(".//collision/geometry/cylinder")
        if cylinder is not None:
            x, y = (float(v) for v in model.find("pose").text.split()[:2])
            out.append((x, y, float(cylinder.find("radius").text)))
    return out


def optimal_length(path_file: Path) -> float:
    """run.py's optimal path: grid cells (r, c) → (0.15 r − 4.575, 0.15 c + 5.075), start and goal added."""
    cells = np.load(path_file, allow_pickle=False)
    points = np.column_stack([cells[:, 0] * SPACING - SPACING / 2 - 30 * SPACING, cells[:, 1] * SPACING + SPACING / 2 + 5.0])
    points = np.vstack([START[:2], points, GOAL])
    return float(np.hypot(*np.diff(points, axis=0).T).sum())


def scenario(world_file: Path, scale: float):
    """The fuzzynav scenario of a BARN world at ``scale``."""
    from fuzzynav.world.scenario import scenario_from_dict

    x0, y0 = X0 - MARGIN, Y0 - MARGIN
    move = lambda x, y: [scale * (x - x0), scale * (y - y0)]  # noqa: E731
    top = GOAL[1] + TOLERANCE + MARGIN
    return scenario_from_dict({
        "name": world_file.stem, "world": {"width": scale * (MARGIN - x0), "height": scale * (top - y0)},
        "robot": dict(zip("xy", move(*START[:2])), theta=START[2]),
        "goal": dict(zip("xy", move(*GOAL)), tolerance=scale * TOLERANCE),
        "obstacles": [{"circle": {"center": move(x, y), "radius": scale * r}} for x, y, r in posts(world_file)],
        "max_time": TIME_LIMIT}, source=str(world_file))


def run_world(barn: Path, index: int, scale: float, controller: str, sensors: str | None) -> dict:
    """One run: outcome, time (s) and BARN score of world ``index``."""
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.robot.sensors import named_ring
    from fuzzynav.sim.simulator import BatchSimulator

    sim = BatchSimulator(scenario(barn / f"world_{index}.world", scale), make_controller(controller),
                         sensors=None if sensors is None else named_ring(sensors), seed=0, record=False).run()
    outcome, seconds = sim.outcomes()[0], float(sim.steps[0]) * sim.params.dt
    t_opt = scale * optimal_length(barn / f"path_{index}.npy") / 2.0
    score = t_opt / min(max(seconds, 2 * t_opt), 8 * t_opt) if outcome == "reached" else 0.0
    return {"world": index, "outcome": outcome, "time": round(seconds, 2), "score": round(score, 4)}


def summary(rows: list[dict]) -> dict:
    """Rates (%), median time of the successes and the mean BARN score of ``rows``."""
    n = len(rows)
    rate = lambda what: round(100.0 * sum(r["outcome"] == what for r in rows) / n, 1)  # noqa: E731
    times = [r["time"] for r in rows if r["outcome"] == "reached"]
    return {"n": n, "success": rate("reached"), "collision": rate("collision"), "timeout": rate("timeout"),
            "median_time": round(statistics.median(times), 2) if times else None,
            "score": round(sum(r["score"] for r in rows) / n, 4)}


def world_range(text: str) -> list[int]:
    first, _, last = text.partition("-")
    return list(range(int(first), int(last or first) + 1))


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--barn", type=Path, required=True, help="folder of world_N.world and path_N.npy")
    parser.add_argument("--worlds", default="0-149", help="range of world indices, e.g. 150-299")
    parser.add_argument("--scale", type=float, default=1.0)
    parser.add_argument("--controller", default="fuzzy-5b")
    parser.add_argument("--sensors", default=None, help="sensor ring by name (default: the controller's)")
    parser.add_argument("--out", type=Path, help="write the rows and the summary as JSON here")
    args = parser.parse_args(argv)
    started = time.perf_counter()
    rows = [run_world(args.barn, i, args.scale, args.controller, args.sensors) for i in world_range(args.worlds)]
    result = {"controller": args.controller, "sensors": args.sensors, "scale": args.scale, "worlds": args.worlds,
              "summary": summary(rows), "seconds": round(time.perf_counter() - started, 1), "runs": rows}
    print(json.dumps({k: v for k, v in result.items() if k != "runs"}))
    if args.out:
        args.out.write_text(json.dumps(result, indent=1))


if __name__ == "__main__":
    main()
