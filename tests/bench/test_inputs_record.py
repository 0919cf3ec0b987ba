"""``fuzzynav bench --resume`` never mixes runs of two contents under one name: the model files
and folder-suite scenario files a campaign read are hashed in ``inputs.json``."""

import json

from fuzzynav.cli import main
from fuzzynav.world.scenario import load_scenario, scenario_from_dict
from fuzzynav.world.scenario_file import save_scenario


def _bench(worlds, out, *extra, controllers="goal-seeking"):
    return main(["bench", str(worlds), "--controllers", controllers, "--workers", "1", "--out", str(out),
                 "--quiet", "--gallery", "0", *extra])


def _folder(tmp_path):
    folder = tmp_path / "worlds"
    folder.mkdir()
    save_scenario(load_scenario("fig-IV-13"), folder / "a.yaml")
    return folder


def test_an_edited_world_file_is_refused_on_resume(tmp_path, capsys):
    folder, out = _folder(tmp_path), tmp_path / "campaign"
    assert _bench(folder, out) == 0
    record = json.loads((out / "inputs.json").read_text())
    assert record["models"] == {} and [len(d) for d in record["worlds"].values()] == [64, 64]  # a.yaml, the references
    assert _bench(folder, out, "--resume") == 0  # unchanged: resumes
    edited = load_scenario(folder / "a.yaml").to_dict()
    edited["max_time"] = 55.0  # the same name, another world
    (folder / "a.yaml").unlink()
    save_scenario(scenario_from_dict(edited), folder / "a.yaml")
    capsys.readouterr()
    assert _bench(folder, out, "--resume") == 2
    err = capsys.readouterr().err.strip()
    assert "changed since its runs were made" in err and "a.yaml" in err and len(err.splitlines()) == 1


def test_a_replaced_model_file_is_refused_on_resume(tmp_path, capsys):
    model = tmp_path / "m.json"
    assert main(["train", "q-goal", "--episodes", "3", "--quiet", "--out", str(model)]) == 0
    out = tmp_path / "campaign"
    assert _bench("circles:1:3", out, controllers=str(model)) == 0
    assert list(json.loads((out / "inputs.json").read_text())["models"]) == ["m"]
    assert main(["train", "q-goal", "--episodes", "3", "--seed", "1", "--quiet", "--out", str(model)]) == 0
    capsys.readouterr()
    assert _bench("circles:1:3", out, "--resume", controllers=str(model)) == 2
    assert "changed since its runs were made: m;" in capsys.readouterr().err


def test_a_damaged_inputs_record_is_a_clear_error(tmp_path, capsys):
    out = tmp_path / "campaign"
    assert _bench("circles:1:3", out) == 0
    (out / "inputs.json").write_text('{"models": {"m": "abc"}, "worlds": {}}\n')
    capsys.readouterr()
    assert _bench("circles:1:3", out, "--resume") == 2
    err = capsys.readouterr().err.strip()
    assert "inputs.json" in err and "models.m" in err and "64 lowercase hexadecimal" in err


def test_a_model_file_named_in_capitals_is_a_model_file_for_every_command(tmp_path, capsys):
    model = tmp_path / "M.JSON"  # train writes it (the extension's case does not matter there)
    assert main(["train", "q-goal", "--episodes", "3", "--quiet", "--out", str(model)]) == 0
    out = tmp_path / "campaign"
    assert _bench("circles:1:3", out, controllers=str(model)) == 0
    assert list(json.loads((out / "inputs.json").read_text())["models"]) == ["M"]
    capsys.readouterr()
    assert main(["fis", "show", str(model)]) == 2  # read as the model file it is
    assert "a 'q-goal' model file, not a fuzzy system" in capsys.readouterr().err


def test_the_folder_spelled_otherwise_or_another_of_its_name_is_compared_too(tmp_path, capsys):
    folder, out = _folder(tmp_path), tmp_path / "campaign"
    assert _bench(folder, out) == 0
    assert list(json.loads((out / "inputs.json").read_text())["worlds"]) == ["worlds/a.yaml", "worlds/benchmark.json"]
    other = tmp_path / "elsewhere" / "worlds"  # the same suite name, another world under the same file name
    other.mkdir(parents=True)
    save_scenario(scenario_from_dict({**load_scenario("fig-IV-13").to_dict(), "max_time": 55.0}), other / "a.yaml")
    for spelled in (other, f"{folder}/../worlds"):
        if spelled != other:
            (folder / "a.yaml").write_bytes((other / "a.yaml").read_bytes())
        capsys.readouterr()
        assert _bench(spelled, out, "--resume") == 2
        assert "changed since its runs were made: worlds/a.yaml;" in capsys.readouterr().err


def test_edited_reference_data_is_refused_on_resume(tmp_path, capsys):
    folder, out = _folder(tmp_path), tmp_path / "campaign"
    assert _bench(folder, out) == 0  # no benchmark.json: its reference data is none
    (folder / "benchmark.json").write_text('{"scenarios": {"a": {"barn_optimal_path_m": 2.0}}}\n')
    capsys.readouterr()
    assert _bench(folder, out, "--resume") == 2  # the scores of the runs made would not be those of the new ones
    assert "changed since its runs were made: worlds/benchmark.json;" in capsys.readouterr().err
