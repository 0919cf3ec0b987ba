"""Every scenario validation rule through the command line: exit 2, the message names the field."""

from pathlib import Path

import pytest

from fuzzynav.cli import main

GOOD = {
    "robot": "robot: {x: 1.0, y: 1.0, theta: 0.0}",
    "goal": "goal: {x: 18.0, y: 18.0, tolerance: 0.3}",
    "obstacles": "obstacles:\n  - circle: {center: [5, 5], radius: 1.0}",
}


def scenario_text(**replace):
    parts = {**GOOD, **replace}
    return "\n".join(v for v in parts.values() if v) + "\n"


CASES = [
    # (id, file text, text expected in the message)
    ("unknown-top-key", scenario_text(extra="obstacels: []"), "obstacels: unknown key 'obstacels' (did you mean 'obstacles'?)"),
    ("unknown-nested-key", scenario_text(goal="goal: {x: 18, y: 18, tolerence: 0.3}"), "goal.tolerence: unknown key 'tolerence' (did you mean 'tolerance'?)"),
    ("unknown-shape", scenario_text(obstacles="obstacles:\n  - cirle: {center: [5, 5], radius: 1}"), "obstacles[0].cirle: unknown key 'cirle' (did you mean 'circle'?)"),
    ("unknown-shape-param", scenario_text(obstacles="obstacles:\n  - circle: {centre: [5, 5], radius: 1}"), "obstacles[0].circle.centre: unknown key"),
    ("missing-shape-param", scenario_text(obstacles="obstacles:\n  - circle: {center: [5, 5]}"), "obstacles[0].circle.radius: missing"),
    ("two-shapes-in-one", scenario_text(obstacles="obstacles:\n  - {circle: {center: [5, 5], radius: 1}, wall: {start: [1, 1], end: [2, 2]}}"), "obstacles[0]: must be a mapping with exactly one of"),
    ("obstacles-not-list", scenario_text(obstacles="obstacles: {circle: 1}"), "obstacles: must be a list"),
    ("wrong-type-string", scenario_text(obstacles="obstacles:\n  - circle: {center: [5, 5], radius: big}"), "obstacles[0].circle.radius: must be a number"),
    ("wrong-type-bool", scenario_text(robot="robot: {x: true, y: 1}"), "robot.x: must be a number"),
    ("wrong-type-point", scenario_text(obstacles="obstacles:\n  - circle: {center: 5, radius: 1}"), "obstacles[0].circle.center: must be a list of two numbers"),
    ("wrong-type-mapping", scenario_text(goal="goal: [18, 18]"), "goal: must be a mapping"),
    ("wrong-type-name", scenario_text(extra="name: [a, b]"), "name: must be a string"),
    ("nan", scenario_text(robot="robot: {x: .nan, y: 1}"), "robot.x: must be finite"),
    ("inf", scenario_text(extra="world: {width: .inf, height: 20}"), "world.width: must be finite"),
    ("world-size", scenario_text(extra="world: {width: 0, height: 20}"), "world.width: must be > 0"),
    ("radius-zero", scenario_text(obstacles="obstacles:\n  - circle: {center: [5, 5], radius: 0}"), "obstacles[0].circle.radius: must be > 0"),
    ("radius-negative", scenario_text(obstacles="obstacles:\n  - circle: {center: [5, 5], radius: -1}"), "obstacles[0].circle.radius: must be > 0"),
    ("ellipse-radius", scenario_text(obstacles="obstacles:\n  - ellipse: {center: [5, 5], radii: [2, 0]}"), "obstacles[0].ellipse.radii[1]: must be > 0"),
    ("wall-thickness", scenario_text(obstacles="obstacles:\n  - wall: {start: [2, 12], end: [10, 12], thickness: 0}"), "obstacles[0].wall.thickness: must be > 0"),
    ("wall-zero-length", scenario_text(obstacles="obstacles:\n  - wall: {start: [2, 12], end: [2, 12]}"), "obstacles[0].wall.end: must differ from start"),
    ("polygon-two-points", scenario_text(obstacles="obstacles:\n  - polygon: {points: [[8, 8], [10, 8]]}"), "obstacles[0].polygon.points: needs at least 3 points, got 2"),
    ("polygon-self-intersecting", scenario_text(obstacles="obstacles:\n  - polygon: {points: [[8, 8], [10, 10], [10, 8], [8, 10]]}"), "obstacles[0].polygon.points: polygon is self-intersecting"),
    ("start-inside-obstacle", scenario_text(robot="robot: {x: 5.2, y: 5.0}"), "robot: start (5.2, 5) is inside obstacles[0] (circle)"),
    ("start-footprint-overlaps", scenario_text(robot="robot: {x: 6.1, y: 5.0}"), "robot: start (6.1, 5) is within the robot footprint (0.3 m) of obstacles[0]"),
    ("start-outside-world", scenario_text(robot="robot: {x: 25, y: 1}"), "robot: start (25, 1) is outside the 20 x 20 m world"),
    ("goal-inside-obstacle", scenario_text(goal="goal: {x: 5, y: 5.5}"), "goal: goal (5, 5.5) is inside obstacles[0] (circle)"),
    ("goal-outside-world", scenario_text(goal="goal: {x: 18, y: -1}"), "goal: goal (18, -1) is outside"),
    ("goal-tolerance", scenario_text(goal="goal: {x: 18, y: 18, tolerance: -0.1}"), "goal.tolerance: must be > 0"),
    ("missing-robot", scenario_text(robot=""), "robot: missing"),
    ("missing-robot-x", scenario_text(robot="robot: {y: 1}"), "robot.x: missing"),
    ("no-task", scenario_text(goal=""), "goal: a scenario needs exactly one task"),
    ("two-tasks", scenario_text(extra="path: [[3, 3], [9, 3]]"), "exactly one task: goal, path or target (found goal, path)"),
    ("path-tolerance-without-path", scenario_text(extra="path_tolerance: 0.5"), "path_tolerance: only allowed with a path task"),
    ("path-waypoint-outside", scenario_text(goal="path: [[3, 3], [30, 3]]"), "path[1]: waypoint (30, 3) is outside"),
    ("path-waypoint-type", scenario_text(goal="path: [[3, 3], [x, 3]]"), "path[1][0]: must be a number"),
    ("path-empty", scenario_text(goal="path: []"), "path: needs at least 2 points"),
    ("path-speed", scenario_text(goal="path: [[3, 3], [4, 3]]\nspeed: 0"), "speed: must be > 0"),
    ("target-motion-type", scenario_text(goal="target: {x: 4, y: 12, motion: {type: lines}}"), "target.motion.type: unknown motion 'lines' (did you mean 'line'?)"),
    ("target-motion-param", scenario_text(goal="target: {x: 4, y: 12, motion: {type: line}}"), "target.motion.velocity: missing"),
    ("target-motion-unknown-param", scenario_text(goal="target: {x: 4, y: 12, motion: {type: line, velocity: [1, 0], sped: 1}}"), "target.motion.sped: unknown key"),
    ("target-period", scenario_text(goal="target: {x: 4, y: 12, motion: {type: sinusoid, velocity: [1, 0], amplitude: 1, period: 0}}"), "target.motion.period: must be > 0"),
    ("target-circle-radius", scenario_text(goal="target: {x: 4, y: 12, motion: {type: circle, center: [4, 12], speed: 1}}"), "target.motion.center: must differ from the target start"),
    ("target-inside-obstacle", scenario_text(goal="target: {x: 5, y: 5}"), "target: target (5, 5) is inside obstacles[0]"),
    ("max-time", scenario_text(extra="max_time: 0"), "max_time: must be > 0"),
    ("unreadable-yaml", "robot: {x: 1, y: 1\ngoal: {x: 5, y: 5}\n", "line 2, column 5: invalid YAML"),
    ("duplicate-key", scenario_text(extra="goal: {x: 3, y: 3}"), "duplicate key 'goal'"),
    ("not-a-mapping", "- robot\n- goal\n", "must be a mapping, got list"),
]


@pytest.mark.parametrize("text, expected", [c[1:] for c in CASES], ids=[c[0] for c in CASES])
def test_bad_scenario_exits_2_naming_file_and_field(tmp_path, capsys, text, expected):
    file = tmp_path / "bad.yaml"
    file.write_text(text)
    status = main(["run", str(file), "--controller", "anything", "--json"])
    out, err = capsys.readouterr()
    assert status == 2 and out == ""
    assert str(file) in err
    assert expected in err


def test_binary_file(tmp_path, capsys):
    file = tmp_path / "bad.yaml"
    file.write_bytes(b"\xff\xfe\x00robot")
    assert main(["run", str(file), "--controller", "x"]) == 2
    assert "cannot read file" in capsys.readouterr().err


def test_a_folder_is_not_a_scenario_file(tmp_path, capsys):
    assert main(["run", str(tmp_path), "--controller", "fuzzy-5b"]) == 2
    assert f"{tmp_path}: SCENARIO: is a directory" in capsys.readouterr().err


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="needs /dev/zero (POSIX)")
def test_a_device_is_not_a_missing_scenario(capsys):
    assert main(["run", "/dev/zero", "--controller", "fuzzy-5b"]) == 2
    assert "/dev/zero: is a socket or device, not a regular file" in capsys.readouterr().err


@pytest.mark.parametrize("argv, expected", [
    (["run", "no-such-scenario", "--controller", "x"], "SCENARIO: no such scenario file or built-in scenario"),
    (["run", "example-gaol", "--controller", "x"], "did you mean example-goal"),
    (["run", "example-goal", "--controller", "no-such-controller"], "--controller: unknown controller"),
    (["run", "example-goal", "--controller", "x", "--max-time", "-1"], "--max-time: must be > 0, got -1.0"),
    (["run", "example-goal", "--model", "/nonexistent/model.json"], "no such model file"),
    (["scenarios", "--show", "example-gaol"], "--show: no built-in scenario 'example-gaol' (did you mean example-goal"),
])
def test_bad_command_line(capsys, argv, expected):
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and expected in err
