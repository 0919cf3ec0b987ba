"""The one way kernels are compiled (numba), with the on-disk cache.

numba checks a cached kernel against its own source file only: a kernel whose callee in another
file changed would be loaded as compiled against the old callee (a wrong answer, or a crash). So
at import, :func:`clear_stale_caches` fingerprints the package's kernel sources (the files naming this
module or numba) and, when any changed since the last check, deletes every cached kernel of the package (they are compiled again
on first use). Installs and upgrades rewrite every file, so numba's own check suffices there; the
guard is for working copies (an editable install being edited), wherever their caches are: beside
the sources, or under ``NUMBA_CACHE_DIR`` when it is set (a folder per source folder, named by numba).

numba's cache is not safe between processes (numba/numba#4807 on GitHub): two processes that compile two
signatures of one kernel at once (the forked workers of ``evaluate``, ``bench`` or the demo, on a
cold cache) can write one data file name for both, so a later run may load one signature's machine
code for the other. Every kernel's cache file is therefore wrapped in :class:`LockedCacheFile`,
which holds an advisory lock on its cache folder while it reads or writes (where ``fcntl``
exists: Linux and macOS; Windows keeps numba's own guard).

The first time in a process that one of the package's kernels is compiled rather than loaded
from the cache, one line on stderr (:data:`COMPILE_NOTICE`) says so: a cold first run is silent
for a while otherwise. ``fuzzynav warmup`` compiles them all up front, with a progress bar.
"""

from __future__ import annotations

import contextlib
import hashlib
import mmap
import os
import sys
from pathlib import Path

try:
    import fcntl
except ImportError:  # Windows
    fcntl = None

import numba
from numba.core import event

PACKAGE = Path(os.path.abspath(__file__)).parent  # as imported (symbolic links kept): the path numba names
# its cache folders under NUMBA_CACHE_DIR by (the absolute path of each kernel's source file)
STAMP = "fuzzynav-kernel-sources.stamp"  # in the package's own __pycache__
CACHE_LOCK = "fuzzynav-kernel-cache.lock"  # one per cache folder (LockedCacheFile)
CACHE_SUFFIXES = (".nbi", ".nbc")
COMPILE_NOTICE = ("fuzzynav: compiling kernels not yet in the cache (once: later runs load them; a first run "
                  "can spend one to two minutes here, docs/results/first-run.md)")


def _kernel_sources(package: Path) -> list[Path]:
    """The package's source files that define kernels or what they inline (those naming this
    module or numba)."""
    return sorted(source for source in package.rglob("*.py")
                  if any(name in source.read_text(encoding="utf-8", errors="replace") for name in ("fuzzynav.jit", "numba")))


def _fingerprint(sources: list[Path], package: Path) -> str:
    """A digest of the name in ``package``, size and modification time of each of ``sources`` (the
    same whichever path, through a symbolic link or not, the package is reached by)."""
    digest = hashlib.sha256()
    for source in sources:
        stat = source.stat()
        digest.update(f"{source.relative_to(package).as_posix()}|{stat.st_size}|{stat.st_mtime_ns}\n".encode())
    return digest.hexdigest()


def _cache_places(package: Path, cache_dir: str) -> tuple[Path, list[Path]]:
    """The stamp of the last check and the folders where numba keeps ``package``'s kernels: each
    source folder's ``__pycache__``, or, under ``cache_dir`` (``NUMBA_CACHE_DIR``) when it is set,
    the folder numba names for each source folder."""
    if not cache_dir:
        return package / "__pycache__" / STAMP, list(package.rglob("__pycache__"))
    from numba.core.caching import _CacheLocator

    def mirror(folder: Path) -> Path:
        return Path(cache_dir) / _CacheLocator.get_suitable_cache_subpath(str(folder / "__init__.py"))

    folders = sorted({mirror(source.parent) for source in package.rglob("*.py")})
    return mirror(package) / STAMP, [folder for folder in folders if folder.is_dir()]


def clear_stale_caches(package: Path = PACKAGE, cache_dir: str | None = None) -> bool:
    """Delete the numba caches of ``package`` (beside it, or under ``cache_dir``, by default numba's
    ``NUMBA_CACHE_DIR``) when its kernel sources changed since the last check of those caches
    (module docstring); returns whether it deleted any. Quiet where nothing is writable."""
    try:
        stamp, folders = _cache_places(package, numba.config.CACHE_DIR if cache_dir is None else cache_dir)
        now = _fingerprint(_kernel_sources(package), package)
        if stamp.is_file() and stamp.read_text() == now:
            return False
        cached = [f for folder in folders for f in folder.iterdir() if f.suffix in CACHE_SUFFIXES]
        for old in cached:
            old.unlink(missing_ok=True)
        stamp.parent.mkdir(parents=True, exist_ok=True)
        temporary = stamp.with_name(f".{STAMP}.{os.getpid()}.tmp")
        temporary.write_text(now)
        os.replace(temporary, stamp)
        return bool(cached)
    except OSError:  # a read-only install: numba's own check (every file rewritten by an upgrade)
        return False
    except (ImportError, AttributeError):  # a numba whose cache locator moved (a private class): its own check
        return False


def jit(function=None, *, fastmath: tuple = (), nogil: bool = False):
    """``numba.njit`` with the on-disk cache and NumPy's floating-point error model (x / 0 is
    inf or nan, as in the rest of the package). The cache lives in ``__pycache__`` beside this
    package, or — when that is not writable (a read-only install) — in numba's user-wide cache
    directory (``NUMBA_CACHE_DIR`` overrides both); with no writable place at all, the kernels
    are compiled in memory at every start.

    ``@jit(fastmath=("contract",))`` lets the compiler fuse a * b + c into one instruction (one
    rounding instead of two, where the processor has FMA): for polynomial kernels
    (:mod:`fuzzynav.fuzzy.engine.vmath`), whose last bits may then differ between processors
    (never between two runs on one).

    ``@jit(nogil=True)`` releases the GIL while the kernel runs, so that threads of one process
    run it at once (:mod:`fuzzynav.threads`)."""
    if function is None:
        return lambda f: jit(f, fastmath=fastmath, nogil=nogil)
    options = {"error_model": "numpy", "fastmath": set(fastmath) if fastmath else False, "nogil": nogil}
    try:
        kernel = numba.njit(cache=True, **options)(function)
    except RuntimeError:  # "cannot cache function ...: no locator available"
        return numba.njit(**options)(function)
    cache = getattr(kernel, "_cache", None)  # none under NUMBA_DISABLE_JIT=1 (the plain function)
    if cache is not None:
        cache._cache_file = LockedCacheFile(cache._cache_file)
    return kernel


class LockedCacheFile:
    """A kernel's numba cache file (index and data files) whose ``save`` and ``load`` hold a lock on
    the cache folder: exclusive while saving (read the index, pick a data file, write both), shared
    while loading, so no process reads or picks names from an index another is rewriting (module
    docstring). Without ``fcntl``, or where the lock file cannot be opened (a folder it may not
    write), it reads and writes as numba does."""

    def __init__(self, cache_file) -> None:
        self._cache_file = cache_file
        self._lock_path = os.path.join(cache_file._cache_path, CACHE_LOCK)

    @contextlib.contextmanager
    def _locked(self, exclusive: bool):
        try:
            lock = open(self._lock_path, "a+b") if fcntl is not None else None
        except OSError:  # a folder it may not write: numba's own way
            lock = None
        if lock is None:
            yield
            return
        with lock:  # closing the file releases the lock
            with contextlib.suppress(OSError):  # a file system without locks: numba's own way
                fcntl.flock(lock, fcntl.LOCK_EX if exclusive else fcntl.LOCK_SH)
            yield

    def save(self, key, data) -> None:
        with self._locked(exclusive=True):
            self._cache_file.save(key, data)

    def load(self, key):
        with self._locked(exclusive=False):
            return self._cache_file.load(key)

    def flush(self) -> None:
        with self._locked(exclusive=True):
            self._cache_file.flush()

    def __getattr__(self, name: str):
        """Anything else numba may read of its cache file, from the file itself."""
        if name == "_cache_file":  # not set yet (a copy being made): no recursion
            raise AttributeError(name)
        return getattr(self._cache_file, name)


class CompileNotice(event.Listener):
    """Prints :data:`COMPILE_NOTICE` on stderr once, when numba starts compiling (a cache miss,
    not a load) a kernel of this package; :meth:`silence` stops it (a caller that reports the
    compilation its own way, such as ``fuzzynav warmup``). Whether it was said is one byte of memory
    shared with the processes forked after it was made (``evaluate``'s and ``bench``'s workers on
    Linux), so a command says it once, not once per worker; workers started afresh (spawned, as
    on macOS and Windows, or Ray's) each have their own."""

    def __init__(self) -> None:
        self._said = mmap.mmap(-1, 1)  # anonymous and shared: a forked worker sees its parent's byte

    @property
    def said(self) -> bool:
        return bool(self._said[0])

    @said.setter
    def said(self, value: bool) -> None:
        self._said[0] = int(bool(value))

    def silence(self) -> None:
        """Say nothing from now on in this process and the workers it forks."""
        self.said = True

    def on_start(self, compile_event) -> None:
        dispatcher = compile_event.data.get("dispatcher") if isinstance(compile_event.data, dict) else None
        module = getattr(getattr(dispatcher, "py_func", None), "__module__", "") or ""
        if not self.said and module.startswith("fuzzynav"):
            self.said = True
            sys.stderr.write(COMPILE_NOTICE + "\n")  # one write: worker processes do not glue lines
            sys.stderr.flush()

    def on_end(self, compile_event) -> None:
        """Nothing to do when a compilation ends."""


NOTICE = CompileNotice()
event.register("numba:compile", NOTICE)
clear_stale_caches()
