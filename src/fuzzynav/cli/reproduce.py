"""``fuzzynav reproduce ID|all --out DIR [--quick]`` — reproduce the thesis' figures and tables."""

from __future__ import annotations

import json
import time
from pathlib import Path

from fuzzynav.atomic import write_text_atomic
from fuzzynav.cli import arguments
from fuzzynav.experiments import registry


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "reproduce",
        help="reproduce a figure or table of the thesis",
        description="Reproduce thesis figures/tables; writes PNG figures and <ID>.json numbers.",
    )
    parser.add_argument("ids", nargs="*", metavar="ID", help="experiment ids, or 'all'")
    parser.add_argument("--list", action="store_true", help="list the experiment ids")
    parser.add_argument("--out", type=Path, default=Path("fuzzynav-out/reproduce"), help="output folder")
    parser.add_argument("--quick", action="store_true", help="short runs (smoke test), not the thesis' setting")
    parser.add_argument("--seed", type=arguments.seed, default=0, help="random seed (default 0)")
    parser.set_defaults(func=run)


def run(args) -> int:
    if args.list or not args.ids:
        for key, text in registry.available().items():
            print(f"{key:24s} {text}")
        return 0
    ids = list(registry.available()) if args.ids == ["all"] else args.ids
    functions = [(key, registry.experiment(key)) for key in ids]  # validate every id first
    args.out.mkdir(parents=True, exist_ok=True)
    for key, function in functions:
        start = time.perf_counter()
        numbers = function(args.out, quick=args.quick, seed=args.seed)
        write_text_atomic(args.out / f"{key}.json", json.dumps(numbers, indent=2, default=float))
        print(f"{key}: done in {time.perf_counter() - start:.1f} s -> {args.out}", flush=True)
    return 0
