"""N robots of one task as a Gymnasium vector environment, stepped in one batched call.

``FuzzynavVectorEnv(num_envs, task, **options)`` or
``gymnasium.make_vec("fuzzynav/ObstacleAvoidance-v0", num_envs=64, vectorization_mode="vector_entry_point")``.
Sub-environment i behaves as :class:`~fuzzynav.gym.env.FuzzynavEnv` reset with ``seed + i``
(the seeding of ``gymnasium.vector.SyncVectorEnv``) and afterwards drawing its episodes from its
own generator, so the same seeds and actions give the same observations.

Autoreset follows Gymnasium's default ``AutoresetMode.NEXT_STEP``: the step that ends an episode
returns its last observation with ``terminated`` / ``truncated``; the next ``step`` call resets
that sub-environment — ignoring its action — and returns the new episode's first observation with
reward 0 and both flags false. ``info`` holds arrays over the sub-environments
(``reward_heads`` (N, H), ``success``, ``collision``), each with its ``_name`` mask.
"""

from __future__ import annotations

import numpy as np
from gymnasium.utils import seeding
from gymnasium.vector import AutoresetMode, VectorEnv
from gymnasium.vector.utils import batch_space

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.gym.episodes import OPTIONS, Episodes


class FuzzynavVectorEnv(VectorEnv):
    """``num_envs`` robots of one task (options as :class:`~fuzzynav.gym.env.FuzzynavEnv`, no rendering)."""

    metadata = {"autoreset_mode": AutoresetMode.NEXT_STEP, "render_modes": []}

    def __init__(self, num_envs: int, task: str = "goal", **options):
        validation.count(num_envs, field="num_envs", hi=validation.MAX_ROBOTS)
        if options.pop("render_mode", None) is not None:
            raise InputError("the vector environment does not render; render one FuzzynavEnv", field="render_mode")
        validation.known_keys(options, OPTIONS, field="options")
        self.num_envs = int(num_envs)
        self.episodes = Episodes(self.num_envs, task, **options)
        self.single_observation_space = self.episodes.observation_space
        self.single_action_space = self.episodes.action_space
        self.observation_space = batch_space(self.single_observation_space, self.num_envs)
        self.action_space = batch_space(self.single_action_space, self.num_envs)
        self.render_mode = None
        self._rngs = [seeding.np_random()[0] for _ in range(self.num_envs)]
        self._ended = np.zeros(self.num_envs, dtype=bool)
        self._started = False

    def reset(self, *, seed: int | list | None = None, options: dict | None = None):
        """New episodes everywhere; ``seed`` an int (sub-env i gets ``seed + i``) or a list;
        ``options={"scenarios": [...]}`` starts sub-env i on the i-th scenario (e.g. held-out worlds)."""
        if seed is None:
            seeds = [None] * self.num_envs
        elif isinstance(seed, (int, np.integer)):
            seeds = [validation.seed(seed, field="seed") + i for i in range(self.num_envs)]
        else:
            seeds = [None if s is None else validation.seed(s, field=f"seed[{i}]")
                     for i, s in enumerate(validation.sequence(seed, field="seed"))]
            if len(seeds) != self.num_envs:
                raise InputError(f"{len(seeds)} seeds for {self.num_envs} environments", field="seed")
        for i, s in enumerate(seeds):
            if s is not None:
                self._rngs[i] = seeding.np_random(s)[0]
        scenarios = validation.known_keys({} if options is None else options, ("scenarios",),
                                         field="options").get("scenarios")
        self.episodes.start(range(self.num_envs), self._rngs, scenarios)
        self._ended[:] = False
        self._started = True
        return self.episodes.observe(), {}

    def step(self, actions):
        if not self._started:
            raise RuntimeError("call reset() before step()")
        ended = self._ended.copy()
        rewards, terminated, truncated, info = self.episodes.step(actions, ~ended)
        if ended.any():
            rows = np.flatnonzero(ended)
            self.episodes.start(rows, [self._rngs[i] for i in rows])
        self._ended = terminated | truncated
        mask = np.ones(self.num_envs, dtype=bool)
        infos = {}
        for key, value in info.items():
            infos[key], infos[f"_{key}"] = value, mask
        return self.episodes.observe(), rewards, terminated, truncated, infos
