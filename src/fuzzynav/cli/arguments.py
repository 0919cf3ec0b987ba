"""What the sub-commands share (not a sub-command itself): :func:`command`, which declares one
with an example for its ``--help``, and the argument types.

A bad value is an argparse error: usage and message on stderr, exit status 2, no traceback.
"""

from __future__ import annotations

import argparse
import os
import re
import tempfile
import textwrap
from collections.abc import Callable
from pathlib import Path

from fuzzynav.errors import InputError


def plain(text: str) -> str:
    """``text`` without the reStructuredText of docstrings: ``:func:`name``` → name, double or
    single backticks → quotes (help texts are read in a terminal)."""
    text = re.sub(r":\w+:`~?([^`]+)`", r"\1", text)
    return re.sub(r"`{1,2}([^`]+)`{1,2}", r"'\1'", text)


class _Wrapper(textwrap.TextWrapper):
    """textwrap's wrapper that may also break a brace list after one of its commas
    (``robot.actuation.{latency,steering_rate,`` / ``acceleration,slip}``) and a list of choices
    after one of its bars (``circles|mixed|``), but never inside a word: a word longer than the line
    overflows it."""

    def __init__(self, width: int):
        super().__init__(width, break_long_words=False)

    def _split(self, text):
        breaks = r"(?<=,)(?=[^\s{}]*\})|(?<=\|)(?=\w)"  # after a comma inside braces, after a bar
        return [piece for chunk in super()._split(text) for piece in re.split(breaks, chunk) if piece]


class ExampleFormatter(argparse.HelpFormatter):
    """argparse's formatter on plain text (:func:`plain`), except that a text whose first line is a
    heading (ends with ``:``, as the ``examples:`` epilog) keeps its lines as written, and that the
    help of an option breaks no word (:class:`_Wrapper`)."""

    def _fill_text(self, text, width, indent):
        if text.split("\n", 1)[0].endswith(":"):
            return "".join(indent + line for line in text.splitlines(keepends=True))
        return super()._fill_text(plain(text), width, indent)

    def _split_lines(self, text, width):
        return _Wrapper(width).wrap(self._whitespace_matcher.sub(" ", plain(text)).strip())


def with_example(example: str, epilog: str = "") -> dict:
    """The ``epilog`` and ``formatter_class`` keywords of ``add_parser`` that end a ``--help``
    with ``example`` (one command a line, comments allowed) after ``epilog``."""
    lines = "\n".join(f"  {line}" for line in example.strip().splitlines())
    return {"epilog": (f"{epilog.rstrip()}\n\n" if epilog else "") + f"examples:\n{lines}\n",
            "formatter_class": ExampleFormatter}


def command(subparsers, name: str, run: Callable[[argparse.Namespace], int], *, example: str,
            when_stopped: str | None = None, **texts) -> argparse.ArgumentParser:
    """The parser of sub-command ``name`` (``texts``: ``help``, ``description``, ``epilog`` of
    ``add_parser``), which runs ``run(args) -> exit status``, its ``--help`` ending with
    ``example`` (:func:`with_example`); the caller adds its arguments. ``when_stopped`` is said
    after "interrupted" when Ctrl-C stops the command (how to go on; ``run`` may change it)."""
    epilog = texts.pop("epilog", "")
    parser = subparsers.add_parser(name, **texts, **with_example(example, epilog))
    parser.set_defaults(func=run, when_stopped=when_stopped)
    return parser


def names(text: str) -> list[str]:
    """``--controllers A,B``: the comma-separated names (empty items dropped); none at all is a
    usage error (it ran every default controller instead)."""
    found = [name.strip() for name in text.split(",") if name.strip()]
    if not found:
        raise argparse.ArgumentTypeError(f"give at least one name, got {text!r}")
    return found


_INTEGER = re.compile(r"\s*[+-]?\d+\s*", re.ASCII)


def decimal(text: str) -> float:
    """The type of every option and value that is a number: :func:`fuzzynav.fuzzy.formula.decimal`
    (ASCII decimal; ValueError otherwise), which the fuzzy-system readers share."""
    from fuzzynav.fuzzy.formula import decimal as ascii_decimal

    return ascii_decimal(text)


def whole(text: str) -> int:
    """An integer in ASCII digits (``int`` also reads ``1_000`` and other scripts' digits), for an
    option whose range its command checks; ValueError otherwise (argparse's usage error)."""
    if not _INTEGER.fullmatch(text):
        raise ValueError(f"{text!r} is not an integer")
    return int(text)


def _integer(text: str, lo: int, hi: int) -> int:
    """``text`` as an integer in [lo, hi], ASCII digits only (a 5,000-digit number is refused by its
    length, not parsed)."""
    if len(text.strip()) > 30:
        raise argparse.ArgumentTypeError(f"must be an integer in [{lo}, {hi}], got {len(text.strip())} characters")
    try:
        value = whole(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be an integer in [{lo}, {hi}], got {text!r}") from None
    if not lo <= value <= hi:
        raise argparse.ArgumentTypeError(f"must be an integer in [{lo}, {hi}], got {value}")
    return value


def seed(text: str) -> int:
    """``--seed``: a non-negative integer, at most 2**63 - 1 (NumPy's ``SeedSequence`` rejects
    negative entropy)."""
    from fuzzynav import validation  # numpy: imported when a command parses, not for ``fuzzynav --help``

    if text.strip().startswith("-") and text.strip()[1:].isdigit():
        raise argparse.ArgumentTypeError(f"must be a non-negative integer, got {text.strip()}")
    return _integer(text, 0, validation.MAX_SEED)


def small_seed(text: str) -> int:
    """``--seed`` of runs that seed scikit-learn's MLP or a tuner (``reproduce``): at most 2**32 - 1."""
    from fuzzynav import validation

    value = seed(text)
    if value > validation.MAX_SMALL_SEED:
        raise argparse.ArgumentTypeError(f"must be an integer in [0, {validation.MAX_SMALL_SEED}], got {value}")
    return value


def count(hi: int, lo: int = 1) -> Callable[[str], int]:
    """The argument type of a count option: an integer in [lo, hi], refused by argparse (exit 2)
    before any work starts; the option's help states the limit."""
    def parse(text: str) -> int:
        return _integer(text, lo, hi)

    parse.__name__ = "count"
    return parse


def path(text: str) -> Path:
    """A file or folder argument (``--out``, ``--save-failures``): not empty, which would
    quietly mean the current folder."""
    if not text.strip():
        raise argparse.ArgumentTypeError("is empty: name a file or folder (. for the current one)")
    return Path(text)


def check_writable(path, field: str, *, create: bool = True) -> Path:
    """``path`` as a file this process can write at the end of a long run, checked before the run:
    not a folder, and its folder — or, with ``create`` (saves make missing folders), the nearest
    folder above it that exists — a folder it may write in, tried by making (and removing) a
    temporary file there (root may "access" ``/proc`` but not write there). A stream
    (``/dev/stdout``) passes. Otherwise an InputError naming ``field``."""
    path = Path(os.path.realpath(path)) if Path(path).is_symlink() else Path(path)  # a save writes the target
    if path.is_dir():
        raise InputError("is a directory; give the file to write", source=str(path), field=field)
    if path.exists() and not path.is_file():  # a device or a pipe, written in place
        return path
    folder = path.parent
    while create and not folder.exists() and folder != folder.parent:
        folder = folder.parent
    if folder.exists() and not folder.is_dir():
        raise InputError(f"cannot write in {folder}: a file, not a folder", source=str(path), field=field)
    if not folder.is_dir():
        raise InputError(f"no folder {folder} to write it in", source=str(path), field=field)
    if not os.access(folder, os.W_OK | os.X_OK):
        raise InputError(f"cannot write in the folder {folder}", source=str(path), field=field)
    try:
        handle, probe = tempfile.mkstemp(dir=folder, prefix=".fuzzynav-", suffix=".tmp")
    except OSError as error:
        raise InputError(f"cannot write ({error.strerror or error})", source=str(path), field=field) from None
    os.close(handle)
    os.unlink(probe)
    return path


def check_folder(folder, field: str, files=()) -> Path:
    """``folder`` as an output folder, checked before the work that fills it (without making it):
    not a file, and each of ``files`` in it not a folder but a file this process can write
    (:func:`check_writable`). Otherwise an InputError naming ``field``."""
    folder = Path(folder)
    if folder.exists() and not folder.is_dir():
        raise InputError("is a file, not a folder (give a new or an existing folder)", source=str(folder), field=field)
    for name in files:
        if (folder / name).is_dir():
            raise InputError("is a folder where this command writes a file", source=str(folder / name), field=field)
        check_writable(folder / name, field)
    return folder


def file_name(text: str) -> str:
    """A file argument read or written as given (``--model``, ``--csv``, ``-o``, a world file): a file
    name (:func:`fuzzynav.validation.file_path`), so an empty one is refused rather than taken for no
    file (stdout, the default controller) or for the current folder."""
    from fuzzynav import validation

    return _file_argument(validation.file_path, text)


def figure_path(text: str) -> str:
    """``--plot`` / ``-o`` of a figure: a file name whose suffix matplotlib can write (none = PNG),
    checked by :func:`fuzzynav.viz.trajectories.figure_file`, as the Python API checks it."""
    from fuzzynav.viz.trajectories import figure_file

    return _file_argument(figure_file, text)


def gif_path(text: str) -> str:
    """``--animate``: the animated GIF to write (Pillow's writer), so the name must end in ``.gif``
    (:func:`fuzzynav.viz.animation.gif_file`)."""
    from fuzzynav.viz.animation import gif_file

    return _file_argument(gif_file, text)


def _file_argument(check, text: str) -> str:
    """``text`` when ``check(text)`` takes it; its problem as argparse's error otherwise."""
    try:
        check(text)
    except InputError as error:
        raise argparse.ArgumentTypeError(error.problem) from None
    return text
