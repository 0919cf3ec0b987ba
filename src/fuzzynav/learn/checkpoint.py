"""Resumable training: checkpoints of a learner + RNG + episode counter + curve, and a train loop.

A checkpoint is one JSON document (``.json``, or the same document stored as a 0-d string in an
``.npz``) written atomically (temporary file, then rename — :mod:`fuzzynav.storage`), so an
interrupted run (Ctrl-C, crash) always leaves the previous checkpoint intact. It holds

- ``learner``: the learner's :meth:`to_dict` (qualities, visit counts, its episode counter),
- ``rng``: ``Generator.bit_generator.state`` (JSON-safe: big integers are exact in JSON),
- ``episode``: batches of episodes completed, and ``curve``: the per-episode records so far,
- ``extra``: the settings that shape the run (task, phase, seed, batch size, ...).

A checkpoint is checked against itself when read: ``digest``, the SHA-256 of the rest of the
document (canonical JSON), must match, and the curve must hold exactly ``episode`` batches, each
with as many rows in every record, every value one a run can give (``success`` true or false,
``mean_reward`` finite, ``steps`` a whole number ≥ 1) — an edited episode counter or curve is
refused instead of resuming into another model. A checkpoint without a digest (written by hand or
by an older version) gets these checks, and its learner's episode counter must equal ``episode``
(with a digest it may be larger: a learner that trained before :func:`train_loop` was called).
Resuming is refused — an :class:`~fuzzynav.errors.InputError` naming the field — when the
checkpoint belongs to another run: any setting of ``extra`` or of the learner differs, or the
checkpoint has already done more episodes than the run asks for (:func:`check_same_run`).
Temporary files a killed save left beside the checkpoint are removed when training starts.

Checkpoints are taken between batches of episodes only, so no environment state needs saving;
:func:`train_loop` resumed from a checkpoint therefore continues *exactly* where it stopped: the
same qualities and curve, bit for bit, as an uninterrupted run with the same seed — provided the
environment draws all its randomness from the ``rng`` it is given.

The environment protocol of :func:`train_loop` (a batch of B episodes, Gymnasium-like)::

    env.reset(rng) -> obs                                   # B new episodes
    env.step(action, rng) -> obs, reward, terminated, truncated, info

with ``reward`` (B,) or (B, H), ``terminated`` / ``truncated`` (B,) booleans and ``info`` a dict
that may hold ``"success"`` (B,) booleans. Rows whose episode has ended keep being stepped with
the others until the whole batch is done; their results are ignored.
"""

from __future__ import annotations

import hashlib
import json
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from fuzzynav import progress as progress_bars, validation
from fuzzynav.errors import InputError
from fuzzynav.learn.state import episode_count, restore_state
from fuzzynav.storage import read_document, remove_stale_temporaries, save_document

KIND = "fuzzynav-checkpoint"
_STATE_FIELDS = ("q", "visits", "episode", "premise")
_CURVE_FIELDS = ("mean_reward", "steps", "success")


def save_checkpoint(path, learner, rng: np.random.Generator, episode: int, curve: dict,
                    extra: dict | None = None) -> None:
    """Write a checkpoint atomically in the format of its extension (``.json`` or ``.npz``)."""
    document = {
        "kind": KIND,
        "episode": int(episode),
        "rng": rng.bit_generator.state,
        "learner": learner.to_dict(),
        "curve": curve,
        "extra": extra or {},
        "saved_at": time.time(),
    }
    document["digest"] = _digest(document)
    save_document(Path(path), document)


def _digest(document: dict) -> str:
    """SHA-256 of the document without its ``digest``, as canonical JSON."""
    rest = {key: value for key, value in document.items() if key != "digest"}
    return hashlib.sha256(json.dumps(rest, sort_keys=True, separators=(",", ":")).encode()).hexdigest()


def load_checkpoint(path) -> dict:
    """Read a checkpoint document written by :func:`save_checkpoint`."""
    document = read_document(path, "checkpoint")
    if document["kind"] != KIND:
        raise InputError(f"not a training checkpoint (kind {document['kind']!r})", source=str(path),
                         field="kind")
    for name in ("episode", "rng", "learner", "curve"):
        if name not in document:
            raise InputError("missing field in checkpoint", source=str(path), field=name)
    episode_count(document["episode"], str(path), "episode")
    for name in ("rng", "learner"):
        validation.mapping(document[name], str(path), name)
    curve = document["curve"]
    if not isinstance(curve, dict) or not all(isinstance(curve.get(key), list) for key in _CURVE_FIELDS):
        raise InputError(f"must map {', '.join(_CURVE_FIELDS)} to lists", source=str(path), field="curve")
    for key in _CURVE_FIELDS:
        for i, row in enumerate(curve[key]):
            _check_record(key, row, str(path), f"curve.{key}[{i}]")
    _check_itself(document, str(path))
    return document


def _check_record(key: str, row, source: str, field: str) -> None:
    """One batch's record of curve field ``key``: a list of one value per episode of the batch
    (a list per reward head for ``mean_reward``), each a value :func:`run_episodes` can give —
    ``success`` true or false (or 1 or 0), ``mean_reward`` a finite number, ``steps`` a whole
    number ≥ 1."""
    if not isinstance(row, list) or not row:
        raise InputError(f"must be a list of the batch's episodes, got {str(row)[:60]}", source=source, field=field)
    try:
        values = np.asarray(row)
    except ValueError:  # ragged
        values = np.asarray(None)
    if values.dtype.kind not in "biuf":
        raise InputError(f"must hold numbers, got {str(row)[:60]}", source=source, field=field)
    if values.ndim not in ((1, 2) if key == "mean_reward" else (1,)):
        raise InputError(f"must be a list of the batch's episodes, got {str(row)[:60]}", source=source, field=field)
    flat, numbers = values.ravel(), values.ravel().astype(float)
    if key == "success":
        bad, want = ~np.isin(numbers, (0.0, 1.0)), "true or false"
    elif key == "mean_reward":
        bad, want = ~np.isfinite(numbers), "a finite number"
    else:
        whole = np.isfinite(numbers) & (numbers == np.round(numbers)) & (numbers >= 1) & (values.dtype.kind != "b")
        bad, want = ~whole, "a whole number of steps ≥ 1"
    if bad.any():
        raise InputError(f"must be {want}, got {validation.shown(flat[np.argmax(bad)].item())}", source=source,
                         field=field)


def _check_itself(document: dict, source: str) -> None:
    """The checkpoint's fields agree with each other and with its digest (module docstring)."""
    curve, episode = document["curve"], document["episode"]
    for key in _CURVE_FIELDS:
        if len(curve[key]) != episode:
            raise InputError(f"holds {len(curve[key])} batches, but the checkpoint says {episode} were done: the "
                             "file was edited; train afresh without --resume", source=source, field=f"curve.{key}")
    for i, rows in enumerate(zip(*(curve[key] for key in _CURVE_FIELDS))):
        if len({len(row) for row in rows}) != 1:
            raise InputError("its records disagree on the number of episodes of this batch", source=source,
                             field=f"curve[{i}]")
    counted = document["learner"].get("episode", 0)
    if "digest" not in document and counted != episode:  # with a digest, its learner may have trained before
        raise InputError(f"the learner counts {validation.shown(counted)} batches of episodes, but the checkpoint "
                         f"says {episode} were done: the file was edited; train afresh without --resume",
                         source=source, field="learner.episode")


def _check_digest(document: dict, source: str) -> None:
    """The ``digest`` (when there is one) is that of the document: no field was edited. Checked
    last, so that a field edited into a bad value is named by its own check first."""
    if "digest" in document and document["digest"] != _digest(document):
        raise InputError("does not match the checkpoint's content: the file was edited or damaged; train afresh "
                         "without --resume", source=source, field="digest")


def episodes_done(curve: dict) -> int:
    """The single episodes of a learning ``curve`` (a checkpoint's, :func:`load_checkpoint`): its
    batches' sizes added (earlier batches may differ in size)."""
    return sum(len(row) for row in curve["success"])


def check_same_run(document: dict, settings: dict, budget: int | None = None, source: str = "checkpoint") -> None:
    """Refuse to resume from ``document`` when it was written by another run: every key of
    ``settings`` (and of the checkpoint's own ``extra``) must hold the same value, and the single
    episodes it has done must not exceed ``budget`` (when given)."""
    saved = document.get("extra")
    if not isinstance(saved, dict):
        raise InputError("the checkpoint does not record the settings of its run", source=source, field="extra")
    for name in sorted(settings.keys() | saved.keys()):
        if name not in saved:
            raise InputError(f"the checkpoint does not record {name} (this run: {settings[name]!r}); "
                             "train afresh without --resume", source=source, field=name)
        if saved[name] != settings.get(name):
            raise InputError(f"the checkpoint was written by a run with {name} {saved[name]!r}, this run has "
                             f"{settings.get(name)!r}: resume with the same settings, or train afresh without --resume",
                             source=source, field=name)
    done = episodes_done(document["curve"])
    if budget is not None and done > budget:
        raise InputError(f"the checkpoint has already done {done} episodes of phase {saved.get('phase', '?')!r}, "
                         f"more than the {budget} this run asks for: resume with at least as many episodes, "
                         "or train afresh without --resume", source=source, field="episodes")


def check_resumable(path, settings: dict, budget: int | None = None, learner=None) -> dict:
    """The checkpoint at ``path`` (:func:`load_checkpoint`), once known to be one a run of
    ``settings`` and ``budget`` may go on from (:func:`check_same_run`) — and ``learner``, when
    given (its settings, as :func:`restore` checks them); nothing is restored."""
    document = load_checkpoint(path)
    check_same_run(document, settings, budget, str(path))
    if learner is not None:
        _check_learner(document, learner, str(path))
    return document


def _check_learner(document: dict, learner, source: str) -> None:
    """``learner`` was built with the settings of the one saved in ``document`` (its non-state fields)."""
    saved, current = document["learner"], learner.to_dict()
    for name in current.keys() | saved.keys():
        if name not in _STATE_FIELDS and current.get(name) != saved.get(name):
            raise InputError(f"the checkpoint was written with another setting ({saved.get(name)!r} "
                             f"instead of {current.get(name)!r})", source=source, field=f"learner.{name}")


def restore(learner, rng: np.random.Generator, document: dict, source: str = "checkpoint") -> None:
    """Put a checkpoint's learner state and RNG state into ``learner`` and ``rng`` (in place).

    The learner must have been built with the same settings as the one saved (its non-state
    fields must match); otherwise the checkpoint belongs to another run and is refused.
    """
    _check_learner(document, learner, source)
    restore_state(learner, document["learner"], source)
    try:
        rng.bit_generator.state = document["rng"]
    except (TypeError, ValueError, KeyError, OverflowError) as error:
        raise InputError(f"bad RNG state ({error})", source=source, field="rng") from None
    _check_digest(document, source)


@dataclass
class TrainResult:
    """What :func:`train_loop` returns: the learner (trained in place), curve and episodes done."""

    learner: object
    curve: dict = field(default_factory=dict)
    episode: int = 0
    resumed_from: int | None = None


def run_episodes(env, learner, rng: np.random.Generator) -> dict:
    """Run one batch of B episodes with learning; per-row mean reward, steps and success."""
    obs = env.reset(rng)
    action = learner.begin(obs, rng)
    active = None
    total = steps = success = None
    while active is None or active.any():
        obs, reward, terminated, truncated, info = env.step(action, rng)
        reward = np.asarray(reward, dtype=float)
        terminated = np.asarray(terminated, dtype=bool)
        if active is None:
            active = np.ones(terminated.shape, dtype=bool)
            total, steps = np.zeros(reward.shape), np.zeros(terminated.shape)
            success = np.zeros(terminated.shape, dtype=bool)
        action = learner.step(reward, obs, terminated, rng, active)
        live = active.reshape(active.shape + (1,) * (reward.ndim - 1))
        total += reward * live
        steps += active
        finished = active & (terminated | np.asarray(truncated, dtype=bool))
        if "success" in info:
            success |= finished & np.asarray(info["success"], dtype=bool)
        active = active & ~finished
    learner.end_episode()
    mean = total / steps.reshape(steps.shape + (1,) * (total.ndim - 1))
    return {"mean_reward": mean.tolist(), "steps": steps.astype(int).tolist(),
            "success": success.tolist()}


def train_loop(env, learner, episodes: int, rng: np.random.Generator, *, checkpoint=None,
               checkpoint_every: int = 0, resume: bool = False, progress: bool = False,
               extra: dict | None = None, batch_size: int = 1, desc: str | None = None,
               budget: int | None = None) -> TrainResult:
    """Train ``learner`` for ``episodes`` batches of episodes on ``env``, resumably.

    With ``checkpoint`` (a path), a checkpoint is written every ``checkpoint_every`` batches
    (0: only at the end) and at the end; ``resume`` continues from it when it exists (the
    learner and ``rng`` are restored in place). ``progress`` shows a bar (:func:`fuzzynav.progress.bar`:
    on a terminal, unless quiet) with the episode,
    the mean reward and the success rate of the last batch. The curve maps ``mean_reward``,
    ``steps`` and ``success`` to one entry per batch (a list over its B rows). ``batch_size``
    (B) and ``desc`` only label the bar: it then counts single episodes, B per batch, starting
    from the single episodes of the curve restored (a resumed run whose earlier batches had
    another size, e.g. the smaller last batch of ``learn.tasks.plan.batch_plan``).
    ``extra`` holds the settings that shape the run and ``budget`` the single episodes it is to
    do in all: a checkpoint of another run, or one past the budget, is refused (:func:`check_same_run`).
    """
    if int(episodes) != episodes or episodes < 0:
        raise InputError(f"must be a non-negative integer, got {episodes!r}", field="episodes")
    curve = {"mean_reward": [], "steps": [], "success": []}
    start = resumed_from = None
    if checkpoint is not None:
        remove_stale_temporaries(checkpoint)
    if resume and checkpoint is not None and Path(checkpoint).exists():
        document = check_resumable(checkpoint, extra or {}, budget)
        restore(learner, rng, document, str(checkpoint))
        curve = document["curve"]
        start = resumed_from = int(document["episode"])
    start = start or 0
    done = episodes_done(curve)
    with progress_bars.quiet(not progress):
        bar = progress_bars.bar(total=done + max(int(episodes) - start, 0) * batch_size, initial=done,
                                unit="episode", desc=desc)
    episode = start
    try:
        while episode < episodes:
            record = run_episodes(env, learner, rng)
            for name, value in record.items():
                curve[name].append(value)
            episode += 1
            bar.update(batch_size)
            bar.set_postfix(reward=f"{np.mean(record['mean_reward']):.3f}",
                            success=f"{np.mean(record['success']):.0%}")
            if checkpoint is not None and checkpoint_every and episode % checkpoint_every == 0:
                save_checkpoint(checkpoint, learner, rng, episode, curve, extra)
    finally:
        bar.close()
    if checkpoint is not None:
        save_checkpoint(checkpoint, learner, rng, episode, curve, extra)
    return TrainResult(learner, curve, episode, resumed_from)
