"""The checkpoint of a tuning run (``OUT.tune.npz``): its options, a digest of its training worlds
and every generation's population with its objective values, rewritten atomically after each
generation (:func:`save`) and checked before a resumed run replays it (:func:`load`):
:mod:`fuzzynav.tune.session` explains the replay."""

from __future__ import annotations

import hashlib
import json
import math
from pathlib import Path

import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.tune.fitness import INVALID_COST, OBJECTIVES, Fitness


def path_for(request) -> Path | None:
    """``OUT.tune.npz`` beside ``--out`` of ``request`` (the run's
    :class:`~fuzzynav.tune.session.TuneRequest`, here as everywhere in this module; no checkpoint
    without ``--out``)."""
    return None if request.out is None else Path(f"{request.out}.tune.npz")


def load(path: Path, request, fitness: Fitness) -> list[tuple[np.ndarray, np.ndarray]]:
    """The stored generations [(population, values)], after checking the options match, the
    arrays fit together (a population has a column per searched parameter of ``fitness``'s space)
    and the objective values ``f`` are possible ones (:func:`_check_values`).

    A resumed run does not simulate the stored generations again (that would cost the whole run
    once more): it takes their values ``f`` as stored. It detects damage and another tuning's
    options; populations ``x`` that are not finite or that the optimiser does not ask again when
    replayed (a stored population edited, or a value of ``f`` of an earlier generation edited so
    that the optimiser asked something else next); and a value of ``f`` that no simulation on these
    worlds gives: NaN or infinite, or outside its objective's range — the cost in [0,
    ``INVALID_COST``] (the worst episode's), the failure rate a multiple of 1/W in [0, 1] (W
    training worlds), the mean time (s) in [0, the longest time limit + one step], minus the mean
    least clearance (m) in [−the largest world diagonal, 1] (clearances are clipped at −1 m). It
    does not detect a false value inside those ranges that leaves the replay unchanged — in the
    last stored generation, or one that does not change the optimiser's next population: such a
    value can make a worse candidate the result, steer the search, or (``nsga2``) show in the front
    with the stored objectives. A checkpoint is trusted as the run's own; its file is not signed."""
    validation.check_npz(path, what="tuning checkpoint")
    with np.load(path, allow_pickle=False) as data:
        try:
            options_text = str(data["options"])
            sizes, x, f = data["sizes"], data["x"], data["f"]
        except (KeyError, ValueError) as error:
            raise InputError(f"not a tuning checkpoint ({error})", source=str(path)) from None
        if "worlds" not in data.files:
            raise InputError("the checkpoint does not say which training worlds it was made on (an older "
                             "fuzzynav's): tune afresh", source=str(path), field="worlds")
        worlds = str(data["worlds"])
    try:
        options = validation.parse_json(options_text, str(path))
    except InputError as error:
        raise InputError(error.problem, source=str(path), field="options") from None
    validation.mapping(options, str(path), "options")
    for key, value in request.replayed().items():
        if options.get(key) != value:
            raise InputError(f"the checkpoint was made with {key} = {options.get(key)!r}, this run has {value!r}",
                             source=str(path), field=key)
    if worlds != _worlds_digest(fitness):
        raise InputError(f"the training worlds of {request.worlds} are not the ones the checkpoint was made on (a "
                         "world edited, added or removed since): tune afresh, or restore them", source=str(path),
                         field="--worlds")
    for name, array, columns in (("x", x, len(fitness.space.start)), ("f", f, 1 + len(OBJECTIVES))):
        if array.ndim != 2 or array.shape[1] != columns or array.dtype.kind != "f":
            raise InputError(f"must be a float array of {columns} columns, got {array.dtype} of shape {array.shape}",
                             source=str(path), field=name)
    counts = [int(size) for size in sizes.ravel()] if sizes.dtype.kind in "iu" else []  # Python ints: no wrap-round
    if sizes.ndim != 1 or sizes.dtype.kind not in "iu" or min(counts, default=0) < 0 or sum(counts) != len(x) \
            or len(f) != len(x):
        raise InputError(f"the generations' sizes must be whole numbers ≥ 0 adding up to the {len(x)} rows of x "
                         "and f", source=str(path), field="sizes")
    if not np.isfinite(x).all():
        raise InputError("the populations must be finite numbers (no NaN or infinity)", source=str(path), field="x")
    _check_values(path, f, fitness)
    ends = np.cumsum(counts, dtype=np.int64)
    return [(x[end - size:end], f[end - size:end]) for size, end in zip(counts, ends)]


def _check_values(path: Path, f: np.ndarray, fitness: Fitness) -> None:
    """Refuse objective values ``f`` (rows of :meth:`Fitness.objectives`) that ``fitness``'s worlds
    cannot give (:func:`load`)."""
    worlds = fitness.worlds
    extent = max(math.hypot(s.world.width, s.world.height) for s in worlds.scenarios)
    ranges = ((0.0, INVALID_COST), (0.0, 1.0), (0.0, float(np.max(worlds.max_time + worlds.dt))), (-extent, 1.0))
    names = ("cost", "failure rate", "mean time (s)", "minus mean least clearance (m)")  # Fitness.objectives
    for column, ((lo, hi), name) in enumerate(zip(ranges, names)):
        values = f[:, column]
        bad = ~np.isfinite(values) | (values < lo) | (values > hi)
        if column == 1:  # a failure rate is k of the W worlds
            bad |= np.abs(values * len(worlds) - np.round(values * len(worlds))) > 1e-6
        if bad.any():
            row = int(np.argmax(bad))
            what = "be finite" if not np.isfinite(values[row]) else f"lie in [{lo:g}, {hi:g}]" + (
                f" and be a multiple of 1/{len(worlds)} (the worlds)" if column == 1 else "")
            raise InputError(f"the {name} of candidate {row} must {what}, got {validation.shown(float(values[row]))}",
                             source=str(path), field=f"f[{row}, {column}]")


def _worlds_digest(fitness: Fitness) -> str:
    """A digest of the training worlds as the simulation reads them (set-ups, scenes, starts and
    the navigator's constants): a resumed run must tune on the same worlds."""
    digest = hashlib.sha256()
    for array in map(np.ascontiguousarray, (*fitness.worlds.packed, fitness.worlds.params)):
        digest.update(f"{array.dtype.str}{array.shape}".encode() + array.tobytes())
    return digest.hexdigest()


def save(path: Path, request, generations, fitness: Fitness) -> None:
    from fuzzynav.storage import save_npz_atomic

    save_npz_atomic(path, options=np.array(json.dumps(request.replayed())), worlds=np.array(_worlds_digest(fitness)),
                    sizes=np.array([len(x) for x, _ in generations], dtype=np.int64),
                    x=np.concatenate([x for x, _ in generations]), f=np.concatenate([f for _, f in generations]))
