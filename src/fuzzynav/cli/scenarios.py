"""``fuzzynav scenarios`` — list the built-in scenarios (name and description).

Any listed name can be given to ``fuzzynav run`` instead of a file; ``--show NAME`` prints the
scenario's YAML (or a generated world's, ``mixed-0-003``), a starting point for writing one's own: its ``name:`` line is left out (a
comment says so), so a copy saved as ``my-world.yaml`` is named ``my-world`` in every output.
"""

from __future__ import annotations

import difflib

from fuzzynav.cli import arguments, help_line
from fuzzynav.errors import InputError
from fuzzynav.world.scenario import BUILTIN_DIR, list_scenarios


def register(subparsers) -> None:
    parser = arguments.command(subparsers, "scenarios", run,
                               help=help_line("scenarios"),
                               description="List the built-in scenarios, which `fuzzynav run NAME` runs by name.",
                               example="""
fuzzynav scenarios
fuzzynav scenarios --show fig-IV-15a > my-world.yaml   # a copy named my-world, to edit""")
    parser.add_argument("--show", metavar="NAME", action="append",
                        help="print the YAML of one built-in scenario, or of a generated world (e.g. mixed-0-003)")


def copy_text(text: str, name: str, what: str = "the built-in") -> str:
    """The YAML of built-in scenario ``name`` (or of ``what``) without its ``name:`` line, so that a
    copy takes the name of its file (:func:`fuzzynav.world.scenario.load_scenario`)."""
    lines = [f"# name: the file's name when absent (this is a copy of {what} {name})"
             if line.startswith("name:") else line for line in text.splitlines(keepends=True)]
    return "".join(line if line.endswith("\n") else line + "\n" for line in lines)


def run(args) -> int:
    listing = list_scenarios()
    if args.show is not None:  # (given: an empty name is refused, not read as "list them all")
        if len(args.show) > 1:
            raise InputError(f"is given {len(args.show)} times: it prints the YAML of one scenario", field="--show")
        name = args.show[0]
        if name not in listing:
            from fuzzynav.world.generate import generated_world
            from fuzzynav.world.scenario_file import scenario_yaml

            world = generated_world(name)  # as `fuzzynav run mixed-0-003` runs one
            if world is not None:
                print(copy_text(scenario_yaml(world), name, "the generated world"), end="")
                return 0
            close = difflib.get_close_matches(name, list(listing), n=3)
            hint = f" (did you mean {', '.join(close)}?)" if close else ""
            raise InputError(f"no built-in scenario {name!r}{hint}", field="--show")
        print(copy_text((BUILTIN_DIR / f"{name}.yaml").read_text(), name), end="")
        return 0
    width = max((len(name) for name in listing), default=0)
    for name, description in listing.items():
        print(f"{name:{width}s}  {description}")
    return 0
