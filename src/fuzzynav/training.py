"""Training tasks by name: ``fuzzynav train TASK`` looks them up here.

Each entry maps a task name (``anfis-tracker``, ``fql-goal``…) to ``("module:function",
description)``. The function takes a :class:`TrainRequest` and returns a dict of results
(at least ``model`` — the path written — and whatever it measured). Models are written
atomically with :func:`fuzzynav.models.save_json_atomic` / ``save_npz_atomic`` and carry a ``kind``
that :func:`fuzzynav.models.load_controller` understands.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from fuzzynav.lookup import descriptions, resolve

TRAINERS: dict[str, tuple[str, str]] = {}
TRAINERS["neural-tracker"] = ("fuzzynav.experiments.train_trackers:train_neural_tracker",
                              "MLP tracker by generalized learning (§V.3.2, Fig V.15)")
TRAINERS["anfis-tracker"] = ("fuzzynav.experiments.train_trackers:train_anfis_tracker",
                             "ANFIS tracker, 1 input, 5 bell MFs (§V.3.5, Fig V.23)")
_RL = "fuzzynav.experiments.train_rl"
TRAINERS["q-goal"] = (f"{_RL}:train_q_goal", "tabular Q-learning goal seeking, 13 states x 3 actions (§VI.2)")
TRAINERS["fql-goal"] = (f"{_RL}:train_fql_goal", "FQL goal seeking, 15 rules x 3, steering then speed (§VI.5.1)")
TRAINERS["fql-goal-35"] = (f"{_RL}:train_fql_goal_35", "FQL goal seeking, 35 rules x 5 (Figs VI.13-VI.14)")
TRAINERS["fql-goal-traces"] = (f"{_RL}:train_fql_goal_traces", "FQL goal seeking with eligibility traces (VI.16)")
TRAINERS["fql-avoid"] = (f"{_RL}:train_fql_avoid", "FQL obstacle avoidance, 8 rules x which side is more open, as a goal navigator (§VI.5.2)")
TRAINERS["fql-wall"] = (f"{_RL}:train_fql_wall", "wall follower of Table VI.2 optimised by FQL (§VI.5.3.2)")


@dataclass(frozen=True)
class TrainRequest:
    """What the user asked of one training run (defaults are each task's own when ``None``)."""

    out: Path
    task: str = ""  # the TASK name, recorded in checkpoints (a resume of another task is refused)
    episodes: int | None = None
    seed: int = 0
    resume: bool = False
    checkpoint_every: int | None = None
    curve: Path | None = None  # learning-curve plot to write, if any
    progress: bool = True


def available() -> dict[str, str]:
    """Task names with their descriptions."""
    return descriptions(TRAINERS)


def trainer(task: str):
    """The function that trains ``task``."""
    return resolve(TRAINERS, task, what="training task", field="TASK")
