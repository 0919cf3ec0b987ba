"""Where the cells run: a local process pool (default) or Ray tasks (``fuzzynav[cluster]``).

Both run :func:`fuzzynav.bench.cells.run_cell` on the same cells and hand each cell's rows to
``on_rows`` as it finishes; the campaign writes them in a fixed order at the end, so the final
files do not depend on the backend or on the order in which cells finished.

- ``local``: ``workers`` = 1 runs in this process; more, a :class:`ProcessPoolExecutor` whose
  workers keep their imports and caches from one cell to the next.
- ``ray``: ``ray.init(address=…)`` joins a running cluster (``--ray-address`` or the
  ``RAY_ADDRESS`` environment variable), else starts a local instance with ``workers`` CPUs;
  each cell is one Ray task.
"""

from __future__ import annotations

import contextlib
import ctypes
import multiprocessing
import os
import signal
import socket
import sys
import threading
from collections.abc import Callable, Iterator, Sequence
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from typing import Any

from fuzzynav import threads
from fuzzynav.bench.cells import Cell, run_cell
from fuzzynav.errors import InputError

BACKENDS = ("local", "ray")


FORKED = sys.platform == "linux"  # pool_map's workers start as copies of this process (else afresh)
PR_SET_PDEATHSIG = 1  # prctl(2): the signal a process gets when its parent dies
STOPS = {signal.SIGINT, signal.SIGTERM}  # the signals that stop a command (Ctrl-C, and a kill's)


@contextlib.contextmanager
def _stops_deferred() -> Iterator[None]:
    """Ctrl-C and SIGTERM noted, not raised, while this process forks the pool's workers, and
    raised again on leaving. Raised during the fork, their exception would be ignored by the
    at-fork handlers (Python prints it and runs on: the command would not stop), and a worker
    forked in that instant would print a traceback before :func:`_worker_start` sets its own
    handling (such a worker leaves Ctrl-C to this process and ends on SIGTERM, as it will after).
    Python sets handlers in its main thread only: elsewhere, nothing is deferred; nor where a
    handler was set outside Python (it could not be put back)."""
    if threading.current_thread() is not threading.main_thread() or None in map(signal.getsignal, STOPS):
        yield
        return
    here = os.getpid()
    noted: list[int] = []

    def note(number: int, frame: object) -> None:
        if os.getpid() == here:
            noted.append(number)
        elif number == signal.SIGTERM:
            signal.signal(number, signal.SIG_DFL)
            os.kill(os.getpid(), number)

    before: dict = {}
    try:
        for stop in STOPS:
            before[stop] = signal.signal(stop, note)
        yield
    finally:
        _put_back(before)
        if noted:
            signal.raise_signal(noted[0])


def _put_back(handlers: dict) -> None:
    """Set every signal's handler of ``handlers`` again; one that a handler put back raises in the
    meantime (a Ctrl-C just after its own) is raised once all are back, so none stays deferred."""
    error: BaseException | None = None
    for stop, handler in handlers.items():
        for _ in range(3):  # a signal's exception interrupts a try at most once or twice; no endless retry
            if signal.getsignal(stop) is handler:
                break
            try:
                signal.signal(stop, handler)
            except BaseException as raised:  # raised again below, once the others are back
                error = error or raised
    if error is not None:
        raise error


def _worker_start(parent: int, interrupts: bool, initializer: Callable | None, initargs: tuple) -> None:
    """A pool worker's start: one thread for its batches (the pool spreads the work over the
    cores, :mod:`fuzzynav.threads`); a SIGTERM ending it at once; Ctrl-C left to the process
    ``parent`` when ``interrupts`` (its main thread runs the pool and stops it, :func:`_stop`);
    on Linux a SIGTERM when that process dies (killed, the worker would wait for tasks forever);
    then ``initializer(*initargs)``."""
    threads.set_count(1)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    if interrupts:
        signal.signal(signal.SIGINT, signal.SIG_IGN)
    if sys.platform == "linux":
        with contextlib.suppress(AttributeError, OSError):  # no prctl: the worker outlives a killed parent
            ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGTERM)
        if os.getppid() != parent:  # the parent died before the request was made
            os._exit(1)
    if initializer is not None:
        initializer(*initargs)


def _stop(pool: ProcessPoolExecutor) -> None:
    """End ``pool`` now, on Ctrl-C or SIGTERM in this process: drop the tasks not started and
    terminate the workers (their tasks are lost; what they saved atomically is whole or absent);
    then wait for the pool's manager thread, which closes the pool's pipes: left running, it
    could close one while the interpreter's exit writes to it (``OSError: Bad file descriptor``)."""
    workers = list((getattr(pool, "_processes", None) or {}).values())
    manager = getattr(pool, "_executor_manager_thread", None)
    pool.shutdown(wait=False, cancel_futures=True)
    for worker in workers:
        worker.terminate()
    for worker in workers:
        worker.join(timeout=5.0)
    if manager is not None:
        manager.join(timeout=5.0)


def _shut(pool: ProcessPoolExecutor, *, cancel: bool) -> None:
    """Shut ``pool`` down, waiting for its tasks running (and those queued, unless ``cancel``);
    a Ctrl-C or SIGTERM during the wait stops it at once (:func:`_stop`)."""
    try:
        pool.shutdown(wait=True, cancel_futures=cancel)
    except KeyboardInterrupt:
        _stop(pool)
        raise


def pool_map(task: Callable, items: Sequence, workers: int, on_result: Callable[[int, Any], None], *,
             initializer: Callable | None = None, initargs: tuple = ()) -> None:
    """Run ``task(item)`` for every item, in this process (``workers`` = 1) or in a pool of
    ``workers`` processes whose ``initializer(*initargs)`` runs once each; ``on_result(index,
    result)`` per finished item, in the order they finish. A bounded window of items is in flight,
    so memory stays flat on long runs. When an item fails, the items not yet started are dropped,
    those running are waited for (their results still go to ``on_result``), and then the first
    error is raised. Where :data:`FORKED` (Linux) the workers are forked: they start with this
    process' imports, registries and loaded kernels."""
    if workers == 1:
        if initializer is not None:
            initializer(*initargs)
        for index, item in enumerate(items):
            on_result(index, task(item))
        return
    context = multiprocessing.get_context("fork" if FORKED else "spawn")
    here = threading.current_thread() is threading.main_thread()  # where Ctrl-C is raised
    pool = ProcessPoolExecutor(max_workers=workers, mp_context=context, initializer=_worker_start,
                               initargs=(os.getpid(), here, initializer, initargs))
    try:
        _run_in(pool, task, items, workers, on_result)
    except KeyboardInterrupt:  # Ctrl-C, or SIGTERM as the command line raises it
        _stop(pool)
        raise
    except BaseException:  # a result that could not be handled: the tasks queued are dropped
        _shut(pool, cancel=True)
        raise
    _shut(pool, cancel=False)


def _run_in(pool: ProcessPoolExecutor, task: Callable, items: Sequence, workers: int,
            on_result: Callable[[int, Any], None]) -> None:
    """:func:`pool_map`'s loop over ``pool``."""
    queue = enumerate(items)
    pending: dict = {}
    failure: BaseException | None = None
    with _stops_deferred():  # the first submission forks the workers
        for index, item in queue:
            pending[pool.submit(task, item)] = index
            if len(pending) >= 4 * workers:
                break
    while pending:
        done, _ = wait(pending, return_when=FIRST_COMPLETED)
        for future in done:
            index = pending.pop(future)
            if future.cancelled():
                continue
            if future.exception() is not None:
                if failure is None:
                    failure = future.exception()
                    for waiting in pending:  # the running ones cannot be cancelled: they end
                        waiting.cancel()
                continue
            on_result(index, future.result())
            following = next(queue, None) if failure is None else None
            if following is not None:
                pending[pool.submit(task, following[1])] = following[0]
    if failure is not None:
        raise failure


def ray_address(address: str | None) -> str | None:
    """The Ray cluster to join: ``address`` (``--ray-address``), else ``$RAY_ADDRESS``, else None
    (a local instance); refused, before any run, when Ray would misread it or wait on it: the
    forms are ``auto``, ``local``, ``HOST:PORT`` and ``ray://HOST:PORT``, and a HOST:PORT must
    answer within 5 s (Ray itself keeps retrying an address nobody answers at)."""
    if address is not None and not address.strip():  # was read as none: $RAY_ADDRESS or a local instance
        raise InputError("is empty: give HOST:PORT, ray://HOST:PORT, auto or local, or leave it out",
                         field="--ray-address")
    field = "--ray-address" if address else "RAY_ADDRESS"
    address = address or os.environ.get("RAY_ADDRESS") or None
    if address is None or address in ("auto", "local"):
        return address
    host, colon, port = address.removeprefix("ray://").rpartition(":")
    if not (colon and host and port.isascii() and port.isdigit() and 0 < int(port) < 65536):
        raise InputError(f"must be HOST:PORT, ray://HOST:PORT, auto or local, got {address!r}", field=field)
    try:
        socket.create_connection((host.strip("[]"), int(port)), timeout=5.0).close()
    except OSError as error:
        raise InputError(f"no Ray cluster answers at {address} ({error.strerror or error})", field=field) from None
    return address


def _ray(cells: Sequence[Cell], workers: int, on_rows: Callable[[list[dict]], None], address: str | None) -> None:
    try:
        import ray
    except ImportError:
        raise InputError("the ray backend needs Ray: pip install -e '.[cluster]' in the clone", field="--backend") from None
    address = ray_address(address)
    started = not ray.is_initialized()
    if started:
        options = {"address": address} if address else {"num_cpus": workers, "include_dashboard": False}
        handler = signal.getsignal(signal.SIGTERM)
        try:
            ray.init(log_to_driver=False, **options)
        except (ValueError, ConnectionError) as error:  # e.g. "auto" with no cluster running
            raise InputError(f"Ray could not start or join a cluster: {error}", field="--ray-address") from None
        if threading.current_thread() is threading.main_thread():
            signal.signal(signal.SIGTERM, handler)  # ray.init puts its own (an exit with status 15)
    try:
        task = ray.remote(run_cell)
        pending = [task.remote(cell) for cell in cells]
        while pending:
            done, pending = ray.wait(pending, num_returns=1)
            on_rows(ray.get(done[0]))
    finally:
        if started:
            ray.shutdown()


def execute(cells: Sequence[Cell], on_rows: Callable[[list[dict]], None], *, backend: str = "local",
            workers: int = 1, address: str | None = None) -> None:
    """Run every cell on ``backend`` with ``workers`` processes; ``on_rows(rows)`` per finished cell."""
    if backend == "local":
        pool_map(run_cell, cells, workers, lambda _, rows: on_rows(rows))
    elif backend == "ray":
        _ray(cells, workers, on_rows, address)
    else:
        raise InputError(f"unknown backend {backend!r} (known: {', '.join(BACKENDS)})", field="--backend")
