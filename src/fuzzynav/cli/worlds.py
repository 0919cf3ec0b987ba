"""``fuzzynav worlds generate FAMILY --n N --seed S --out DIR`` — generated worlds as scenario files.

Writes ``DIR/<family>-<seed>-<i>.yaml`` for the N seeded, solvable worlds of
:func:`fuzzynav.world.generate.generate_worlds` — the very worlds ``fuzzynav evaluate --worlds
FAMILY --n N --seed S`` runs — so each can be opened, edited and run with ``fuzzynav run FILE``.
A file of that name already there with other content (an edited world) is not overwritten: the
command is refused before writing any.
"""

from __future__ import annotations

from pathlib import Path

from fuzzynav import validation
from fuzzynav.cli import arguments, help_line


def register(subparsers) -> None:
    parser = subparsers.add_parser("worlds", help=help_line("worlds"),
                                   description="Generated worlds (the ones `fuzzynav evaluate` runs) as files.",
                                   **arguments.with_example("fuzzynav worlds generate mixed --n 3 --out worlds/"))
    actions = parser.add_subparsers(dest="action", metavar="ACTION", required=True)
    generate = arguments.command(actions, "generate", run,
                                 help="write N generated worlds of a family as scenario files",
                                 description=__doc__.split("\n\n")[1],
                                 example="""
fuzzynav worlds generate mixed --n 3 --out worlds/
fuzzynav run worlds/mixed-0-002.yaml""")
    generate.add_argument("family", metavar="FAMILY", help="world family, e.g. circles or mixed (an unknown name lists them all)")
    generate.add_argument("--n", type=arguments.count(validation.MAX_WORLDS), default=10,
                          help=f"number of worlds, 1 to {validation.MAX_WORLDS:,} (default 10)")
    generate.add_argument("--seed", type=arguments.seed, default=0, help="world seed (default 0)")
    generate.add_argument("--out", type=arguments.path, default=Path("worlds"), help="output folder (default worlds/)")


def run(args) -> int:
    from fuzzynav import progress
    from fuzzynav.storage import write_text_atomic
    from fuzzynav.world.generate import check_kind, generate_worlds
    from fuzzynav.world.scenario_file import refuse_overwriting_edits, scenario_yaml

    check_kind(args.family, "FAMILY")
    scenarios = generate_worlds(args.family, args.n, args.seed)
    texts = {args.out / f"{scenario.name}.yaml": scenario_yaml(scenario) for scenario in scenarios}
    refuse_overwriting_edits(texts, args.out, "--out")
    for path, text in progress.bar(texts.items(), desc="worlds", unit="world"):
        write_text_atomic(path, text)
    names = f"{scenarios[0].name}.yaml" + (f" … {scenarios[-1].name}.yaml" if len(scenarios) > 1 else "")
    print(f"wrote {len(scenarios)} scenario file{'s' * (len(scenarios) > 1)} to {args.out}/ ({names}); "
          "run one with `fuzzynav run FILE --controller NAME`")
    return 0
