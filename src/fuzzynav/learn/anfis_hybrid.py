"""The kernels of Jang's hybrid learning for a grid-partitioned ANFIS (thesis §V.3.4, Table V.2; Jang 1993).

:class:`Grid` holds the index bookkeeping of one structure (which MF each rule reads) and the
batch passes of :class:`fuzzynav.learn.anfis.ANFIS`: layers 1–3 (:meth:`Grid.forward`), the
forward pass's least-squares consequents, layers 4–5, and the backward pass's premise gradient.
:class:`StepRule` is Jang's step-size rule.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import scipy.linalg

from fuzzynav.learn import anfis_mf

TINY = np.finfo(float).tiny


class Grid:
    """Index bookkeeping and the batch kernels of one grid-partitioned ANFIS structure."""

    def __init__(self, family: str, counts: Sequence[int], rules: np.ndarray, order: int):
        self.family = family
        self.order = order
        self.offsets = np.concatenate([[0], np.cumsum(counts)])
        self.mf_input = np.repeat(np.arange(len(counts)), counts)  # input read by each MF
        self.columns = rules + self.offsets[:-1]  # (R, n): global MF column of each premise
        n_rules, n_in = rules.shape
        self.incidence = np.zeros((n_rules * n_in, self.offsets[-1]))  # one-hot (rule, input) -> MF
        self.incidence[np.arange(n_rules * n_in), self.columns.ravel()] = 1.0

    def split(self, params: np.ndarray) -> list[np.ndarray]:
        return [params[a:b].copy() for a, b in zip(self.offsets[:-1], self.offsets[1:])]

    def forward(self, X: np.ndarray, params: np.ndarray, with_gradient: bool, xa: np.ndarray | None = None) -> dict:
        """Layers 1–3 on a batch: μ, premise degrees per rule, w, Σw, w̄ (and ∂μ/∂params).

        ``xa`` — :meth:`augmented` of ``X`` when the caller keeps it across epochs.
        """
        xcol = X[:, self.mf_input]
        if with_gradient:
            mu, dmu = anfis_mf.evaluate_with_gradient(self.family, xcol, params)
        else:
            mu, dmu = anfis_mf.evaluate(self.family, xcol, params), None
        degrees = mu[:, self.columns]  # (N, R, n)
        w = degrees.prod(axis=2)
        total = np.maximum(w.sum(axis=1), TINY)
        return {"xa": self.augmented(X) if xa is None else xa, "dmu": dmu, "degrees": degrees, "total": total,
                "wbar": w / total[:, None]}

    def augmented(self, X: np.ndarray) -> np.ndarray:
        """Regressors of one rule's consequent: [x, 1] (first order) or [1] (order 0)."""
        return np.column_stack([X, np.ones(len(X))]) if self.order == 1 else np.ones((len(X), 1))

    def least_squares(self, fwd: dict, y: np.ndarray, ridge: float) -> np.ndarray:
        """Forward pass of Table V.2: consequents (R, n+1 or 1) minimising ‖A θ − y‖² (+ ridge)."""
        xa = fwd["xa"]
        n_rules = fwd["wbar"].shape[1]
        design = (fwd["wbar"][:, :, None] * xa[:, None, :]).reshape(len(y), -1)
        if ridge > 0.0:
            k = design.shape[1]
            design = np.vstack([design, math.sqrt(ridge * len(y)) * np.eye(k)])
            y = np.concatenate([y, np.zeros(k)])
        # rank-revealing QR (LAPACK gelsy): the minimum-norm solution when rules barely fire
        theta = scipy.linalg.lstsq(design, y, lapack_driver="gelsy", check_finite=False)[0]
        return theta.reshape(n_rules, xa.shape[1])

    def outputs(self, fwd: dict, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Layers 4–5: rule outputs f (N, R) and y (N,)."""
        f = fwd["xa"] @ theta.T
        return f, (fwd["wbar"] * f).sum(axis=1)

    def predict(self, X: np.ndarray, params: np.ndarray, theta: np.ndarray) -> np.ndarray:
        return self.outputs(self.forward(X, params, False), theta)[1]

    def premise_gradient(self, fwd: dict, f: np.ndarray, out: np.ndarray, err: np.ndarray) -> np.ndarray:
        """Backward pass of Table V.2: ∂E/∂premises (M, P) for E = ½ Σ e², consequents fixed.

        ∂y/∂w_r = (f_r − y) / Σw, ∂w_r/∂μ_i = Π_{k≠i} μ_k (prefix × suffix products, no division).
        """
        degrees = fwd["degrees"]
        n, n_rules, n_in = degrees.shape
        d_w = err[:, None] * (f - out[:, None]) / fwd["total"][:, None]  # (N, R)
        ones = np.ones((n, n_rules, 1))
        prefix = np.cumprod(np.concatenate([ones, degrees[:, :, :-1]], axis=2), axis=2)
        suffix = np.cumprod(np.concatenate([ones, degrees[:, :, :0:-1]], axis=2), axis=2)[:, :, ::-1]
        d_mu = ((d_w[:, :, None] * prefix * suffix).reshape(n, n_rules * n_in)) @ self.incidence  # (N, M)
        return np.einsum("nm,nmp->mp", d_mu, fwd["dmu"])


class StepRule:
    """Jang's step-size rules: ×increase after 4 consecutive decreases, ×decrease after 2 oscillations."""

    def __init__(self, increase: float, decrease: float):
        self.increase, self.decrease = increase, decrease
        self.last = None
        self.signs: list[int] = []  # +1 error went up, −1 went down, since the last change of k

    def update(self, error: float, k: float) -> float:
        if self.last is not None:
            self.signs.append(1 if error > self.last else -1)
        self.last = error
        recent = self.signs[-4:]
        if len(recent) == 4 and all(s < 0 for s in recent):
            self.signs.clear()
            return k * self.increase
        if len(recent) == 4 and all(recent[i] != recent[i + 1] for i in range(3)):
            self.signs.clear()
            return k * self.decrease
        return k
