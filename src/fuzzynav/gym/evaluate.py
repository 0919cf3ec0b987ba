"""Success of a policy on a fixed set of episodes, all run at once in a vector environment.

``success_rate(policy, task, episodes=100, seed=…)`` runs one episode per sub-environment of a
:class:`~fuzzynav.gym.vector.FuzzynavVectorEnv` (sub-environment i reset with ``seed + i``, or
on ``scenarios[i]``) until every one has ended, with ``policy(obs (N, n_obs)) -> actions``; the
held-out episodes are therefore the same for every agent evaluated with the same arguments.
An episode whose action is NaN or infinite ends there, counted in ``invalid_commands`` (the
environment itself refuses such an action, :mod:`.actions`; here the evaluation goes on).
"""

from __future__ import annotations

import numpy as np

from fuzzynav.gym.vector import FuzzynavVectorEnv


def success_rate(policy, task: str, *, episodes: int = 100, seed: int = 10_000, scenarios=None, **options) -> dict:
    """``{"episodes", "success", "collisions", "timeouts", "invalid_commands"}`` of ``policy`` on ``episodes`` episodes;
    ``scenarios`` (one per episode) pins sub-environment i to ``scenarios[i]``."""
    env = FuzzynavVectorEnv(episodes, task, **options)
    obs, _ = env.reset(seed=seed, options=None if scenarios is None else {"scenarios": list(scenarios)})
    ended = np.zeros(episodes, dtype=bool)
    success = np.zeros(episodes, dtype=bool)
    collision = np.zeros(episodes, dtype=bool)
    invalid = np.zeros(episodes, dtype=bool)
    while not ended.all():
        actions = np.asarray(policy(obs))
        if actions.dtype.kind == "f":  # a non-finite action ends its episode (module docstring)
            finite = np.isfinite(actions.reshape(episodes, -1)).all(axis=1)
            invalid |= ~finite & ~ended
            ended |= ~finite
            actions = np.where(finite.reshape((episodes,) + (1,) * (actions.ndim - 1)), actions, 0).astype(actions.dtype)
            if ended.all():
                break
        obs, _, terminated, truncated, info = env.step(actions)
        now = (terminated | truncated) & ~ended
        success |= now & info["success"]
        collision |= now & info["collision"]
        ended |= now
    return {"episodes": episodes, "success": float(success.mean()), "collisions": int(collision.sum()),
            "timeouts": int((~success & ~collision & ~invalid).sum()), "invalid_commands": int(invalid.sum())}
