"""Every file fuzzynav writes goes through a temporary file and a rename, so an interrupted save
(Ctrl-C, crash, ``kill -9``) never leaves a half-written file where a good one was.

The temporary file ``.NAME.XXXX.tmp`` sits beside ``NAME``; it is removed if the write fails,
and temporaries that a killed process left beside ``NAME`` are removed by the next successful
save of ``NAME`` (:func:`remove_stale_temporaries`) or by a training run that resumes from it.
"""

from __future__ import annotations

import os
import tempfile
import time
from pathlib import Path

from fuzzynav.errors import InputError


def _umask() -> int:
    mask = os.umask(0)
    os.umask(mask)
    return mask


def remove_stale_temporaries(path, older_than: float | None = None) -> list[Path]:
    """Remove the ``.NAME.*.tmp`` files beside ``path`` (those last modified before
    ``older_than``, a ``time.time()``, when given); returns the files removed."""
    path = Path(path)
    removed = []
    for tmp in path.parent.glob(f".{path.name}.*.tmp") if path.parent.is_dir() else ():
        try:
            if older_than is None or tmp.stat().st_mtime < older_than:
                tmp.unlink()
                removed.append(tmp)
        except OSError:
            continue  # gone already, or not ours to remove
    return removed


def atomic_write(path, write) -> None:
    """Write through ``write(handle)`` (a binary file) to a temporary file, then rename it onto ``path``.

    The file gets the usual permissions (0666 less the umask, not mkstemp's 0600); a path that
    cannot be written (missing permission, a directory, ...) is an :class:`InputError` naming it.
    """
    path = Path(path)
    tmp = None
    started = time.time()
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
        with os.fdopen(fd, "wb") as handle:
            write(handle)
            handle.flush()
            os.fsync(handle.fileno())
        os.chmod(tmp, 0o666 & ~_umask())
        os.replace(tmp, path)
    except BaseException as error:
        if tmp is not None and os.path.exists(tmp):
            os.unlink(tmp)
        if isinstance(error, OSError):
            raise InputError(f"cannot write ({error.strerror or error})", source=str(path)) from None
        raise
    remove_stale_temporaries(path, older_than=started - 1.0)


def write_text_atomic(path, text: str) -> None:
    """Write ``text`` (UTF-8) to ``path`` atomically."""
    data = text.encode("utf-8")
    atomic_write(path, lambda handle: handle.write(data))


def savefig_atomic(figure, path, **options) -> None:
    """``figure.savefig(path, **options)`` atomically (format from the suffix, PNG without one)."""
    suffix = Path(path).suffix.lower().lstrip(".")
    options.setdefault("format", suffix or "png")
    atomic_write(path, lambda handle: figure.savefig(handle, **options))
