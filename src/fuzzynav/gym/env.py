"""The Gymnasium environment of one robot: ``gymnasium.make("fuzzynav/GoalSeeking-v0", ...)``.

A batch of one of :class:`~fuzzynav.gym.episodes.Episodes`; see :mod:`fuzzynav.gym.tasks` for the
observations, actions and rewards of each task and :mod:`fuzzynav.gym.sources` for the worlds.
``render_mode="rgb_array"`` returns the frame as an (H, W, 3) array, ``"human"`` draws it in a
matplotlib window (:mod:`.render`).
"""

from __future__ import annotations

import gymnasium
import numpy as np

from fuzzynav import validation
from fuzzynav.errors import InputError
from fuzzynav.gym.episodes import OPTIONS, Episodes

RENDER_MODES = ("human", "rgb_array")


class FuzzynavEnv(gymnasium.Env):
    """One tricycle robot on one task (``task``: ``goal``, ``avoid``, ``wall``, ``path``).

    Keyword arguments: ``actions`` (``"continuous"`` Box (α, V_r) or ``"discrete"``: the thesis'
    candidate actions), ``reward`` (``"thesis"`` or ``"dense"``), ``scenario`` (a scenario file,
    a built-in name such as ``"fig-IV-22a"``, a :class:`~fuzzynav.world.scenario.Scenario`, or a
    list of them), ``worlds`` (a generated family ``"circles"`` / ``"mixed"`` — pool of
    ``n_worlds`` numbered by ``world_seed`` — or a layout ``"random-goal"``,
    ``"random-obstacles"``, ``"wall-course"``, ``"random-paths"``), ``max_steps``,
    ``decision_steps`` (steps Δt = 0.1 s per action), ``render_mode``. Counts are bounded and
    actions checked (:class:`~fuzzynav.gym.episodes.Episodes`, :mod:`fuzzynav.gym.actions`):
    a NaN, infinite, mis-shaped or out-of-range discrete action is an ``InputError``; so is a
    scenario whose robot is not ``params`` (default the thesis' robot), or that sets the robot's
    imperfections or another sensor ring (:func:`~fuzzynav.gym.sources.check_robot`).
    """

    metadata = {"render_modes": list(RENDER_MODES), "render_fps": 10}

    def __init__(self, task: str = "goal", *, render_mode: str | None = None, **options):
        if render_mode is not None and render_mode not in RENDER_MODES:
            raise InputError(f"must be one of {', '.join(RENDER_MODES)} or None, got {render_mode!r}",
                             field="render_mode")
        validation.known_keys(options, OPTIONS, field="options")
        self.episodes = Episodes(1, task, **options)
        self.observation_space = self.episodes.observation_space
        self.action_space = self.episodes.action_space
        self.render_mode = render_mode
        self._renderer = None
        self._live = np.ones(1, dtype=bool)
        self._started = False  # no episode before the first reset()

    @property
    def scenario(self):
        """The scenario of the current episode (world, start, goal or path)."""
        return self.episodes.batch.scenarios[0]

    def reset(self, *, seed: int | None = None, options: dict | None = None):
        """A new episode (``options={"scenario": …}``: on that scenario, a name, file or object)."""
        super().reset(seed=None if seed is None else validation.seed(seed, field="seed"))
        scenario = validation.known_keys({} if options is None else options, ("scenario",), field="options").get("scenario")
        self.episodes.start([0], [self.np_random], None if scenario is None else [scenario])
        self._live[0] = True
        self._started = True
        if self.render_mode == "human":
            self.render()
        return self.episodes.observe()[0], {}

    def step(self, action):
        """One action (checked, :mod:`fuzzynav.gym.actions`); a RuntimeError before :meth:`reset`
        or after the episode has ended."""
        if not self._started:
            raise RuntimeError("call reset() before step()")
        if not self._live[0]:
            raise RuntimeError("the episode has ended: call reset()")
        rewards, terminated, truncated, info = self.episodes.step(action, self._live, single=True)
        self._live[0] = not (terminated[0] or truncated[0])
        if self.render_mode == "human":
            self.render()
        return (self.episodes.observe()[0], float(rewards[0]), bool(terminated[0]), bool(truncated[0]),
                {"reward_heads": info["reward_heads"][0], "success": bool(info["success"][0]),
                 "collision": bool(info["collision"][0])})

    def render(self):
        """The frame of the current episode (``render_mode``); a RuntimeError before :meth:`reset`."""
        if self.render_mode is None:
            gymnasium.logger.warn("render() without a render_mode: pass render_mode='rgb_array' or 'human'")
            return None
        if not self._started:
            raise RuntimeError("call reset() before render()")
        from fuzzynav.gym.render import Renderer

        if self._renderer is None:
            self._renderer = Renderer(self.render_mode, self.metadata["render_fps"])
        batch = self.episodes.batch
        state = batch.state
        ranges = None if state.ranges is None else state.ranges[0]
        return self._renderer.draw(self.scenario, batch.pose[0], batch.target[0] if self.episodes.task.goal else None,
                                   batch.sensors, ranges, batch.obstacle_offsets(0))

    def close(self):
        if self._renderer is not None:
            self._renderer.close()
            self._renderer = None
