"""The neural (CN, §V.3.2) and ANFIS (CNF, §V.3.5) trackers: ``fuzzynav train neural-tracker | anfis-tracker``, model files, loaders.

Data by *generalized learning* (Fig V.14): steering commands α drawn uniformly in [−π/4, π/4]
are applied to the simulated tricycle (eq IV.2, V = 1 m/s) for one control step Δt from random
headings; the angular error each command cancels is θ_er = θ_r − θ_d with θ_r the heading
before and θ_d the heading reached (the sign of :func:`~fuzzynav.control.base.thesis_angle_error`). The pairs (θ_er, α) train

- the MLP of Fig V.13 (two tanh hidden layers of 10, linear output; :mod:`fuzzynav.learn.neural`),
  validated on 100 unseen pairs (Fig V.15);
- a first-order ANFIS with one input θ_er and 5 Gaussian MFs ("5 fonctions d'appartenance
  gaussiennes", §V.3.5.1; Jang's hybrid learning, :mod:`fuzzynav.learn.anfis`), with its training
  curve and validation (Fig V.23). The generalized bell of eq V.8 stays an option
  (``fit_anfis(..., mf="bell")``); it is not better here (docs/results/claims-mutations.md).

One step is the thesis' set-up ("at each Δt … after this action the robot is at its new
position", §V.3.2); the commands reach |θ_er| ≤ V·tan(π/4)·Δt / l = 0.2 rad, and the trackers
clamp larger errors to that range (the command saturates at ±π/4).

Model files (JSON, written atomically) have ``kind`` ``neural-tracker`` / ``anfis-tracker``,
the trained model's document, the input range and the tracker options; :func:`load_model`
rebuilds the :class:`~fuzzynav.control.tracking.ModelTracker`.
The registry names ``neural-tracker`` / ``anfis-tracker`` without a file train the default model
on the fly (seed 0, well under a second) and keep it for the rest of the process.
"""

from __future__ import annotations

import functools
import math
import time
from dataclasses import dataclass

import numpy as np

from fuzzynav import validation
from fuzzynav.control.tracking import DEFAULT_CORNER_RADIUS, DEFAULT_LOOKAHEAD, DEFAULT_SPEED, ModelTracker
from fuzzynav.errors import InputError
from fuzzynav.learn.anfis import ANFIS
from fuzzynav.learn.neural import NeuralInverseModel, fit_inverse_model, generalized_learning_dataset
from fuzzynav.learn.tasks.common import save_model
from fuzzynav.robot import tricycle
from fuzzynav.world.geometry import wrap_angle

MAX_STEERING = math.pi / 4
N_TRAIN = 200
N_VALIDATION = 100  # Fig V.15 / V.23: ~100 unseen pairs
HIDDEN = (10, 10)
ANFIS_MFS = 5
ANFIS_EPOCHS = 200


def tricycle_plant(speed: float = DEFAULT_SPEED, steps: int = 1, params=tricycle.DEFAULT_PARAMS, seed: int = 0):
    """The plant of generalized learning: commands α ``(N,)`` → θ_er ``(N,)`` they cancel.

    Each command is held for ``steps`` steps of the tricycle from a random heading (seeded).
    """
    rng = np.random.default_rng(seed)

    def plant(commands: np.ndarray) -> np.ndarray:
        pose = np.column_stack([np.zeros((len(commands), 2)), rng.uniform(-np.pi, np.pi, len(commands))])
        start = pose[:, 2].copy()
        for _ in range(steps):
            pose = tricycle.step(pose, commands, np.full(len(commands), speed), params)
        return wrap_angle(start - pose[:, 2])

    return plant


@dataclass(frozen=True)
class TrackerData:
    """Training and validation pairs (θ_er ``(N, 1)``, α ``(N,)``) of one seed."""

    x_train: np.ndarray
    y_train: np.ndarray
    x_val: np.ndarray
    y_val: np.ndarray

    @property
    def input_range(self) -> tuple[float, float]:
        return float(self.x_train.min()), float(self.x_train.max())


def tracker_data(seed: int = 0, n_train: int = N_TRAIN, n_val: int = N_VALIDATION) -> TrackerData:
    """Generalized-learning pairs on the default robot; validation pairs from a different seed."""
    seeds = np.random.SeedSequence(seed).generate_state(4)
    x, y = generalized_learning_dataset(tricycle_plant(seed=int(seeds[0])), n_samples=n_train,
                                        command_range=(-MAX_STEERING, MAX_STEERING), random_state=int(seeds[1]))
    xv, yv = generalized_learning_dataset(tricycle_plant(seed=int(seeds[2])), n_samples=n_val,
                                          command_range=(-MAX_STEERING, MAX_STEERING), random_state=int(seeds[3]))
    return TrackerData(x, y, xv, yv)


def fit_neural(data: TrackerData, seed: int = 0, max_iter: int = 5000) -> NeuralInverseModel:
    """The MLP of Fig V.13 on the generalized-learning pairs."""
    return fit_inverse_model(data.x_train, data.y_train, HIDDEN, max_iter=max_iter, random_state=seed)


def fit_anfis(data: TrackerData, seed: int = 0, epochs: int = ANFIS_EPOCHS, mf: str = "gaussian") -> ANFIS:
    """The ANFIS of §V.3.5: one input, 5 MFs (Gaussian as §V.3.5.1 says, or ``"bell"``, eq V.8),
    first order, 20 % validation split."""
    return ANFIS(n_mfs=ANFIS_MFS, mf=mf, order=1, epochs=epochs, validation_fraction=0.2,
                 random_state=seed).fit(data.x_train, data.y_train)


def _validation(model, data: TrackerData) -> dict:
    residual = data.y_val - model.predict(data.x_val)
    return {"validation_rmse_rad": float(np.sqrt(np.mean(residual ** 2))),
            "validation_max_error_rad": float(np.abs(residual).max())}


def _document(kind: str, model, data: TrackerData, seed: int, seconds: float) -> dict:
    return {
        "kind": kind,
        "model": model.to_dict(),
        "input_range": list(data.input_range),
        "speed": DEFAULT_SPEED,
        "corner_radius": DEFAULT_CORNER_RADIUS,
        "lookahead": DEFAULT_LOOKAHEAD,
        "training": {"seed": seed, "n_train": len(data.y_train), "train_seconds": seconds,
                     "source": "generalized learning, one step of the tricycle (thesis §V.3.2, Fig V.14)",
                     **_validation(model, data)},
    }


def _tracker(kind: str, model, document: dict, source: str | None = None, **options) -> ModelTracker:
    if model.n_features_in_ != 1:
        raise InputError(f"a tracker's model reads one input (θ_er), this one reads {model.n_features_in_}",
                         source=source, field="model")
    lo, hi = document["input_range"]
    options = {"speed": document.get("speed", DEFAULT_SPEED),
               "corner_radius": document.get("corner_radius", DEFAULT_CORNER_RADIUS),
               "lookahead": document.get("lookahead", DEFAULT_LOOKAHEAD), **options}
    try:
        return ModelTracker(model, (lo, hi), name=kind, max_steering=MAX_STEERING, **options)
    except InputError as error:  # a bad speed / corner_radius / lookahead of the file: name the file
        raise InputError(error.problem, source=error.source or source, field=error.field) from None


TRACKER_KEYS = ("kind", "model", "input_range", "speed", "corner_radius", "lookahead", "training")  # of _document


def _checked(document: dict, path) -> dict:
    source = str(path) if path is not None else None
    validation.known_keys(document, TRACKER_KEYS, source, required=("model", "input_range"))
    lo, hi = validation.numbers(document["input_range"], source, "input_range", length=2)
    if not lo < hi:
        raise InputError(f"must be [lo, hi] with lo < hi, got {document['input_range']!r}", source=source,
                         field="input_range")
    for key in ("speed", "corner_radius", "lookahead"):
        validation.number(document.get(key, 0.0), source, key, lo=-1e5, hi=1e5)
    return document


def load_neural_tracker(document: dict, path=None, **options) -> ModelTracker:
    """Model loader of kind ``neural-tracker``."""
    document = _checked(document, path)
    source = str(path) if path else None
    model = NeuralInverseModel.from_dict(document["model"], source=source)
    return _tracker("neural-tracker", model, document, source, **options)


def load_anfis_tracker(document: dict, path=None, **options) -> ModelTracker:
    """Model loader of kind ``anfis-tracker``."""
    document = _checked(document, path)
    source = str(path) if path else None
    model = ANFIS.from_dict(document["model"], source=source)
    return _tracker("anfis-tracker", model, document, source, **options)


def anfis_tracker_system(document: dict, path=None):
    """The ANFIS of an ``anfis-tracker`` model file as a fuzzy-library system (TS1, §V.3.4 layers
    1–5): input ``theta_er``, output ``alpha`` — what ``fuzzynav fis show|eval|convert`` read."""
    document = _checked(document, path)
    model = ANFIS.from_dict(document["model"], source=str(path) if path else None)
    return model.to_fuzzy_system(["theta_er"], "alpha", name="anfis-tracker")


@functools.lru_cache(maxsize=4)
def default_document(kind: str, seed: int = 0) -> dict:
    """The model document trained with the defaults (cached for the process)."""
    data = tracker_data(seed)
    start = time.perf_counter()
    model = fit_neural(data, seed) if kind == "neural-tracker" else fit_anfis(data, seed)
    return _document(kind, model, data, seed, time.perf_counter() - start)


def neural_tracker(seed: int = 0, **options) -> ModelTracker:
    """Factory of ``neural-tracker``: the default MLP trained on the fly (options: ``speed``, ``corner_radius``, ``lookahead``)."""
    return load_neural_tracker(default_document("neural-tracker", validation.seed(seed, field="seed")), **options)


def anfis_tracker(seed: int = 0, **options) -> ModelTracker:
    """Factory of ``anfis-tracker``: the default ANFIS trained on the fly."""
    return load_anfis_tracker(default_document("anfis-tracker", validation.seed(seed, field="seed")), **options)


def _train(kind: str, request) -> dict:
    if request.resume or request.checkpoint_every:
        raise InputError("not supported: this task trains in one pass (well under a second)",
                         field="--resume" if request.resume else "--checkpoint-every")
    data = tracker_data(request.seed)
    start = time.perf_counter()
    if kind == "neural-tracker":
        model = fit_neural(data, request.seed, **({"max_iter": request.episodes} if request.episodes else {}))
        count = {"solver_iterations": model.iterations}  # L-BFGS iterations (its loss curve is the final loss alone)
    else:
        model = fit_anfis(data, request.seed, **({"epochs": request.episodes} if request.episodes else {}))
        count = {"epochs": len(model.history_["train_rmse"])}
    document = _document(kind, model, data, request.seed, time.perf_counter() - start)
    save_model(request, document)
    if request.curve:
        from fuzzynav.viz.training import plot_training  # matplotlib only when a plot is asked for

        plot_training(kind, model, data, request.curve)
    return {"model": str(request.out), **count, **document["training"]}


def train_neural_tracker(request) -> dict:
    """``fuzzynav train neural-tracker``: the MLP of §V.3.2 (``--episodes`` = max iterations)."""
    return _train("neural-tracker", request)


def train_anfis_tracker(request) -> dict:
    """``fuzzynav train anfis-tracker``: the ANFIS of §V.3.5 (``--episodes`` = max epochs)."""
    return _train("anfis-tracker", request)


def load_model(document: dict, path=None) -> ModelTracker:
    """Model loader of the kinds ``neural-tracker`` and ``anfis-tracker``."""
    load = load_neural_tracker if document.get("kind") == "neural-tracker" else load_anfis_tracker
    return load(document, path)
