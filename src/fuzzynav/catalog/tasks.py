"""Training tasks and the model kinds they write: ``fuzzynav train TASK`` and ``--model FILE``.

:data:`TASKS` is the one table: a task name (``anfis-tracker``, ``fql-goal``…) maps to
``("module:function", kind, description)``, written as one line per task: its module of
:mod:`fuzzynav.learn.tasks`, whose ``train_<task>`` function takes a
:class:`~fuzzynav.learn.tasks.common.TrainRequest` and returns a dict of results (at least
``model``, the path written). The model file it writes carries ``kind``; the same module's
``load_model(document, path)`` builds the controller back, so :data:`MODEL_LOADERS` (kind →
``"module:load_model"``) is derived from this table.
"""

from __future__ import annotations

from importlib import import_module
from pathlib import Path

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.lookup import descriptions, resolve
from fuzzynav.storage import read_document


def _tasks(table: dict[str, tuple[str, str, str]]) -> dict[str, tuple[str, str, str]]:
    """The entries of ``table`` (task -> (module of :mod:`fuzzynav.learn.tasks`, kind, description)):
    each task's function is ``train_`` + its name (``fql-goal-35`` -> ``train_fql_goal_35``)."""
    return {task: (f"fuzzynav.learn.tasks.{module}:train_{task.replace('-', '_')}", kind, text)
            for task, (module, kind, text) in table.items()}


TASKS: dict[str, tuple[str, str, str]] = _tasks({
    "neural-tracker": ("trackers", "neural-tracker", "MLP tracker by generalized learning (§V.3.2, Fig V.15)"),
    "anfis-tracker": ("trackers", "anfis-tracker", "ANFIS tracker, 1 input, 5 bell MFs (§V.3.5, Fig V.23)"),
    "q-goal": ("tabular_goal", "q-goal", "tabular Q-learning goal seeking, 13 states x 3 actions (§VI.2)"),
    "fql-goal": ("fql_goal", "fql-goal", "FQL goal seeking, 15 rules x 3, steering then speed (§VI.5.1)"),
    "fql-goal-35": ("fql_goal", "fql-goal", "FQL goal seeking, 35 rules x 5 (Figs VI.13-VI.14)"),
    "fql-goal-traces": ("fql_goal", "fql-goal", "FQL goal seeking with eligibility traces (VI.16)"),
    "fql-avoid": ("fql_avoid", "fql-avoid",
                  "FQL obstacle avoidance, 8 rules x which side is more open, as a goal navigator (§VI.5.2)"),
    "fql-wall": ("fql_wall", "fql-wall", "wall follower of Table VI.2 optimised by FQL (§VI.5.3.2)"),
})
TRAINERS: dict[str, tuple[str, str]] = {name: (train, text) for name, (train, _, text) in TASKS.items()}
# kind -> "module:loader"; a loader takes (the parsed document, the path) and returns a Controller.
MODEL_LOADERS: dict[str, str] = {kind: train.split(":")[0] + ":load_model" for train, kind, _ in TASKS.values()}


def available() -> dict[str, str]:
    """Task names with their descriptions."""
    return descriptions(TRAINERS)


def trainer(task: str):
    """The function that trains ``task``."""
    return resolve(TRAINERS, task, what="training task", field="TASK")


def load_controller(path):
    """Build the controller stored in a model file (JSON or NPZ), whatever its kind."""
    document = read_document(validation.file_path(path, field="model"))
    kind = document["kind"]
    if kind not in MODEL_LOADERS:
        raise InputError(
            f"unknown model kind {kind!r}; known: {', '.join(sorted(MODEL_LOADERS)) or 'none'}",
            source=str(path),
            field="kind",
        )
    module_name, loader_name = MODEL_LOADERS[kind].split(":")
    return getattr(import_module(module_name), loader_name)(document, Path(path))
