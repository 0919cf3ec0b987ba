"""The named records the engine's compiled kernels take instead of long argument lists.

Each is a ``typing.NamedTuple``: numba compiles a kernel taking one as a struct whose fields it
reads by name, at no cost over separate arguments, built in Python or inside a kernel alike.

- :class:`Units` — a Mamdani output's implication units (:func:`~.staged_kernels.integral`);
- :class:`Sampled` — its terms sampled at its defuzzifier's points, and the defuzzifier;
- :class:`Groups` — a weighted output's term groups (:func:`~.staged_kernels.group`);
- :class:`Affine` — their constant and linear terms (:func:`~.staged_kernels.weighted_affine`);
- :class:`Lanes` — the centroid's eight running sums of a block of rows (:mod:`.centroid_rows`).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np


class Units(NamedTuple):
    """The implication units of a Mamdani output: one per activation, or (Maximum aggregation) one
    per term and implication, whose activations' degrees max-combine first."""

    of: np.ndarray  # (A,) int: the unit of each activation
    term: np.ndarray  # (U,) int: each unit's term (its row of Sampled.shapes)
    implication: np.ndarray  # (U,) int: each unit's T-norm (norms codes)
    aggregation: int  # the output's S-norm (norms code)


class Sampled(NamedTuple):
    """A Mamdani output's terms sampled at its defuzzifier's points."""

    shapes: np.ndarray  # (T, R): term t's membership at each point
    support: np.ndarray  # (T, 2) int: first and past-the-last non-zero sample; (-1, R) when one is outside [0, 1]
    x: np.ndarray  # (R,): the points, in the output's units
    reduction: int  # the defuzzifier (sampled_defuzzify.REDUCTIONS index)


class Groups(NamedTuple):
    """The term groups of a weighted output: the activations of one term, in order."""

    rows: np.ndarray  # (A,) int: each activation's row of degrees
    groups: np.ndarray  # (A,) int: its group
    opens: np.ndarray  # (A,) bool: whether it is its group's first
    triggered: np.ndarray  # (A, N) bool: where it triggered (read only when masked)
    masked: bool  # False: every activation triggers on every row
    aggregation: int  # the output's S-norm (norms code)


class Affine(NamedTuple):
    """The constant and linear terms of a weighted output's groups: z = c₀ + c · inputs."""

    coefficients: np.ndarray  # (G, n_inputs)
    constants: np.ndarray  # (G,)


class Lanes(NamedTuple):
    """The centroid's running sums, sample k in lane k mod 8, for a block of rows."""

    totals: np.ndarray  # (8, rows): Σ μ
    moments: np.ndarray  # (8, rows): Σ μ x
