"""Progress bars for the long commands (``evaluate``, ``reproduce``, ``train``), on stderr.

A bar is drawn only when stderr is a terminal and the user did not ask for quiet output
(``--quiet``, :func:`quiet`): piped or redirected output and ``--json`` stay clean. tqdm is
imported on first use, so importing this module costs nothing at start-up.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar

_QUIET: ContextVar[bool] = ContextVar("fuzzynav_quiet", default=False)


def enabled() -> bool:
    """True when a progress bar would be shown: stderr is a terminal with room for one (a terminal
    that says it has 0 columns draws nothing: the commands then print their lines instead) and
    output is not quiet."""
    if _QUIET.get() or not sys.stderr.isatty():
        return False
    try:
        return os.get_terminal_size(sys.stderr.fileno()).columns > 0
    except (OSError, ValueError):  # a stand-in stderr without a descriptor: trust isatty
        return True


@contextmanager
def quiet(on: bool = True) -> Iterator[None]:
    """Within the block, no progress bar is shown (``on=False`` leaves the setting as it is)."""
    token = _QUIET.set(_QUIET.get() or on)
    try:
        yield
    finally:
        _QUIET.reset(token)


def bar(iterable: Iterable | None = None, *, total: int | None = None, desc: str | None = None,
        unit: str = "it", leave: bool = True, initial: int = 0):
    """A tqdm bar on stderr, disabled unless :func:`enabled`; iterate it or call ``update``
    (``initial``: the count it starts from, as a resumed run's)."""
    from tqdm import tqdm

    return tqdm(iterable, total=total, desc=desc, unit=unit, leave=leave, disable=not enabled(),
                file=sys.stderr, dynamic_ncols=True, initial=initial)


def write(text: str) -> None:
    """Print ``text`` to stdout without breaking a progress bar being drawn on stderr."""
    from tqdm import tqdm

    tqdm.write(text, file=sys.stdout)
