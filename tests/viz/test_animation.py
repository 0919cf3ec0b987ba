"""Blitted GIF animation (viz/animation.py): frames follow the robot, the background stays."""

import numpy as np
from PIL import Image

from fuzzynav.catalog.controllers import make_controller
from fuzzynav.sim import run_episode
from fuzzynav.viz.animation import animate_episode
from fuzzynav.world.scenario import load_scenario


def _frames(path):
    with Image.open(path) as gif:
        frames, durations = [], []
        for k in range(gif.n_frames):
            gif.seek(k)
            frames.append(np.asarray(gif.convert("RGB"), dtype=int))
            durations.append(gif.info["duration"])
        return frames, durations


def test_gif_frames_follow_the_robot_over_a_fixed_world(tmp_path):
    scenario = load_scenario("fig-IV-15a")
    trace = run_episode(scenario, make_controller("fuzzy-2b-thesis"), seed=0)
    n = animate_episode(trace, scenario, tmp_path / "a.gif", max_frames=12, fps=5, size=200)
    frames, durations = _frames(tmp_path / "a.gif")
    assert n == len(frames) == 12 and set(durations[:-1]) == {200}
    assert durations[-1] == 2500  # the last frame, with the outcome, is held
    assert frames[0].shape == (200, 200, 3)  # size=200 pixels
    changed = [np.any(a != b, axis=2).mean() for a, b in zip(frames, frames[1:])]
    assert min(changed) > 0.001  # every frame moves something (robot, trail, rays, clock)
    assert max(changed) < 0.2  # ... over the same world: no redrawn or shifted background
    # the trail grows: the last frame has more trail-blue pixels than the first
    blue = [np.sum((f[..., 2] > 150) & (f[..., 0] < 90) & (f[..., 1] > 80) & (f[..., 1] < 160)) for f in (frames[0], frames[-1])]
    assert blue[1] > blue[0] + 50


def test_short_episode_keeps_every_step(tmp_path):
    scenario = load_scenario("fig-IV-15a")
    trace = run_episode(scenario, make_controller("fuzzy-2b-thesis"), seed=0, max_time=0.5)
    assert animate_episode(trace, scenario, tmp_path / "s.gif", rays=False) == len(trace.pose)
