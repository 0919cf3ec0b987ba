"""ANFIS, Jang's adaptive-network fuzzy inference system, as a scikit-learn estimator (thesis §V.3.4).

The five layers (§V.3.4, eqs V.8–V.12), for any number of inputs and a grid partition
(every combination of one MF per input is a rule):

1. fuzzification μ_ij(x_i), generalized bell (eq V.8) or Gaussian — the *premise* parameters S1 (V.13);
2. firing strength w_r = Π_i μ_i,m(r,i)(x_i) (product t-norm, eq V.9);
3. normalisation w̄_r = w_r / Σ_s w_s (eq V.10);
4. consequents w̄_r f_r with f_r = p_r·x + r_r (first order) or f_r = r_r (order 0) — the S2 parameters (V.14);
5. sum y = Σ_r w̄_r f_r (eq V.12).

Training is Jang's hybrid rule (Table V.2), one epoch = one forward and one backward pass over the
training set (batch learning):

- forward pass, premises fixed: y is linear in the consequents, so they are the least-squares
  solution of A θ = y (LAPACK's rank-revealing ``gelsy``; with ``ridge > 0``, ridge-stabilised);
- backward pass, consequents fixed: gradient of E = ½ Σ (y − t)² with respect to the premises,
  analytic (:mod:`fuzzynav.learn.anfis_mf`), then a step of fixed length k along −∇E — Jang's
  normalised step Δα = −k ∇E / ‖∇E‖ — taken in coordinates where widths and centres are measured in
  units of their input's span;
- Jang's step-size rules (Jang 1993, §V): k grows by ``step_increase`` after 4 consecutive
  decreases of the error and shrinks by ``step_decrease`` after 2 consecutive oscillations
  (increase–decrease pairs);
- the parameters of the best epoch (validation error if ``validation_fraction > 0``, else training
  error) are kept, and training stops when that error has not improved for ``n_iter_no_change``
  epochs — early stopping on a validation split. A non-finite error restores the best parameters
  and shrinks k, so training cannot diverge.

``history_`` holds the training (and validation) RMSE of every epoch — the training curve of
Fig V.23. :meth:`ANFIS.predict_one` is the scalar call of the control loop (plain Python, a few µs);
:meth:`ANFIS.to_dict` / :meth:`ANFIS.from_dict` round-trip through JSON, and
:meth:`ANFIS.to_fuzzy_system` exports the trained system to the fuzzy library (TS1 / TS0 engine).
"""

from __future__ import annotations

import itertools
import math
import numbers
from collections.abc import Sequence

import numpy as np
from sklearn.base import BaseEstimator, RegressorMixin
from sklearn.utils.validation import check_is_fitted

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.learn import anfis_mf
from fuzzynav.learn.anfis_hybrid import TINY, Grid, StepRule
from fuzzynav.learn.estimator_checks import check_format, check_premises, check_x, check_xy, checked_rules

_FORMAT = "fuzzynav-anfis"
_VERSION = 1
_KEYS = ("format", "version", "params", "n_features_in", "premises", "consequents", "input_range", "output_range",
         "best_epoch", "history")  # of to_dict's document


class ANFIS(RegressorMixin, BaseEstimator):
    """Adaptive-network fuzzy inference system (Jang 1993; thesis §V.3.4, Table V.2).

    Parameters
    ----------
    n_mfs : int or sequence of int
        Membership functions per input (one number for all inputs, or one per input).
    mf : {"bell", "gaussian"}
        Premise family: generalized bell (eq V.8) or Gaussian.
    order : {0, 1}
        Takagi–Sugeno order of the consequents (1 = the thesis' first-order model, §V.3.5.1).
    epochs : int
        Maximum number of hybrid-learning epochs.
    step_size : float
        Initial length k of the normalised premise step (in units of the input span).
    step_increase, step_decrease : float
        Factors of Jang's step-size rules (after 4 decreases / after 2 oscillations).
    validation_fraction : float in [0, 1)
        Share of the samples held out (at random) for the best-epoch checkpoint and early stopping.
    n_iter_no_change, tol : int, float
        Stop when the monitored error has not improved for this many epochs, or is at most ``tol``.
    ridge : float
        0: plain least squares (rank-revealing QR, minimum norm); > 0 adds ``ridge · N · ‖θ‖²``.
    premises : sequence of (n_mfs_i, P) arrays, optional
        Initial premises per input (rows (a, b, c) for bell, (σ, m) for Gaussian), replacing ``n_mfs``;
        default: Jang's grid partition of the training range (:func:`anfis_mf.grid_premises`).
    learn_premises : bool
        False keeps the premises fixed: the fit is then the single least-squares pass.
    random_state : int, numpy.random.Generator or None
        Seeds the validation split (the only random choice).

    Attributes
    ----------
    premises_ : list of (n_mfs_i, P) arrays — trained premise parameters, per input.
    consequents_ : (n_rules, n_features + 1) array (order 1: p_r1 … p_rn, r_r) or (n_rules, 1) (order 0).
    rules_ : (n_rules, n_features) int array — MF index of each input in each rule (grid order).
    input_range_ : (n_features, 2) array — training range of each input (the exported universes).
    output_range_ : (2,) array — training range of the target.
    history_ : dict — per epoch ``train_rmse``, ``validation_rmse`` (``None`` without a split), ``step_size``.
    best_epoch_, n_epochs_, n_features_in_ : int — epoch kept (0-based), epochs run, inputs.
    """

    def __init__(
        self,
        n_mfs: int | Sequence[int] = 3,
        mf: str = "bell",
        order: int = 1,
        epochs: int = 200,
        step_size: float = 0.05,
        step_increase: float = 1.1,
        step_decrease: float = 0.9,
        validation_fraction: float = 0.0,
        n_iter_no_change: int = 50,
        tol: float = 0.0,
        ridge: float = 0.0,
        premises=None,
        learn_premises: bool = True,
        random_state=None,
    ):
        self.n_mfs = n_mfs
        self.mf = mf
        self.order = order
        self.epochs = epochs
        self.step_size = step_size
        self.step_increase = step_increase
        self.step_decrease = step_decrease
        self.validation_fraction = validation_fraction
        self.n_iter_no_change = n_iter_no_change
        self.tol = tol
        self.ridge = ridge
        self.premises = premises
        self.learn_premises = learn_premises
        self.random_state = random_state

    # ------------------------------------------------------------------ checks
    def _check_hyper_parameters(self, n_features: int) -> list[int]:
        if self.mf not in anfis_mf.FAMILIES:
            raise InputError(f"must be one of {', '.join(anfis_mf.FAMILIES)}, got {self.mf!r}", field="mf")
        if self.order not in (0, 1) or isinstance(self.order, bool):
            raise InputError(f"must be 0 or 1, got {self.order!r}", field="order")
        validation.integer(self.epochs, field="epochs", lo=1)
        validation.integer(self.n_iter_no_change, field="n_iter_no_change", lo=1)
        for name in ("step_size", "step_increase"):
            validation.positive(getattr(self, name), field=name)
        if not 0.0 < validation.positive(self.step_decrease, field="step_decrease") < 1.0:
            raise InputError(f"must be in (0, 1), got {self.step_decrease!r}", field="step_decrease")
        if self.step_increase < 1.0:
            raise InputError(f"must be >= 1, got {self.step_increase!r}", field="step_increase")
        if not 0.0 <= validation.number(self.validation_fraction, field="validation_fraction") < 1.0:
            raise InputError(f"must be in [0, 1), got {self.validation_fraction!r}", field="validation_fraction")
        if validation.number(self.tol, field="tol") < 0 or validation.number(self.ridge, field="ridge") < 0:
            raise InputError("tol and ridge must be >= 0", field="tol" if self.tol < 0 else "ridge")
        if self.premises is not None:
            return checked_rules([len(p) for p in check_premises(self.premises, self.mf, n_features, "premises")],
                                 field="premises")
        counts = [self.n_mfs] * n_features if isinstance(self.n_mfs, numbers.Integral) else list(self.n_mfs)
        if len(counts) != n_features or not all(isinstance(c, numbers.Integral) and c >= 1 for c in counts):
            raise InputError(f"must be an integer >= 1 or {n_features} of them, got {self.n_mfs!r}", field="n_mfs")
        return checked_rules([int(c) for c in counts])

    # ------------------------------------------------------------------ training
    def fit(self, X, y):
        """Hybrid learning (Table V.2) on samples ``X`` (N, n_features) and targets ``y`` (N,)."""
        X, y = check_xy(X, y)
        counts = self._check_hyper_parameters(X.shape[1])
        n_samples, n_features = X.shape
        rng = np.random.default_rng(self.random_state)
        n_val = int(round(self.validation_fraction * n_samples))
        order = rng.permutation(n_samples) if n_val else np.arange(n_samples)
        train, val = order[n_val:], order[:n_val]
        if len(train) < 2:
            raise InputError(f"needs at least 2 training samples after the validation split, got {len(train)}",
                             field="X")
        self.n_features_in_ = n_features
        self.input_range_ = np.column_stack([X.min(axis=0), X.max(axis=0)])
        self.output_range_ = np.array([y.min(), y.max()])
        spans = self.input_range_[:, 1] - self.input_range_[:, 0]
        spans = np.where(spans > 0, spans, 1.0)
        self.rules_ = np.array(list(itertools.product(*(range(c) for c in counts))), dtype=np.intp).reshape(-1, n_features)
        grid = Grid(self.mf, counts, self.rules_, self.order)
        if self.premises is not None:
            params = np.concatenate([np.array(p, dtype=float) for p in self.premises])
        else:
            params = np.concatenate([anfis_mf.grid_premises(self.mf, lo, hi, c)
                                     for (lo, hi), c in zip(self.input_range_, counts)])
        mf_spans = spans[grid.mf_input]
        anfis_mf.keep_valid(self.mf, params, mf_spans)
        scale = anfis_mf.parameter_scale(self.mf, params)

        Xt, yt = X[train], y[train]
        Xv, yv = X[val], y[val]
        xa_train = grid.augmented(Xt)
        k = float(self.step_size)
        history = {"train_rmse": [], "validation_rmse": [] if n_val else None, "step_size": []}
        steps = StepRule(self.step_increase, self.step_decrease)
        best = (math.inf, -1, params.copy(), None)
        for epoch in range(self.epochs):
            need_grad = self.learn_premises and epoch < self.epochs - 1
            fwd = grid.forward(Xt, params, need_grad, xa_train)
            theta = grid.least_squares(fwd, yt, self.ridge)
            f, out = grid.outputs(fwd, theta)
            err = out - yt
            train_rmse = math.sqrt(float(err @ err) / len(yt))
            if not math.isfinite(train_rmse) or not np.isfinite(theta).all():
                params, k = best[2].copy(), k * self.step_decrease
                continue
            val_rmse = None
            if n_val:
                ev = grid.predict(Xv, params, theta) - yv
                val_rmse = math.sqrt(float(ev @ ev) / n_val)
            history["train_rmse"].append(train_rmse)
            if n_val:
                history["validation_rmse"].append(val_rmse)
            history["step_size"].append(k)
            monitored = val_rmse if n_val else train_rmse
            if monitored < best[0]:
                best = (monitored, epoch, params.copy(), theta)
            if monitored <= self.tol or epoch - best[1] >= self.n_iter_no_change or not need_grad:
                break
            k = steps.update(train_rmse, k)
            grad = grid.premise_gradient(fwd, f, out, err)
            norm = float(np.linalg.norm(grad * scale))
            if norm > 0.0 and math.isfinite(norm):
                params = params - (k / norm) * scale * scale * grad
                anfis_mf.keep_valid(self.mf, params, mf_spans)
        if best[3] is None:
            raise InputError("training produced no finite least-squares solution", field="y")
        self.best_epoch_ = best[1]
        self.n_epochs_ = len(history["train_rmse"])
        self.premises_ = grid.split(best[2])
        self.consequents_ = best[3]
        self.history_ = history
        self._compile_scalar()
        return self

    # ------------------------------------------------------------------ inference
    def _grid(self) -> Grid:
        return Grid(self.mf, [len(p) for p in self.premises_], self.rules_, self.order)

    def predict(self, X) -> np.ndarray:
        """Outputs (N,) for inputs ``X`` (N, n_features): layers 1–5, vectorised."""
        check_is_fitted(self, "consequents_")
        X = check_x(X, self.n_features_in_)
        return self._grid().predict(X, np.concatenate(self.premises_), self.consequents_)

    def _compile_scalar(self) -> None:
        """Plain-Python copies of the parameters for :meth:`predict_one`."""
        self._scalar_premises = [[tuple(float(v) for v in row) for row in p] for p in self.premises_]
        self._scalar_rules = [
            (tuple(int(m) for m in idx), tuple(float(v) for v in theta[:-1]), float(theta[-1]))
            for idx, theta in zip(self.rules_, self.consequents_)
        ]
        # one input: rule r is MF r, so each rule is one flat tuple (MF parameters, slope, constant)
        self._scalar_single = None
        if self.n_features_in_ == 1:
            self._scalar_single = [(*self._scalar_premises[0][idx[0]], coefs[0] if coefs else 0.0, const)
                                   for idx, coefs, const in self._scalar_rules]

    def predict_one(self, x) -> float:
        """Output for one input vector (or one number, for a single-input ANFIS), in plain Python.

        The control-loop call: no NumPy dispatch (timed by benchmarks/anfis_bench.py). Same result as
        :meth:`predict` up to rounding (falls back to it where a membership power would overflow).
        """
        single = self._scalar_single
        try:
            if single is not None and not isinstance(x, (list, tuple, np.ndarray)):
                x = float(x)
                num = den = 0.0
                if self.mf == "bell":
                    for a, b, c, p, r in single:
                        u = (x - c) / a
                        w = 1.0 / (1.0 + (u * u) ** b)
                        num += w * (p * x + r)
                        den += w
                else:
                    for s, m, p, r in single:
                        u = (x - m) / s
                        w = math.exp(-0.5 * u * u)
                        num += w * (p * x + r)
                        den += w
                return num / (den if den > TINY else TINY)
            return self._predict_one_grid(tuple(float(v) for v in np.ravel(x)))
        except OverflowError:
            return float(self.predict(np.array([np.ravel(x)], dtype=float))[0])

    def _predict_one_grid(self, xs: tuple) -> float:
        premises = self._scalar_premises
        if len(xs) != len(premises):
            raise InputError(f"expected {len(premises)} input value(s), got {len(xs)}", field="x")
        if self.mf == "bell":
            mus = [[1.0 / (1.0 + (((xi - c) / a) ** 2) ** b) for a, b, c in p] for xi, p in zip(xs, premises)]
        else:
            mus = [[math.exp(-0.5 * ((xi - m) / s) ** 2) for s, m in p] for xi, p in zip(xs, premises)]
        num = den = 0.0
        for idx, coefs, const in self._scalar_rules:
            w = 1.0
            for mu, m in zip(mus, idx):
                w *= mu[m]
            f = const
            for c, xi in zip(coefs, xs):
                f += c * xi
            num += w * f
            den += w
        return num / (den if den > TINY else TINY)

    # ------------------------------------------------------------------ files and export
    def to_dict(self) -> dict:
        """JSON-safe document: hyper-parameters and learned parameters (exact float round trip)."""
        check_is_fitted(self, "consequents_")
        params = self.get_params()
        if params["premises"] is not None:
            params["premises"] = [np.asarray(p, dtype=float).tolist() for p in params["premises"]]
        if not isinstance(params["random_state"], (int, type(None))):
            params["random_state"] = None
        if not isinstance(params["n_mfs"], numbers.Integral):
            params["n_mfs"] = [int(c) for c in params["n_mfs"]]
        return {
            "format": _FORMAT,
            "version": _VERSION,
            "params": params,
            "n_features_in": int(self.n_features_in_),
            "premises": [p.tolist() for p in self.premises_],
            "consequents": self.consequents_.tolist(),
            "input_range": self.input_range_.tolist(),
            "output_range": self.output_range_.tolist(),
            "best_epoch": int(self.best_epoch_),
            "history": self.history_,
        }

    @classmethod
    def from_dict(cls, document, source: str | None = None) -> ANFIS:
        """Rebuild a fitted estimator from :meth:`to_dict`'s document (InputError naming the field)."""
        check_format(document, _FORMAT, _VERSION, "an ANFIS", source, keys=_KEYS, required=("n_features_in",))
        n = validation.integer(document["n_features_in"], source, "n_features_in", lo=1)
        try:
            model = cls(**document["params"])
            counts = model._check_hyper_parameters(n)
        except (KeyError, TypeError) as error:
            raise InputError(f"bad or missing hyper-parameters ({error})", source=source, field="params") from None
        except InputError as error:
            raise InputError(error.problem, source=source, field=f"params.{error.field}") from None
        if model.premises is not None:
            counts = [len(p) for p in model.premises]
        premises = check_premises(document.get("premises"), model.mf, n, "premises", source)
        checked_rules([len(p) for p in premises], source, "premises")
        if [len(p) for p in premises] != counts:
            raise InputError(f"MF counts {[len(p) for p in premises]} do not match n_mfs {counts}",
                             source=source, field="premises")
        model.rules_ = np.array(list(itertools.product(*(range(c) for c in counts))), dtype=np.intp).reshape(-1, n)
        width = n + 1 if model.order == 1 else 1
        model.consequents_ = validation.finite_array(document.get("consequents"), source, "consequents", shape=(len(model.rules_), width))
        model.input_range_ = validation.finite_array(document.get("input_range"), source, "input_range", shape=(n, 2))
        model.output_range_ = validation.finite_array(document.get("output_range"), source, "output_range", shape=(2,))
        for where, (lo, hi) in [*((f"input_range[{i}]", r) for i, r in enumerate(model.input_range_)),
                                ("output_range", model.output_range_)]:
            if lo > hi:
                raise InputError(f"must be [lo, hi] with lo ≤ hi, got [{lo:g}, {hi:g}]", source=source, field=where)
        model.premises_ = premises
        model.n_features_in_ = n
        model.best_epoch_ = validation.integer(document.get("best_epoch", -1), source, "best_epoch", lo=-1)
        history = document.get("history", {"train_rmse": [], "validation_rmse": None, "step_size": []})
        if not isinstance(history, dict) or not isinstance(history.get("train_rmse"), list):
            raise InputError("must be an object with a 'train_rmse' list", source=source, field="history")
        model.history_ = history
        model.n_epochs_ = len(model.history_.get("train_rmse", []))
        model._compile_scalar()
        return model

    def to_fuzzy_system(self, input_names: Sequence[str] | None = None, output_name: str = "y", name: str = "anfis"):
        """The trained ANFIS as a :class:`fuzzynav.fuzzy.FuzzySystem` (``ts1``, or ``ts0`` for order 0).

        Inputs get terms ``mf0, mf1, …`` (Bell or Gaussian, same parameters), the output one term per
        rule ``r0, r1, …`` (:class:`~fuzzynav.fuzzy.Linear` p·x + r, or :class:`~fuzzynav.fuzzy.Singleton`),
        product t-norm, weighted average — layers 2–5 exactly. Universes are the training ranges and
        the fuzzy library clamps inputs to them, so the exported system equals :meth:`predict` on the
        training range and holds the border value beyond it.
        """
        from fuzzynav.fuzzy import Bell, FuzzySystem, Gaussian, Linear, Rule, Singleton, Variable

        check_is_fitted(self, "consequents_")
        names = list(input_names) if input_names is not None else [f"x{i + 1}" for i in range(self.n_features_in_)]
        if len(names) != self.n_features_in_:
            raise InputError(f"expected {self.n_features_in_} names, got {len(names)}", field="input_names")
        family = Bell if self.mf == "bell" else Gaussian
        inputs = []
        for var, p, (lo, hi) in zip(names, self.premises_, self.input_range_):
            hi = hi if hi > lo else lo + 1.0
            inputs.append(Variable(var, (lo, hi), {f"mf{j}": family(*row) for j, row in enumerate(p)}))
        if self.order == 1:
            terms = {f"r{k}": Linear(theta[:-1], theta[-1]) for k, theta in enumerate(self.consequents_)}
            lo, hi = self.output_range_
        else:
            terms = {f"r{k}": Singleton(theta[0]) for k, theta in enumerate(self.consequents_)}
            lo = min(self.output_range_[0], self.consequents_.min())
            hi = max(self.output_range_[1], self.consequents_.max())
        output = Variable(output_name, (lo, hi if hi > lo else lo + 1.0), terms)
        rules = [Rule(tuple((var, f"mf{m}") for var, m in zip(names, idx)), ((output_name, f"r{k}"),))
                 for k, idx in enumerate(self.rules_)]
        return FuzzySystem(inputs, [output], rules, method="ts1" if self.order == 1 else "ts0",
                           tnorm="product", defuzzifier="weighted_average", name=name,
                           description="exported from a trained ANFIS (thesis §V.3.4)")
