"""``fuzzynav reproduce ID…|all --out OUT [--quick] [--fis ROLE=FILE]`` — reproduce the thesis'
figures and tables, optionally with a rule base replaced (:mod:`fuzzynav.experiments.rule_bases`).

Reproduce thesis figures/tables: OUT/<ID>/ holds the PNG figures and <ID>.json numbers,
OUT/index.html the thesis' claim beside our figure for each.

Each experiment writes into ``OUT/<id>/`` (PNG figures and ``<id>.json``, the numbers it
measured, and ``claim.json``, the claim's checks and verdict); ``OUT/index.html`` puts the thesis'
claim beside our figure and numbers for every experiment in OUT, with its checks, its verdict
(reproduced, partly, not reproduced) and the run time
(:mod:`fuzzynav.experiments.report`). The experiments are shared among ``--workers`` processes
(default: one per core; each experiment's numbers do not depend on it, its run time does).
"""

from __future__ import annotations

import contextlib
import sys
import time
from pathlib import Path

from fuzzynav import progress, threads, validation
from fuzzynav.catalog import experiments as registry
from fuzzynav.catalog.roles import replaced_files
from fuzzynav.cli import arguments, help_line

EXAMPLES = """
fuzzynav reproduce --list
fuzzynav reproduce fig-V-28 fig-IV-23 --out figures/
fuzzynav reproduce all --quick --out figures/"""


def register(subparsers) -> None:
    parser = arguments.command(subparsers, "reproduce", run, help=help_line("reproduce"),
                               description=__doc__.split("\n\n")[1], example=EXAMPLES)
    parser.add_argument("ids", nargs="*", metavar="ID", help="experiment ids, or 'all'")
    parser.add_argument("--list", action="store_true", help="list the experiment ids")
    parser.add_argument("--out", type=arguments.path, default=Path("fuzzynav-out/reproduce"),
                        help="output folder (default: fuzzynav-out/reproduce)")
    parser.add_argument("--quick", action="store_true", help="short runs (smoke test), not the thesis' setting")
    parser.add_argument("--seed", type=arguments.small_seed, default=0,
                        help="random seed, 0 to 2**32 - 1 (default 0)")
    parser.add_argument("--quiet", action="store_true", help="no progress bars")
    parser.add_argument("--fis", action="append", metavar="ROLE=FILE",
                        help="run with the rule base of ROLE replaced (gsb, oab, foa, roa, loa, vrb, wall, tracker; "
                             "any .yaml/.json/.fll/.fis file; repeat per role; `fuzzynav fis convert CONTROLLER:ROLE` "
                             "writes a start) — to check that a claim depends on its table")
    parser.add_argument("--workers", type=arguments.count(validation.MAX_WORKERS), default=None, metavar="N",
                        help=f"experiments run at once, 1 to {validation.MAX_WORKERS} (default: the number of "
                             "cores); their numbers do not depend on it, their run times do")


_WORKER = contextlib.ExitStack()  # a worker's settings, kept until it exits


def start_worker(systems: dict) -> None:
    """A worker process' setup: the replaced rule bases, and no progress bars (processes running
    side by side cannot share the terminal's lines; the command's own bar counts the experiments)."""
    from fuzzynav.experiments import rule_bases

    _WORKER.enter_context(progress.quiet())
    _WORKER.enter_context(rule_bases.replaced(systems))


def reproduce_one(item: tuple[str, Path, bool, int]) -> tuple[dict, float, list[str]]:
    """Run experiment ``(id, its folder, quick, seed)``; its numbers, the seconds it took and the
    roles whose rule base it looked up (:func:`fuzzynav.experiments.rule_bases.reading`)."""
    from fuzzynav.errors import InputError
    from fuzzynav.experiments import rule_bases

    key, folder, quick, seed = item
    try:
        function = registry.experiment(key)
    except InputError as error:  # the command knew it (it checks every id first): its caller registered it
        raise InputError(f"{error.problem}: it was registered in the calling process, which worker processes "
                         "started afresh (macOS, Windows) do not share; run it with --workers 1",
                         field="--workers") from None
    start = time.perf_counter()
    with rule_bases.reading() as read:
        numbers = function(folder, quick=quick, seed=seed)
    return numbers, time.perf_counter() - start, sorted(read)


def run(args) -> int:
    from fuzzynav.bench.backends import pool_map
    from fuzzynav.errors import InputError
    from fuzzynav.experiments import report, rule_bases

    if args.list and args.ids:
        raise InputError("lists the experiments and runs none: give the ids without --list to run them", field="--list")
    if args.list or not args.ids:
        listing = registry.available()
        for key, text in listing.items():
            print(f"{key:24s} {text}")
        print(f"{len(listing)} figures and tables")
        if not args.list:  # a usage error, after the list that helps to correct it
            print("nothing run: name the ids to reproduce, or all (e.g. fuzzynav reproduce fig-IV-23 --out figures/)",
                  file=sys.stderr)
            return 2
        return 0
    if "all" in args.ids and args.ids != ["all"]:
        raise InputError("'all' runs every experiment: give it alone, or the ids you want", field="ID")
    ids = list(registry.available()) if args.ids == ["all"] else list(dict.fromkeys(args.ids))  # each id once
    for key in ids:  # validate every id first
        registry.experiment(key)
    systems = rule_bases.from_options(args.fis)
    replaced = replaced_files(args.fis)  # absolute: the record stays true wherever it is read from
    report.not_anothers(args.out)
    args.out.mkdir(parents=True, exist_ok=True)
    arguments.check_writable(args.out / "index.html", "--out")  # before the first experiment, not after it
    workers = min(args.workers or threads.cores(), len(ids))
    if workers > 1:  # the longest first, by an earlier run's time in --out (unknown ones first of all)
        earlier = {key: report.recorded_seconds(args.out, key, quick=args.quick) for key in ids}
        ids = sorted(ids, key=lambda key: -(earlier[key] or float("inf")))
    items = [(key, report.experiment_dir(args.out, key), args.quick, args.seed) for key in ids]
    if not args.quiet:  # a line before the first result, which may take minutes (no bar when piped)
        print(f"reproducing {len(ids)} experiment{'s' * (len(ids) > 1)} into {args.out} ({workers} worker"
              f"{'s' * (workers > 1)}); a line as each one ends", file=sys.stderr)
    with progress.quiet(args.quiet), rule_bases.replaced(systems):
        bar = progress.bar(total=len(items), desc="reproduce", unit="figure")

        def finished(index: int, result: tuple[dict, float, list[str]]) -> None:
            key, folder = items[index][:2]
            numbers, seconds, read = result
            unused = sorted(set(replaced) - set(read))  # replaced, but never looked up: nothing changed
            if replaced:
                numbers = {**numbers, "replaced_rule_bases": replaced}
            if unused:
                numbers = {**numbers, "unused_rule_bases": unused}
            record = report.record_run(args.out, key, numbers, seconds, quick=args.quick, seed=args.seed)
            report.write_index(args.out)
            verdict = record["verdict"] + (" (quick run)" if args.quick else "") + (
                f" with {', '.join(f'{role}={path}' for role, path in replaced.items())}" if replaced else "") + (
                f" (this experiment does not use {', '.join(unused)}: its numbers are the published tables')"
                if unused else "")
            progress.write(f"{key}: {verdict}, {record['seconds']:.1f} s -> {folder}")
            bar.update()

        pool_map(reproduce_one, items, workers, finished, initializer=None if workers == 1 else start_worker,
                 initargs=(systems,))
        bar.close()
    print(f"report: {args.out / 'index.html'}")
    return 0
