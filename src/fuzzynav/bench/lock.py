"""One writer per campaign folder: ``bench`` holds an exclusive lock on ``<out>/.bench.lock``.

The lock is the operating system's (``fcntl.flock``), so it is released whenever the process
ends — a ``kill -9`` leaves no stale lock behind — and a second ``fuzzynav bench`` on the same
``--out`` is refused at once with an :class:`~fuzzynav.errors.InputError` naming the folder
(exit 2), instead of both appending to the same files. On systems without ``fcntl`` (Windows)
no lock is taken.
"""

from __future__ import annotations

import contextlib
import os
from pathlib import Path

from fuzzynav.errors import InputError

LOCK_FILE = ".bench.lock"


@contextlib.contextmanager
def campaign_lock(out: Path):
    """Hold the lock of the folder ``out`` (created if needed) for the ``with`` block."""
    try:
        import fcntl
    except ImportError:  # pragma: no cover - Windows
        yield
        return
    out.mkdir(parents=True, exist_ok=True)  # an OSError here names the path (a file in the way, ...)
    path = out / LOCK_FILE
    fd = os.open(path, os.O_RDWR | os.O_CREAT, 0o644)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            raise InputError("another `fuzzynav bench` is writing this campaign (its lock is held): wait for it "
                             "to finish, or choose another --out", source=str(out), field="--out") from None
        try:  # these errors carry no file name: give it
            os.ftruncate(fd, 0)
            os.write(fd, f"{os.getpid()}\n".encode())
        except OSError as error:
            raise InputError(f"cannot write the campaign's lock file ({error.strerror or error})", source=str(path),
                             field="--out") from None
        yield
        with contextlib.suppress(OSError):
            os.unlink(path)
    finally:
        os.close(fd)
