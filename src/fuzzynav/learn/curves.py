"""Learning curves: smoothing and the "episodes to converge" criterion (Table VI.1, Figs VI.1–VI.16).

The thesis reads convergence off its plots of the mean reinforcement per episode ("from episode
1000 the robot converges", Fig VI.1; Table VI.1) without a definition. We use the settling-time
definition of control engineering, on the trailing moving average m_k of the curve over
``window`` episodes:

- the *plateau* P is the mean of the raw curve over its last ``tail`` fraction (at least one
  window);
- the *band* is ``tolerance`` (default 5 %) of the distance the curve travelled, |P − m_0|
  (the start level m_0 is the first window's mean) — scale-free, and meaningful for rewards of
  either sign where "5 % of P" is not (P may be ≈ 0 or negative);
- the curve has converged at episode k when m stays within P ± band from k to the end;
  :func:`episodes_to_converge` returns that k counted in episodes (1-based, i.e. the number of
  episodes needed). A curve that never left its band converges at its first full window; a
  result of ``len(curve) + 1`` means the curve had not settled by its end.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.errors import InputError


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


def moving_average(values, window: int) -> np.ndarray:
    """Trailing mean over ``window`` episodes (the first entries average what exists so far)."""
    values = np.asarray(values, dtype=float)
    if values.ndim != 1:
        raise InputError(f"a curve must be 1-D, got shape {values.shape}", field="curve")
    if int(window) != window or window < 1:
        raise InputError(f"must be a positive integer, got {window!r}", field="window")
    cumulative = np.concatenate([[0.0], np.cumsum(values)])
    index = np.arange(1, values.size + 1)
    lower = np.maximum(index - int(window), 0)
    return (cumulative[index] - cumulative[lower]) / (index - lower)


def plateau(values, tail: float = 0.1, window: int = 50) -> float:
    """Mean of the last ``tail`` fraction of the curve (at least ``window`` episodes)."""
    values = np.asarray(values, dtype=float)
    count = min(values.size, max(int(window), int(np.ceil(tail * values.size))))
    return float(values[-count:].mean())


def episodes_to_converge(values, window: int = 50, tolerance: float = 0.05, tail: float = 0.1) -> int:
    """Episodes needed for the smoothed curve to settle within ``tolerance`` of its plateau."""
    values = np.asarray(values, dtype=float)
    if values.size == 0:
        raise InputError("the learning curve is empty", field="curve")
    if not 0 < tolerance < 1:
        raise InputError(f"must be in (0, 1), got {tolerance}", field="tolerance")
    smooth = moving_average(values, window)
    first_full = min(int(window), values.size) - 1
    final = plateau(values, tail, window)
    band = max(tolerance * abs(final - smooth[first_full]), 1e-9 * (1.0 + abs(final)))  # ≥ rounding
    outside = np.flatnonzero(np.abs(smooth[first_full:] - final) > band)
    return first_full + 1 if outside.size == 0 else first_full + int(outside[-1]) + 2
