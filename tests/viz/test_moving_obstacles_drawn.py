"""Plots and GIFs draw moving obstacles where they are at each frame, with their tracks."""

import numpy as np
from matplotlib.figure import Figure
from PIL import Image

from fuzzynav.control.batched import ConstantCommand
from fuzzynav.sim.simulator import run_episode
from fuzzynav.viz.animation import animate_episode
from fuzzynav.viz.moving import MovingArtists, draw_moving
from fuzzynav.world.scenario import scenario_from_dict

SCENARIO = scenario_from_dict({
    "robot": {"x": 2, "y": 2}, "goal": {"x": 18, "y": 18}, "max_time": 8.0,
    "obstacles": [{"circle": {"center": [4, 10], "radius": 1.0}, "motion": {"type": "line", "velocity": [1.5, 0]}},
                  {"circle": {"center": [15, 4], "radius": 0.5}}]}, source="test")


def data_extent(ax, patch):
    vertices = (patch.get_transform() - ax.transData).transform(patch.get_path().vertices)
    return vertices.min(axis=0), vertices.max(axis=0)


def test_each_frame_places_the_obstacle_at_its_offset_and_draws_its_track_so_far():
    trace = run_episode(SCENARIO, ConstantCommand(0.0, 0.0))
    ax = Figure().add_subplot(111)
    artists = MovingArtists(ax, SCENARIO, trace)
    for k in (0, 30, 80):
        artists.show(k)
        low, high = data_extent(ax, artists.patches[0])
        np.testing.assert_allclose((low + high) / 2, [4 + 1.5 * 0.1 * k, 10], atol=1e-9)
        assert len(artists.trails.get_segments()[0]) == k + 1


def test_the_static_plot_shows_start_end_and_track():
    trace = run_episode(SCENARIO, ConstantCommand(0.0, 0.0))
    ax = Figure().add_subplot(111)
    draw_moving(ax, SCENARIO, trace)
    centres = [np.mean(data_extent(ax, p), axis=0) for p in ax.patches]
    np.testing.assert_allclose(centres, [[4, 10], [4 + 1.5 * 8.0, 10]], atol=1e-9)  # faded start, solid end
    track = ax.collections[0].get_segments()[0]
    np.testing.assert_allclose(track[[0, -1]], [[4, 10], [16, 10]], atol=1e-9)


def test_the_gif_shows_the_obstacle_moving(tmp_path):
    trace = run_episode(SCENARIO, ConstantCommand(0.0, 0.0))
    frames = animate_episode(trace, SCENARIO, tmp_path / "moving.gif", max_frames=5, rays=False)
    gif = Image.open(tmp_path / "moving.gif")
    images = []
    for i in range(frames):
        gif.seek(i)
        images.append(np.asarray(gif.convert("RGB"), dtype=int))
    assert np.abs(images[0] - images[-1]).sum() > np.abs(images[0] - images[1]).sum() > 0
