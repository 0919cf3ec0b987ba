"""Defuzzification of one output for a batch (fuzzylite 8 semantics).

Integral defuzzifiers sample the aggregated set on ``resolution`` midpoints of the output range
(or, as MATLAB does, on ``resolution`` points from end to end): centroid Σyμ/Σμ; bisector, the
sample where the running area is closest to half (averaged over ties); mean / smallest / largest
of the samples of maximum membership. Weighted defuzzifiers
group the activations by term (aggregated with the output's S-norm, or summed when it has none)
and average (``WeightedAverage``) or sum (``WeightedSum``) the terms' crisp values: a constant's
value, a linear term on the input values, a function of the degree, or — ``Tsukamoto`` — the
abscissa where a monotone term reaches the degree.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.fuzzy.engine.level_sets import LevelSetCentroid
from fuzzynav.fuzzy.engine.model import OutputVariable
from fuzzynav.fuzzy.formula import Function
from fuzzynav.fuzzy.membership import Linear, Singleton
from fuzzynav.fuzzy.operators import SNORMS, TNORMS
from fuzzynav.fuzzy.terms import Constant, Scaled

_BLOCK = 2_000_000  # elements of a (rows × samples) block of an integral defuzzifier


def midpoints(lo: float, hi: float, resolution: int) -> np.ndarray:
    """``resolution`` cell midpoints of [lo, hi] (fuzzylite's Op.midpoints)."""
    return lo + (np.arange(resolution) + 0.5) * ((hi - lo) / resolution)


def is_takagi_sugeno(mf) -> bool:
    """Terms whose crisp value does not come from an inverse: constants, linear terms, functions."""
    return isinstance(mf, (Constant, Singleton, Linear, Function))


def _crisp(mf, degree, inputs: np.ndarray, values: dict, tsukamoto: bool) -> np.ndarray:
    if isinstance(mf, (Constant, Singleton)):
        return np.full_like(degree, mf.params()[0])
    if isinstance(mf, Linear):  # a sum of columns: faster than a (N, n) @ (n,) product for few inputs
        z = np.full(inputs.shape[1], mf.constant)
        for c, column in zip(mf.coefficients, inputs):
            z += c * column
        return z
    if isinstance(mf, Function):
        return mf(degree, values)
    if tsukamoto:
        with np.errstate(all="ignore"):
            return np.asarray(mf.inverse(degree), dtype=float)
    return mf(degree)


def weighted(var: OutputVariable, groups: dict, inputs: np.ndarray, values: dict) -> np.ndarray:
    """Weighted average / sum over the activated terms; ``groups[label] = (degree, present)``
    (``present`` None: everywhere); ``inputs`` holds the input values as rows (n_inputs, N)."""
    n = inputs.shape[1]
    if not groups:
        return np.full(n, np.nan)
    kind = var.defuzzifier.type
    labels = list(groups)
    degrees = np.stack([groups[label][0] for label in labels])  # (n_groups, N)
    masks = [groups[label][1] for label in labels]
    mfs = [var.terms[label] for label in labels]
    if kind != "Tsukamoto" and all(isinstance(mf, (Constant, Singleton, Linear)) for mf in mfs):
        z = _affine(mfs, inputs)
    else:
        z = np.stack([_crisp(mf, d, inputs, values, _tsukamoto(mf, kind)) for mf, d in zip(mfs, degrees)])
    with np.errstate(invalid="ignore"):
        terms = degrees * z
    if any(m is not None for m in masks):
        present = np.stack([np.ones(n, dtype=bool) if m is None else m for m in masks])
        terms = np.where(present, terms, 0.0)
        degrees = np.where(present, degrees, 0.0)
        any_present = present.any(axis=0)
    else:
        any_present = True
    num, den = terms.sum(axis=0), degrees.sum(axis=0)
    with np.errstate(invalid="ignore", divide="ignore"):
        y = num / den
        if var.defuzzifier.kind == "WeightedSum":
            y = y * den
    return np.where(any_present, y, np.nan)


def _tsukamoto(mf, kind: str) -> bool:
    base = mf.term if isinstance(mf, Scaled) else mf
    return kind == "Tsukamoto" or (kind == "Automatic" and not is_takagi_sugeno(mf) and hasattr(base, "inverse"))


def _affine(mfs: list, inputs: np.ndarray) -> np.ndarray:
    """Crisp values of constant and linear terms at once: (n_terms, N) = C (n_terms, n_in) @ inputs + c."""
    coef = np.zeros((len(mfs), inputs.shape[0]))
    const = np.empty(len(mfs))
    for k, mf in enumerate(mfs):
        if isinstance(mf, Linear):
            coef[k], const[k] = mf.coefficients, mf.constant
        else:
            const[k] = mf.params()[0]
    return coef @ inputs + const[:, None]


def aggregated(var: OutputVariable, activations: list, samples: np.ndarray, rows: slice) -> np.ndarray:
    """The aggregated fuzzy output sampled at ``samples``, for the rows ``rows``: (n_rows, R).

    ``activations`` lists (label, degree, triggered, implication) in trigger order. With the
    ``Maximum`` aggregation the degrees of one term are combined first (max_r T(w_r, μ) =
    T(max_r w_r, μ) for any T-norm, which is monotone), otherwise every activation is folded
    in order, as fuzzylite does.
    """
    snorm = SNORMS[var.aggregation or "UnboundedSum"]
    shapes = {}
    first = activations[0][1][rows]
    agg = np.zeros((first.shape[0], samples.shape[0]))
    if var.aggregation == "Maximum":
        grouped: dict = {}
        for label, degree, triggered, implication in activations:
            w = degree[rows] if triggered is None else np.where(triggered[rows], degree[rows], 0.0)
            key = (label, implication)
            grouped[key] = w if key not in grouped else np.maximum(grouped[key], w)
        items = [(label, w, implication) for (label, implication), w in grouped.items()]
    else:
        items = [(label, d[rows] if t is None else np.where(t[rows], d[rows], 0.0), imp)
                 for label, d, t, imp in activations]
    for label, w, implication in items:
        if label not in shapes:
            shapes[label] = var.terms[label](samples)
        implied = TNORMS[implication](w[:, None], shapes[label][None, :])
        agg = snorm(agg, implied)
    return agg


def _max_min_degrees(activations: list) -> tuple[list, np.ndarray]:
    """Term labels and their degrees (N, T), max-aggregated over the rules concluding on them."""
    grouped: dict = {}
    for label, degree, triggered, _ in activations:
        w = degree if triggered is None else np.where(triggered, degree, 0.0)
        grouped[label] = w if label not in grouped else np.maximum(grouped[label], w)
    return list(grouped), np.column_stack(list(grouped.values()))


def integral(var: OutputVariable, activations: list, n: int, cache: dict | None = None) -> np.ndarray:
    """Centroid, bisector or mean / smallest / largest of maximum, row blocks of bounded size.

    A max–min centroid runs on :class:`~fuzzynav.fuzzy.engine.level_sets.LevelSetCentroid`
    (exact, O(log R) per row and term), kept in ``cache`` between calls.
    """
    d = var.defuzzifier
    if d.grid == "linspace":
        samples = np.linspace(var.minimum, var.maximum, d.resolution)
    else:
        samples = midpoints(var.minimum, var.maximum, d.resolution)
    out = np.full(n, np.nan)
    if not activations:
        return out
    if (d.kind == "Centroid" and var.aggregation == "Maximum" and cache is not None
            and all(implication == "Minimum" for *_, implication in activations)):
        labels, degrees = _max_min_degrees(activations)
        key = (var.name, tuple(labels))
        if key not in cache:
            shapes = np.array([np.broadcast_to(var.terms[label](samples), samples.shape) for label in labels])
            cache[key] = LevelSetCentroid(shapes, samples) if LevelSetCentroid.applies(shapes) else None
        if cache[key] is not None and not np.isnan(degrees).any():
            return cache[key].centroid(degrees)
    step = max(1, _BLOCK // samples.shape[0])
    for start in range(0, n, step):
        rows = slice(start, min(n, start + step))
        mu = aggregated(var, activations, samples, rows)
        out[rows] = _reduce(d.kind, mu, samples)
    return out


def _reduce(kind: str, mu: np.ndarray, x: np.ndarray) -> np.ndarray:
    with np.errstate(invalid="ignore", divide="ignore"):
        if kind == "Centroid":
            return (mu @ x) / mu.sum(axis=1)
        if kind == "Bisector":
            area = np.nancumsum(mu, axis=1)
            gap = np.abs(area / area[:, -1:] - 0.5)
            ties = gap == np.min(gap, axis=1, keepdims=True)
            count = ties.sum(axis=1)
            return np.where(count > 0, (ties * x).sum(axis=1) / np.where(count > 0, count, 1), np.nan)
        top = (mu > 0) & (mu == mu.max(axis=1, keepdims=True))
        count = top.sum(axis=1)
        if kind == "MeanOfMaximum":
            value = (top * x).sum(axis=1) / np.where(count > 0, count, 1)
        elif kind == "SmallestOfMaximum":
            value = x[np.argmax(top, axis=1)]
        else:  # LargestOfMaximum
            value = x[x.shape[0] - 1 - np.argmax(top[:, ::-1], axis=1)]
        return np.where(count > 0, value, np.nan)
