"""Command line: ``fuzzynav <command> ...``.

Each sub-command lives in its own module under :mod:`fuzzynav.cli` and exposes
``register(subparsers)``, which declares it with :func:`fuzzynav.cli.arguments.command` (its
parser, and the ``func(args) -> int`` it runs) and adds its arguments. Only the modules of the
commands named on the command line are imported (:func:`build_parser`): ``fuzzynav --help`` lists
the others by their line in :data:`COMMAND_MODULES`. Bad input
raises :class:`~fuzzynav.errors.InputError`: its message goes to stderr and the exit status is 2.
"""

from __future__ import annotations

import argparse
import difflib
import errno
import gc
import io
import os
import re
import signal
import sys
from collections.abc import Sequence
from importlib import import_module

from fuzzynav import __version__
from fuzzynav.cli import arguments
from fuzzynav.errors import InputError, escaped

# Sub-command modules, in the order ``fuzzynav --help`` lists them: module -> (command, its line in
# that list). The lines are kept here so that listing the commands imports none of their modules.
COMMAND_MODULES: dict[str, tuple[str, str]] = {
    "demo": ("demo", "run the thesis' controllers on the built-in scenarios (plots + metrics table)"),
    "warmup": ("warmup", "compile the simulator's kernels now (first run only), with a progress bar"),
    "run": ("run", "run a controller on a scenario"),
    "scenarios": ("scenarios", "list the built-in scenarios"),
    "train": ("train", "train a learning controller (ANFIS, MLP, Q-learning, fuzzy Q-learning)"),
    "reproduce": ("reproduce", "reproduce a figure or table of the thesis"),
    "fis": ("fis", "show, evaluate, convert, plot or export (C) a fuzzy system"),
    "evaluate": ("evaluate", "run a controller over N generated worlds"),
    "worlds": ("worlds", "write generated worlds as scenario files"),
    "bench": ("bench", "run navigators against each other on suites of worlds"),
    "importer": ("import", "convert standard benchmark worlds into scenario files"),
    "tune": ("tune", "tune a controller's fuzzy system by GA, PSO, DE, CMA-ES, NSGA-II or ant colony"),
}


def help_line(module: str) -> str:
    """The line of the sub-command of ``module`` in ``fuzzynav --help`` (its ``help``)."""
    return COMMAND_MODULES[module][1]


class Parser(argparse.ArgumentParser):
    """The parser of every command: options by their whole name only, as a prefix was taken for the
    option it begins (``bench --seed 3`` would be read as ``--seeds 3``)."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **{"allow_abbrev": False, **kwargs})

    def parse_args(self, args=None, namespace=None):  # type: ignore[override]
        """As argparse's, an unknown option named with the closest one of the command as a hint."""
        namespace, extras = self.parse_known_args(args, namespace)
        if extras:  # said by the command's own parser: its usage line and name, as its other errors
            parsers = list(_reached(self, namespace))
            options = [o for parser in parsers for a in parser._actions for o in a.option_strings]
            word = next((extra.split("=")[0] for extra in extras if extra.startswith("-")), "")
            close = difflib.get_close_matches(word, options, n=1, cutoff=0.7)
            parsers[-1].error(f"unrecognized arguments: {' '.join(extras)}"
                              + (f" (did you mean {close[0]}?)" if close else ""))
        return namespace


def _reached(parser: argparse.ArgumentParser, namespace):
    """``parser`` and the sub-commands' parsers ``namespace`` went through."""
    yield parser
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction) and getattr(namespace, action.dest, None) in action.choices:
            yield from _reached(action.choices[getattr(namespace, action.dest)], namespace)


def build_parser(argv: Sequence[str] | None = None) -> argparse.ArgumentParser:
    """The parser of the command line. Every sub-command's module is imported and registered, or,
    given the words ``argv`` to parse, only those of the commands ``argv`` names: the others are
    listed with their line alone (a parser without arguments argparse never reaches, since it picks
    a sub-command by its exact name), so a command does not import the modules of all the others."""
    parser = Parser(  # its sub-commands' parsers are of its class (argparse's add_subparsers)
        prog="fuzzynav",
        description="Neuro-fuzzy navigation of a simulated tricycle robot (Cherroun, 2014).",
        **arguments.with_example("""
fuzzynav demo --out fuzzynav-out     # every built-in thesis scenario with its controllers
fuzzynav run fig-IV-23 --plot u.png  # one episode of the default navigator
fuzzynav COMMAND --help              # a command's options, with examples"""),
    )
    parser.add_argument("--version", action="version", version=f"fuzzynav {__version__}")
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND")
    for module_name, (command, line) in COMMAND_MODULES.items():
        if argv is None or command in argv:
            import_module(f"fuzzynav.cli.{module_name}").register(subparsers)
        else:
            subparsers.add_parser(command, help=line)
    return parser


class _Closed(io.TextIOBase):
    """What stands for a standard stream the command was started without (``<&-``, ``>&-``; Python
    makes it None, and ``print`` to None writes nothing): reading or writing it is an error, not a
    lost answer nor an ``AttributeError``."""

    def __init__(self, name: str):
        self.name = name

    @property
    def buffer(self) -> _Closed:
        """The binary stream under it (``sys.stdin.buffer``): as closed as it is."""
        return self

    def read(self, size: int | None = -1) -> str:
        raise OSError(errno.EBADF, f"standard {self.name} is closed")

    def write(self, text: str) -> int:
        raise OSError(errno.EBADF, f"standard {self.name} is closed")


def _survive_any_terminal() -> None:
    """Characters the terminal's encoding lacks (``§``, ``θ``, ``≥`` on ``PYTHONIOENCODING=ascii``)
    are written as ``\\u00a7`` escapes instead of failing with ``UnicodeEncodeError``; a closed
    standard input or output refuses what is read from or written to it (:class:`_Closed`)."""
    if sys.stdin is None:
        sys.stdin = _Closed("input")
    if sys.stdout is None:
        sys.stdout = _Closed("output")
    for stream in (sys.stdout, sys.stderr):
        reconfigure = getattr(stream, "reconfigure", None)
        if callable(reconfigure):
            reconfigure(errors="backslashreplace")


def _check_numba_threads() -> None:
    """``NUMBA_NUM_THREADS`` below 1 makes importing numba raise (other text it ignores)."""
    value = os.environ.get("NUMBA_NUM_THREADS", "").strip()
    if re.fullmatch(r"[+-]?\d+", value, re.ASCII) and int(value) < 1:
        raise InputError(f"must be a whole number of threads, at least 1, got {value!r} (the environment variable "
                         "numba reads)", field="NUMBA_NUM_THREADS")


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised where the process is, so that it ends as Ctrl-C ends it: every save under
    way removes its temporary file, and the command exits with 143 instead of leaving them."""


RECEIVED: list[int] = []
"""The signals that have asked this process to stop (SIGINT, SIGTERM), in order: a library may
catch the exception a signal raises and fail in its place — numba's compiler, when Ctrl-C lands in
llvmlite's ctypes callback, swallows the KeyboardInterrupt and raises ``RuntimeError: no compiled
object yet`` — so :func:`main` ends such a failure as the interrupt, not with its traceback."""


def _terminate(signum, frame) -> None:
    RECEIVED.append(signum)
    raise Terminated


def _interrupt(signum, frame) -> None:
    RECEIVED.append(signum)
    signal.default_int_handler(signum, frame)


def _quiet_when_stopped(unraisable) -> None:
    """``sys.unraisablehook``: the stop a library swallowed is not printed as a traceback ("Exception
    ignored on calling ctypes callback function"); :func:`main` says it in one line. Anything else
    goes to Python's own hook."""
    if not isinstance(unraisable.exc_value, KeyboardInterrupt):
        sys.__unraisablehook__(unraisable)


def _stopped(signum: int, args) -> int:
    """Say how the command was stopped, and how to go on where the command says
    (``when_stopped``); the exit status (128 + the signal, as a shell reports it)."""
    hint = getattr(args, "when_stopped", None)
    print(("terminated" if signum == signal.SIGTERM else "interrupted") + (f": {hint}" if hint else ""),
          file=sys.stderr)
    return 128 + signum


def _who(parser, args) -> str:
    """The start of an error line: the name of the deepest (sub-)command ``args`` reached
    (``fuzzynav fis eval``, as argparse's own errors say it; ``fuzzynav`` before it is read)."""
    return list(_reached(parser, args))[-1].prog if parser is not None and args is not None else "fuzzynav"


def main(argv: list[str] | None = None) -> int:
    _survive_any_terminal()
    if argv is None:  # the process' own command (not a call from Python, whose signals are the caller's)
        signal.signal(signal.SIGTERM, _terminate)
        if signal.getsignal(signal.SIGINT) is signal.default_int_handler:  # not where Ctrl-C is ignored
            signal.signal(signal.SIGINT, _interrupt)
        sys.unraisablehook = _quiet_when_stopped
        if hasattr(os, "register_at_fork"):  # a forked worker's SIGTERM ends it, from its first instruction
            os.register_at_fork(after_in_child=lambda: signal.signal(signal.SIGTERM, signal.SIG_DFL))
    words = sys.argv[1:] if argv is None else argv
    parser = args = None
    try:
        _check_numba_threads()
        parser = build_parser(words)  # (imports the command: Ctrl-C may come here too)
        args = parser.parse_args(words)
        if not getattr(args, "func", None):
            parser.print_help()
            return 2
        return int(args.func(args) or 0)
    except InputError as error:
        print(f"{_who(parser, args)}: error: {error}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        # the reader of stdout went away (``fuzzynav fis show ... | head``): quietly, no traceback
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 141
    except OSError as error:
        # a file named on the command line cannot be read or written (missing folder, permission, ...)
        where = f"{escaped(error.filename)}: " if error.filename else ""
        problem = error.strerror or error
        if isinstance(error, FileExistsError) and error.filename and os.path.isfile(error.filename):
            problem = "is a file, not a folder (give a new or an existing folder)"
        print(f"{_who(parser, args)}: error: {where}{problem}", file=sys.stderr)
        return 2
    except Terminated:
        return _stopped(signal.SIGTERM, args)
    except KeyboardInterrupt:
        return _stopped(signal.SIGINT, args)
    except Exception:
        if not RECEIVED:
            raise
        return _stopped(RECEIVED[-1], args)  # a library failed where the signal had stopped it (RECEIVED)
    finally:
        if argv is None:
            # the process' own command, which ends here: the collections of the interpreter's shutdown
            # would walk every object numba made (0.1 to 0.3 s); frozen, they are left to the exit
            gc.freeze()


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
