"""The learned state of a table learner (tabular Q / SARSA / Q(λ), fuzzy Q-learning, §III.4,
Algorithm VI.1) read back from a file: its quality table ``q``, the visit counts behind the
1/(1+visits) learning rate (eq III.24) and its episode count.

Checkpoints (:mod:`fuzzynav.learn.checkpoint`) and the learners' ``from_dict`` share
:func:`restore_state`: a table that is not numeric, not of the learner's shape or not finite, or a
negative visit count, is
an :class:`~fuzzynav.errors.InputError` naming the field — a damaged file never resumes
training from NaN qualities.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.errors import InputError


def episode_count(value, source: str | None, field: str) -> int:
    """An episode count read from a file: a non-negative integer (not a bool, not a float)."""
    if isinstance(value, bool) or not isinstance(value, int) or value < 0:
        raise InputError(f"must be a non-negative integer, got {value!r}", source=source, field=field)
    return value


def state_array(saved: dict, name: str, shape: tuple, source: str | None) -> np.ndarray:
    """The table ``saved[name]`` as floats: numbers only, finite, of the learner's ``shape``."""
    try:
        values = np.asarray(saved[name], dtype=float)
    except (KeyError, TypeError, ValueError):
        raise InputError(f"must be a table of numbers of shape {shape}", source=source,
                         field=f"learner.{name}") from None
    if values.shape != shape:
        raise InputError(f"table shape {values.shape} does not match {shape}", source=source, field=f"learner.{name}")
    if not np.isfinite(values).all():
        raise InputError("holds NaN or infinite values", source=source, field=f"learner.{name}")
    return values


def restore_state(learner, saved: dict, source: str | None = None) -> None:
    """Put the learned state of ``saved`` (a learner's ``to_dict()``: tables ``q``, ``visits`` of
    the learner's shape, finite, the visits not negative, and its ``episode`` count, 0 when absent)
    into ``learner``."""
    q = state_array(saved, "q", learner.q.shape, source)
    visits = state_array(saved, "visits", learner.q.shape, source)
    if (visits < 0).any():  # 1 / (1 + visits) would be negative or, at −1, infinite: NaN qualities
        raise InputError("visit counts must not be negative", source=source, field="learner.visits")
    learner.episode = episode_count(saved.get("episode", 0), source, "learner.episode")
    learner.q, learner.visits = q, visits
