"""The record of one episode: arrays over time (docs/ARCHITECTURE.md, "Data flow of one run").

Row k of the *state* arrays (``t``, ``pose``, ``ranges``, ``target``, ``waypoint_index``) is the
state at t_k = k Δt, k = 0 … K; row k of the *command* arrays (``steering``, ``speed``,
``behaviour``) is the clipped command applied from t_k to t_{k+1}, k = 0 … K − 1. So states
have one row more than commands, and ``steps`` = K.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

OUTCOMES = ("reached", "collision", "timeout", "invalid_command")


@dataclass(frozen=True)
class Trace:
    """One robot's episode. ``outcome`` is ``"reached"`` (goal reached, path completed or target
    captured), ``"collision"`` (footprint touched an obstacle or the boundary), ``"timeout"`` or
    ``"invalid_command"`` (the controller returned a NaN or infinite command: ``invalid_command``
    says at which step and what, :mod:`fuzzynav.sim.commands`)."""

    scenario: str
    controller: str
    task: str
    dt: float
    t: np.ndarray  # (K+1,)
    pose: np.ndarray  # (K+1, 3)
    ranges: np.ndarray  # (K+1, S) readings sensed at each state
    target: np.ndarray  # (K+1, 2) point aimed at (goal, current waypoint, target position)
    waypoint_index: np.ndarray  # (K+1,) int (0 outside path tasks)
    steering: np.ndarray  # (K,) rad
    speed: np.ndarray  # (K,) m/s
    behaviour: np.ndarray  # (K,) str: active behaviour label (Fig IV.15 A…H)
    sensor_angles: np.ndarray  # (S,)
    max_range: float
    outcome: str
    robot_radius: float
    collision_by: str | None = None  # "robot" | "obstacle" after a collision (fuzzynav.sim.fault)
    obstacle_offsets: np.ndarray | None = None  # (K+1, M, 2) translations of the moving obstacles, None: static
    invalid_command: str | None = None  # "step 3: steering nan, speed 1.0" when the outcome is "invalid_command"

    @property
    def steps(self) -> int:
        """Number of control steps (commands) in the episode."""
        return int(len(self.steering))

    @property
    def time(self) -> float:
        """Duration of the episode (s)."""
        return float(self.t[-1])

    @property
    def reached(self) -> bool:
        """True when the task was achieved (goal reached, path completed, target captured)."""
        return self.outcome == "reached"

    @property
    def collision(self) -> bool:
        """True when the episode ended in a collision."""
        return self.outcome == "collision"

    def behaviour_changes(self) -> list[int]:
        """Command indices k where the active behaviour differs from the one at k − 1."""
        labels = self.behaviour
        return [k for k in range(1, len(labels)) if labels[k] != labels[k - 1]]
