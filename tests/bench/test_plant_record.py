"""``fuzzynav bench --plant``: the campaign records its plant and never mixes runs of two plants."""

import json

from fuzzynav.cli import main


def _bench(out, *extra):
    return main(["bench", "circles:1:3", "--controllers", "goal-seeking", "--workers", "1", "--out", str(out),
                 "--quiet", "--gallery", "0", *extra])


def test_a_campaign_records_its_plant_and_refuses_to_resume_with_another(tmp_path, capsys):
    kinematic = tmp_path / "kinematic"
    assert _bench(kinematic) == 0
    assert json.loads((kinematic / "plant.json").read_text()) == {"plant": "kinematic"}
    assert "plant" not in json.loads((kinematic / "summary.json").read_text())["arguments"]  # files as before
    capsys.readouterr()
    assert _bench(kinematic, "--resume", "--plant", "mujoco") == 2
    err = capsys.readouterr().err
    assert "kinematic plant" in err and "--plant" in err

    physical = tmp_path / "mujoco"
    assert _bench(physical, "--plant", "mujoco") == 0
    assert json.loads((physical / "plant.json").read_text()) == {"plant": "mujoco"}
    assert json.loads((physical / "summary.json").read_text())["arguments"]["plant"] == "mujoco"
    rows = [json.loads(line) for line in (physical / "runs.jsonl").read_text().splitlines()]
    assert len(rows) == 1 and rows[0]["outcome"] in ("reached", "collision", "timeout")
    assert rows[0]["path_length_m"] > 1.0  # the MuJoCo plant moved the robot
    assert _bench(physical, "--resume") == 2  # the default plant is another one


def test_a_bad_plant_record_is_refused_on_resume(tmp_path, capsys):
    out = tmp_path / "campaign"
    assert _bench(out) == 0
    (out / "plant.json").write_text('{"plant": "bullet"}\n')
    capsys.readouterr()
    assert _bench(out, "--resume") == 2
    err = capsys.readouterr().err.strip()
    assert "plant.json" in err and "bullet" in err
