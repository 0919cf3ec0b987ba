"""What the catalog knows of a controller or a training task, said once: :class:`ControllerSpec`
and :class:`TaskSpec` (after Gymnasium's ``EnvSpec``).

A spec is registered once (:func:`fuzzynav.catalog.controllers.register_controller`,
:func:`fuzzynav.catalog.tasks.register_task`, or an installed distribution's entry point in the
groups ``fuzzynav.controllers`` / ``fuzzynav.tasks``); everything else — the ``--controller`` and
``TASK`` look-ups, the rule-base roles of ``--fis``, the refusal of a controller that cannot do a
scenario's task, the controller tables of the user guide — is derived from the specs. A spec
checks its own fields when it is made; :mod:`tests.catalog.test_controller_contract` checks every
registered controller against its spec (as scikit-learn's ``check_estimator``).
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

# the tasks a scenario can set (fuzzynav.world.scenario): reach a goal, follow a path, catch a target
TASK_KINDS = ("goal", "path", "target")
# what a controller reads besides its pose and its task (the ring it needs, or none)
SENSES = {
    "none": "the goal / path only",
    "rays": "7 range sensors",
    "lidar": "a lidar, 271 beams over 270° (which it brings)",
}
BRIEF = 60  # characters of a controller's line in ``fuzzynav run --help`` (with its name, within 85 columns)
_NAME = re.compile(r"^[a-z0-9][a-z0-9-]*$")
_TARGET = re.compile(r"^[A-Za-z_][\w.]*:[A-Za-z_]\w*$")


def _check_name(name: str, what: str) -> None:
    if not isinstance(name, str) or not _NAME.match(name):
        raise ValueError(f"{what} {name!r} is not a name (lower-case letters, digits and dashes)")


def _check_tasks(tasks, owner: str) -> None:
    if isinstance(tasks, str) or not tasks or any(task not in TASK_KINDS for task in tasks):
        raise ValueError(f"{owner}: tasks must be some of {', '.join(TASK_KINDS)}, got {tasks!r}")


def _check_target(target: str, what: str) -> None:
    if not isinstance(target, str) or not _TARGET.match(target):
        raise ValueError(f"{what} must be 'module:attribute', got {target!r}")


@dataclass(frozen=True)
class ControllerSpec:
    """A controller, as ``--controller NAME`` finds it.

    - ``factory``: ``"module:function"`` that takes keyword options and returns a
      :class:`~fuzzynav.control.base.Controller` (imported only when one is made);
    - ``description``: what it is, one line; ``citation``: its source (a thesis section or table,
      or the paper of a classic method);
    - ``tasks``: the scenario tasks it can do (of :data:`TASK_KINDS`); ``run``, ``evaluate`` and
      ``bench`` refuse the others; ``goal_directed``: it completes them (reaches the goal, the
      path's end, the target) — ``False`` for a behaviour alone, such as the wall follower, which
      runs on the task's scenarios until the time is up;
    - ``sensors``: what it reads of the world (a key of :data:`SENSES`); ``needs_map``: it is shown
      the whole map before the episode (``prepare(scenario)``, :class:`~fuzzynav.control.hooks.MapAware`);
    - ``roles``: ``{role: built-in fuzzy system}`` of the rule bases ``--fis ROLE=FILE`` may replace;
    - ``aliases``: other names it answers to (a name is never re-pointed: the old behaviour keeps
      its own name, an alias keeps an old name working); ``version``: bumped when the behaviour
      under this name changes, so recorded numbers say which one they measured;
    - ``brief``: its line in ``fuzzynav run --help``, at most :data:`BRIEF` characters, when the
      description is longer (:attr:`short`).
    """

    name: str
    factory: str
    description: str
    citation: str
    tasks: tuple[str, ...]
    sensors: str = "none"
    needs_map: bool = False
    goal_directed: bool = True
    roles: Mapping[str, str] = field(default_factory=dict)
    aliases: tuple[str, ...] = ()
    version: int = 1
    brief: str = ""

    def __post_init__(self):
        _check_name(self.name, "controller name")
        _check_target(self.factory, f"controller {self.name}: factory")
        for alias in self.aliases:
            _check_name(alias, f"controller {self.name}: alias")
        if not self.description or not self.citation:
            raise ValueError(f"controller {self.name}: give a description and a citation")
        _check_tasks(self.tasks, f"controller {self.name}")
        if self.sensors not in SENSES:
            raise ValueError(f"controller {self.name}: sensors must be one of {', '.join(SENSES)}, "
                             f"got {self.sensors!r}")
        if not isinstance(self.version, int) or self.version < 1:
            raise ValueError(f"controller {self.name}: version must be an integer >= 1, got {self.version!r}")
        if not isinstance(self.brief, str) or len(self.brief) > BRIEF:
            raise ValueError(f"controller {self.name}: brief must be at most {BRIEF} characters, got {self.brief!r}")
        object.__setattr__(self, "tasks", tuple(self.tasks))
        object.__setattr__(self, "aliases", tuple(self.aliases))
        object.__setattr__(self, "roles", MappingProxyType(dict(self.roles)))

    @property
    def summary(self) -> str:
        """The description with its source (:func:`fuzzynav.list_controllers`)."""
        return f"{self.description} ({self.citation})"

    @property
    def short(self) -> str:
        """Its line in ``fuzzynav run --help``: ``brief``, else the description up to its first
        ``;``, cut after a word (``…``) to :data:`BRIEF` characters."""
        text = self.brief or self.description.split(";")[0].strip()
        return text if len(text) <= BRIEF else text[:BRIEF - 1].rsplit(" ", 1)[0].rstrip(",:") + "…"


@dataclass(frozen=True)
class TaskSpec:
    """A training task, as ``fuzzynav train TASK`` finds it.

    ``trainer`` is ``"module:function"`` taking a
    :class:`~fuzzynav.learn.tasks.common.TrainRequest` and returning a dict of results (at least
    ``model``, the path written); the model file it writes carries ``kind``, and ``loader``
    (``"module:function"``, default: ``load_model`` of the trainer's module) builds the controller
    back from a model document of that kind; ``tasks`` are the scenario tasks such a model drives
    (a model run on another is refused, as a built-in controller is).
    """

    name: str
    trainer: str
    kind: str
    description: str
    loader: str = ""
    aliases: tuple[str, ...] = ()
    tasks: tuple[str, ...] = ("goal",)  # the scenario tasks its model drives (goal, path, target)

    def __post_init__(self):
        _check_name(self.name, "task name")
        _check_target(self.trainer, f"task {self.name}: trainer")
        _check_name(self.kind, f"task {self.name}: model kind")
        if not self.description:
            raise ValueError(f"task {self.name}: give a description")
        if not self.loader:
            object.__setattr__(self, "loader", self.trainer.split(":")[0] + ":load_model")
        _check_target(self.loader, f"task {self.name}: loader")
        _check_tasks(self.tasks, f"task {self.name}")
        object.__setattr__(self, "tasks", tuple(self.tasks))
