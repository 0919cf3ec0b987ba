"""The plot and animation API checks its arguments as the command line does: an InputError naming
the argument, before anything is drawn or trained (never a ZeroDivisionError, a matplotlib
ValueError, a MemoryError or a GIF written under another suffix)."""

import math

import pytest
from matplotlib.figure import Figure

import fuzzynav
from fuzzynav.catalog.controllers import make_controller
from fuzzynav.errors import InputError
from fuzzynav.sim import run_episode
from fuzzynav.viz.animation import MAX_PIXELS, MAX_SIZE, animate_episode
from fuzzynav.viz.trajectories import plot_episode, plot_trajectory, save_figure
from fuzzynav.world.scenario import load_scenario


@pytest.fixture(scope="module")
def episode():
    scenario = load_scenario("fig-IV-15a")
    return run_episode(scenario, make_controller("fuzzy-2b-thesis"), seed=0), scenario


@pytest.mark.parametrize("options, field", [
    ({"fps": 0}, "fps"), ({"fps": math.nan}, "fps"), ({"fps": -1}, "fps"), ({"fps": 1000}, "fps"),
    ({"fps": "10"}, "fps"),
    ({"max_frames": 0}, "max_frames"), ({"max_frames": -1}, "max_frames"), ({"max_frames": 2.5}, "max_frames"),
    ({"size": 0}, "size"), ({"size": 10**6}, "size"), ({"size": 63}, "size"), ({"size": 100.5}, "size"),
    ({"path": "a.png"}, "path"), ({"path": 5}, "path"), ({"path": "x" * 300 + ".gif"}, "path"),
])
def test_animation_arguments_are_checked_before_drawing(episode, tmp_path, options, field):
    trace, scenario = episode
    path = options.pop("path", tmp_path / "a.gif")
    if isinstance(path, str):
        path = tmp_path / path
    (tmp_path / "folder.gif").mkdir()
    with pytest.raises(InputError, match="is a folder"):
        animate_episode(trace, scenario, tmp_path / "folder.gif", max_frames=3, size=100)
    (tmp_path / "folder.gif").rmdir()
    with pytest.raises(InputError) as caught:
        animate_episode(trace, scenario, path, **{"max_frames": 3, "size": 100, **options})
    assert caught.value.field == field
    assert list(tmp_path.iterdir()) == []


def test_animation_frames_are_bounded_in_pixels(episode, tmp_path):
    trace, scenario = episode
    assert len(trace.pose) > 101 and 100 * MAX_SIZE**2 == MAX_PIXELS  # `run --animate --size 4000` fits
    with pytest.raises(InputError, match="at most 100 frames") as caught:
        animate_episode(trace, scenario, tmp_path / "a.gif", size=MAX_SIZE, max_frames=101)
    assert caught.value.field == "max_frames"
    assert animate_episode(trace, scenario, tmp_path / "A.GIF", max_frames=2, size=64, fps=100) == 2


def test_plot_paths_must_be_figures_matplotlib_writes(episode, tmp_path):
    trace, scenario = episode
    with pytest.raises(InputError, match="x.nosuch.*cannot write '.nosuch' files") as caught:
        plot_episode(trace, scenario, tmp_path / "x.nosuch")
    assert caught.value.field == "path"
    with pytest.raises(InputError, match="is a folder"):
        plot_episode(trace, scenario, tmp_path)
    with pytest.raises(InputError, match="cannot write"):
        save_figure(Figure(), tmp_path / "y.nosuch")
    assert list(tmp_path.iterdir()) == []
    plot_episode(trace, scenario, tmp_path / "x.svg")
    assert (tmp_path / "x.svg").read_text().lstrip().startswith("<?xml")


@pytest.mark.parametrize("every", [2.5, 0, -3, "2", True])
def test_ray_every_is_an_integer_of_at_least_one(episode, every):
    trace, scenario = episode
    with pytest.raises(InputError) as caught:
        plot_trajectory(trace, scenario, rays=True, ray_every=every)
    assert caught.value.field == "ray_every"
    ax = plot_trajectory(trace, scenario, rays=True, ray_every=7)
    assert any(text.get_text() == "range sensors, every 7 steps" for text in ax.get_legend().get_texts())


def test_train_checks_the_curve_file_before_training(tmp_path):
    with pytest.raises(InputError, match="cannot write '.nosuch' files") as caught:
        fuzzynav.train("q-goal", tmp_path / "tr.json", episodes=1, curve=tmp_path / "c.nosuch")
    assert caught.value.field == "curve"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("call, field", [
    (lambda t, s, d: plot_episode(t, s, rays="no"), "rays"),
    (lambda t, s, d: plot_trajectory(t, s, rays=1), "rays"),
    (lambda t, s, d: plot_trajectory(t, s, markers="false"), "markers"),
    (lambda t, s, d: animate_episode(t, s, d / "a.gif", rays="no", max_frames=2, size=64), "rays"),
    (lambda t, s, d: fuzzynav.train("q-goal", d / "q.json", episodes=1, resume="no"), "resume"),
    (lambda t, s, d: fuzzynav.train("q-goal", d / "q.json", episodes=1, progress=None), "progress"),
])
def test_flags_are_true_or_false_not_truthy(episode, tmp_path, call, field):
    trace, scenario = episode
    with pytest.raises(InputError, match="must be true or false") as caught:
        call(trace, scenario, tmp_path)
    assert caught.value.field == field
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("draw", [
    lambda trace, other, tmp_path: plot_episode(trace, other, tmp_path / "e.png"),
    lambda trace, other, tmp_path: animate_episode(trace, other, tmp_path / "e.gif"),
    lambda trace, other, tmp_path: plot_trajectory(trace, other),
])
def test_a_trace_is_drawn_only_on_the_scenario_it_ran_on(episode, tmp_path, draw):
    # drawn on another world, its collision stood in empty space under its own title
    trace, _ = episode
    with pytest.raises(InputError, match=r"scenario: the trace was run on the goal scenario 'fig-IV-15a', not on the "
                                         r"path scenario 'example-path'"):
        draw(trace, load_scenario("example-path"), tmp_path)
    assert not list(tmp_path.iterdir())
