"""BARN worlds (Perille, Truong, Xiao & Stone, *Benchmarking metric ground navigation*, SSRR 2020;
the ICRA BARN Challenge) run with a navigator: success / collisions / timeouts, median time of the
successes and the challenge's score, for a range of worlds at a scale.

The worlds are read and converted, and the runs scored, as ``fuzzynav import barn`` and
``fuzzynav bench`` do (:mod:`fuzzynav.world.barn`: every post a circle, the challenge's start,
goal, 1 m tolerance and 100 s limit, the field moved to the origin and multiplied by ``--scale``;
:func:`fuzzynav.bench.measures.barn_score`: success × t_opt / clip(t, 2 t_opt, 8 t_opt), t_opt the
optimal path of ``path_N.npy`` at 2 m/s); this script runs a range of worlds in one process
without writing scenario files.

Usage (the BARN folder holds ``world_N.world`` and ``path_N.npy``, e.g. a copy of
``jackal_helper/worlds/BARN`` of Daffan/the-barn-challenge with ``path_files/`` flattened)::

    python benchmarks/barn_eval.py --barn DIR --worlds 0-149 --scale 1.0 --controller fuzzy-5b-gap \
        [--sensors thesis|beam|lidar] [--max-speed 2] [--out result.json]
"""

from __future__ import annotations

import json
import statistics
import time
from pathlib import Path

from fuzzynav.cli import Parser


def scenario(world_file: Path, scale: float, max_speed: float | None = None):
    """The fuzzynav scenario of a BARN world at ``scale`` (the robot's top speed ``max_speed`` m/s,
    if given: BARN's Jackal drives at most 2 m/s)."""
    from fuzzynav.world.barn import barn_scenario, read_posts
    from fuzzynav.world.scenario import scenario_from_dict

    document = barn_scenario(read_posts(world_file), world_file.stem, scale)
    if max_speed is not None:
        document["robot"]["max_speed"] = max_speed
    return scenario_from_dict(document, source=str(world_file))


def run_world(barn: Path, index: int, scale: float, controller: str, sensors: str | None,
              max_speed: float | None = None, options: dict | None = None) -> dict:
    """One run: outcome, time (s) and BARN score of world ``index``."""
    from fuzzynav.bench.measures import barn_score
    from fuzzynav.catalog.controllers import make_controller
    from fuzzynav.robot.sensors import named_ring
    from fuzzynav.sim.simulator import BatchSimulator
    from fuzzynav.world.barn import optimal_path_length

    sim = BatchSimulator(scenario(barn / f"world_{index}.world", scale, max_speed), make_controller(controller, **(options or {})),
                         sensors=None if sensors is None else named_ring(sensors), seed=0, record=False).run()
    outcome, seconds = sim.outcomes()[0], float(sim.steps[0]) * sim.params.dt
    score = barn_score(outcome == "reached", seconds, scale * optimal_path_length(barn / f"path_{index}.npy"))
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
    parser = Parser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--barn", type=Path, required=True, help="folder of world_N.world and path_N.npy")
    parser.add_argument("--worlds", default="0-149", help="range of world indices, e.g. 150-299")
    parser.add_argument("--scale", type=float, default=1.0)
    parser.add_argument("--controller", default="fuzzy-5b")
    parser.add_argument("--sensors", default=None, help="sensor ring by name (default: the controller's)")
    parser.add_argument("--max-speed", type=float, default=None,
                        help="the robot's top speed in m/s (default: the scenario's 4; BARN's Jackal: 2)")
    parser.add_argument("--out", type=Path, help="write the rows and the summary as JSON here")
    parser.add_argument("--options", type=json.loads, default=None, metavar="JSON",
                        help="the controller's options, e.g. '{\"guidance\": {\"guide_car_reuse\": 0}}'")
    args = parser.parse_args(argv)
    started = time.perf_counter()
    rows = [run_world(args.barn, i, args.scale, args.controller, args.sensors, args.max_speed, args.options)
            for i in world_range(args.worlds)]
    result = {"controller": args.controller, "sensors": args.sensors, "scale": args.scale, "worlds": args.worlds,
              "max_speed": args.max_speed, "options": args.options,
              "summary": summary(rows), "seconds": round(time.perf_counter() - started, 1), "runs": rows}
    print(json.dumps({k: v for k, v in result.items() if k != "runs"}))
    if args.out:
        args.out.write_text(json.dumps(result, indent=1))


if __name__ == "__main__":
    main()
