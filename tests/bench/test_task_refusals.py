"""A controller is never run on worlds of a task it cannot do: ``demo``, ``bench`` on a folder of
scenario files, a campaign planned in Python and :func:`fuzzynav.evaluate` refuse it first, with
:func:`fuzzynav.catalog.controllers.check_task`'s message naming the scenario; and every argument
of :func:`fuzzynav.evaluate` is checked (an InputError naming it, never a TypeError)."""

import pytest

from fuzzynav.bench.campaign import Plan, run_campaign
from fuzzynav.bench.evaluate import evaluate
from fuzzynav.bench.suites import parse_suite
from fuzzynav.cli import main
from fuzzynav.cli.demo import demo_runs
from fuzzynav.errors import InputError
from fuzzynav.world.scenario import load_scenario
from fuzzynav.world.scenario_file import save_scenario


@pytest.mark.parametrize("scenario, controller, task", [("fig-IV-23", "fuzzy-tracker", "goal"),
                                                        ("path-n", "goal-seeking", "path")])
def test_demo_refuses_a_controller_of_another_task_before_any_run(scenario, controller, task, tmp_path, capsys):
    out = tmp_path / "d1"
    assert main(["demo", "--scenario", scenario, "--controllers", controller, "--out", str(out), "--no-plots"]) == 2
    err = capsys.readouterr().err
    assert f"{scenario}: --controllers: {controller} cannot do a {task} task" in err
    assert not out.exists()


def test_demo_runs_each_controller_given_on_the_scenarios_whose_task_it_can_do():
    skipped: list = []
    runs = demo_runs(["fig-IV-23", "path-n"], ["goal-seeking", "fuzzy-tracker"], skipped)
    assert runs == [("fig-IV-23", "goal-seeking"), ("path-n", "fuzzy-tracker")]
    assert skipped == [("fig-IV-23", "fuzzy-tracker"), ("path-n", "goal-seeking")]
    with pytest.raises(InputError, match="goal-seeking cannot do a path task") as caught:
        demo_runs(["fig-IV-23", "path-n"], ["goal-seeking"])
    assert (caught.value.source, caught.value.field) == ("path-n", "--controllers")


def test_demo_refuses_a_scenario_files_own_controller_of_another_task(tmp_path):
    world = tmp_path / "mine.yaml"
    world.write_text("robot: {x: 2, y: 2}\ngoal: {x: 15, y: 15}\ncontrollers: [goal-seeking, fuzzy-tracker]\n")
    with pytest.raises(InputError, match="fuzzy-tracker cannot do a goal task") as caught:
        demo_runs([str(world)])
    assert (caught.value.source, caught.value.field) == (str(world), "controllers[1]")
    assert len(demo_runs()) > 10  # the built-in scenarios' own lists all fit their tasks


@pytest.fixture
def mixed_folder(tmp_path):
    folder = tmp_path / "F"
    for name, file in (("fig-IV-23", "a-goal.yaml"), ("path-n", "p.yaml"), ("fig-V-29", "t.yaml")):
        save_scenario(load_scenario(name), folder / file)
    return folder


def test_bench_refuses_a_folder_file_of_another_task_before_any_run(mixed_folder, tmp_path, capsys):
    out = tmp_path / "bp"
    assert main(["bench", str(mixed_folder), "--controllers", "goal-seeking", "--out", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert f"{mixed_folder / 'p.yaml'}: --controllers: goal-seeking cannot do a path task" in err
    assert "campaign runs goal tasks only" in err
    assert not out.exists()


def test_a_campaign_planned_in_python_is_checked_too(mixed_folder, tmp_path):
    tracker = Plan((parse_suite("circles:1"),), (("fuzzy-tracker", "fuzzy-tracker"),), 1, 0.3)
    with pytest.raises(InputError, match="fuzzy-tracker cannot do a goal task") as caught:
        run_campaign(tracker, tmp_path / "o1", progress=False)
    assert caught.value.source == "circles:1:0"
    model = Plan((parse_suite(str(mixed_folder)),), (("m", str(tmp_path / "m.json")),), 1, 0.3)
    with pytest.raises(InputError, match="model file m cannot do a path task") as caught:
        run_campaign(model, tmp_path / "o2", progress=False)
    assert caught.value.source == str(mixed_folder / "p.yaml")
    assert not (tmp_path / "o1").exists() and not (tmp_path / "o2").exists()


def test_evaluate_refuses_a_controller_that_cannot_do_goal_tasks():
    with pytest.raises(InputError, match="fuzzy-tracker cannot do a goal task") as caught:
        evaluate(controller="fuzzy-tracker", worlds="mixed", n=1)
    assert caught.value.field == "controller"


@pytest.mark.parametrize("argument, value", [
    ("workers", "2"), ("workers", None), ("workers", 2.5), ("workers", 0), ("progress", 5), ("options", 5),
    ("options", {1: 2}), ("systems", 5), ("model", 5), ("save_failures", 5), ("sensors", []), ("controller", 5),
])
def test_evaluate_checks_each_arguments_type(argument, value):
    arguments = {"controller": "goal-seeking", "worlds": "circles", "n": 1, argument: value}
    if argument == "model":
        arguments["controller"] = None
    with pytest.raises(InputError) as caught:
        evaluate(**arguments)
    assert caught.value.field == argument


def test_evaluate_wants_a_folder_to_save_failures_in(tmp_path):
    (tmp_path / "file").write_text("")
    with pytest.raises(InputError, match="is a file; give a folder") as caught:
        evaluate("goal-seeking", "circles", 1, save_failures=tmp_path / "file")
    assert caught.value.field == "save_failures"
    with pytest.raises(InputError, match="not a usable folder name") as caught:
        evaluate("goal-seeking", "circles", 1, save_failures=tmp_path / ("x" * 300) / "y")
    assert caught.value.field == "save_failures"
