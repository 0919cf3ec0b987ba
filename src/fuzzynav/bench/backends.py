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

import os
from collections.abc import Callable, Sequence
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait

from fuzzynav.bench.cells import Cell, run_cell
from fuzzynav.errors import InputError

BACKENDS = ("local", "ray")


def _local(cells: Sequence[Cell], workers: int, on_rows: Callable[[list[dict]], None]) -> None:
    if workers == 1:
        for cell in cells:
            on_rows(run_cell(cell))
        return
    with ProcessPoolExecutor(max_workers=workers) as pool:
        pending = set()
        queue = iter(cells)
        for cell in queue:  # keep a bounded window in flight: memory stays flat on long campaigns
            pending.add(pool.submit(run_cell, cell))
            if len(pending) >= 4 * workers:
                break
        while pending:
            done, pending = wait(pending, return_when=FIRST_COMPLETED)
            for future in done:
                on_rows(future.result())
                following = next(queue, None)
                if following is not None:
                    pending.add(pool.submit(run_cell, following))


def _ray(cells: Sequence[Cell], workers: int, on_rows: Callable[[list[dict]], None], address: str | None) -> None:
    try:
        import ray
    except ImportError:
        raise InputError("the ray backend needs Ray: pip install 'fuzzynav[cluster]'", field="--backend") from None
    address = address or os.environ.get("RAY_ADDRESS")
    started = not ray.is_initialized()
    if started:
        options = {"address": address} if address else {"num_cpus": workers, "include_dashboard": False}
        ray.init(log_to_driver=False, **options)
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
        _local(cells, workers, on_rows)
    elif backend == "ray":
        _ray(cells, workers, on_rows, address)
    else:
        raise InputError(f"unknown backend {backend!r} (known: {', '.join(BACKENDS)})", field="--backend")
