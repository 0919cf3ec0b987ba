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


def test_a_frame_rate_a_gif_cannot_hold_is_rounded_to_the_nearest_it_can(tmp_path):
    # a GIF's frame time is whole 10 ms: 15 fps is 66.7 ms, played as 70 (14.3 fps), not cut to 60 (16.7 fps)
    scenario = load_scenario("fig-IV-15a")
    trace = run_episode(scenario, make_controller("fuzzy-2b-thesis"), seed=0, max_time=1.0)
    for fps, step in ((15, 70), (12, 80), (100, 10), (0.1, 10000)):
        animate_episode(trace, scenario, tmp_path / "r.gif", max_frames=3, fps=fps, size=64, rays=False)
        assert set(_frames(tmp_path / "r.gif")[1][:-1]) == {step}, fps


def test_short_episode_keeps_every_step(tmp_path):
    scenario = load_scenario("fig-IV-15a")
    trace = run_episode(scenario, make_controller("fuzzy-2b-thesis"), seed=0, max_time=0.5)
    assert animate_episode(trace, scenario, tmp_path / "s.gif", rays=False) == len(trace.pose)


def test_the_legend_of_long_behaviour_names_fits_the_frame():
    """The GIF's legend stays inside the figure and off the axes' labels, however long the
    behaviours' meanings (a yielding navigator's overflowed both sides of a 400-pixel frame)."""
    from dataclasses import replace

    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from fuzzynav.viz.animation import behaviour_legend

    scenario = load_scenario("fig-IV-15a")
    trace = run_episode(scenario, make_controller("fuzzy-2b-thesis"), seed=0, max_time=1.0)
    labels = ["YIELD", "CAR-BACK", "CAR-FWD", "GAP+VRB"] * len(trace.behaviour)
    trace = replace(trace, behaviour=np.array(labels[:len(trace.behaviour)]))
    figure = Figure(figsize=(5, 5), dpi=80, layout="constrained")
    FigureCanvasAgg(figure)
    ax = figure.add_subplot(111)
    ax.set_xlabel("x (m)")
    behaviour_legend(figure, trace)
    figure.canvas.draw()
    renderer = figure.canvas.get_renderer()
    legend, frame = figure.legends[0].get_window_extent(renderer), figure.bbox
    assert frame.x0 <= legend.x0 and legend.x1 <= frame.x1 and frame.y0 <= legend.y0
    assert legend.y1 <= ax.xaxis.label.get_window_extent(renderer).y0  # below the axis label
