"""The cores of one process for compiled kernels that release the GIL (``@jit(nogil=True)``).

A batch of independent items — the jobs of a tuning generation (:mod:`fuzzynav.tune.episodes`),
each one robot on one world — is cut into contiguous chunks that a pool of threads runs, each
chunk one kernel call writing its own rows of the output. Items do not share state, so the
result is the same, bit for bit, for any number of threads.

:func:`count` is how many threads a process uses: one per core it may run on, unless
:func:`set_count` said otherwise (``fuzzynav tune --workers N``). The workers of a process pool
(:func:`fuzzynav.bench.backends.pool_map`) use one each, since the pool already spreads its work
over the cores. The thread pool is made on first use and joined before the process forks (a fork
copies no thread of it half-way; parent and child each make a new one when they next need it).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor

CHUNKS_PER_THREAD = 8  # chunks cut per thread, so that a thread done early takes the next one
_chosen: int | None = None
_pool: tuple[int, ThreadPoolExecutor] | None = None  # (its threads, the pool)


def cores() -> int:
    """The cores this process may run on."""
    try:
        return len(os.sched_getaffinity(0)) or 1
    except AttributeError:  # macOS, Windows
        return os.cpu_count() or 1


def count() -> int:
    """Threads a batch of this process runs on (module docstring)."""
    return _chosen if _chosen is not None else cores()


def set_count(threads: int | None) -> None:
    """Run this process' batches on ``threads`` threads (``None``: one per core)."""
    global _chosen
    if threads is not None and threads < 1:
        raise ValueError(f"threads must be at least 1, not {threads}")
    _chosen = threads


def spread(task: Callable[[int, int], None], items: int, *, threads: int | None = None,
           per_thread: int = CHUNKS_PER_THREAD) -> None:
    """Run ``task(start, stop)`` over contiguous chunks of ``range(items)``, ``per_thread`` chunks
    a thread, on ``threads`` threads (default :func:`count`; in this thread when one is enough);
    the first error of a chunk is raised after every chunk has ended."""
    threads = min(count() if threads is None else threads, items)
    if threads <= 1:
        if items:
            task(0, items)
        return
    chunks = min(items, threads * per_thread)
    edges = [items * i // chunks for i in range(chunks + 1)]
    pool = _executor(max(threads, count()))
    futures = [pool.submit(task, start, stop) for start, stop in zip(edges, edges[1:])]
    errors = [future.exception() for future in futures]
    for error in errors:
        if error is not None:
            raise error


def _executor(threads: int) -> ThreadPoolExecutor:
    """This process' pool, of at least ``threads`` threads (made on first use, or anew larger):
    a batch of fewer chunks than threads keeps the others idle."""
    global _pool
    if _pool is None or _pool[0] < threads:
        _join()
        _pool = (threads, ThreadPoolExecutor(max_workers=threads, thread_name_prefix="fuzzynav"))
    return _pool[1]


def _join() -> None:
    """End the pool's threads (before a fork, or to make one of another size)."""
    global _pool
    if _pool is not None:
        _pool[1].shutdown(wait=True)
    _pool = None


if hasattr(os, "register_at_fork"):  # not on Windows, which does not fork
    os.register_at_fork(before=_join)
