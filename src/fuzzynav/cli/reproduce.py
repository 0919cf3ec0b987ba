"""``fuzzynav reproduce ID…|all --out DIR [--quick] [--fis ROLE=FILE]`` — reproduce the thesis'
figures and tables, optionally with a rule base replaced (:mod:`fuzzynav.experiments.rule_bases`).

Reproduce thesis figures/tables: DIR/<ID>/ holds the PNG figures and <ID>.json numbers,
DIR/index.html the thesis' claim beside our figure for each.

Each experiment writes into ``DIR/<id>/`` (PNG figures and ``<id>.json``, the numbers it
measured, and ``claim.json``, the claim's checks and verdict); ``DIR/index.html`` puts the thesis'
claim beside our figure and numbers for every experiment in DIR, with its checks, its verdict
(reproduced, partly, not reproduced) and the run time
(:mod:`fuzzynav.experiments.report`).
"""

from __future__ import annotations

import time
from pathlib import Path

from fuzzynav import progress
from fuzzynav.catalog import experiments as registry
from fuzzynav.catalog.roles import parse_option
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
    parser.add_argument("--out", type=Path, default=Path("fuzzynav-out/reproduce"), help="output folder")
    parser.add_argument("--quick", action="store_true", help="short runs (smoke test), not the thesis' setting")
    parser.add_argument("--seed", type=arguments.seed, default=0, help="random seed (default 0)")
    parser.add_argument("--quiet", action="store_true", help="no progress bars")
    parser.add_argument("--fis", action="append", metavar="ROLE=FILE",
                        help="run with the rule base of ROLE replaced (gsb, oab, foa, roa, loa, vrb, wall, tracker; "
                             "any .yaml/.json/.fll/.fis file; repeat per role; `fuzzynav fis convert CONTROLLER:ROLE` "
                             "writes a start) — to check that a claim depends on its table")


def run(args) -> int:
    from fuzzynav.experiments import report, rule_bases

    if args.list or not args.ids:
        listing = registry.available()
        for key, text in listing.items():
            print(f"{key:24s} {text}")
        print(f"{len(listing)} figures and tables")
        if not args.list:
            print("nothing run: name the ids to reproduce, or all (e.g. fuzzynav reproduce fig-IV-23 --out figures/)")
        return 0
    ids = list(registry.available()) if args.ids == ["all"] else args.ids
    functions = [(key, registry.experiment(key)) for key in ids]  # validate every id first
    systems = rule_bases.from_options(args.fis)
    replaced = {role: path for role, path in map(parse_option, args.fis or [])}
    args.out.mkdir(parents=True, exist_ok=True)
    with progress.quiet(args.quiet), rule_bases.replaced(systems):
        bar = progress.bar(total=len(functions), desc="reproduce", unit="figure")
        for key, function in functions:
            bar.set_postfix_str(key)
            start = time.perf_counter()
            numbers = function(report.experiment_dir(args.out, key), quick=args.quick, seed=args.seed)
            if replaced:
                numbers = {**numbers, "replaced_rule_bases": replaced}
            record = report.record_run(args.out, key, numbers, time.perf_counter() - start, quick=args.quick,
                                       seed=args.seed)
            report.write_index(args.out)
            verdict = record["verdict"] + (" (quick run)" if args.quick else "") + (
                f" with {', '.join(f'{role}={path}' for role, path in replaced.items())}" if replaced else "")
            progress.write(f"{key}: {verdict}, {record['seconds']:.1f} s -> {report.experiment_dir(args.out, key)}")
            bar.update()
        bar.close()
    print(f"report: {args.out / 'index.html'}")
    return 0
