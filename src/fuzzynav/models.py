"""Trained-model files: every model file says what it is, and this module loads it safely.

A model file is JSON (``.json``) or NumPy ``.npz`` loaded with ``allow_pickle=False``; both
carry a ``kind`` field. ``fuzzynav run SCENARIO --model FILE`` calls :func:`load_controller`.
:func:`save_json_atomic` / :func:`save_npz_atomic` write a temporary file and rename it, so a
crash while saving never corrupts the previous model.
"""

from __future__ import annotations

import json
from importlib import import_module
from pathlib import Path

import numpy as np

from fuzzynav import validation
from fuzzynav.atomic import atomic_write
from fuzzynav.errors import InputError

# kind -> "module:loader"; a loader takes (the parsed document, the path) and returns a Controller.
MODEL_LOADERS: dict[str, str] = {}
MODEL_LOADERS["neural-tracker"] = "fuzzynav.experiments.train_trackers:load_neural_tracker"
MODEL_LOADERS["anfis-tracker"] = "fuzzynav.experiments.train_trackers:load_anfis_tracker"
MODEL_LOADERS["q-goal"] = "fuzzynav.experiments.train_rl:load_q_goal"
MODEL_LOADERS["fql-goal"] = "fuzzynav.control.learned:load_fuzzy_model"
MODEL_LOADERS["fql-avoid"] = "fuzzynav.control.learned:load_fuzzy_model"
MODEL_LOADERS["fql-wall"] = "fuzzynav.control.learned:load_fuzzy_model"


def save_json_atomic(path, document: dict) -> None:
    """Write ``document`` as JSON to ``path`` atomically (temporary file, then rename)."""
    data = json.dumps(document, indent=2, sort_keys=False).encode()
    atomic_write(Path(path), lambda handle: handle.write(data))


def save_npz_atomic(path, **arrays) -> None:
    """Write arrays as ``.npz`` atomically; strings are stored as 0-d unicode arrays."""
    atomic_write(Path(path), lambda handle: np.savez(handle, **arrays))


def read_model(path) -> dict:
    """Read a model file into a dict (JSON object, or the arrays of an ``.npz``) with its ``kind``.

    Bounded before anything is decoded (:mod:`fuzzynav.validation`): a JSON file by its size,
    nesting and values; an ``.npz`` by the sizes its zip and array headers declare
    (:func:`fuzzynav.validation.check_npz`), never unpickled.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("no such model file", source=str(path))
    if path.suffix == ".npz":
        validation.check_npz(path)
        try:
            with np.load(path, allow_pickle=False) as data:
                document = {key: data[key] for key in data.files}
        except Exception as error:  # corrupt data past the checked headers (zlib, CRC, truncation, ...)
            raise InputError(f"cannot read model file ({type(error).__name__}: {error})", source=str(path)) from None
        if "kind" in document:
            document["kind"] = str(document["kind"]) if document["kind"].dtype.kind == "U" else document["kind"]
    else:
        document = validation.parse_json(validation.read_text(path, max_bytes=validation.MAX_MODEL_BYTES), str(path))
    if not isinstance(document, dict) or "kind" not in document:
        raise InputError("not a fuzzynav model file (no 'kind' field)", source=str(path), field="kind")
    validation.text(document["kind"], str(path), "kind", max_length=100)
    return document


def load_controller(path):
    """Build the controller stored in a model file, whatever its kind."""
    document = read_model(path)
    kind = document["kind"]
    if kind not in MODEL_LOADERS:
        raise InputError(
            f"unknown model kind {kind!r}; known: {', '.join(sorted(MODEL_LOADERS)) or 'none'}",
            source=str(path),
            field="kind",
        )
    module_name, loader_name = MODEL_LOADERS[kind].split(":")
    return getattr(import_module(module_name), loader_name)(document, Path(path))
