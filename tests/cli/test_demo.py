"""The main job: runs the built-in scenarios' controllers and writes plots and metrics."""

import json
from pathlib import Path

import pytest

from fuzzynav.cli import main
from fuzzynav.cli.demo import demo_runs
from fuzzynav.errors import InputError
from fuzzynav.world.scenario import scenario_from_dict


def test_demo_runs_a_scenario_and_writes_plot_and_tables(tmp_path, capsys, monkeypatch):
    runs = demo_runs()
    assert runs, "the built-in scenarios name no controllers"
    name, controller = runs[0]
    assert main(["demo", "--out", str(tmp_path), "--scenario", name]) == 0
    rows = json.loads((tmp_path / "metrics.json").read_text())
    assert {row["scenario"] for row in rows} == {name}
    assert controller in {row["controller"] for row in rows}
    assert (tmp_path / f"{name}--{controller}.png").stat().st_size > 1000
    table = (tmp_path / "metrics.md").read_text()
    assert table.startswith("| scenario | controller |") and name in table
    assert f"{name} / {controller}" in capsys.readouterr().out


def test_runs_whose_plots_would_share_a_file_are_refused_before_any_run(tmp_path):
    # each run's plot is SCENARIO--CONTROLLER.png: two files of one name: key, or a name given twice,
    # would draw one plot over the other
    text = Path(__file__).parents[2].joinpath("src/fuzzynav/world/scenarios/example-goal.yaml").read_text()
    for folder in ("a", "b"):
        (tmp_path / folder).mkdir()
        (tmp_path / folder / "same.yaml").write_text(text)
    with pytest.raises(InputError, match=r"b/same\.yaml: --scenario: scenario '.+' is also the name of .+a/same\.yaml"):
        demo_runs([str(tmp_path / "a" / "same.yaml"), str(tmp_path / "b" / "same.yaml")], ["goal-seeking"])
    for name, other in (("my world", "my_world"), ("Hall", "hall")):  # other names, one plot file ("Hall": any case)
        for folder, scenario_name in (("a", name), ("b", other)):
            (tmp_path / folder / "named.yaml").write_text(text.replace("name: example-goal", f"name: {scenario_name}"))
        with pytest.raises(InputError, match=rf"b/named\.yaml: --scenario: scenario '{other}' is also the name of "
                                             rf".+a/named\.yaml, as the name of a file \({other}--….png\)"):
            demo_runs([str(tmp_path / "a" / "named.yaml"), str(tmp_path / "b" / "named.yaml")], ["goal-seeking"])
    with pytest.raises(InputError, match="fig-IV-23: --scenario: is given twice"):
        demo_runs(["fig-IV-23", "fig-IV-23"])
    with pytest.raises(InputError, match="--controllers: goal-seeking is given twice"):
        demo_runs(["fig-IV-23"], ["goal-seeking", "goal-seeking"])


def test_scenario_controllers_key_is_validated():
    doc = {"robot": {"x": 1, "y": 1}, "goal": {"x": 5, "y": 5}, "controllers": "goal-seeking"}
    with pytest.raises(InputError, match="controllers"):
        scenario_from_dict(doc, source="s.yaml")
    doc["controllers"] = ["goal-seeking"]
    assert scenario_from_dict(doc, source="s.yaml").controllers == ("goal-seeking",)


def test_demo_workers_change_the_wall_time_only(tmp_path, capsys):
    """Runs shared among worker processes give the same rows, plots and lines, in the runs' order."""
    outputs = {}
    for workers in ("1", "3"):
        out = tmp_path / workers
        assert main(["demo", "--scenario", "path-n", "--workers", workers, "--out", str(out)]) == 0
        lines = [line for line in capsys.readouterr().out.splitlines() if line.startswith("[")]
        outputs[workers] = (lines, (out / "metrics.json").read_text(),
                            {plot.name: plot.read_bytes() for plot in out.glob("*.png")})
    lines, metrics, plots = outputs["3"]
    assert outputs["1"] == outputs["3"]
    assert [line.split("]")[0] for line in lines] == [f"[{i}/5" for i in range(1, 6)]
    assert len(plots) == 5 and len(json.loads(metrics)) == 5


def test_the_next_hint_names_a_command_this_shell_can_type(tmp_path, monkeypatch):
    """Run as ``.venv/bin/fuzzynav`` without activating the environment, the closing hint says
    ``.venv/bin/fuzzynav``, not a bare ``fuzzynav`` the shell would not find."""
    from fuzzynav.cli import demo

    bin_dir = tmp_path / ".venv" / "bin"
    bin_dir.mkdir(parents=True)
    (bin_dir / "fuzzynav").write_text("#!/bin/sh\n")
    monkeypatch.setattr(demo.sys, "executable", str(bin_dir / "python"))
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(demo.shutil, "which", lambda name: None)
    assert demo.command_name() == str(Path(".venv") / "bin" / "fuzzynav")
    elsewhere = tmp_path / "elsewhere"  # run from outside the folder that holds .venv: no ../../ path
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    assert demo.command_name() == str(bin_dir / "fuzzynav")
    monkeypatch.setattr(demo.shutil, "which", lambda name: str(bin_dir / name))
    assert demo.command_name() == "fuzzynav"


def test_an_unusable_out_is_refused_before_any_compiling(tmp_path, capsys, monkeypatch):
    """A folder named metrics.json in --out used to fail after every run had finished."""
    from fuzzynav.cli import warmup

    monkeypatch.setattr(warmup, "warm_up", lambda *a, **k: pytest.fail("compiled before checking --out"))
    (tmp_path / "metrics.json").mkdir()
    assert main(["demo", "--scenario", "fig-IV-23", "--out", str(tmp_path), "--no-plots"]) == 2
    err = capsys.readouterr().err
    assert "metrics.json" in err and "--out" in err and "is a folder" in err
