"""``fuzzynav tune CONTROLLER:ROLE --worlds SUITE [--what mf|rules|both] [--method ga|pso|aco|de|cmaes|nsga2]
[--objectives success,time,clearance] [--budget EVALS] [--seed S] [--out tuned.yaml] [--resume] [--curve PNG]
[--workers N]``
(:mod:`fuzzynav.tune`).

Optimise a role's membership breakpoints and/or rule conclusions on training worlds (every
candidate of a generation on every world in compiled calls spread over the cores), then test it on
held-out worlds.

Both the start and the result are tested on the held-out worlds; the tuned system is written as
``.yaml``, ``.json``, ``.fll`` or ``.fis``, which ``run``, ``bench``, ``evaluate`` and ``reproduce``
take as ``--fis ROLE=FILE``. Every option is checked before any simulation.
"""

from __future__ import annotations

import json
import sys
from dataclasses import replace
from functools import partial
from pathlib import Path

from fuzzynav import progress, threads, validation
from fuzzynav.cli import arguments, help_line
from fuzzynav.errors import InputError

EXAMPLES = """
fuzzynav tune fuzzy-2b:oab --method ga --budget 3000 --worlds mixed:40 --seed 0 --out oab.yaml --curve oab.png
fuzzynav evaluate --controller fuzzy-2b --fis oab=oab.yaml --worlds mixed --n 100 --seed 1000"""


def register(subparsers) -> None:
    parser = arguments.command(subparsers, "tune", run,
                               help=help_line("tune"),
                               description=__doc__.split("\n\n")[1], example=EXAMPLES,
                               when_stopped="the same command with --resume goes on from the last generation saved")
    parser.add_argument("target", metavar="CONTROLLER:ROLE",
                        help="e.g. fuzzy-2b:oab, fuzzy-2b:gsb, goal-seeking:gsb, wall-follow:wall, fuzzy-5b:gsb")
    parser.add_argument("--worlds", required=True, metavar="SUITE",
                        help="training worlds: folder of scenario files or FAMILY[:COUNT[:SEED]] (as bench reads them)")
    parser.add_argument("--holdout", metavar="SUITE",
                        help="held-out worlds (default for a family: the same family and count, world seed + 1000)")
    parser.add_argument("--validation", default="auto", metavar="SUITE",
                        help="worlds the result is chosen on: the start or one of the 3 best candidates, whichever "
                             "does best there (default for a family: the same family and count, world seed + 500; "
                             "'none' for none); their episodes count in --budget")
    parser.add_argument("--what", default="both", help="mf (breakpoints), rules (conclusions) or both (default)")
    parser.add_argument("--method", default="ga", help="ga (default), pso, de, cmaes, nsga2 or aco (--what rules)")
    parser.add_argument("--objectives", metavar="A,B", help="nsga2's objectives among success, time, clearance")
    parser.add_argument("--budget", type=arguments.whole, default=3000, metavar="EVALS",
                        help="simulated episodes (one candidate on one training world each; default 3000)")
    parser.add_argument("--population", type=arguments.whole, default=10, metavar="N",
                        help="candidates per generation (ants per iteration; default 10)")
    parser.add_argument("--seed", type=arguments.seed, default=0, help="random seed (default 0)")
    parser.add_argument("--out", metavar="FILE", help="tuned system to write: .yaml, .json, .fll or .fis")
    parser.add_argument("--resume", action="store_true", help="continue from the checkpoint beside --out")
    parser.add_argument("--curve", metavar="PNG", type=arguments.figure_path,
                        help="write the learning curve (best training cost against episodes)")
    parser.add_argument("--workers", type=arguments.count(validation.MAX_WORKERS), default=None, metavar="N",
                        help=f"threads simulating the episodes, 1 to {validation.MAX_WORKERS} (default: the cores this "
                             "process may use); the result does not depend on it")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.add_argument("--json", action="store_true", help="print the results as one JSON object")


def run(args) -> int:
    from fuzzynav.tune.checkpoint import path_for
    from fuzzynav.tune.session import TuneRequest, check, tune

    objectives = tuple(name.strip() for name in args.objectives.split(",")) if args.objectives else ()
    if args.out:  # (its folder must exist, as before) checked before the first generation is simulated
        arguments.check_writable(args.out, "--out", create=False)
    if args.curve:
        arguments.check_writable(args.curve, "--curve")
    request = TuneRequest(target=args.target, worlds=args.worlds, what=args.what, method=args.method,
                          budget=args.budget, seed=args.seed, population=args.population, objectives=objectives,
                          holdout=args.holdout, validation=args.validation, out=args.out, resume=args.resume, curve=args.curve,
                          progress=not (args.quiet or args.json))
    check(request)
    checkpoint = path_for(request)
    if checkpoint is not None and checkpoint.is_dir():  # found now, not when the first generation is saved
        raise InputError("is a directory where tune keeps its checkpoint", source=str(checkpoint), field="--out")
    notes = []  # said when the search starts (every check passed), not after it
    if request.resume and checkpoint is not None and not checkpoint.is_file():
        notes.append(f"--resume: no checkpoint at {checkpoint}: tuning from the start")
    if request.out is None:
        notes.append("no --out: the tuned system will be reported, not written (and no checkpoint kept)")
    if notes:
        request = replace(request, on_start=partial(print, "\n".join(notes), file=sys.stderr))
    with threads.using(args.workers), progress.quiet(not request.progress):
        result = tune(request)
    written = _write(request, result)
    if args.json:
        shown = {key: value for key, value in result.items() if key != "system"}
        if "front" in shown:
            shown["front"] = [{k: v for k, v in member.items() if k not in ("genes", "system")}
                              for member in shown["front"]]
        print(json.dumps({**shown, "files": written}))
        return 0
    print(f"{request.target} by {request.method} ({request.what}): {result['evaluations']} evaluations, "
          f"{result['episodes']} episodes, {result['evaluations_per_s']:.1f} evaluations/s "
          f"({result['episodes_per_s']:.0f} episodes/s)")
    for part in ("training", "holdout"):
        if part in result["start"]:
            print(f"  {part:8s} start: {_line(result['start'][part])}")
            print(f"  {part:8s} tuned: {_line(result['tuned'][part])}")
    if "validation" in result:
        chosen = result["validation"]
        print(f"  validation ({chosen['worlds']}) start: {_line(chosen['start'])}")
        for k, numbers in enumerate(chosen["candidates"], 1):
            print(f"  validation candidate {k}: {_line(numbers)}")
        print(f"  kept the {chosen['kept']}" + (": no candidate beat it on the validation worlds"
                                                if chosen["kept"] == "start" else ""))
    for path in written:
        print(f"  wrote {path}")
    return 0


def _worlds(n: int) -> str:
    return f"{n} world{'s' * (n != 1)}"


def _line(numbers: dict) -> str:
    if "off_band_m" in numbers:  # wall following
        return (f"lasted {100 * numbers['success_rate']:5.1f} % (at >= P/2: {100 * numbers['followed_rate']:5.1f} %), "
                f"collisions {numbers['collisions']}, closer than d_m "
                f"{100 * numbers['too_close_share']:4.1f} % of steps, outside [d_m, d_s] {numbers['off_band_m']:.2f} m, "
                f"speed {numbers['mean_speed_mps']:.2f} m/s over {_worlds(numbers['worlds'])}")
    time = numbers["mean_time_s"]
    return (f"success {100 * numbers['success_rate']:5.1f} %, collisions {numbers['collisions']}, "
            f"timeouts {100 * numbers['timeout_rate']:4.1f} %, mean time {'n/a' if time is None else f'{time:.2f} s'}"
            f" over {_worlds(numbers['worlds'])}")


def _write(request, result) -> list[str]:
    """Write the tuned system (and the Pareto front's members beside it), and the curve."""
    from fuzzynav.fuzzy.io import save

    written = []
    if request.out:
        save(result["system"], request.out)
        written.append(request.out)
        out = Path(request.out)
        for k, member in enumerate(result.get("front", [])):
            path = out.with_name(f"{out.stem}.front{k}{out.suffix}")
            save(member["system"], path)
            member["file"] = str(path)
            written.append(str(path))
    if request.curve:
        from fuzzynav.tune.curve import plot_curve

        plot_curve(result["curve"], request.curve, title=f"{request.target}, {request.method}",
                   start=result["start"]["training"]["cost"])
        written.append(request.curve)
    return written
