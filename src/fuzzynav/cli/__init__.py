"""Command line: ``fuzzynav <command> ...``.

Each sub-command lives in its own module under :mod:`fuzzynav.cli` and exposes
``register(subparsers)``, which declares it with :func:`fuzzynav.cli.arguments.command` (its
parser, and the ``func(args) -> int`` it runs) and adds its arguments. Bad input
raises :class:`~fuzzynav.errors.InputError`: its message goes to stderr and the exit status is 2.
"""

from __future__ import annotations

import argparse
import os
import sys
from importlib import import_module

from fuzzynav import __version__
from fuzzynav.cli import arguments
from fuzzynav.errors import InputError

# Sub-command modules, in the order ``fuzzynav --help`` lists them.
COMMAND_MODULES: list[str] = [
    "demo",
    "warmup",
    "run",
    "scenarios",
    "train",
    "reproduce",
    "fis",
    "evaluate",
    "worlds",
    "bench",
    "importer",
    "tune",
]


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="fuzzynav",
        description="Neuro-fuzzy navigation of a simulated tricycle robot (Cherroun, 2014).",
        **arguments.with_example("""
fuzzynav demo --out fuzzynav-out     # every built-in thesis scenario with its controllers
fuzzynav run fig-IV-23 --plot u.png  # one episode of the default navigator
fuzzynav COMMAND --help              # a command's options, with examples"""),
    )
    parser.add_argument("--version", action="version", version=f"fuzzynav {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    for module_name in COMMAND_MODULES:
        import_module(f"fuzzynav.cli.{module_name}").register(subparsers)
    return parser


def _survive_any_terminal() -> None:
    """Characters the terminal's encoding lacks (``§``, ``θ``, ``≥`` on ``PYTHONIOENCODING=ascii``)
    are written as ``\\u00a7`` escapes instead of failing with ``UnicodeEncodeError``."""
    for stream in (sys.stdout, sys.stderr):
        reconfigure = getattr(stream, "reconfigure", None)
        if callable(reconfigure):
            reconfigure(errors="backslashreplace")


def main(argv: list[str] | None = None) -> int:
    _survive_any_terminal()
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "func", None):
        parser.print_help()
        return 2
    try:
        return int(args.func(args) or 0)
    except InputError as error:
        print(f"fuzzynav {args.command}: error: {error}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        # the reader of stdout went away (``fuzzynav fis show ... | head``): quietly, no traceback
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141
    except OSError as error:
        # a file named on the command line cannot be read or written (missing folder, permission, ...)
        where = f"{error.filename}: " if error.filename else ""
        problem = error.strerror or error
        if isinstance(error, FileExistsError) and error.filename and os.path.isfile(error.filename):
            problem = "is a file, not a folder (give a new or an existing folder)"
        print(f"fuzzynav {args.command}: error: {where}{problem}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
