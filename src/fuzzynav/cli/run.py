"""``fuzzynav run SCENARIO [--controller NAME [--fis ROLE=FILE] | --model FILE]`` — run one episode.

SCENARIO is a scenario file or a built-in name (``fuzzynav scenarios``). Without ``--controller``
or ``--model`` it runs :func:`default_controller`: the default navigator ``fuzzy-5b`` on a goal,
else the first controller the scenario lists in its ``controllers`` key, else the fuzzy tracker
``fuzzy-tracker`` (a goal scenario that lists its own gets a note naming them). Prints a one-line summary, or with ``--json`` exactly one
JSON object with the metrics of :func:`fuzzynav.sim.metrics.metrics` (and ``fis``: {role: file}
when ``--fis`` replaced a rule base). Exit status 0 whenever the episode ran (reached, collided
or timed out), 2 for bad input (message on stderr).
"""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

from fuzzynav import validation
from fuzzynav.catalog.controllers import briefs, check_task, scenario_controllers
from fuzzynav.cli import arguments, help_line
from fuzzynav.errors import InputError

_RINGS = ("range sensors: thesis (7 rays, 30° apart), beam (the 7 with a 30° sonar cone) or lidar (271 rays "
          "over 270°); default: {whose} (lidar for fuzzy-5b and its other name fuzzy-5b-gap-robust, fuzzy-5b-gap "
          "and fuzzy-2b-gap, thesis for the others)")
SENSORS_HELP = _RINGS.format(whose="the scenario's, else the controller's")
WORLDS_SENSORS_HELP = _RINGS.format(whose="the controller's")  # evaluate: generated worlds name no sensors


PLANT_HELP = ("what moves the robot and reads its sensors: kinematic (the thesis' model, default) or mujoco (a "
              "rigid-body tricycle in the MuJoCo physics engine; the optional extra 'physics'; docs/physics.md)")

DEFAULT_CONTROLLER = "fuzzy-5b"  # the default navigator (docs/guide/controllers.md)
DEFAULT_TRACKER = "fuzzy-tracker"  # the thesis' fuzzy tracker CF (Table V.1): paths and moving targets


def default_controller(scenario, source: str) -> str:
    """The controller run when none is named: :data:`DEFAULT_CONTROLLER` on a goal task, else the
    first of the scenario's own ``controllers`` (a tracker for a path, a pursuer for a target),
    else :data:`DEFAULT_TRACKER` (``source``: the scenario as the user named it, for an error)."""
    if scenario.task == "goal":
        return DEFAULT_CONTROLLER
    if scenario.controllers:
        return scenario_controllers(scenario, source)[0]
    return DEFAULT_TRACKER


def register(subparsers) -> None:
    width = max(map(len, briefs()))
    parser = arguments.command(subparsers, "run", run,
                               help=help_line("run"),
                               description="Run one episode of a controller on a scenario file or built-in scenario "
                                           "(`fuzzynav scenarios` lists the built-ins).",
                               epilog="controllers (--controller NAME; in full: docs/guide/controllers.md):\n"
                               + "\n".join(f"  {name:{width}s}  {text}" for name, text in briefs().items()),
                               example="""
fuzzynav run fig-IV-23                                # the default navigator, fuzzy-5b
fuzzynav run my-world.yaml --controller dwa --plot dwa.png --animate dwa.gif
fuzzynav run path-n --model anfis.json --json""")
    parser.add_argument("scenario", metavar="SCENARIO",
                        help="scenario YAML file, built-in name, or generated world (e.g. mixed-0-009)")
    source = parser.add_mutually_exclusive_group()
    source.add_argument("--controller", metavar="NAME",
                        help=f"built-in controller name (default: {DEFAULT_CONTROLLER} on a goal, else the first of the "
                             f"scenario's own 'controllers', else {DEFAULT_TRACKER})")
    source.add_argument("--model", metavar="FILE", type=arguments.file_name, help="trained model file (JSON or NPZ)")
    parser.add_argument("--fis", action="append", metavar="ROLE=FILE",
                        help="replace the controller's fuzzy system for ROLE (e.g. gsb=my-gsb.yaml; any .yaml/.json/"
                             ".fll/.fis file; repeat per role; `fuzzynav fis convert CONTROLLER:ROLE` writes a start)")
    parser.add_argument("--seed", type=arguments.seed, default=0, help="random seed (sensor noise, controllers; default 0)")
    parser.add_argument("--max-time", type=arguments.decimal, default=None, metavar="S", help="override the scenario's max_time")
    parser.add_argument("--sensors", metavar="RING", default=None, help=SENSORS_HELP)
    parser.add_argument("--plant", metavar="PLANT", default="kinematic", help=PLANT_HELP)
    parser.add_argument("--json", action="store_true", help="print the metrics as one JSON object")
    parser.add_argument("--plot", metavar="PNG", type=arguments.figure_path, help="write the trajectory and command plots")
    parser.add_argument("--rays", action="store_true", help="draw sensor rays on the --plot")
    parser.add_argument("--animate", metavar="GIF", type=arguments.gif_path, help="write an animated GIF of the episode")
    parser.add_argument("--size", type=arguments.whole, metavar="PX",
                        help="width and height of the --animate GIF in pixels (default 400)")
    parser.add_argument("--fps", type=arguments.decimal, help="frames per second of the --animate GIF (default 10); the GIF samples at most 100 "
                             "steps, so an episode longer than 100 / FPS seconds plays faster than real time")


def run(args) -> int:
    from fuzzynav.catalog.roles import make_with_systems, replaced_files, systems_from_options
    from fuzzynav.robot.sensors import named_ring
    from fuzzynav.sim import metrics, run_episode
    from fuzzynav.sim.plants import check_plant
    from fuzzynav.world.scenario_file import open_scenario, shadows_a_name

    if args.max_time is not None:
        from fuzzynav.world.limits import MAX_TIME

        validation.number(args.max_time, field="--max-time", lo=0.0, lo_open=True, hi=MAX_TIME)
    if args.fis and args.model:
        raise InputError("--fis replaces a built-in controller's rule base, not a model file's", field="--fis")
    if args.rays and not args.plot:
        raise InputError("draws the sensor rays on the --plot figure: give --plot FILE too", field="--rays")
    gif = {name: value for name, value in (("size", args.size), ("fps", args.fps)) if value is not None}
    if gif and not args.animate:
        raise InputError("sets the --animate GIF: give --animate FILE.gif too", field=f"--{next(iter(gif))}")
    if args.size is not None and not 64 <= args.size <= 4000:
        raise InputError(f"must be between 64 and 4000 pixels, got {args.size}", field="--size")
    if args.fps is not None and not (math.isfinite(args.fps) and 0.1 <= args.fps <= 100):
        raise InputError(f"must be between 0.1 and 100 frames per second, got {args.fps}", field="--fps")
    check_plant(args.plant)
    if args.plot and args.animate and Path(args.plot).resolve() == Path(args.animate).resolve():
        raise InputError(f"{args.animate} is the --plot file too: one would overwrite the other; give two names",
                         field="--animate")
    for flag, target in (("--plot", args.plot), ("--animate", args.animate)):  # before the episode, not after
        if target:
            arguments.check_writable(target, flag)
    scenario = open_scenario(args.scenario)
    if shadows_a_name(args.scenario):
        print(f"note: {args.scenario} is the file {Path(args.scenario).resolve()}, not the built-in scenario or "
              "generated world of that name (rename the file, or run from another folder, to run that one)",
              file=sys.stderr)
    if args.model is None and args.controller is None:
        args.controller = default_controller(scenario, args.scenario)
        if scenario.task == "goal" and scenario.controllers and args.controller not in scenario.controllers:
            print(f"note: {scenario.name} names its own controllers ({', '.join(scenario.controllers)}); this runs "
                  f"the default {args.controller}: --controller NAME runs one of them", file=sys.stderr)
    if args.model:
        from fuzzynav.catalog.tasks import load_controller

        controller = load_controller(args.model, scenario.task)
    else:
        check_task(args.controller, scenario.task)
        controller = make_with_systems(args.controller, systems_from_options(args.controller, args.fis))
    trace = run_episode(scenario, controller, seed=args.seed, max_time=args.max_time,
                        sensors=None if args.sensors is None else named_ring(args.sensors), plant=args.plant)
    numbers = metrics(trace, scenario) | ({"fis": replaced_files(args.fis)} if args.fis else {})
    if args.plot:
        from fuzzynav.viz.trajectories import plot_episode

        plot_episode(trace, scenario, args.plot, rays=args.rays)
        print(f"wrote {args.plot} (trajectory and commands)", file=sys.stderr)
    if args.animate:
        from fuzzynav.viz.animation import animate_episode

        frames = animate_episode(trace, scenario, args.animate, **gif)
        print(f"wrote {args.animate} ({frames} frames)", file=sys.stderr)
    if args.json:
        print(json.dumps(numbers))
    else:
        print(f"{numbers['scenario']} / {numbers['controller']}: {numbers['outcome']} after "
              f"{numbers['time_s']:.1f} s simulated, path {numbers['path_length_m']:.2f} m, "
              f"min clearance {numbers['min_clearance_m']:.2f} m"
              + "".join(f", --fis {role}={path}" for role, path in numbers.get("fis", {}).items()))
    return 0
