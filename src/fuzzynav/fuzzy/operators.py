"""T-norm and S-norm names (computed, compiled, by :mod:`fuzzynav.fuzzy.engine.staged_kernels`), hedges
and activation methods, vectorised (thesis §II.3; fuzzylite 8).

T-norms (conjunction, implication): AlgebraicProduct, BoundedDifference, DrasticProduct,
EinsteinProduct, HamacherProduct, Minimum, NilpotentMinimum. S-norms (disjunction,
aggregation): AlgebraicSum, BoundedSum, DrasticSum, EinsteinSum, HamacherSum, Maximum,
NilpotentMaximum, NormalizedSum, UnboundedSum. Hedges: not, very (x²), somewhat (√x),
extremely, seldom, any (always 1).
"""

from __future__ import annotations

import numpy as np


def _seldom(x):
    with np.errstate(invalid="ignore"):
        return np.where(x <= 0.5, np.sqrt(0.5 * x), 1.0 - np.sqrt(0.5 * (1.0 - x)))


TNORMS = ("AlgebraicProduct", "BoundedDifference", "DrasticProduct", "EinsteinProduct", "HamacherProduct", "Minimum",
          "NilpotentMinimum")  # computed by fuzzynav.fuzzy.engine.norms.tnorm
SNORMS = ("AlgebraicSum", "BoundedSum", "DrasticSum", "EinsteinSum", "HamacherSum", "Maximum", "NilpotentMaximum",
          "NormalizedSum", "UnboundedSum")  # computed by fuzzynav.fuzzy.engine.norms.snorm
HEDGES = {
    "not": lambda x: 1.0 - x,
    "very": lambda x: x * x,
    "somewhat": lambda x: np.sqrt(x),
    "extremely": lambda x: np.where(x <= 0.5, 2.0 * x * x, 1.0 - 2.0 * (1.0 - x) ** 2),
    "seldom": _seldom,
    "any": lambda x: np.ones_like(x),
}
ACTIVATIONS = ("General", "First", "Last", "Highest", "Lowest", "Proportional", "Threshold")
COMPARATORS = {"<": np.less, "<=": np.less_equal, "==": np.equal, "!=": np.not_equal, ">=": np.greater_equal,
               ">": np.greater}


def activate(kind: str, params: tuple, degrees: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Which rules fire, and how strongly: ``degrees`` (N, n_rules) -> (degrees, triggered), both (N, n_rules).

    fuzzylite 8's activation methods, row by row: General triggers every rule (even at degree 0);
    First / Last the first / last ``n`` rules (in rule order) whose degree is > 0 and >= threshold;
    Highest / Lowest the ``n`` rules of highest / lowest positive degree (ties: rule order);
    Proportional the rules of positive degree, divided by their sum; Threshold the rules whose
    degree compares true with the threshold. A rule not triggered adds nothing to its output (not
    even a term of degree 0, which matters to Tsukamoto's inverse and to an empty output).
    """
    if kind == "General":
        return degrees, np.ones(degrees.shape, dtype=bool)
    if kind == "Proportional":
        positive = degrees > 0
        total = np.where(positive, degrees, 0.0).sum(axis=1, keepdims=True)
        return np.where(positive, degrees / np.where(total > 0, total, 1.0), 0.0), positive
    if kind == "Threshold":
        comparator, threshold = params
        return degrees, COMPARATORS[comparator](degrees, threshold)
    if kind in ("First", "Last"):
        n, threshold = params
        eligible = (degrees > 0) & (degrees >= threshold)
        order = eligible if kind == "First" else eligible[:, ::-1]
        kept = order & (np.cumsum(order, axis=1) <= n)
        return degrees, kept if kind == "First" else kept[:, ::-1]
    (n,) = params
    positive = degrees > 0
    key = np.where(positive, -degrees if kind == "Highest" else degrees, np.inf)
    rank = np.argsort(np.argsort(key, axis=1, kind="stable"), axis=1, kind="stable")
    return degrees, positive & (rank < n)
