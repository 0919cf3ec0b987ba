"""``fuzzynav scenarios`` — list the built-in scenarios (name and description).

Any listed name can be given to ``fuzzynav run`` instead of a file; ``--show NAME`` prints the
scenario's YAML, a starting point for writing one's own.
"""

from __future__ import annotations

import difflib

from fuzzynav.cli import arguments
from fuzzynav.errors import InputError
from fuzzynav.world.scenario import BUILTIN_DIR, list_scenarios


def register(subparsers) -> None:
    parser = arguments.command(subparsers, "scenarios", run,
                               help="list the built-in scenarios",
                               description="List the built-in scenarios, which `fuzzynav run NAME` runs by name.")
    parser.add_argument("--show", metavar="NAME", help="print the YAML of one built-in scenario")


def run(args) -> int:
    listing = list_scenarios()
    if args.show:
        if args.show not in listing:
            close = difflib.get_close_matches(args.show, list(listing), n=3)
            hint = f" (did you mean {', '.join(close)}?)" if close else ""
            raise InputError(f"no built-in scenario {args.show!r}{hint}", field="--show")
        print((BUILTIN_DIR / f"{args.show}.yaml").read_text(), end="")
        return 0
    width = max((len(name) for name in listing), default=0)
    for name, description in listing.items():
        print(f"{name:{width}s}  {description}")
    return 0
