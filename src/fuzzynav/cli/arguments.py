"""What the sub-commands share (not a sub-command itself): :func:`command`, which declares one,
and the argument types.

A bad value is an argparse error: usage and message on stderr, exit status 2, no traceback.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable


def command(subparsers, name: str, run: Callable[[argparse.Namespace], int], **texts) -> argparse.ArgumentParser:
    """The parser of sub-command ``name`` (``texts``: ``help``, ``description``… of ``add_parser``),
    which runs ``run(args) -> exit status``; the caller adds its arguments."""
    parser = subparsers.add_parser(name, **texts)
    parser.set_defaults(func=run)
    return parser


def seed(text: str) -> int:
    """``--seed``: a non-negative integer (NumPy's ``SeedSequence`` rejects negative entropy)."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a non-negative integer, got {text!r}") from None
    if value < 0:
        raise argparse.ArgumentTypeError(f"must be a non-negative integer, got {value}")
    return value


def figure_path(text: str) -> str:
    """``--plot`` / ``-o`` of a figure: a file name whose suffix matplotlib can write (none = PNG)."""
    from matplotlib.backend_bases import FigureCanvasBase

    suffix = text.rpartition(".")[2].lower() if "." in text.rpartition("/")[2] else ""
    supported = FigureCanvasBase.get_supported_filetypes()
    if suffix and suffix not in supported:
        raise argparse.ArgumentTypeError(f"{text!r}: matplotlib cannot write '.{suffix}' files "
                                         f"(use one of {', '.join(sorted(supported))})")
    return text


def gif_path(text: str) -> str:
    """``--animate``: the animated GIF to write (Pillow's writer), so the name must end in ``.gif``."""
    if not text.lower().endswith(".gif"):
        raise argparse.ArgumentTypeError(f"{text!r}: the animation is written as GIF, give a name ending in .gif")
    return text
