"""Training tasks and the model kinds they write: ``fuzzynav train TASK`` and ``--model FILE``.

Each task is one :class:`~fuzzynav.catalog.specs.TaskSpec`, registered once below with
:func:`register_task` (a name taken twice is an error): its name (``anfis-tracker``,
``fql-goal``…), its module of :mod:`fuzzynav.learn.tasks`, whose ``train_<task>`` function takes a
:class:`~fuzzynav.learn.tasks.common.TrainRequest` and returns a dict of results (at least
``model``, the path written), the ``kind`` of the model file it writes and a description. The same
module's ``load_model(document, path)`` builds the controller back, so :func:`model_loaders`
(kind → ``"module:load_model"``) is derived from the specs. A task from outside the package is
registered the same way — :func:`register_task` — or by an installed distribution's entry point
in the group ``fuzzynav.tasks`` (an object: a spec or a list of specs).
"""

from __future__ import annotations

from pathlib import Path

from fuzzynav import validation
from fuzzynav.catalog.specs import TaskSpec
from fuzzynav.errors import InputError
from fuzzynav.lookup import Registry, load, unknown
from fuzzynav.storage import read_document


def _one_loader_per_kind(spec: TaskSpec, registered: list[TaskSpec]) -> None:
    """A model kind is read by one loader and drives one set of scenario tasks: a new task of a
    known kind must name the same ones."""
    for other in registered:
        if other.kind == spec.kind and other.loader != spec.loader:
            raise ValueError(f"model kind {spec.kind!r} is already read by {other.loader} (task {other.name}), "
                             f"not {spec.loader}")
        if other.kind == spec.kind and other.tasks != spec.tasks:
            raise ValueError(f"model kind {spec.kind!r} drives {', '.join(other.tasks)} tasks (task {other.name}), "
                             f"not {', '.join(spec.tasks)}")


TASKS: Registry[TaskSpec] = Registry("training task", "TASK", TaskSpec, group="fuzzynav.tasks",
                                     check=_one_loader_per_kind)


def register_task(spec: TaskSpec) -> TaskSpec:
    """Add ``spec`` to the training tasks (a ``ValueError`` when its name is taken, or when its
    model kind is read by another loader)."""
    return TASKS.register(spec)


def _thesis_task(name: str, module: str, kind: str, description: str, tasks: tuple[str, ...] = ("goal",)) -> None:
    """Register the task ``name`` of ``fuzzynav.learn.tasks.<module>``: its function is ``train_``
    + its name (``fql-goal-35`` -> ``train_fql_goal_35``)."""
    register_task(TaskSpec(name, f"fuzzynav.learn.tasks.{module}:train_{name.replace('-', '_')}", kind, description,
                           tasks=tasks))


TRACKING = ("path", "target")  # the trackers' scenario tasks, as the built-in trackers' (catalog.controllers)
_thesis_task("neural-tracker", "trackers", "neural-tracker", "MLP tracker by generalized learning (§V.3.2, Fig V.15)",
             TRACKING)
_thesis_task("anfis-tracker", "trackers", "anfis-tracker", "ANFIS tracker, 1 input, 5 Gaussian MFs (§V.3.5, Fig V.23)",
             TRACKING)
_thesis_task("q-goal", "tabular_goal", "q-goal", "tabular Q-learning goal seeking, 13 states x 3 actions (§VI.2)")
_thesis_task("fql-goal", "fql_goal", "fql-goal", "FQL goal seeking, 15 rules x 3, steering then speed (§VI.5.1)")
_thesis_task("fql-goal-35", "fql_goal", "fql-goal", "FQL goal seeking, 35 rules x 5 (Figs VI.13-VI.14)")
_thesis_task("fql-goal-traces", "fql_goal", "fql-goal", "FQL goal seeking with eligibility traces (Fig VI.16)")
_thesis_task("fql-avoid", "fql_avoid", "fql-avoid",
             "FQL obstacle avoidance, 8 rules x which side is more open, as a goal navigator (§VI.5.2)")
_thesis_task("fql-wall", "fql_wall", "fql-wall", "wall follower of Table VI.2 optimised by FQL (§VI.5.3.2)")


def model_loaders() -> dict[str, str]:
    """kind -> ``"module:function"`` of the loader of that model kind; a loader takes (the parsed
    document, the path) and returns a Controller."""
    return {spec.kind: spec.loader for spec in TASKS.values()}


def available() -> dict[str, str]:
    """Task names with their descriptions."""
    return {name: TASKS[name].description for name in sorted(TASKS)}


def trainer(task: str):
    """The function that trains ``task``."""
    return load(TASKS.find(task).trainer)


def load_controller(path, task: str | None = None):
    """Build the controller stored in a model file (JSON or NPZ), whatever its kind; with a
    scenario ``task`` (goal, path, target), refuse a model whose kind does not drive it."""
    document = read_document(validation.file_path(path, field="model"))
    kind = document["kind"]
    loaders = model_loaders()
    if kind == "fuzzynav-checkpoint":  # learn.checkpoint.KIND
        raise InputError("a training checkpoint, not a model: `fuzzynav train TASK --out FILE --resume` goes on "
                         "from it, and FILE is the model to run", source=str(path), field="kind")
    if kind not in loaders:  # a close kind suggested (Q-goal: q-goal)
        raise InputError(unknown(loaders, kind, what="model kind", field="kind").problem, source=str(path), field="kind")
    tasks = {spec.kind: spec.tasks for spec in TASKS.values()}.get(kind)  # None: a loader without a task spec
    if task is not None and tasks is not None and task not in tasks:
        raise InputError(f"this {kind} model cannot do a {task} task (it does: {', '.join(tasks)})",
                         source=str(path), field="--model")
    return load(loaders[kind])(document, Path(path))
