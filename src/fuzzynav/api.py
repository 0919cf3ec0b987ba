"""Conveniences of the public Python API that have no home lower down (see :mod:`fuzzynav`).

:func:`train` runs a training task by name, as ``fuzzynav train TASK`` does;
:func:`list_controllers` and :func:`list_training_tasks` name what
:func:`fuzzynav.make_controller` and :func:`train` accept.
"""

from __future__ import annotations

from pathlib import Path


def list_controllers() -> dict[str, str]:
    """The built-in controller names with a one-line description each (``fuzzynav run --help``)."""
    from fuzzynav.catalog.controllers import available

    return available()


def list_training_tasks() -> dict[str, str]:
    """The training task names with a one-line description each (``fuzzynav train --help``)."""
    from fuzzynav.catalog.tasks import available

    return available()


def train(task: str, out: str | Path, *, episodes: int | None = None, seed: int = 0, resume: bool = False,
          curve: str | Path | None = None, progress: bool = False) -> dict:
    """Train the learning controller ``task`` (see :func:`list_training_tasks`) and write its model
    file to ``out``; returns the results (``model`` and what the task measured, e.g.
    ``converged_at`` per phase). ``episodes`` defaults to the task's own budget; ``curve`` writes
    the learning-curve plot (a suffix matplotlib writes, checked before training as ``train --curve``
    is: :func:`fuzzynav.viz.trajectories.figure_file`); :func:`fuzzynav.load_controller` reads the model back.
    """
    from fuzzynav import validation
    from fuzzynav.catalog.tasks import trainer
    from fuzzynav.learn.tasks.common import TrainRequest
    from fuzzynav.settings import flag
    from fuzzynav.viz.trajectories import figure_file

    validation.text(task, field="task", max_length=200)
    if episodes is not None:
        validation.count(episodes, field="episodes", hi=validation.MAX_EPISODES)
    request = TrainRequest(out=validation.file_path(out, field="out"), episodes=episodes,
                           seed=validation.seed(seed, field="seed"), resume=flag(resume, "resume"),
                           curve=None if curve is None else figure_file(curve, field="curve"),
                           progress=flag(progress, "progress"))
    return trainer(task)(request)
