"""``fuzzynav run SCENARIO --controller NAME | --model FILE`` — run one episode (issue 3).

SCENARIO is a scenario file or a built-in name (``fuzzynav scenarios``). Prints a one-line
summary, or with ``--json`` exactly one JSON object with the metrics of
:func:`fuzzynav.sim.metrics.metrics`. Exit status 0 whenever the episode ran (reached, collided
or timed out), 2 for bad input (message on stderr).
"""

from __future__ import annotations

import json
import math

from fuzzynav.cli import arguments
from fuzzynav.errors import InputError

SENSORS_HELP = ("range sensors: thesis (7 rays, 30° apart), beam (the 7 with a 30° sonar cone) or lidar (271 rays "
                "over 270°); default: the scenario's, else the controller's (lidar for fuzzy-2b / fuzzy-5b, "
                "thesis for the -thesis variants)")


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "run",
        help="run a controller on a scenario",
        description="Run one episode of a controller on a scenario file or built-in scenario.",
    )
    parser.add_argument("scenario", metavar="SCENARIO", help="scenario YAML file or built-in name")
    source = parser.add_mutually_exclusive_group(required=True)
    source.add_argument("--controller", metavar="NAME", help="built-in controller name")
    source.add_argument("--model", metavar="FILE", help="trained model file (JSON or NPZ)")
    parser.add_argument("--seed", type=arguments.seed, default=0, help="random seed (sensor noise, controllers; default 0)")
    parser.add_argument("--max-time", type=float, default=None, metavar="S", help="override the scenario's max_time")
    parser.add_argument("--sensors", metavar="RING", default=None, help=SENSORS_HELP)
    parser.add_argument("--json", action="store_true", help="print the metrics as one JSON object")
    parser.add_argument("--plot", metavar="PNG", type=arguments.figure_path, help="write the trajectory and command plots")
    parser.add_argument("--rays", action="store_true", help="draw sensor rays on the --plot")
    parser.add_argument("--animate", metavar="GIF", type=arguments.gif_path, help="write an animated GIF of the episode")
    parser.set_defaults(func=run)


def run(args) -> int:
    from fuzzynav.control.registry import make_controller
    from fuzzynav.robot.sensors import named_ring
    from fuzzynav.sim import metrics, run_episode
    from fuzzynav.world.scenario import load_scenario

    if args.max_time is not None and not (math.isfinite(args.max_time) and args.max_time > 0):
        raise InputError(f"must be a finite number > 0, got {args.max_time!r}", field="--max-time")
    scenario = load_scenario(args.scenario)
    if args.model:
        from fuzzynav.models import load_controller

        controller = load_controller(args.model)
    else:
        controller = make_controller(args.controller)
    trace = run_episode(scenario, controller, seed=args.seed, max_time=args.max_time,
                        sensors=None if args.sensors is None else named_ring(args.sensors))
    numbers = metrics(trace, scenario)
    if args.plot:
        from fuzzynav.viz.trajectories import plot_episode

        plot_episode(trace, scenario, args.plot, rays=args.rays)
    if args.animate:
        from fuzzynav.viz.animation import animate_episode

        animate_episode(trace, scenario, args.animate)
    if args.json:
        print(json.dumps(numbers))
    else:
        print(f"{numbers['scenario']} / {numbers['controller']}: {numbers['outcome']} after "
              f"{numbers['time_s']:.1f} s, path {numbers['path_length_m']:.2f} m, "
              f"min clearance {numbers['min_clearance_m']:.2f} m")
    return 0
