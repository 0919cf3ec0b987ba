"""Gymnasium environments of fuzzynav: the thesis' navigation tasks for any RL agent.

Importing this package registers (needs the ``rl`` extra, i.e. ``gymnasium``):

=====================================  =================================================
``fuzzynav/GoalSeeking-v0``            reach a goal in the empty workspace (§VI.5.1)
``fuzzynav/ObstacleAvoidance-v0``      reach a goal among obstacles (§VI.5.2)
``fuzzynav/WallFollowing-v0``          follow walls without touching them (§VI.5.3)
``fuzzynav/PathTracking-v0``           follow a polyline of waypoints (§V.3)
=====================================  =================================================

>>> import gymnasium, fuzzynav.gym
>>> env = gymnasium.make("fuzzynav/ObstacleAvoidance-v0", scenario="fig-IV-22a")
>>> vec = gymnasium.make_vec("fuzzynav/GoalSeeking-v0", num_envs=64, vectorization_mode="vector_entry_point")

Each id accepts the keyword arguments of :class:`~fuzzynav.gym.env.FuzzynavEnv`; ``make_vec``
with ``vectorization_mode="vector_entry_point"`` gives the batched
:class:`~fuzzynav.gym.vector.FuzzynavVectorEnv`. :class:`~fuzzynav.gym.fql_agent.FQLAgent`
trains the thesis' fuzzy Q-learning through the same interface.
"""

from __future__ import annotations

from gymnasium.envs.registration import register, registry

from fuzzynav.gym.env import FuzzynavEnv
from fuzzynav.gym.vector import FuzzynavVectorEnv

ENV_IDS = {
    "fuzzynav/GoalSeeking-v0": "goal",
    "fuzzynav/ObstacleAvoidance-v0": "avoid",
    "fuzzynav/WallFollowing-v0": "wall",
    "fuzzynav/PathTracking-v0": "path",
}

for _id, _task in ENV_IDS.items():
    if _id not in registry:
        register(id=_id, entry_point="fuzzynav.gym.env:FuzzynavEnv",
                 vector_entry_point="fuzzynav.gym.vector:FuzzynavVectorEnv", kwargs={"task": _task})

__all__ = ["ENV_IDS", "FuzzynavEnv", "FuzzynavVectorEnv"]
