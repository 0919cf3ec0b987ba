"""Nanoseconds a value of the fused kernel's exp, log and Gaussian / Bell / Sigmoid terms, against NumPy.

    python benchmarks/fuzzify_bench.py            # 10,000 values, best of 7 CPU-time runs each

The kernel's versions (:mod:`fuzzynav.fuzzy.engine.vmath`, :func:`~fuzzynav.fuzzy.engine.fuzzify_terms.term_column`)
and NumPy's (``np.exp``, ``np.log``, the NumPy formulas of :mod:`fuzzynav.fuzzy.membership`) are
timed in the same run on the same values: uniform in [−20, 20] (log: their absolute values).
Also Σ μ and Σ μ x of the centroid (:func:`~fuzzynav.fuzzy.engine.sampled_defuzzify.centroid_sums`) a
sample, over 200 samples, called from compiled code (as the kernel does).
"""

from __future__ import annotations

import time

import numpy as np

from fuzzynav.cli import Parser
from fuzzynav.fuzzy.engine import fuzzify_terms, vmath
from fuzzynav.fuzzy.engine.sampled_defuzzify import centroid_sums
from fuzzynav.fuzzy.membership import Bell, Gaussian, Sigmoid
from fuzzynav.jit import jit


def _ns(call, values: int, repeats: int) -> float:
    call()
    best = np.inf
    for _ in range(7):
        start = time.process_time()
        for _ in range(repeats):
            call()
        best = min(best, (time.process_time() - start) / repeats)
    return 1e9 * best / values


@jit
def _centroid_loop(mu, x, rounds):
    total = 0.0
    for r in range(rounds):
        mu[r % 200] += 1e-9  # a new set each round: nothing to hoist
        a, b = centroid_sums(mu, x, r % 8, 200 - r % 8)
        total += a + b
    return total


def main(argv=None) -> int:
    parser = Parser(description=__doc__.splitlines()[0])
    parser.add_argument("--values", type=int, default=10_000)
    args = parser.parse_args(argv)
    n, repeats = args.values, max(1, 2_000_000 // args.values)
    x = np.random.default_rng(0).uniform(-20.0, 20.0, n)
    positive, out = np.abs(x), np.empty(n)
    rows = [("exp", lambda: vmath.exp_column(x, out), lambda: np.exp(x, out=out)),
            ("log", lambda: vmath.log_column(positive, out), lambda: np.log(positive, out=out))]
    for name, mf in (("Gaussian", Gaussian(3.0, 0.5)), ("Bell", Bell(2.3, 1.7, 0.3)), ("Bell b=2", Bell(2.3, 2.0, 0.3)),
                     ("Sigmoid", Sigmoid(1.3, 0.5))):
        code, params, height = fuzzify_terms.pack_term(mf)
        p = np.array(params)
        rows.append((name, lambda c=code, p=p, h=height: fuzzify_terms.term_column(c, p, 0, len(p), h, x, out),
                     lambda mf=mf: mf(x)))
    print(f"ns a value over {n:,} values (CPU time, best of 7)")
    print(f"{'':<10} {'fuzzynav':>9} {'NumPy':>9}")
    for name, ours, numpy_version in rows:
        print(f"{name:<10} {_ns(ours, n, repeats):>9.2f} {_ns(numpy_version, n, repeats):>9.2f}")
    mu, at = np.zeros(200), np.linspace(0.0, 1.0, 200)
    mu[:] = np.random.default_rng(1).random(200)
    rounds = 200_000
    print(f"centroid sums: {_ns(lambda: _centroid_loop(mu, at, rounds), 200 * rounds, 1):.3f} ns a sample")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
