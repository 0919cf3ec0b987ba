"""Training tasks and the model kinds they write: ``fuzzynav train TASK`` and ``--model FILE``.

:data:`TASKS` is the one table: a task name (``anfis-tracker``, ``fql-goal``…) maps to
``("module:function", kind, description)``. The function, in a module of
:mod:`fuzzynav.learn.tasks`, takes a :class:`~fuzzynav.learn.tasks.common.TrainRequest` and
returns a dict of results (at least ``model``, the path written). The model file it writes carries
``kind``; the same module's ``load_model(document, path)`` builds the controller back, so
:data:`MODEL_LOADERS` (kind → ``"module:load_model"``) is derived from this table.
"""

from __future__ import annotations

from importlib import import_module
from pathlib import Path

from fuzzynav.errors import InputError
from fuzzynav.lookup import descriptions, resolve
from fuzzynav.storage import read_document

_TASKS = "fuzzynav.learn.tasks"
TASKS: dict[str, tuple[str, str, str]] = {}
TASKS["neural-tracker"] = (f"{_TASKS}.trackers:train_neural_tracker", "neural-tracker",
                           "MLP tracker by generalized learning (§V.3.2, Fig V.15)")
TASKS["anfis-tracker"] = (f"{_TASKS}.trackers:train_anfis_tracker", "anfis-tracker",
                          "ANFIS tracker, 1 input, 5 bell MFs (§V.3.5, Fig V.23)")
TASKS["q-goal"] = (f"{_TASKS}.tabular_goal:train_q_goal", "q-goal",
                   "tabular Q-learning goal seeking, 13 states x 3 actions (§VI.2)")
TASKS["fql-goal"] = (f"{_TASKS}.fql_goal:train_fql_goal", "fql-goal",
                     "FQL goal seeking, 15 rules x 3, steering then speed (§VI.5.1)")
TASKS["fql-goal-35"] = (f"{_TASKS}.fql_goal:train_fql_goal_35", "fql-goal",
                        "FQL goal seeking, 35 rules x 5 (Figs VI.13-VI.14)")
TASKS["fql-goal-traces"] = (f"{_TASKS}.fql_goal:train_fql_goal_traces", "fql-goal",
                            "FQL goal seeking with eligibility traces (VI.16)")
TASKS["fql-avoid"] = (f"{_TASKS}.fql_avoid:train_fql_avoid", "fql-avoid",
                      "FQL obstacle avoidance, 8 rules x which side is more open, as a goal navigator (§VI.5.2)")
TASKS["fql-wall"] = (f"{_TASKS}.fql_wall:train_fql_wall", "fql-wall",
                     "wall follower of Table VI.2 optimised by FQL (§VI.5.3.2)")

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
    document = read_document(path)
    kind = document["kind"]
    if kind not in MODEL_LOADERS:
        raise InputError(
            f"unknown model kind {kind!r}; known: {', '.join(sorted(MODEL_LOADERS)) or 'none'}",
            source=str(path),
            field="kind",
        )
    module_name, loader_name = MODEL_LOADERS[kind].split(":")
    return getattr(import_module(module_name), loader_name)(document, Path(path))
