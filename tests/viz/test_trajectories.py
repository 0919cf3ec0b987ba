from dataclasses import replace

import numpy as np

from fuzzynav.sim import run_episode
from fuzzynav.viz.animation import animate_episode
from fuzzynav.viz.trajectories import change_labels, merged_changes, plot_commands, plot_episode, plot_trajectory
from fuzzynav.world.scenario import load_scenario, scenario_from_dict
from tests.sim.controllers import HeadingController


def passing_episode():
    """The heading controller passes near a circle: behaviour goes seek → near → seek."""
    scenario = scenario_from_dict({
        "robot": {"x": 2, "y": 10}, "goal": {"x": 18, "y": 10},
        "obstacles": [{"circle": {"center": [10, 11.9], "radius": 1.0}}],
    })
    return scenario, run_episode(scenario, HeadingController())


def test_change_labels():
    assert change_labels(3) == ["A", "B", "C"]
    assert change_labels(28)[26:] == ["AA", "AB"]


def test_behaviour_change_markers_as_fig_IV_15():
    scenario, trace = passing_episode()
    assert trace.reached and list(dict.fromkeys(trace.behaviour)) == ["seek", "near"]
    changes = trace.behaviour_changes()
    assert len(changes) == 2
    ax = plot_trajectory(trace, scenario, rays=True)
    letters = [t for t in ax.texts if t.get_text() in ("A", "B")]
    assert [t.get_text() for t in letters] == ["A", "B"]
    np.testing.assert_allclose([t.xy for t in letters], trace.pose[changes, :2])
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert {"seek", "near", "A, B, …: where the behaviour changes"} <= set(legend)


def test_commands_plot_is_fig_IV_14():
    _, trace = passing_episode()
    steering_ax, speed_ax = plot_commands(trace)
    np.testing.assert_allclose(speed_ax.lines[0].get_ydata(), trace.speed)
    np.testing.assert_allclose(steering_ax.lines[0].get_ydata(), np.degrees(trace.steering))


def test_episode_png_and_gif(tmp_path):
    scenario = load_scenario("example-target")
    trace = run_episode(scenario, HeadingController(cruise=1.5, floor=0.5))
    plot_episode(trace, scenario, tmp_path / "e.png")
    assert (tmp_path / "e.png").stat().st_size > 10_000
    assert animate_episode(trace, scenario, tmp_path / "e.gif", max_frames=5) == 5
    assert (tmp_path / "e.gif").read_bytes()[:6] == b"GIF89a"


def test_bursts_of_changes_share_one_marker():
    scenario, trace = passing_episode()
    labels = trace.behaviour.copy()
    k = trace.behaviour_changes()[0]
    labels[k + 1: k + 4] = labels[k - 1]  # a flip back and forth within 0.4 s: chatter
    burst = replace(trace, behaviour=labels)
    assert len(burst.behaviour_changes()) == 4
    markers = merged_changes(burst)
    assert markers == [k, trace.behaviour_changes()[1]]
    ax = plot_trajectory(burst, scenario)
    assert [t.get_text() for t in ax.texts if t.get_text() in ("A", "B", "C", "D")] == ["A", "B"]
