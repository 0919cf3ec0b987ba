"""``fuzzynav evaluate --controller NAME | --model FILE --worlds circles|mixed [--n 100] [--seed 0] [--sensors RING] [--workers N] [--json]``.

Runs a built-in controller or a trained model file (``fuzzynav train``) over N seeded, solvable
generated worlds (:mod:`fuzzynav.world.generate`) and reports the success, collision and timeout
rates, the mean time and the mean path length of the successful episodes
(:func:`fuzzynav.bench.evaluate.evaluate`). ``--json`` prints exactly one JSON object
(with the per-world outcomes); otherwise a short table, with ``--progress`` one line per world on
stderr. A progress bar shows on a terminal (not with ``--quiet`` or ``--json``).
The worlds are shared among ``--workers`` processes (default: one per core); every episode is
seeded alone, so the numbers do not depend on it. ``--save-failures DIR`` writes every world not reached as ``DIR/<world>.yaml`` with the plot of its
episode, ``DIR/<world>.png``: ``fuzzynav run DIR/<world>.yaml --controller NAME`` reruns it.
"""

from __future__ import annotations

import json
import sys

from fuzzynav import progress as progress_bars, threads, validation
from fuzzynav.catalog.controllers import CONTROLLERS, check_task
from fuzzynav.catalog.roles import make_with_systems, replaced_files, systems_from_options
from fuzzynav.cli import arguments, help_line
from fuzzynav.cli.run import DEFAULT_CONTROLLER, PLANT_HELP, WORLDS_SENSORS_HELP
from fuzzynav.errors import InputError
from fuzzynav.world.generate import KINDS, check_family


def register(subparsers) -> None:
    parser = arguments.command(subparsers, "evaluate", run,
                               help=help_line("evaluate"),
                               description="Success / collision / timeout rates, mean time and path length of a "
                                           "controller over N seeded random worlds (solvable by construction).",
                               example="""
fuzzynav evaluate --worlds mixed --n 20                 # the default navigator, fuzzy-5b
fuzzynav evaluate --controller fuzzy-5b-thesis --worlds mixed --n 100 --save-failures failed/
fuzzynav evaluate --model fql-avoid.json --worlds circles --json""")
    source = parser.add_mutually_exclusive_group()
    source.add_argument("--controller", metavar="NAME",
                        help=f"built-in controller of goal tasks (default {DEFAULT_CONTROLLER}; "
                             f"{', '.join(sorted(n for n, spec in CONTROLLERS.items() if 'goal' in spec.tasks))})")
    source.add_argument("--model", metavar="FILE", type=arguments.file_name,
                        help="trained model file (JSON or NPZ, `fuzzynav train`)")
    parser.add_argument("--worlds", required=True, metavar="FAMILY", help=f"world family: {' | '.join(KINDS)}")
    parser.add_argument("--fis", action="append", metavar="ROLE=FILE",
                        help="replace the controller's fuzzy system for ROLE (any .yaml/.json/.fll/.fis; repeat)")
    parser.add_argument("--n", type=arguments.count(validation.MAX_WORLDS), default=100,
                        help=f"number of worlds, 1 to {validation.MAX_WORLDS:,} (default 100)")
    parser.add_argument("--seed", type=arguments.seed, default=0, help="world and episode seed (default 0)")
    parser.add_argument("--sensors", metavar="RING", default=None, help=WORLDS_SENSORS_HELP)
    parser.add_argument("--plant", metavar="PLANT", default="kinematic", help=PLANT_HELP)
    parser.add_argument("--workers", type=arguments.count(validation.MAX_WORKERS), default=None, metavar="N",
                        help=f"parallel processes, 1 to {validation.MAX_WORKERS} (default: the cores this process may use); "
                             "the result does not depend on it")
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--progress", action="store_true", help="one line per world on stderr")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.add_argument("--save-failures", type=arguments.path, metavar="DIR",
                        help="write each world not reached as DIR/<world>.yaml with its plot DIR/<world>.png")


def run(args) -> int:
    from fuzzynav.bench.evaluate import evaluate
    from fuzzynav.sim.plants import check_plant

    check_family(args.worlds, args.n, args.seed)
    check_plant(args.plant)
    if args.model is None and args.controller is None:
        args.controller = DEFAULT_CONTROLLER
    if args.fis and args.model:
        raise InputError("--fis replaces a built-in controller's rule base, not a model file's", field="--fis")
    systems = systems_from_options(args.controller, args.fis) if args.fis else None
    if args.controller is not None:
        check_task(args.controller, "goal")  # every generated world is a goal task
        make_with_systems(args.controller, systems)  # unknown names fail before any world is drawn

    if args.save_failures is not None:
        if args.save_failures.exists() and not args.save_failures.is_dir():
            raise InputError(f"{args.save_failures} is a file; give a folder", field="--save-failures")
        # made now, so that an unwritable place fails before any run (and removed if nothing is saved)
        made = [folder for folder in (args.save_failures, *args.save_failures.parents) if not folder.exists()]
        args.save_failures.mkdir(parents=True, exist_ok=True)
        arguments.check_writable(args.save_failures / f"{args.worlds}-{args.seed}-000.yaml", "--save-failures")

    def progress(i, run):
        print(f"[{i + 1}/{args.n}] {run['scenario']}: {run['outcome']} in {run['time_s']:.1f} s", file=sys.stderr)

    with progress_bars.quiet(args.quiet or args.json or args.progress):
        try:
            result = evaluate(args.controller, args.worlds, args.n, args.seed, progress if args.progress else None,
                              model=args.model, systems=systems, save_failures=args.save_failures,
                              sensors=args.sensors, plant=args.plant, workers=args.workers or threads.cores())
        except InputError as error:  # the library's name of the option, as the command line spells it
            if error.field != "save_failures":
                raise
            raise InputError(error.problem, source=error.source, field="--save-failures") from None
    if args.fis:
        result["fis"] = replaced_files(args.fis)
    if args.json:
        print(json.dumps(result))
        return 0
    source = f" (model {result['model']})" if result["model"] else "".join(
        f" (--fis {role}={path})" for role, path in result.get("fis", {}).items())
    print(f"controller {result['controller']}{source} on {result['n']} {result['worlds']} world{'s' * (result['n'] != 1)} (seed {result['seed']}, "
          f"{result['plant']} plant)")
    for key in ("success_rate", "collision_rate", "timeout_rate"):
        print(f"  {key:20s} {100 * result[key]:6.1f} %")
    for key, unit in (("mean_time_s", "s"), ("mean_path_length_m", "m")):
        value = result[key]
        print(f"  {key:20s} {'n/a' if value is None else f'{value:6.2f} {unit}'}  (over the episodes that reached the goal)")
    saved = [run["saved"] for run in result["episodes"] if "saved" in run]
    if args.save_failures is not None and not saved:
        for folder in made:  # the folders made above, deepest first: no empty folder left behind
            folder.rmdir()
    if args.save_failures is not None:
        rerun = f"--model {args.model}" if args.model else f"--controller {args.controller}"
        print(f"saved {len(saved)} failed world{'s' * (len(saved) != 1)} (scenario + plot) to {args.save_failures}/; rerun one with: "
              f"fuzzynav run {saved[0]} {rerun} --seed {args.seed}" if saved else
              "no world failed: nothing saved")
    return 0
