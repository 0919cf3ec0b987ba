"""The cores of one process for compiled kernels that release the GIL (``@jit(nogil=True)``).

A batch of independent items — the jobs of a tuning generation (:mod:`fuzzynav.tune.episodes`),
each one robot on one world — is cut into contiguous chunks that threads take one after another,
each chunk one kernel call writing its own rows of the output. Items do not share state, so the
result is the same, bit for bit, for any number of threads.

:func:`count` is how many threads a process uses: one per core it may run on, unless
:func:`set_count` (or :func:`using`) said otherwise (``fuzzynav tune --workers N``). The workers of
a process pool (:func:`fuzzynav.bench.backends.pool_map`) use one each, since the pool already
spreads its work over the cores. The threads live in one pool per process, made on first use and
joined before the process forks (a fork copies no thread of it half-way; parent and child each
make a new one when they next need it). A :func:`spread` called from one of its threads runs its
chunks in that thread.
"""

from __future__ import annotations

import contextlib
import functools
import itertools
import math
import os
import threading
from collections.abc import Callable, Iterator
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

CHUNKS_PER_THREAD = 8  # chunks cut per thread, so that a thread done early takes the next one
_chosen: int | None = None
_pool: tuple[int, ThreadPoolExecutor] | None = None  # (its threads, the pool)
_lock = threading.Lock()  # around _pool
_inside = threading.local()  # .chunk set while a pool thread runs a chunk


def cores() -> int:
    """The cores this process may run on: those of its CPU affinity (every core where the system
    does not say), fewer where a Linux control group caps its CPU time (a container or a CI
    runner given 2 CPUs on a larger machine: :func:`cpu_quota`). The default of every
    ``--workers`` and of the threads of a batch."""
    try:
        allowed = len(os.sched_getaffinity(0)) or 1
    except AttributeError:  # macOS, Windows
        allowed = os.cpu_count() or 1
    quota = cpu_quota()
    return max(1, min(allowed, math.ceil(quota))) if quota is not None else allowed


@functools.cache
def cpu_quota(root: Path = Path("/sys/fs/cgroup"), membership: Path = Path("/proc/self/cgroup")) -> float | None:
    """The CPUs' worth of time this process' control group may use — the least quota / period of
    its group and of the groups above it (cgroup v2's ``cpu.max``, v1's ``cpu.cfs_quota_us`` and
    ``cpu.cfs_period_us``; a container sees its own group as the root) — or None where no group
    caps it or nothing can be read (not Linux, no cgroup file system). Read once per process."""
    try:
        lines = membership.read_text().splitlines()
    except OSError:
        return None
    shares = []
    for line in lines:
        parts = line.split(":", 2)
        if len(parts) != 3:
            continue
        controllers, group = parts[1], Path(parts[2].lstrip("/"))
        if controllers == "":  # v2: "0::/group"
            bases = [root]
        elif "cpu" in controllers.split(","):  # v1: "N:cpu,cpuacct:/group"
            bases = [root / "cpu", root / "cpu,cpuacct"]
        else:
            continue
        for base in bases:
            for level in (group, *group.parents):  # the group, then each group above it up to the root
                share = _share(base / level / "cpu.max" if controllers == "" else base / level)
                if share is not None:
                    shares.append(share)
    return min(shares) if shares else None


def _share(place: Path) -> float | None:
    """quota / period of the cgroup file ``place`` (v2's ``cpu.max``) or folder (v1's two files):
    None where it sets no cap or cannot be read."""
    try:
        if place.name == "cpu.max":
            quota, period = place.read_text().split()[:2]
        else:
            quota = (place / "cpu.cfs_quota_us").read_text().strip()
            period = (place / "cpu.cfs_period_us").read_text().strip()
        if quota in ("max", "-1"):
            return None
        share = int(quota) / int(period)
    except (OSError, ValueError, ZeroDivisionError):
        return None
    return share if share > 0 else None


def count() -> int:
    """Threads a batch of this process runs on (module docstring)."""
    return _chosen if _chosen is not None else cores()


def set_count(threads: int | None) -> None:
    """Run this process' batches on ``threads`` threads (``None``: one per core)."""
    global _chosen
    if threads is not None and threads < 1:
        raise ValueError(f"threads must be at least 1, not {threads}")
    _chosen = threads


@contextlib.contextmanager
def using(threads: int | None) -> Iterator[None]:
    """:func:`set_count` for the ``with`` block, then the count as it was."""
    before = _chosen
    set_count(threads)
    try:
        yield
    finally:
        set_count(before)


def spread(task: Callable[[int, int], None], items: int, *, threads: int | None = None,
           per_thread: int = CHUNKS_PER_THREAD) -> None:
    """Run ``task(start, stop)`` over contiguous chunks of ``range(items)``, about ``per_thread``
    chunks a thread, on at most ``threads`` threads at once (default :func:`count`; in this thread
    when one is enough, or when this is a pool thread already), each thread taking the next chunk
    when it is done. Every chunk is run; then the first error in chunk order is raised, or an
    :class:`ExceptionGroup` of them all when the chunks failed in different ways."""
    threads = min(count() if threads is None else threads, items)
    if threads <= 1 or getattr(_inside, "chunk", False):
        if items:
            task(0, items)
        return
    chunks = min(items, threads * per_thread)
    edges = [items * i // chunks for i in range(chunks + 1)]
    following = itertools.count()  # next() of it is atomic: each chunk is taken once
    errors: dict[int, Exception] = {}
    stopping = threading.Event()  # set on Ctrl-C or SIGTERM here: no chunk is started after it

    def runner() -> None:
        _inside.chunk = True
        try:
            while not stopping.is_set() and (i := next(following)) < chunks:
                try:
                    task(edges[i], edges[i + 1])
                except Exception as error:  # noqa: BLE001 - raised by spread once every chunk has run
                    errors[i] = error
        finally:
            _inside.chunk = False

    try:
        for future in [_executor(threads).submit(runner) for _ in range(threads)]:
            future.result()
    except BaseException:  # KeyboardInterrupt, as the command line raises SIGTERM too: the chunks running end
        stopping.set()
        raise
    failed = [errors[i] for i in sorted(errors)]
    if failed and all(type(error) is type(failed[0]) for error in failed):
        raise failed[0]
    if failed:
        raise ExceptionGroup(f"{len(failed)} of {chunks} chunks failed", failed)


def _executor(threads: int) -> ThreadPoolExecutor:
    """This process' pool, of at least ``threads`` threads (made on first use, or anew larger)."""
    global _pool
    with _lock:
        if _pool is None or _pool[0] < threads:
            old, _pool = _pool, (threads, ThreadPoolExecutor(max_workers=threads, thread_name_prefix="fuzzynav"))
            if old is not None:
                old[1].shutdown(wait=False)  # its threads end once idle
        return _pool[1]


def _join() -> None:
    """End the pool's threads before a fork (not from one of them, which cannot join itself)."""
    global _pool
    with _lock:
        old, _pool = _pool, None
    if old is not None:
        old[1].shutdown(wait=not getattr(_inside, "chunk", False))


if hasattr(os, "register_at_fork"):  # not on Windows, which does not fork
    os.register_at_fork(before=_join)
