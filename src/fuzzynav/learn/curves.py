"""Learning curves: smoothing and the "episodes to converge" criterion (Table VI.1, Figs VI.1–VI.16).

The thesis reads convergence off its plots of the mean reinforcement per episode ("from episode
1000 the robot converges", Fig VI.1; Table VI.1) without a definition. A criterion that compares
the curve with the level of its *last* episodes answers "near the end of whatever budget was
given" (a longer run has more late noise to leave a band and a later plateau to approach). The
criterion here looks only a fixed distance ahead, so its answer does not depend on the budget:

- m_j is the trailing mean of the curve over ``window`` (W) episodes ending at episode j, judged
  at the ends of the training batches only (``batch`` B episodes run in parallel with the same
  knowledge, so the order of episodes inside a batch means nothing; the count is the number of
  episodes experienced, a multiple of B);
- for a candidate episode k, the *plateau* P_k is the mean of the raw curve over the ``hold`` (H)
  episodes that follow k, and the *band* is ``tolerance`` (5 %) of the larger of |P_k| ("within
  5 % of the plateau") and the distance the curve travelled, |P_k − m_0| (m_0: the first
  window's mean; the travel keeps the band meaningful for a plateau near 0 or of either sign),
  but at least ``noise`` (3) standard errors σ_k / √W of a window's mean (σ_k: standard
  deviation of the raw curve over the hold) — a band narrower than the noise of the smoothed
  curve could never be met by a settled curve of a task with random starts. The standard error
  assumes independent episodes; when the episodes of a batch share one random world
  (``clustered``), their rewards are correlated — the world sets the level of all B of them — and
  the independent samples are the batches: σ_k is then the standard deviation of the *batch
  means* over the hold and a window's mean has W / B of them (standard error σ_k / √(W / B));
- the curve has converged at episode k when every m_j, j = k, k + B, …, k + H, lies within
  P_k ± band — and, if a ``success`` curve (one 0/1 per episode) is given, the success rate over
  the hold is at least ``target`` (95 %): the task is solved while still exploring, not merely
  stuck on a plateau of failures;
- :func:`episodes_to_converge` returns the first such k (1-based: the episodes needed), or
  ``len(curve) + 1`` if no k ≤ len(curve) − H qualifies (not settled within the budget).

The answer depends on the first k + H episodes only: training longer (same seed, schedules that
do not know the budget) cannot change it. A curve that sits at its plateau from the start
converges at its first full window (k = W).
"""

from __future__ import annotations

import numpy as np
from numpy.lib.stride_tricks import sliding_window_view

from fuzzynav.errors import InputError

WINDOW = 50  # episodes of the trailing mean
HOLD_WINDOWS = 10  # default hold H = 10 W
TOLERANCE = 0.05
NOISE = 3.0  # standard errors of a window's mean
TARGET_SUCCESS = 0.95


def records(curve: dict, field: str = "mean_reward", head: int | None = None) -> np.ndarray:
    """One field of a :func:`fuzzynav.learn.checkpoint.train_loop` curve as an array (batches, B).

    Rows of a batch are independent learners (seeds) or, for a shared learner, consecutive
    episodes (flatten with ``.ravel()`` to get them in order). ``head`` picks one reward column
    of a multi-head learner (default: the mean over heads).
    """
    if field not in curve:
        raise InputError(f"no {field!r} in the curve (has {', '.join(curve)})", field=field)
    values = np.asarray(curve[field], dtype=float)
    if values.ndim == 3:
        values = values.mean(axis=2) if head is None else values[:, :, head]
    return values


def _curve(values, field: str = "curve") -> np.ndarray:
    values = np.asarray(values, dtype=float)
    if values.ndim != 1:
        raise InputError(f"a curve must be 1-D, got shape {values.shape}", field=field)
    return values


def _count(value, field: str) -> int:
    if int(value) != value or value < 1:
        raise InputError(f"must be a positive integer, got {value!r}", field=field)
    return int(value)


def moving_average(values, window: int) -> np.ndarray:
    """Trailing mean over ``window`` episodes (the first entries average what exists so far)."""
    values = _curve(values)
    window = _count(window, "window")
    cumulative = np.concatenate([[0.0], np.cumsum(values)])
    index = np.arange(1, values.size + 1)
    lower = np.maximum(index - window, 0)
    return (cumulative[index] - cumulative[lower]) / (index - lower)


def episodes_to_converge(values, window: int = WINDOW, tolerance: float = TOLERANCE, *, hold: int | None = None,
                         batch: int = 1, success=None, target: float = TARGET_SUCCESS,
                         noise: float = NOISE, clustered: bool = False) -> int:
    """Episodes needed for the smoothed curve to settle on the plateau that follows (module docstring)."""
    values = _curve(values)
    if values.size == 0:
        raise InputError("the learning curve is empty", field="curve")
    if not 0 < tolerance < 1:
        raise InputError(f"must be in (0, 1), got {tolerance}", field="tolerance")
    window, batch = _count(window, "window"), _count(batch, "batch")
    hold = _count(HOLD_WINDOWS * window if hold is None else hold, "hold")
    if window % batch or hold % batch:
        raise InputError(f"window {window} and hold {hold} must be multiples of the batch {batch}", field="batch")
    n = values.size
    ends = np.arange(window, n + 1, batch)  # batch ends with a full window
    steps = hold // batch
    if ends.size <= steps:
        return n + 1
    smooth = moving_average(values, window)[ends - 1]
    start = smooth[0]
    candidates = ends[: ends.size - steps]
    cumulative = np.concatenate([[0.0], np.cumsum(values)])
    squares = np.concatenate([[0.0], np.cumsum(values**2)])
    level = (cumulative[candidates + hold] - cumulative[candidates]) / hold
    if clustered:  # the batch means are the independent samples; σ from their successive differences
        if steps < 2:
            raise InputError(f"a clustered hold needs at least 2 batches, got {hold} episodes", field="hold")
        means = values[: n - n % batch].reshape(-1, batch).mean(axis=1)
        jumps = np.concatenate([[0.0], np.cumsum(np.diff(means) ** 2)])
        first = candidates // batch
        spread = np.sqrt((jumps[first + steps - 1] - jumps[first]) / (2 * (steps - 1)))
        samples = window // batch
    else:
        spread = np.sqrt(np.maximum((squares[candidates + hold] - squares[candidates]) / hold - level**2, 0.0))
        samples = window
    scale = np.maximum(np.abs(level), np.abs(level - start))
    band = np.maximum.reduce([tolerance * scale, noise * spread / np.sqrt(samples),
                              np.full(level.shape, 1e-9 * (1.0 + np.abs(level).max()))])  # ≥ rounding
    ahead = sliding_window_view(smooth, steps + 1)  # m_k, m_{k+B}, …, m_{k+H} of every candidate
    settled = (np.abs(ahead - level[:, None]) <= band[:, None]).all(axis=1)
    if success is not None:
        success = _curve(success, "success")
        if success.size != n:
            raise InputError(f"{success.size} success records for {n} rewards", field="success")
        solved = np.concatenate([[0.0], np.cumsum(success)])
        settled &= (solved[candidates + hold] - solved[candidates]) / hold >= target
    found = np.flatnonzero(settled)
    return int(candidates[found[0]]) if found.size else n + 1
