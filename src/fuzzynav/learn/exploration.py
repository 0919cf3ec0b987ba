"""Exploration–exploitation policies (thesis §III.4.10, eqs III.27–III.30), vectorised.

Every policy chooses, for each row of a batch of action values ``q`` of shape ``(..., n_actions)``,
one action index, drawing randomness from an explicit :class:`numpy.random.Generator`; ``t`` is
the episode index that the policy's schedule (ε, τ) is evaluated at (:mod:`.schedules`).
Fuzzy Q-learning (Algorithm VI.1) calls the same policies with one row per rule.

- :class:`Greedy` (III.27): the best action; exact ties are broken uniformly at random, so that
  an untrained table (all zeros) does not always pick its first action.
- :class:`EpsilonGreedy` (III.28): a uniformly random action with probability ε, the greedy one
  otherwise. The thesis' text swaps the two probabilities ("greedy with probability ε") while
  calling ε = 0 a purely random choice and letting ε decay as learning proceeds; we use the
  standard convention [SUT98] that makes ε a decaying *exploration* rate.
- :class:`Softmax` (III.29): probabilities proportional to the action values. Eq III.29 is only a
  distribution for positive values, so the values of each row are shifted first:
  p ∝ Q − min_a Q + offset (offset > 0, in reward units), which keeps every action possible and
  equals III.29 up to that shift.
- :class:`Boltzmann` (III.30): p ∝ exp(Q / τ). As τ → 0 it becomes greedy and as τ → ∞ uniform;
  the thesis' sentence says the opposite, which contradicts its own equation.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.learn.schedules import (
    SCHEDULES,
    Schedule,
    as_schedule,
    schedule_from_dict,
    schedule_to_dict,
    share_schedule,
)


def _shape(q: np.ndarray, batch: int | None) -> tuple[int, ...]:
    """Shape of the choices: one per row of ``q``, for each of ``batch`` copies if given."""
    return q.shape[:-1] if batch is None else (int(batch),) + q.shape[:-1]


def row_max(q: np.ndarray) -> np.ndarray:
    """``q.max(axis=-1)``, fast for large batches of short rows (element-wise maxima of columns:
    NumPy reductions along a short last axis are ~10× slower than that beyond a few thousand
    values)."""
    if q.size < 1024 or q.shape[-1] > 16:
        return q.max(axis=-1)
    best = q[..., 0].copy()
    for column in range(1, q.shape[-1]):
        np.maximum(best, q[..., column], out=best)
    return best


def greedy_choice(q: np.ndarray, rng: np.random.Generator, batch: int | None = None) -> np.ndarray:
    """Index of the largest value of each row of ``q``; exact ties broken uniformly at random.

    With ``batch``, ``q`` is shared by ``batch`` rows of choices (result (batch,) + q.shape[:-1]),
    each breaking ties independently; randomness is drawn only when some row has a tie.
    """
    q = np.asarray(q, dtype=float)
    ties = q >= row_max(q)[..., None]
    shape = _shape(q, batch)
    if ties.sum() == ties.size // q.shape[-1]:  # no ties anywhere: the plain argmax
        best = np.argmax(q, axis=-1)
        return best if batch is None else np.repeat(best[None], batch, axis=0)
    return np.argmax(rng.random(shape + q.shape[-1:]) * ties, axis=-1)


def sample_rows(p: np.ndarray, rng: np.random.Generator, batch: int | None = None) -> np.ndarray:
    """One index per row of (unnormalised, non-negative) probabilities ``p`` by inverse CDF."""
    cumulative = np.cumsum(p, axis=-1)
    u = rng.random(_shape(p, batch) + (1,)) * cumulative[..., -1:]
    return np.minimum((cumulative <= u).sum(axis=-1), p.shape[-1] - 1)


class Policy(ABC):
    """Base class: :meth:`choose` samples from :meth:`probabilities` (subclasses may be faster)."""

    kind: ClassVar[str] = "policy"

    @abstractmethod
    def probabilities(self, q: np.ndarray, t: float = 0) -> np.ndarray:
        """Probability of each action, same shape as ``q``."""

    def choose(self, q: np.ndarray, rng: np.random.Generator, t: float = 0,
               batch: int | None = None) -> np.ndarray:
        """One action index per row of ``q`` (shape ``q.shape[:-1]``).

        With ``batch``, the same values ``q`` serve ``batch`` independent rows of choices
        (shape ``(batch,) + q.shape[:-1]``) — a shared table computed once, not copied.
        """
        return sample_rows(self.probabilities(q, t), rng, batch)

    def to_dict(self) -> dict:
        """JSON-safe form, for checkpoints."""
        document = {"kind": self.kind}
        for name, value in vars(self).items():
            document[name] = schedule_to_dict(value) if isinstance(value, tuple(SCHEDULES.values())) else value
        return document


@dataclass
class Greedy(Policy):
    """Eq III.27: always the best action (random among exact ties)."""

    kind: ClassVar[str] = "greedy"

    def probabilities(self, q, t=0):
        q = np.asarray(q, dtype=float)
        ties = (q >= q.max(axis=-1, keepdims=True)).astype(float)
        return ties / ties.sum(axis=-1, keepdims=True)

    def choose(self, q, rng, t=0, batch=None):
        return greedy_choice(q, rng, batch)


@dataclass
class EpsilonGreedy(Policy):
    """Eq III.28: random action with probability ε(t), greedy otherwise."""

    epsilon: Schedule = field(default_factory=lambda: as_schedule(0.1))
    kind: ClassVar[str] = "epsilon_greedy"

    def __post_init__(self):
        self.epsilon = share_schedule(self.epsilon, "epsilon")

    def probabilities(self, q, t=0):
        q = np.asarray(q, dtype=float)
        eps = float(self.epsilon(t))
        return eps / q.shape[-1] + (1.0 - eps) * Greedy().probabilities(q)

    def choose(self, q, rng, t=0, batch=None):
        """One uniform u per choice: explore when u < ε, then ⌊u / ε · N⌋ is the random action."""
        q = np.asarray(q, dtype=float)
        eps = float(self.epsilon(t))
        greedy = greedy_choice(q, rng, batch)
        if eps <= 0.0:
            return greedy
        u = rng.random(_shape(q, batch))
        random_action = np.minimum((u * (q.shape[-1] / eps)).astype(int), q.shape[-1] - 1)
        return np.where(u < eps, random_action, greedy)


@dataclass
class Softmax(Policy):
    """Eq III.29 on shifted values: p ∝ Q − min_a Q + offset."""

    offset: float = 1.0
    kind: ClassVar[str] = "softmax"

    def __post_init__(self):
        validation.positive(self.offset, field="offset")

    def probabilities(self, q, t=0):
        q = np.asarray(q, dtype=float)
        p = q - q.min(axis=-1, keepdims=True) + self.offset
        return p / p.sum(axis=-1, keepdims=True)


@dataclass
class Boltzmann(Policy):
    """Eq III.30: p ∝ exp(Q / τ(t)), computed stably (values shifted by their row maximum)."""

    tau: Schedule = field(default_factory=lambda: as_schedule(1.0))
    kind: ClassVar[str] = "boltzmann"

    def __post_init__(self):
        self.tau = as_schedule(self.tau, "tau")

    def probabilities(self, q, t=0):
        q = np.asarray(q, dtype=float)
        tau = float(self.tau(t))
        validation.positive(tau, field="tau")
        p = np.exp((q - q.max(axis=-1, keepdims=True)) / tau)
        return p / p.sum(axis=-1, keepdims=True)


POLICIES = {cls.kind: cls for cls in (Greedy, EpsilonGreedy, Softmax, Boltzmann)}


def policy_from_dict(document: dict, field_name: str = "policy") -> Policy:
    """Inverse of :meth:`Policy.to_dict`."""
    parameters = dict(document)
    kind = parameters.pop("kind", None)
    if kind not in POLICIES:
        raise InputError(f"unknown policy kind {kind!r}; known: {', '.join(POLICIES)}", field=field_name)
    for name, value in parameters.items():
        if isinstance(value, dict):
            parameters[name] = schedule_from_dict(value, f"{field_name}.{name}")
    try:
        return POLICIES[kind](**parameters)
    except TypeError as error:
        raise InputError(f"bad parameters for policy {kind!r} ({error})", field=field_name) from None
