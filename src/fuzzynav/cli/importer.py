"""``fuzzynav import barn WORLD.world… --out DIR [--scale S]`` — BARN worlds as scenario files.

Writes ``DIR/world_N.yaml`` for each world (:mod:`fuzzynav.world.barn`) and ``DIR/benchmark.json``
with BARN's optimal path length of each (read from ``path_N.npy`` beside the world file or in
``path_files/``; without it the BARN score is not computed), so ``fuzzynav bench DIR`` runs them.
A scenario file already in DIR that is not an import of its world (an edited one) is not
overwritten: the command is refused before writing any.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from fuzzynav.cli import arguments, help_line
from fuzzynav.errors import InputError


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "import",
        help=help_line("importer"),
        description="Convert worlds of a standard benchmark into scenario files (`fuzzynav bench DIR` runs them).",
        **arguments.with_example("fuzzynav import barn BARN/world_*.world --out barn-1.5 --scale 1.5"),
    )
    formats = parser.add_subparsers(dest="format", metavar="FORMAT", required=True)
    barn = arguments.command(formats, "barn", run, help="BARN worlds (Gazebo .world files of the BARN Challenge)",
                             description="BARN worlds: posts become circles; the challenge's start, goal "
                                         "(1 m tolerance), 100 s limit and optimal path (for its score).",
                             example="""
fuzzynav import barn BARN/world_*.world --out barn-1.5 --scale 1.5
fuzzynav bench barn-1.5 --controllers fuzzy-5b,dwa --out barn-bench""")
    barn.add_argument("worlds", nargs="+", metavar="WORLD.world", type=arguments.file_name,
                      help="BARN world files (world_N.world)")
    barn.add_argument("--out", required=True, type=arguments.path, metavar="DIR", help="folder for the scenario files")
    barn.add_argument("--scale", type=arguments.decimal, default=1.0, metavar="S",
                      help="multiply every length by S (default 1: BARN's true size)")


def _imported_at(target: Path, posts: Path, stem: str, earlier, scale: float) -> bool:
    """Whether ``target`` holds what importing the BARN world ``posts`` at the ``earlier`` scale of
    the folder's reference file wrote, that scale being another than ``scale``."""
    import yaml

    from fuzzynav.world.barn import barn_scenario, read_posts

    if not isinstance(earlier, (int, float)) or isinstance(earlier, bool) or earlier == scale or not target.is_file():
        return False
    try:
        return target.read_text() == yaml.safe_dump(barn_scenario(read_posts(posts), stem, earlier), sort_keys=False)
    except (InputError, UnicodeDecodeError):  # a scale no import takes, a file of no text: not an import
        return False


def run(args) -> int:
    import yaml

    from fuzzynav.bench.suites import REFERENCE_FILE, read_references
    from fuzzynav.storage import write_text_atomic
    from fuzzynav.world.barn import (
        barn_scenario,
        check_scale,
        find_path_file,
        optimal_path_length,
        read_posts,
        world_index,
    )
    from fuzzynav.world.scenario import scenario_from_dict
    from fuzzynav.world.scenario_file import refuse_overwriting_edits

    check_scale(args.scale)
    out = arguments.check_folder(args.out, "--out", (REFERENCE_FILE,))  # made by the first file written
    reference_file = out / REFERENCE_FILE
    references = read_references(reference_file) if reference_file.is_file() else {}  # read as bench reads it
    read: dict[str, tuple] = {}  # every world is read and checked before any file is written
    for name in args.worlds:
        path = Path(name)
        if path.stem in read:
            raise InputError(f"given twice ({read[path.stem][0]} and {path}): both would be written to "
                             f"{out / path.stem}.yaml", source=path.stem)
        document = barn_scenario(read_posts(path), path.stem, args.scale)
        scenario_from_dict(document, source=str(path))  # the start must fit the robot, and so on
        entry = {"barn_world": world_index(path), "scale": args.scale}
        path_file = find_path_file(path)
        if path_file is None:
            print(f"fuzzynav import barn: {path}: no path_N.npy found, no BARN score for it", file=sys.stderr)
        else:
            entry["barn_optimal_path_m"] = round(args.scale * optimal_path_length(path_file), 6)
        read[path.stem] = (path, document, entry)
    # what each file will hold; one already there otherwise is an edit, left alone (as worlds generate
    # leaves it), unless an import at another scale wrote it: that is redone
    texts = {stem: yaml.safe_dump(document, sort_keys=False) for stem, (_, document, _) in read.items()}
    refuse_overwriting_edits({out / f"{stem}.yaml": text for stem, text in texts.items()
                              if not _imported_at(out / f"{stem}.yaml", read[stem][0], stem,
                                                  references.get(stem, {}).get("scale"), args.scale)}, out, "--out")
    for stem, (_, _, entry) in read.items():
        write_text_atomic(out / f"{stem}.yaml", texts[stem])
        references[stem] = entry
    write_text_atomic(reference_file, json.dumps({"source": "BARN", "scenarios": references}, indent=1, sort_keys=True) + "\n")
    print(f"{len(args.worlds)} BARN world{'s' * (len(args.worlds) != 1)} -> {out}", file=sys.stderr)
    return 0
