"""What a new user meets first: generated worlds as files, failures to rerun, a user's world in
the demo, help that lists the controllers, progress bars only on a terminal, readable numbers."""

import json
import os
import subprocess
import sys

import numpy as np
import pytest

from fuzzynav import progress
from fuzzynav.catalog.controllers import available, make_controller
from fuzzynav.cli import main
from fuzzynav.cli.demo import markdown_table
from fuzzynav.cli.printing import result_lines
from fuzzynav.sim import metrics, run_episode
from fuzzynav.viz.palette import BEHAVIOURS, behaviour_style
from fuzzynav.world.generate import generate_worlds
from fuzzynav.world.scenario import load_scenario
from tests.world.same_world import assert_same_goal_scenario


def test_worlds_generate_writes_the_worlds_evaluate_runs(tmp_path, capsys):
    assert main(["worlds", "generate", "circles", "--n", "2", "--seed", "3", "--out", str(tmp_path)]) == 0
    assert "wrote 2 scenario files" in capsys.readouterr().out
    for original in generate_worlds("circles", 2, 3):
        assert_same_goal_scenario(load_scenario(tmp_path / f"{original.name}.yaml"), original)
    assert main(["worlds", "generate", "circle", "--out", str(tmp_path)]) == 2
    assert "FAMILY" in capsys.readouterr().err


def test_save_failures_writes_worlds_that_rerun_to_the_same_outcome(tmp_path, capsys):
    out = tmp_path / "failed"
    assert main(["evaluate", "--controller", "goal-seeking", "--worlds", "mixed", "--n", "3", "--json",
                 "--save-failures", str(out)]) == 0
    result = json.loads(capsys.readouterr().out)
    failed = [run for run in result["episodes"] if run["outcome"] != "reached"]
    assert failed, "goal seeking alone should hit an obstacle in one of these worlds"
    assert sorted(p.name for p in out.iterdir()) == sorted(f"{r['scenario']}.{ext}" for r in failed
                                                           for ext in ("png", "yaml"))
    for run in failed:
        scenario = load_scenario(out / f"{run['scenario']}.yaml")
        assert scenario.controllers == ("goal-seeking",)
        again = metrics(run_episode(scenario, make_controller("goal-seeking"), seed=0), scenario)
        assert (again["outcome"], again["time_s"]) == (run["outcome"], run["time_s"])
    # a second run saves the same files again, but never over a world edited since
    assert main(["evaluate", "--controller", "goal-seeking", "--worlds", "mixed", "--n", "3", "--quiet",
                 "--save-failures", str(out)]) == 0
    edited = out / f"{failed[0]['scenario']}.yaml"
    edited.write_text(edited.read_text() + "# my change\n")
    capsys.readouterr()
    assert main(["evaluate", "--controller", "goal-seeking", "--worlds", "mixed", "--n", "3", "--quiet",
                 "--save-failures", str(out)]) == 2
    assert (f"--save-failures: {edited.name} already there, with other content (edited?): not overwritten"
            in capsys.readouterr().err)
    assert edited.read_text().endswith("# my change\n")


def test_demo_runs_a_users_world_with_the_controllers_given(tmp_path, capsys):
    world = tmp_path / "mine.yaml"
    world.write_text("robot: {x: 2, y: 2}\ngoal: {x: 15, y: 15}\nobstacles:\n  - circle: {center: [8, 8], radius: 1}\n")
    assert main(["demo", "--scenario", str(world), "--out", str(tmp_path / "none")]) == 2
    assert "--controllers" in capsys.readouterr().err
    assert main(["demo", "--scenario", str(world), "--scenario", "path-v", "--controllers", "fuzzy-2b,fuzzy-tracker",
                 "--out", str(tmp_path / "out"), "--no-plots"]) == 0
    out = capsys.readouterr().out  # each controller on the scenario whose task it can do
    assert "wrote 2 runs" in out and "left out: fuzzy-tracker on " in out and "left out: fuzzy-2b on path-v" in out
    last = out.rstrip().splitlines()[-1]  # `fuzzynav`, or the script's path when it is not on the PATH
    assert last.startswith("next: `") and "fuzzynav run fig-IV-23 --plot u.png`" in last
    table = (tmp_path / "out" / "metrics.md").read_text()
    assert "mean_cross_track_m" in table.splitlines()[0] and "| mine | fuzzy-2b |" in table
    assert main(["demo", "--scenario", str(world), "--controllers", "fuzzy-2b", "--out", str(tmp_path / "one"),
                 "--no-plots"]) == 0
    assert "wrote 1 run: " in capsys.readouterr().out  # not "1 runs"


def test_metrics_table_carries_each_tasks_own_columns():
    rows = [{"scenario": "g", "controller": "c", "task": "goal", "outcome": "reached", "time_s": 1.0},
            {"scenario": "p", "controller": "c", "task": "path", "outcome": "reached", "time_s": 2.0,
             "mean_cross_track_m": 0.0123, "max_cross_track_m": 0.2, "waypoints_reached": 3}]
    header, _, goal, path, _, legend = markdown_table(rows).splitlines()
    assert legend.startswith("time_s: simulated seconds")
    assert header.endswith("| mean_cross_track_m | max_cross_track_m | waypoints_reached |")
    assert goal.endswith("|  |  |  |") and path.endswith("| 0.012 | 0.200 | 3 |")

    # two controllers that drive alike on every scenario both ran get a line saying so
    twin = [dict(row, controller="d") for row in rows]
    assert markdown_table(rows + twin).splitlines()[-1] == (
        "c and d give the same numbers, to the digits shown, on all 2 scenarios both ran: they drive alike there.")
    twin[0]["time_s"] = 1.5
    assert "same numbers" not in markdown_table(rows + twin)


def test_run_help_lists_every_controller(capsys):
    with pytest.raises(SystemExit):
        main(["run", "--help"])
    text = capsys.readouterr().out
    assert all(name in text for name in available())
    listing = text.split("controllers (--controller NAME", 1)[1].split("\nexamples:")[0].strip().splitlines()[1:]
    assert len(listing) == len(available()) and max(map(len, listing)) <= 85  # one short line each


def test_progress_bars_only_on_a_terminal(monkeypatch):
    monkeypatch.setattr("sys.stderr.isatty", lambda: False, raising=False)
    assert not progress.enabled()
    monkeypatch.setattr("sys.stderr.isatty", lambda: True, raising=False)
    assert progress.enabled()
    with progress.quiet():
        assert not progress.enabled() and progress.bar(total=3).disable
    assert progress.enabled()
    monkeypatch.setattr("sys.stderr.fileno", lambda: 2, raising=False)
    monkeypatch.setattr("os.get_terminal_size", lambda fd: os.terminal_size((0, 0)))
    assert not progress.enabled()  # a terminal of 0 columns draws no bar: lines instead


def test_printed_results_carry_units_and_meaning():
    lines = result_lines({"train_seconds": 0.05, "validation_rmse_rad": 5e-4, "solver_iterations": 27,
                          "success_rate": 0.9})
    assert lines == ["training time: 0.05 s", "validation RMSE (steering angle): 5.00e-04 rad",
                     "solver iterations (L-BFGS): 27", "success rate: 90.0 %"]


def test_a_behaviour_keeps_its_colour_whatever_the_order():
    colours = [behaviour_style(label)[0] for label in BEHAVIOURS]
    assert behaviour_style("FOA+VRB") == BEHAVIOURS["FOA+VRB"]
    # a label of one's own gets a colour from its name, not from the labels styled before it
    probe = ("import sys; from fuzzynav.viz.palette import behaviour_style as s; "
             "[s(label) for label in sys.argv[1:]]; print(s('my own')[0])")
    drawn = {subprocess.run([sys.executable, "-c", probe, *first], capture_output=True, text=True,
                            check=True).stdout.strip() for first in ([], ["zz", "other"], ["a", "b", "c", "d"])}
    assert drawn == {behaviour_style("my own")[0]}
    assert len(set(colours[:5])) == 5  # the five-behaviour navigator's labels are told apart


def test_plot_colours_follow_the_behaviour_not_its_order():
    from fuzzynav.viz.trajectories import plot_trajectory

    scenario = load_scenario("fig-IV-15a")
    trace = run_episode(scenario, make_controller("fuzzy-2b"))
    ax = plot_trajectory(trace, scenario)
    segments = ax.collections[0]
    first = np.asarray(segments.get_colors())
    expected = {"GSB": behaviour_style("GSB")[0], "OA": behaviour_style("OA")[0]}
    from matplotlib.colors import to_rgba

    assert all(np.allclose(first[k], to_rgba(expected[str(b)])) for k, b in enumerate(trace.behaviour))
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert "GSB: goal seeking (Table IV.1)" in legend and any(t.startswith("A, B") for t in legend)


def test_a_generated_world_opens_by_the_name_evaluate_gives_it(capsys):
    from fuzzynav.world.generate import generated_world

    assert generated_world("circles-2-004").to_dict() == generate_worlds("circles", 5, 2)[4].to_dict()
    assert generated_world("fig-IV-23") is None and generated_world("mixed-a-1") is None
    assert main(["run", "circles-2-004", "--controller", "goal-seeking"]) == 0
    assert capsys.readouterr().out.startswith("circles-2-004 / goal-seeking:")
    assert main(["run", "circles-2-x", "--controller", "goal-seeking"]) == 2


def test_neural_tracker_training_reports_its_solver_iterations(tmp_path, capsys):
    assert main(["train", "neural-tracker", "--out", str(tmp_path / "nt.json")]) == 0
    lines = dict(line.split(": ", 1) for line in capsys.readouterr().out.splitlines())
    assert int(lines["solver iterations (L-BFGS)"]) > 1
    assert lines["training time"].endswith(" s") and lines["validation RMSE (steering angle)"].endswith(" rad")
    assert main(["run", "path-v", "--model", str(tmp_path / "nt.json")]) == 0


def test_animation_size_and_rate(tmp_path, capsys):
    from PIL import Image

    gif = tmp_path / "a.gif"
    assert main(["run", "fig-IV-13", "--controller", "goal-seeking", "--max-time", "2", "--animate", str(gif),
                 "--size", "160", "--fps", "20"]) == 0
    with Image.open(gif) as image:
        assert image.size == (160, 160) and image.info["duration"] == 50
    assert main(["run", "fig-IV-13", "--controller", "goal-seeking", "--animate", str(gif), "--size", "9"]) == 2
    assert "--size" in capsys.readouterr().err


def test_demo_with_only_a_goal_navigator_leaves_the_other_tasks_out(capsys):
    from fuzzynav.cli.demo import demo_runs
    from fuzzynav.errors import InputError

    skipped = []
    runs = demo_runs(controllers=["fuzzy-5b"], skipped=skipped)
    assert runs and all(controller == "fuzzy-5b" for _, controller in runs)
    assert ("path-v", "fuzzy-5b") in skipped and ("example-target", "fuzzy-5b") in skipped
    with pytest.raises(InputError, match="fuzzy-5b cannot do a path task"):
        demo_runs(["path-v"], ["fuzzy-5b"])  # a scenario named is refused, not left out
    with pytest.raises(InputError) as caught:
        demo_runs(controllers=["dwaa"])
    assert caught.value.field == "--controllers"


@pytest.mark.parametrize("command", ["demo", "warmup"])
def test_a_bad_controller_name_is_refused_before_the_compile_banner(command, tmp_path, capsys):
    assert main([command, "--controllers", "fuzzy5b", *(["--out", str(tmp_path)] if command == "demo" else [])]) == 2
    out, err = capsys.readouterr()
    assert "--controllers: unknown controller 'fuzzy5b'" in err and "compiling" not in out + err


def test_no_controller_is_made_before_the_compile_banner(monkeypatch, tmp_path):
    """Making a controller (neural-tracker) or loading a scenario may compile: numba's own notice
    must not come before the banner, two banners on a first run."""
    from fuzzynav.catalog import controllers
    from fuzzynav.cli import demo
    from fuzzynav.jit import NOTICE

    events = []
    monkeypatch.setattr(NOTICE, "said", False)
    runs = demo.demo_runs
    monkeypatch.setattr(demo, "demo_runs", lambda *a: events.append(f"runs, notice silenced: {NOTICE.said}") or runs(*a))
    monkeypatch.setattr("fuzzynav.cli.warmup.announce", lambda: events.append("announce"))
    make = controllers.make_controller
    monkeypatch.setattr(controllers, "make_controller", lambda *a, **k: events.append("make") or make(*a, **k))
    assert main(["demo", "--scenario", "fig-IV-12a", "--controllers", "goal-seeking", "--no-plots",
                 "--out", str(tmp_path / "d")]) == 0
    assert events[:2] == ["runs, notice silenced: True", "announce"] and "make" in events  # loading may compile
    events.clear()
    assert main(["warmup", "--controllers", "goal-seeking"]) == 0
    assert events[0] == "announce" and "make" in events


def test_a_thesis_figure_run_without_a_controller_says_which_it_names(capsys):
    """``run fig-IV-12a`` runs the default navigator, not the figure's: it says so and names the
    figure's own controllers (a newcomer expected Table IV.1's goal seeker)."""
    assert main(["run", "fig-IV-12a", "--max-time", "0.2"]) == 0
    out, err = capsys.readouterr()
    assert out.startswith("fig-IV-12a / fuzzy-5b:")
    assert "note: fig-IV-12a names its own controllers (goal-seeking" in err and "--controller NAME" in err
    assert main(["run", "fig-IV-12a", "--controller", "goal-seeking", "--max-time", "0.2"]) == 0
    assert "note:" not in capsys.readouterr().err


def test_no_note_when_the_default_is_among_the_scenarios_own(tmp_path, capsys):
    world = tmp_path / "opt.yaml"
    world.write_text("controllers: [fuzzy-2b, fuzzy-5b]\nrobot: {x: 2, y: 2}\ngoal: {x: 5, y: 5}\n")
    assert main(["run", str(world), "--max-time", "0.2"]) == 0
    out, err = capsys.readouterr()
    assert out.startswith("opt / fuzzy-5b:") and "note:" not in err


def test_a_path_or_target_scenario_naming_no_controller_runs_the_fuzzy_tracker(tmp_path, capsys):
    (tmp_path / "zig.yaml").write_text("robot: {x: 2, y: 2, theta: 0.5}\npath: [[3, 3], [8, 5], [12, 10]]\n")
    (tmp_path / "chase.yaml").write_text("robot: {x: 2, y: 2}\n"
                                         "target: {x: 10, y: 10, motion: {type: line, velocity: [0.3, 0]}}\n")
    for name in ("zig", "chase"):
        assert main(["run", str(tmp_path / f"{name}.yaml")]) == 0
        out, err = capsys.readouterr()
        assert out.startswith(f"{name} / fuzzy-tracker: reached after ") and "s simulated" in out and "note:" not in err


def test_a_file_named_like_a_built_in_scenario_says_which_it_runs(tmp_path, monkeypatch, capsys):
    """A file ``fig-IV-12a`` (or ``mixed-0-002``) in the folder hides the scenario of that name, and
    the run's line is labelled alike: the run says it is the file."""
    monkeypatch.chdir(tmp_path)
    for name in ("fig-IV-12a", "mixed-0-002"):
        (tmp_path / name).write_text("robot: {x: 2, y: 2}\ngoal: {x: 5, y: 5}\n")
        assert main(["run", name, "--controller", "goal-seeking", "--max-time", "0.2"]) == 0
        err = capsys.readouterr().err
        assert f"note: {name} is the file {tmp_path / name}, not the built-in scenario or generated world" in err
    (tmp_path / "mine").write_text("robot: {x: 2, y: 2}\ngoal: {x: 5, y: 5}\n")
    assert main(["run", "mine", "--controller", "goal-seeking", "--max-time", "0.2"]) == 0
    assert "note:" not in capsys.readouterr().err
