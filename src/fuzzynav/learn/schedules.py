"""Schedules for exploration parameters and learning rates (thesis §III.4.9.1, eq III.24).

A schedule maps a counter ``t`` (a scalar episode index, or an array of visit counts) to a value;
every schedule is vectorised over ``t``. Exploration parameters (ε, τ) are functions of the episode
index; the learning rate β is either a function of the episode index or, for
:class:`InverseVisits`, of the number of updates already applied to each (state, action) pair
(eq III.24: β = 1 / (1 + visits), which satisfies Σβ = ∞, Σβ² < ∞ — the convergence conditions
of TD(0) and Q-learning quoted in §III.4.9.1 [WAT89, SUT98]).

The thesis counts the visits "since the start of the episode"; counting them since the start of
learning, as here, is what the quoted convergence conditions require (a per-episode count would
reset β to 1 every episode).

Schedules are plain dataclasses; :func:`schedule_to_dict` / :func:`schedule_from_dict` make them
JSON-safe for checkpoints.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass
from typing import ClassVar

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError


@dataclass(frozen=True)
class Constant:
    """β, ε or τ fixed for the whole run."""

    value: float
    kind: ClassVar[str] = "constant"
    per_visit: ClassVar[bool] = False

    def __post_init__(self):
        validation.number(self.value, field="value", lo=0.0)

    @property
    def peak(self) -> float:
        """The largest value it takes."""
        return float(self.value)

    def __call__(self, t):
        return np.full(np.shape(t), float(self.value)) if np.ndim(t) else float(self.value)


@dataclass(frozen=True)
class ExponentialDecay:
    """``max(floor, start · rate**t)`` — the usual decaying ε (§III.4.10) or learning rate."""

    start: float
    rate: float
    floor: float = 0.0
    kind: ClassVar[str] = "exponential"
    per_visit: ClassVar[bool] = False

    def __post_init__(self):
        validation.number(self.rate, field="rate", lo=0.0, lo_open=True, hi=1.0)
        validation.number(self.start, field="start", lo=0.0)
        validation.number(self.floor, field="floor", lo=0.0, hi=self.start)

    @property
    def peak(self) -> float:
        """The largest value it takes (at t = 0)."""
        return float(self.start)

    def __call__(self, t):
        return np.maximum(self.floor, self.start * np.power(self.rate, t))


@dataclass(frozen=True)
class InverseVisits:
    """Eq III.24: ``scale / (1 + visits)**power`` per (state, action) pair, at least ``floor``.

    ``power`` = 1 is eq III.24; any power in (0.5, 1] keeps Σβ = ∞, Σβ² < ∞ and converges much
    faster with a discounted bootstrap (polynomial rates, Even-Dar & Mansour 2003).
    """

    scale: float = 1.0
    power: float = 1.0
    floor: float = 0.0
    kind: ClassVar[str] = "inverse_visits"
    per_visit: ClassVar[bool] = True

    def __post_init__(self):
        validation.number(self.power, field="power", lo=0.5, lo_open=True, hi=1.0)
        validation.number(self.scale, field="scale", lo=0.0, lo_open=True)
        validation.number(self.floor, field="floor", lo=0.0, hi=self.scale)

    @property
    def peak(self) -> float:
        """The largest value it takes (before any visit)."""
        return float(self.scale)

    def __call__(self, visits):
        rate = self.scale / np.power(1.0 + np.asarray(visits, dtype=float), self.power)
        return np.maximum(self.floor, rate)


Schedule = Constant | ExponentialDecay | InverseVisits
SCHEDULES = {cls.kind: cls for cls in (Constant, ExponentialDecay, InverseVisits)}


def as_schedule(value, field: str = "schedule") -> Schedule:
    """A schedule from a schedule, a number (→ :class:`Constant`) or a dict (checkpoint form)."""
    if isinstance(value, tuple(SCHEDULES.values())):
        return value
    if isinstance(value, dict):
        return schedule_from_dict(value, field)
    if isinstance(value, (int, float, np.floating, np.integer)) and not isinstance(value, bool):
        try:
            return Constant(float(value))
        except InputError as error:
            raise InputError(error.problem, field=field) from None
    raise InputError(f"expected a number or a schedule, got {value!r}", field=field)


def share_schedule(value, field: str) -> Schedule:
    """:func:`as_schedule` for a value that is a share of something — a probability ε or a
    learning rate β — so never above 1."""
    schedule = as_schedule(value, field)
    if schedule.peak > 1.0:
        raise InputError(f"must stay within [0, 1], but starts at {schedule.peak!r}", field=field)
    return schedule


def schedule_to_dict(schedule: Schedule) -> dict:
    """JSON-safe form ``{"kind": ..., parameters...}``."""
    return {"kind": schedule.kind, **asdict(schedule)}


def schedule_from_dict(document: dict, field: str = "schedule") -> Schedule:
    """Inverse of :func:`schedule_to_dict`."""
    parameters = dict(document)
    kind = parameters.pop("kind", None)
    if kind not in SCHEDULES:
        raise InputError(f"unknown schedule kind {kind!r}; known: {', '.join(SCHEDULES)}", field=field)
    try:
        return SCHEDULES[kind](**parameters)
    except TypeError as error:
        raise InputError(f"bad parameters for schedule {kind!r} ({error})", field=field) from None
    except InputError as error:
        raise InputError(error.problem, field=f"{field}.{error.field}") from None
