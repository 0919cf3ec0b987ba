"""Vectorised training environments of chapter VI (goal seeking, obstacle avoidance, wall following).

:class:`~.env.RobotEnv` steps B episodes together on the robot and world layers; the layouts of
:mod:`.layouts` say where they start; :class:`~.premise.GridPremise` is the fast premise of the
fuzzy Q-learners. The tasks themselves (which inputs, actions and rewards) are assembled in
:mod:`fuzzynav.learn.tasks`.
"""

from fuzzynav.learn.envs.env import RobotEnv, RobotState
from fuzzynav.learn.envs.layouts import FixedGoal, RandomGoal, RandomObstacles, WallCourse
from fuzzynav.learn.envs.premise import GridPremise

__all__ = ["FixedGoal", "GridPremise", "RandomGoal", "RandomObstacles", "RobotEnv", "RobotState", "WallCourse"]
