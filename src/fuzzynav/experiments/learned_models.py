"""The models the chapter V experiments run for the learned trackers, and their replacement.

The neural (CN, §V.3.2) and ANFIS (CNF, §V.3.5) trackers have no rule table for ``reproduce
--fis`` to replace: their experiments train their model for the run's seed
(:func:`fuzzynav.learn.tasks.trackers.default_document`). Inside :func:`replaced`, a model
document ({kind: document}, as ``fuzzynav train`` writes it) stands in for the trained one —
in the training figures (Figs V.15, V.23: the validation of the model) and in every run of
that tracker (Figs V.16–V.19, V.24–V.34) — so a claim can be checked against a wrong model
(``benchmarks/mutations.py``: sign-flipped or zeroed output layer, a model trained on wrong
targets or stopped early).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.experiments.stand_ins import StandIns
from fuzzynav.learn.tasks import trackers

KINDS = ("neural-tracker", "anfis-tracker")
_LOADERS = {"neural-tracker": trackers.load_neural_tracker, "anfis-tracker": trackers.load_anfis_tracker}
_STAND_INS = StandIns("replaced_learned_models", KINDS, "learned tracker(s)", "kinds", "models")
replaced = _STAND_INS.replaced
"""``with replaced({kind: model document}):`` the experiments inside run those documents' models."""


def replacement(kind: str) -> dict | None:
    """The model document that replaces ``kind``'s trained model now, or None."""
    return _STAND_INS.current().get(kind)


def tracker(kind: str, seed: int, **options):
    """The tracker ``kind`` the experiments run: the replacement's model, else the one trained with ``seed``."""
    document = replacement(kind) or trackers.default_document(kind, seed)
    return _LOADERS[kind](document, **options)


def model(kind: str, seed: int, quick: bool):
    """The estimator of ``kind`` the training figures validate: the replacement's, else one trained
    now with ``seed`` (the ANFIS for 50 epochs when ``quick``)."""
    document = replacement(kind)
    if document is not None:
        return tracker(kind, seed).model
    data = trackers.tracker_data(seed)
    if kind == "neural-tracker":
        return trackers.fit_neural(data, seed)
    return trackers.fit_anfis(data, seed, epochs=50 if quick else trackers.ANFIS_EPOCHS)


# --- wrong models, for the mutation harness (benchmarks/mutations.py) ------------------------------

def _output_layer(document: dict, scale: float) -> dict:
    """``document`` with its model's output layer multiplied by ``scale`` (the MLP's last weights
    and bias, the ANFIS' consequent parameters p, r of eq V.11): α becomes ``scale`` · f(θ_er)."""
    model = dict(document["model"])
    if document["kind"] == "neural-tracker":
        model["weights"] = [*model["weights"][:-1], [[scale * w for w in row] for row in model["weights"][-1]]]
        model["biases"] = [*model["biases"][:-1], [scale * b for b in model["biases"][-1]]]
    else:
        model["consequents"] = [[scale * v for v in row] for row in model["consequents"]]
    return {**document, "model": model}


def _retrained(document: dict, seed: int, targets=None, short: bool = False) -> dict:
    """``document`` with its model trained again on the same θ_er, on ``targets(α)`` instead of α,
    or stopped early (``short``: 2 L-BFGS iterations, 1 ANFIS epoch)."""
    data = trackers.tracker_data(seed)
    if targets is not None:
        data = trackers.TrackerData(data.x_train, targets(data.y_train), data.x_val, data.y_val)
    if document["kind"] == "neural-tracker":
        fitted = trackers.fit_neural(data, seed, max_iter=2) if short else trackers.fit_neural(data, seed)
    else:
        fitted = trackers.fit_anfis(data, seed, epochs=1) if short else trackers.fit_anfis(data, seed)
    return {**document, "model": fitted.to_dict()}


def mutations(kind: str, seed: int = 0) -> list[tuple[str, dict]]:
    """(name, model document) of the wrong models of learned tracker ``kind``: the output layer
    sign-flipped, zeroed or halved; trained on negated or shuffled targets (pairs that do not belong
    together); training stopped early. (The trackers have one input, θ_er: there is none to swap.)"""
    document = trackers.default_document(kind, seed)
    shuffle = np.random.default_rng(seed).permutation
    return [(f"{kind}: output layer sign-flipped", _output_layer(document, -1.0)),
            (f"{kind}: output layer zeroed", _output_layer(document, 0.0)),
            (f"{kind}: output layer halved", _output_layer(document, 0.5)),
            (f"{kind}: trained on negated targets", _retrained(document, seed, np.negative)),
            (f"{kind}: trained on shuffled targets", _retrained(document, seed, shuffle)),
            (f"{kind}: training stopped early", _retrained(document, seed, short=True))]
