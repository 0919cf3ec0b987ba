"""The batches a phase of a learning task runs: full batches of its robots, then one smaller last
batch of the remainder, counted from where its checkpoint stopped when the run is resumed."""

from __future__ import annotations

from pathlib import Path

from fuzzynav.learn.checkpoint import episodes_done, load_checkpoint


def batch_plan(episodes: int, batch: int, done: tuple[int, int] = (0, 0)) -> list[tuple[int, int]]:
    """(batches to reach, episodes per batch) of a phase of ``episodes`` single episodes: full
    batches of ``batch``, then one last batch of the remainder (fewer parallel episodes) if any.
    ``done``: the (batches, single episodes) a resumed checkpoint has already run, whose last batch
    may have been a smaller one — the plan covers the episodes still to run."""
    batches, singles = done
    full, rest = divmod(max(int(episodes) - singles, 0), int(batch))
    plan = [(batches + n, size) for n, size in ((full, batch), (full + 1, rest)) if n and size]
    return plan or [(batches, batch)]  # nothing left to run: the loop only restores the checkpoint


def checkpoint_progress(path: Path, resume: bool) -> tuple[int, int]:
    """(batches, single episodes) done by the checkpoint at ``path`` when resuming from it, else (0, 0)."""
    if not (resume and Path(path).exists()):
        return 0, 0
    document = load_checkpoint(path)
    return int(document["episode"]), episodes_done(document["curve"])
