"""Neural inverse model by generalized learning (thesis §V.3.2, Figs V.12–V.15), robot-free.

*Generalized learning* (Fig V.14): apply commands u to the plant, observe its outputs y, and train
a network on the pairs (y, u) so that it maps a desired output back to the command that produces
it — the inverse model. For the tracker of §V.3.2, u is the steering angle α and y the angular
error θ_er it leaves; the plant is whatever callable the caller passes (the tricycle model for
the tracker), so this module knows nothing of robots.

The network is the thesis' multilayer perceptron (Fig V.13): tanh ("tansig") hidden layers — two
by default — and one linear output neuron, trained by back-propagation of the squared error with
scikit-learn's :class:`~sklearn.neural_network.MLPRegressor`. Solver: ``"lbfgs"`` by default — the
gradient is back-propagated and the step is quasi-Newton, which on a few hundred pairs converges
far better than first-order descent (scikit-learn's advice for small data sets; MATLAB's toolbox,
whose "tansig" name the thesis uses, also defaults to a second-order method); ``"sgd"`` gives the textbook
gradient-descent back-propagation with momentum, ``"adam"`` its adaptive variant.

Inputs and targets are standardised for training and the scaling is folded back into the first
and last layers, so a :class:`NeuralInverseModel` is just its weights: a NumPy forward pass for
batches, a plain-Python one for the control loop, and a JSON document (no pickle).
"""

from __future__ import annotations

import math
import numbers
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field

import numpy as np
from sklearn.exceptions import ConvergenceWarning
from sklearn.neural_network import MLPRegressor

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.learn.estimator_checks import check_format

_FORMAT = "fuzzynav-mlp"
_VERSION = 1
_KEYS = ("format", "version", "activation", "output_activation", "weights", "biases", "loss_curve", "iterations")
SOLVERS = ("lbfgs", "sgd", "adam")


@dataclass(eq=False)
class NeuralInverseModel:
    """A trained MLP: tanh hidden layers, linear output (Fig V.13), on raw (unscaled) inputs.

    ``weights[l]`` is (n_in_l, n_out_l), ``biases[l]`` (n_out_l,); the last layer has one output.
    ``loss_curve`` is the training loss per iteration (half mean squared error on standardised
    targets) when the solver records it (``sgd``, ``adam``), else the final loss alone (``lbfgs``);
    ``iterations`` is the number of solver iterations the training ran (0 when unknown).
    """

    weights: list[np.ndarray]
    biases: list[np.ndarray]
    loss_curve: list[float] = field(default_factory=list)
    iterations: int = 0

    def __post_init__(self):
        self._compile_scalar()

    @property
    def n_features_in_(self) -> int:
        return int(self.weights[0].shape[0])

    def predict(self, X) -> np.ndarray:
        """Commands (N,) for observed errors ``X`` (N, n_features) or (N,) — vectorised NumPy."""
        X = np.asarray(X, dtype=float)
        if X.ndim == 1 and self.n_features_in_ == 1:
            X = X[:, None]
        if X.ndim != 2 or X.shape[1] != self.n_features_in_:
            raise InputError(f"expected shape (N, {self.n_features_in_}), got {X.shape}", field="X")
        if not np.isfinite(X).all():  # as ANFIS.predict: NaN would come out as a command, ±∞ saturate unseen
            raise InputError("must be finite numbers (no NaN or infinity)", field="X")
        h = X
        for W, b in zip(self.weights[:-1], self.biases[:-1]):
            h = np.tanh(h @ W + b)
        return h @ self.weights[-1][:, 0] + self.biases[-1][0]

    def _compile_scalar(self) -> None:
        """Contiguous copies for :meth:`predict_one`: first-layer row, hidden layers, output column."""
        self._first = np.ascontiguousarray(self.weights[0][0]) if self.n_features_in_ == 1 else None
        self._hidden = [(np.ascontiguousarray(W.T), b) for W, b in zip(self.weights[1:-1], self.biases[1:-1])]
        self._out = (np.ascontiguousarray(self.weights[-1][:, 0]), float(self.biases[-1][0]))

    def predict_one(self, x) -> float:
        """Command for one observation (a number, or a sequence for several inputs).

        A handful of small NumPy calls (no scikit-learn, no batch bookkeeping): the control-loop call.
        """
        if self._first is not None and isinstance(x, (float, int, np.floating)):
            h = np.tanh(self._first * float(x) + self.biases[0])
        else:
            xs = np.asarray(x, dtype=float).ravel()
            if xs.shape != (self.n_features_in_,):
                raise InputError(f"expected {self.n_features_in_} input value(s), got {xs.size}", field="x")
            h = np.tanh(xs @ self.weights[0] + self.biases[0])
        for WT, b in self._hidden:
            h = np.tanh(WT.dot(h) + b)
        w, b = self._out
        return float(w.dot(h)) + b

    def to_dict(self) -> dict:
        """JSON-safe document of the weights (exact float round trip)."""
        return {
            "format": _FORMAT,
            "version": _VERSION,
            "activation": "tanh",
            "output_activation": "identity",
            "weights": [W.tolist() for W in self.weights],
            "biases": [b.tolist() for b in self.biases],
            "loss_curve": [float(v) for v in self.loss_curve],
            "iterations": int(self.iterations),
        }

    @classmethod
    def from_dict(cls, document, source: str | None = None) -> NeuralInverseModel:
        """Rebuild from :meth:`to_dict`'s document; InputError names the bad field."""
        check_format(document, _FORMAT, _VERSION, "an MLP", source, keys=_KEYS)
        for key, value in (("activation", "tanh"), ("output_activation", "identity")):
            if document.get(key, value) != value:  # the only network this class evaluates
                raise InputError(f"must be {value!r}, got {document.get(key)!r}", source=source, field=key)
        weights, biases = document.get("weights"), document.get("biases")
        if not isinstance(weights, list) or not isinstance(biases, list) or len(weights) != len(biases) or not weights:
            raise InputError("weights and biases must be lists of the same non-zero length", source=source,
                             field="weights")
        Ws, bs = [], []
        for i, (W, b) in enumerate(zip(weights, biases)):
            W, b = _finite(W, 2, f"weights[{i}]", source), _finite(b, 1, f"biases[{i}]", source)
            if (Ws and W.shape[0] != Ws[-1].shape[1]) or W.shape[1] != b.shape[0]:
                raise InputError(f"layer shapes do not chain ({W.shape}, bias {b.shape})", source=source,
                                 field=f"weights[{i}]")
            Ws.append(W)
            bs.append(b)
        if Ws[-1].shape[1] != 1:
            raise InputError("the output layer must have one neuron", source=source, field=f"weights[{len(Ws) - 1}]")
        curve = document.get("loss_curve", [])
        iterations = document.get("iterations", 0)
        validation.integer(iterations, source, "iterations", lo=0)
        return cls(Ws, bs, [float(v) for v in _finite(curve, 1, "loss_curve", source)] if curve else [], iterations)


def fit_inverse_model(
    errors,
    commands,
    hidden_layer_sizes: Sequence[int] = (10, 10),
    *,
    solver: str = "lbfgs",
    max_iter: int = 5000,
    tol: float = 1e-10,
    l2: float = 0.0,
    random_state: int | None = 0,
) -> NeuralInverseModel:
    """Train the inverse model (§V.3.2): observed ``errors`` (N,) or (N, k) -> ``commands`` (N,).

    ``hidden_layer_sizes`` — tanh layers (the thesis uses two, sizes "chosen by trial", Fig V.13);
    ``solver`` — see the module docstring; ``l2`` — weight decay (MLPRegressor's ``alpha``).
    A solver that stops at ``max_iter`` is not an error (the returned loss curve shows it).
    """
    X = np.asarray(errors, dtype=float)
    X = X[:, None] if X.ndim == 1 else X
    y = np.asarray(commands, dtype=float)
    if X.ndim != 2 or len(X) < 2:
        raise InputError(f"expected at least 2 samples of shape (N,) or (N, k), got {X.shape}", field="errors")
    if y.shape != (len(X),):
        raise InputError(f"expected shape ({len(X)},), got {y.shape}", field="commands")
    if not (np.isfinite(X).all() and np.isfinite(y).all()):
        raise InputError("training pairs contain NaN or infinite values", field="errors" if not np.isfinite(X).all()
                         else "commands")
    sizes = tuple(hidden_layer_sizes)
    if not sizes or not all(isinstance(s, numbers.Integral) and s >= 1 for s in sizes):
        raise InputError(f"must be one or more integers >= 1, got {hidden_layer_sizes!r}", field="hidden_layer_sizes")
    if solver not in SOLVERS:
        raise InputError(f"must be one of {', '.join(SOLVERS)}, got {solver!r}", field="solver")
    if random_state is not None:  # scikit-learn's random_state takes 32-bit seeds only
        validation.integer(random_state, field="seed", lo=0, hi=validation.MAX_SMALL_SEED)
    x_mean, x_std = X.mean(axis=0), X.std(axis=0)
    x_std = np.where(x_std > 0, x_std, 1.0)
    y_mean, y_std = float(y.mean()), float(y.std()) or 1.0
    net = MLPRegressor(hidden_layer_sizes=sizes, activation="tanh", solver=solver, alpha=l2, max_iter=max_iter,
                       tol=tol, random_state=random_state, **({"n_iter_no_change": max_iter} if solver != "lbfgs"
                                                            else {"max_fun": 10 * max_iter}))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ConvergenceWarning)
        net.fit((X - x_mean) / x_std, (y - y_mean) / y_std)
    weights = [W.copy() for W in net.coefs_]
    biases = [b.copy() for b in net.intercepts_]
    # fold the standardisation into the first and last layers: the model runs on raw values
    biases[0] = biases[0] - (x_mean / x_std) @ weights[0]
    weights[0] = weights[0] / x_std[:, None]
    biases[-1] = biases[-1] * y_std + y_mean
    weights[-1] = weights[-1] * y_std
    curve = list(getattr(net, "loss_curve_", None) or [net.loss_])
    return NeuralInverseModel(weights, biases, [float(v) for v in curve], int(net.n_iter_))


def generalized_learning_dataset(
    plant: Callable[[np.ndarray], np.ndarray],
    commands=None,
    *,
    n_samples: int = 200,
    command_range: tuple[float, float] = (-math.pi / 4, math.pi / 4),
    random_state=None,
) -> tuple[np.ndarray, np.ndarray]:
    """Pairs (observed error, command) by applying commands to a plant model (Fig V.14).

    ``plant(commands)`` takes the commands (N,) and returns what each produces, (N,) or (N, k) —
    for the tracker, the angular error θ_er after applying α. ``commands`` defaults to ``n_samples``
    values drawn uniformly from ``command_range`` (|α| ≤ π/4, the trackers' steering limit) with
    ``random_state``. Returns ``(errors (N, k), commands (N,))``: the inverse model's inputs and targets.
    """
    if commands is None:
        validation.integer(n_samples, field="n_samples", lo=2)
        lo, hi = (float(v) for v in command_range)
        if not (math.isfinite(lo) and math.isfinite(hi) and lo < hi):
            raise InputError(f"must be finite with lo < hi, got {command_range!r}", field="command_range")
        commands = np.random.default_rng(random_state).uniform(lo, hi, int(n_samples))
    commands = np.asarray(commands, dtype=float)
    if commands.ndim != 1 or len(commands) < 1 or not np.isfinite(commands).all():
        raise InputError(f"expected a finite 1-D array, got shape {commands.shape}", field="commands")
    observed = np.asarray(plant(commands.copy()), dtype=float)
    if observed.ndim == 1:
        observed = observed[:, None]
    if observed.ndim != 2 or len(observed) != len(commands):
        raise InputError(f"the plant returned shape {observed.shape} for {len(commands)} commands", field="plant")
    if not np.isfinite(observed).all():
        raise InputError("the plant returned NaN or infinite values", field="plant")
    return observed, commands


@dataclass(frozen=True)
class InverseValidation:
    """The inverse model on unseen pairs (Fig V.15): desired vs network commands and their error."""

    errors: np.ndarray
    desired: np.ndarray
    predicted: np.ndarray

    @property
    def residual(self) -> np.ndarray:
        return self.desired - self.predicted

    @property
    def rmse(self) -> float:
        return float(np.sqrt(np.mean(self.residual**2)))

    @property
    def max_abs_error(self) -> float:
        return float(np.abs(self.residual).max())


def validate_inverse_model(
    model: NeuralInverseModel,
    plant: Callable[[np.ndarray], np.ndarray],
    *,
    n_samples: int = 100,
    command_range: tuple[float, float] = (-math.pi / 4, math.pi / 4),
    random_state=None,
) -> InverseValidation:
    """Fig V.15: fresh commands (seed ``random_state``, unseen in training) through the plant and the model."""
    errors, commands = generalized_learning_dataset(plant, n_samples=n_samples, command_range=command_range,
                                                    random_state=random_state)
    return InverseValidation(errors, commands, model.predict(errors))


def _finite(value, ndim: int, name: str, source: str | None) -> np.ndarray:
    try:
        array = np.array(value, dtype=float)
    except (TypeError, ValueError):
        array = None
    if array is None or array.ndim != ndim or 0 in array.shape or not np.isfinite(array).all():
        raise InputError(f"expected a non-empty finite {ndim}-D array of numbers", source=source, field=name)
    return array
