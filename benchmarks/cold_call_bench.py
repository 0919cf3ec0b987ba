"""What a call costs right after another engine's batch, against the same call back to back.

    python benchmarks/cold_call_bench.py FUZZYLITE/examples/takagi-sugeno/matlab/juggler.fll

Run in a Python with both fuzzynav and pyfuzzylite (the ``.venv-fll`` of ``.ci/run``). For the
engine of the FLL file: the median time (CPU clock, microseconds) of fuzzynav's ``evaluate`` on
10 and on 10,000 random inputs, of an empty compiled function of one array and of as many arrays
as the fused kernel takes, and of ``np.empty`` —
each back to back ("warm") and right after pyfuzzylite evaluates 10,000 rows ("after the peer").
This is the cost that ``fuzzy_bench.py --examples`` pays once a sample with ``--calls 1``: both
engines pay it, and it weighs most on the fastest calls (README, "Speed on fuzzylite's examples").
"""

from __future__ import annotations

import functools
import statistics
import sys
import time

import numba
import numpy as np

from fuzzynav.cli import Parser
from fuzzynav.errors import InputError
from fuzzynav.fuzzy.io.fll import from_fll_engine


def _inputs(engine, n: int, rng) -> np.ndarray:
    return np.column_stack([rng.uniform(v.minimum, v.maximum, n) if np.isfinite(v.maximum - v.minimum)
                            else rng.uniform(-1.0, 1.0, n) for v in engine.inputs])


def main(argv=None) -> int:
    parser = Parser(description=__doc__.split("\n\n")[0])
    parser.add_argument("fll", help="an FLL engine (e.g. one of fuzzylite's examples)")
    parser.add_argument("--repeats", type=int, default=21, help="samples of each timing (default 21)")
    args = parser.parse_args(argv)
    if args.repeats < 1:
        parser.error("--repeats must be at least 1")
    try:
        import fuzzylite as fl
    except ImportError:
        parser.error("pyfuzzylite is not importable here: run this in a Python that has it (e.g. .venv-fll)")
    try:
        text = open(args.fll, encoding="utf-8").read()
        ours = from_fll_engine(text, source=args.fll)
    except (OSError, UnicodeDecodeError, InputError) as error:
        parser.error(f"{args.fll}: {error}")
    theirs = fl.FllImporter().from_string(text)
    rng = np.random.default_rng(0)
    peer_batch = _inputs(ours, 10_000, rng)

    def peer():
        theirs.input_values = peer_batch
        theirs.process()

    calls = {f"fuzzynav evaluate, {n:,} rows": functools.partial(ours.evaluate, _inputs(ours, n, rng)) for n in (10, 10_000)}
    ours.evaluate(peer_batch[:1])
    arguments = [peer_batch, *ours._packed[1]]  # the fused kernel's 38 arrays (it is handed them as 4), on an empty function
    namespace: dict = {}
    exec(f"def nothing({', '.join(f'a{i}' for i in range(len(arguments)))}): return 0", namespace)
    one_argument, every_argument = numba.njit(lambda a: 0), numba.njit(namespace["nothing"])
    calls["compiled function of one argument"] = lambda: one_argument(peer_batch)
    calls[f"the same of {len(arguments)} arrays"] = lambda: every_argument(*arguments)
    calls["np.empty((10, 1))"] = lambda: np.empty((10, 1))
    print(f"{args.fll}: median of {args.repeats}, CPU clock, µs")
    for label, call in calls.items():
        call()
        warm, cold = [], []
        for _ in range(args.repeats):
            t0 = time.process_time()
            call()
            warm.append(time.process_time() - t0)
        for _ in range(args.repeats):
            peer()
            t0 = time.process_time()
            call()
            cold.append(time.process_time() - t0)
        print(f"{label:36s} warm {1e6 * statistics.median(warm):8.1f}   after the peer {1e6 * statistics.median(cold):8.1f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
