"""Strong fuzzy partitions (thesis §IV.3): Σ_i μ_i(x) = 1 at every point of the universe.

The thesis builds every input of its controllers the same way (Figs IV.5, IV.6, IV.10, V.4,
V.5): triangles between ordered peaks, the two outer sets open shoulders. With such a partition
at most two sets are non-zero at any x, and the TS0 output (IV.4) needs no division.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from fuzzynav.fuzzy.membership import Triangular
from fuzzynav.fuzzy.variable import Variable


def strong_partition(peaks: Sequence[float], labels: Sequence[str], universe=None) -> dict[str, Triangular]:
    """Triangular sets peaking at ``peaks`` (strictly increasing), outer sets open shoulders.

    Set i rises from peak i−1 to peak i and falls to peak i+1; the first set is 1 for every
    x ≤ peaks[0] (``Triangular(-inf, p0, p1)``), the last 1 for every x ≥ peaks[-1]. If
    ``universe`` is given, every peak must lie inside it. Returns ``{label: mf}`` in order, ready
    for :class:`Variable`.
    """
    peaks = [float(p) for p in peaks]
    labels = list(labels)
    if len(peaks) != len(labels):
        raise ValueError(f"{len(peaks)} peaks for {len(labels)} labels")
    if len(peaks) < 2:
        raise ValueError("a strong partition needs at least two sets")
    if any(not math.isfinite(p) for p in peaks) or any(b <= a for a, b in zip(peaks, peaks[1:])):
        raise ValueError(f"peaks must be finite and strictly increasing, got {peaks}")
    if universe is not None:
        lo, hi = universe
        outside = [p for p in peaks if not lo <= p <= hi]
        if outside:
            raise ValueError(f"peaks {outside} outside the universe {tuple(universe)}")
    n = len(peaks)
    left = [-math.inf] + peaks[:-1]
    right = peaks[1:] + [math.inf]
    return {labels[i]: Triangular(left[i], peaks[i], right[i]) for i in range(n)}


@dataclass
class PartitionReport:
    """Result of :func:`check_strong_partition`."""

    variable: str
    strong: bool
    max_deviation: float  # max over the samples of |Σμ − 1|
    problems: list[str] = field(default_factory=list)  # one line per interval where Σμ ≠ 1

    def __bool__(self) -> bool:
        return self.strong


def _sample_points(variable: Variable, n_dense: int) -> np.ndarray:
    lo, hi = variable.universe
    points = [np.linspace(lo, hi, n_dense)]
    for mf in variable.terms.values():
        bps = mf.breakpoints()
        if bps:
            bps = np.asarray(bps)
            points.append(bps)
            points.append(np.nextafter(bps, -np.inf))
            points.append(np.nextafter(bps, np.inf))
    x = np.unique(np.concatenate(points))
    return x[(x >= lo) & (x <= hi)]


def check_strong_partition(variable: Variable, *, atol: float = 1e-9, n_dense: int = 2001) -> PartitionReport:
    """Check Σμ = 1 over ``variable``'s universe; report every interval where it fails.

    Samples a dense grid plus every breakpoint of the piecewise-linear terms (and the floats on
    either side of it, to catch jumps). Each problem line reads
    ``"Σμ in [0.5, 0.5] on [1.0, 2.0]"`` (range of the sum over the failing run of samples).
    """
    x = _sample_points(variable, n_dense)
    total = variable.fuzzify(x, clamp=False).sum(axis=1)
    deviation = np.abs(total - 1.0)
    bad = deviation > atol
    problems = []
    if bad.any():
        edges = np.flatnonzero(np.diff(np.concatenate(([0], bad.astype(np.int8), [0]))))
        for start, stop in zip(edges[::2], edges[1::2]):
            run = total[start:stop]
            problems.append(
                f"Σμ in [{run.min():.6g}, {run.max():.6g}] on [{x[start]:.6g}, {x[stop - 1]:.6g}]"
            )
    return PartitionReport(variable.name, not problems, float(deviation.max(initial=0.0)), problems)
