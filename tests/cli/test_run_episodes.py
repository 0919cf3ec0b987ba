"""`fuzzynav run` and `fuzzynav scenarios` on good input (test controllers registered for the test)."""

import json

import pytest
import yaml

from fuzzynav import storage
from fuzzynav.catalog import controllers as registry, tasks
from fuzzynav.catalog.specs import ControllerSpec
from fuzzynav.cli import main

ALL = ("goal", "path", "target")
TEST_CONTROLLERS = (
    ControllerSpec("test-heading", "tests.sim.controllers:HeadingController", "proportional heading", "tests", ALL),
    ControllerSpec("test-constant", "tests.sim.controllers:ConstantController", "constant", "tests", ALL),
)


@pytest.fixture
def heading():
    for spec in TEST_CONTROLLERS:
        registry.register_controller(spec)
    yield
    for spec in TEST_CONTROLLERS:
        registry.CONTROLLERS.unregister(spec.name)


def test_json_is_one_object_with_the_metrics(heading, capsys, tmp_path):
    file = tmp_path / "open.yaml"
    file.write_text("robot: {x: 2, y: 2}\ngoal: {x: 15, y: 12}\n")
    assert main(["run", str(file), "--controller", "test-heading", "--json"]) == 0
    out = capsys.readouterr().out
    numbers = json.loads(out)
    assert out.count("\n") == 1 and isinstance(numbers, dict)
    for key in ("scenario", "controller", "reached_goal", "collision", "time_s", "path_length_m",
                "min_clearance_m", "steps"):
        assert key in numbers
    assert numbers["scenario"] == "open" and numbers["controller"] == "p-heading"
    assert numbers["reached_goal"] is True and numbers["collision"] is False


def test_collision_still_exits_0(heading, capsys):
    assert main(["run", "example-goal", "--controller", "test-heading", "--json"]) == 0
    numbers = json.loads(capsys.readouterr().out)
    assert numbers["collision"] is True and numbers["reached_goal"] is False


def test_max_time_and_summary_line(heading, capsys):
    assert main(["run", "example-goal", "--controller", "test-constant", "--max-time", "0.5"]) == 0
    out = capsys.readouterr().out
    assert out.startswith("example-goal / constant: timeout after 0.5 s")


def test_plot(heading, capsys, tmp_path):
    png = tmp_path / "out" / "run.png"
    argv = ["run", "example-path", "--controller", "test-heading", "--plot", str(png), "--rays", "--json"]
    assert main(argv) == 0
    assert json.loads(capsys.readouterr().out)["completed"] is True
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_animation(heading, capsys, tmp_path):
    gif = tmp_path / "run.gif"
    argv = ["run", "example-goal", "--controller", "test-heading", "--max-time", "0.5", "--animate", str(gif)]
    assert main(argv) == 0
    from PIL import Image

    with Image.open(gif) as image:
        assert image.format == "GIF" and image.n_frames == 6  # states at t = 0, 0.1, …, 0.5


def test_model_file(monkeypatch, capsys, tmp_path):
    loaders = {**tasks.model_loaders(), "test-heading": "tests.sim.controllers:load_heading_model"}
    monkeypatch.setattr(tasks, "model_loaders", lambda: loaders)
    model = tmp_path / "model.json"
    storage.save_json_atomic(model, {"kind": "test-heading", "gain": 2.0})
    assert main(["run", "example-target", "--model", str(model), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["task"] == "target"


def test_scenarios_lists_built_ins(capsys):
    assert main(["scenarios"]) == 0
    out = capsys.readouterr().out
    assert "example-goal" in out and "one obstacle of each shape" in out
    assert main(["scenarios", "--show", "example-path"]) == 0
    assert yaml.safe_load(capsys.readouterr().out)["path"][0] == [4, 4]
