"""Scenario rules found missing in review: exit 2 naming the field instead of a traceback, a
collision at t = 0, NaN poses or a robot driven beyond its speed limit."""

import pytest

from fuzzynav.cli import main

CASES = [
    # (id, scenario text, controller, message)
    ("repeated-waypoint", "robot: {x: 1, y: 1}\npath: [[1, 1], [5, 5], [5, 5], [9, 9]]\n", "fuzzy-tracker",
     "path[2]: repeats path[1] (zero-length segment)"),
    ("single-waypoint", "robot: {x: 1, y: 1}\npath: [[5, 5]]\n", "stanley", "path: needs at least 2 points, got 1"),
    ("path-speed-above-limit", "robot: {x: 1, y: 1}\npath: [[1, 1], [5, 5]]\nspeed: 100\n", "fuzzy-tracker",
     "speed: must be at most the robot's 4 m/s, got 100"),
    ("start-on-boundary", "robot: {x: 0.1, y: 5}\ngoal: {x: 18, y: 18}\n", "goal-seeking",
     "robot: start (0.1, 5) is within the robot footprint (0.3 m) of the world boundary"),
]


@pytest.mark.parametrize("text, controller, message", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_rule(tmp_path, capsys, text, controller, message):
    path = tmp_path / "s.yaml"
    path.write_text(text)
    assert main(["run", str(path), "--controller", controller, "--json"]) == 2
    captured = capsys.readouterr()
    assert f"{path}: {message}" in captured.err and captured.out == ""


def test_speed_at_the_limit_and_start_clear_of_boundary_run(tmp_path, capsys):
    path = tmp_path / "s.yaml"
    path.write_text("robot: {x: 0.3, y: 5}\npath: [[0.3, 5], [8, 5]]\nspeed: 4\n")
    assert main(["run", str(path), "--controller", "pure-pursuit", "--json"]) == 0
    assert '"completed": true' in capsys.readouterr().out
