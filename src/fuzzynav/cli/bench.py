"""``fuzzynav bench SUITE… --controllers a,b,c [--seeds K] [--workers N] [--backend local|ray]
[--out DIR] [--resume]`` — a benchmark campaign (:mod:`fuzzynav.bench`).

SUITE is a folder of scenario files (e.g. written by ``fuzzynav import barn``) or a generated
family ``FAMILY[:COUNT[:SEED]]`` (circles, mixed, dense, utrap). Controllers are registered
names (``fuzzynav run --help`` lists them) or trained model files (``.json``/``.npz``, labelled by
their file name without the suffix). Writes runs.csv / runs.jsonl as runs finish, then
summary.md, summary.json, plots and index.html into --out.
"""

from __future__ import annotations

import os
import sys
from pathlib import Path

from fuzzynav.cli import arguments
from fuzzynav.errors import InputError


def _positive_int(text: str) -> int:
    value = arguments.seed(text)
    if value < 1:
        import argparse

        raise argparse.ArgumentTypeError(f"must be >= 1, got {value}")
    return value


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "bench",
        help="run navigators against each other on suites of worlds",
        description="Run every controller on every world of the suites (x seeds), write runs.csv as runs "
                    "finish, then rates with 95 %% Wilson intervals, medians, plots and index.html.",
    )
    parser.add_argument("suites", nargs="+", metavar="SUITE",
                        help="folder of scenario files, or FAMILY[:COUNT[:SEED]] with FAMILY circles|mixed|dense|utrap")
    parser.add_argument("--controllers", required=True, metavar="A,B,C",
                        help="comma-separated controller names or model files (.json/.npz)")
    parser.add_argument("--seeds", type=_positive_int, default=1, metavar="K",
                        help="seeds 0..K-1 (generated families: K world sets; default 1)")
    parser.add_argument("--workers", type=_positive_int, default=None, metavar="N",
                        help="parallel workers (default: the number of cores)")
    parser.add_argument("--backend", choices=("local", "ray"), default="local",
                        help="local process pool (default) or Ray tasks (pip install 'fuzzynav[cluster]')")
    parser.add_argument("--ray-address", metavar="ADDR", default=None,
                        help="Ray cluster to join (default: $RAY_ADDRESS, else a local instance)")
    parser.add_argument("--out", default="bench-out", metavar="DIR", help="output folder (default bench-out)")
    parser.add_argument("--resume", action="store_true", help="continue the campaign already in --out")
    parser.add_argument("--gallery", type=arguments.seed, default=6, metavar="N",
                        help="failed runs drawn per controller (default 6, 0: none)")
    parser.add_argument("--quiet", action="store_true", help="no progress bar")
    parser.set_defaults(func=run)


def _controllers(text: str) -> tuple[tuple[str, str], ...]:
    from fuzzynav.bench.cells import build_controller, is_model_file

    specs = [spec.strip() for spec in text.split(",") if spec.strip()]
    if not specs:
        raise InputError("no controller given", field="--controllers")
    pairs = []
    for spec in specs:
        if is_model_file(spec):
            if not Path(spec).is_file():
                raise InputError("no such model file", source=spec, field="--controllers")
            spec = str(Path(spec).resolve())
        try:  # unknown names and bad model files fail before any run
            build_controller(spec)
        except InputError as error:
            if is_model_file(spec):
                raise
            raise InputError(error.problem, field="--controllers") from None
        pairs.append((Path(spec).stem if is_model_file(spec) else spec, spec))
    labels = [label for label, _ in pairs]
    if len(set(labels)) != len(labels):
        raise InputError(f"controller labels repeat ({', '.join(labels)})", field="--controllers")
    return tuple(pairs)


def run(args) -> int:
    from fuzzynav.bench.campaign import Plan, run_campaign
    from fuzzynav.bench.report import write_reports
    from fuzzynav.bench.suites import parse_suite
    from fuzzynav.robot.tricycle import DEFAULT_PARAMS

    suites = tuple(parse_suite(spec) for spec in args.suites)
    names = [suite.name for suite in suites]
    if len(set(names)) != len(names):
        raise InputError(f"suites repeat ({', '.join(names)})", field="SUITE")
    plan = Plan(suites, _controllers(args.controllers), args.seeds, DEFAULT_PARAMS.radius)
    out = Path(args.out)
    workers = args.workers or os.cpu_count() or 1
    rows = run_campaign(plan, out, resume=args.resume, backend=args.backend, workers=workers,
                        address=args.ray_address, progress=not args.quiet)
    arguments_used = {"suites": names, "controllers": [label for label, _ in plan.controllers], "seeds": args.seeds}
    write_reports(plan, rows, out, gallery=args.gallery, arguments=arguments_used)
    print(f"{len(rows)} runs in {out}: summary.md, summary.json, index.html", file=sys.stderr)
    return 0
