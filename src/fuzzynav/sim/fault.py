"""Who moved into whom when a robot collides (``collision_by`` of the run JSON, docs/dynamic.md).

At the step of the collision, let n be the unit vector from the robot's centre towards the
contact (the nearest point of the obstacle it touches; reversed when the centre is inside). The
robot closed the gap by (p_k − p_{k−1}) · n, the obstacle by −(o_k − o_{k−1}) · n (o its offset,
zero for an obstacle that stands still). The collision is the ``"robot"``'s when it closed the gap
at least as much as the obstacle did — always so for a standing obstacle and for the world's
boundary — and the ``"obstacle"``'s otherwise: a robot standing still that is hit is not at fault.
This is the "at-fault" split of crowd-navigation benchmarks, where a collision counts against a
planner only when the robot moved into the other agent.
"""

from __future__ import annotations

import numpy as np

from fuzzynav.kernels import step as step_kernel


def collision_by(state, before, moved, mover_of_column, radius: float) -> np.ndarray:
    """``"robot"`` or ``"obstacle"`` for each row of ``state`` (the robots that just collided,
    :data:`fuzzynav.kernels.step.STATE_FIELDS`) whose centre was at ``before`` (R, 2) one step
    earlier; ``moved`` (M, 2) is each moving obstacle's translation over that step and
    ``mover_of_column`` maps a kernel column (and −1) to its moving obstacle's index, −1 when it
    stands still."""
    xy = state[:, step_kernel.X:step_kernel.Y + 1]
    contact = state[:, step_kernel.NEAREST_X:step_kernel.NEAREST_Y + 1] - xy
    distance = state[:, step_kernel.OBSTACLE_DISTANCE]
    contact = np.where((distance < 0)[:, None], -contact, contact)
    norm = np.hypot(contact[:, 0], contact[:, 1])
    unit = contact / np.where(norm > 0, norm, 1.0)[:, None]
    mover = mover_of_column[state[:, step_kernel.OBSTACLE_COLUMN].astype(int)]
    by_robot = np.einsum("ij,ij->i", xy - before, unit)
    by_obstacle = -np.einsum("ij,ij->i", moved[np.maximum(mover, 0)] if len(moved) else np.zeros_like(xy), unit)
    boundary = state[:, step_kernel.BOUNDARY]
    robot = (mover < 0) | ((boundary < radius) & (boundary <= distance)) | (by_robot >= by_obstacle)
    return np.where(robot, "robot", "obstacle")
