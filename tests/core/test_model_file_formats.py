"""Model files are written in the format their extension names and read whatever their name says."""

import json
import zipfile

import numpy as np
import pytest

from fuzzynav import storage
from fuzzynav.cli import main
from fuzzynav.errors import InputError


def run_cli(capsys, *argv):
    status = main(list(argv))
    captured = capsys.readouterr()
    return status, captured.out, captured.err


def train_q_goal(capsys, out):
    status, _, err = run_cli(capsys, "train", "q-goal", "--episodes", "10", "--quiet", "--out", str(out))
    assert status == 0, err


def test_npz_out_writes_an_npz_that_runs(capsys, tmp_path):
    out = tmp_path / "q.npz"
    train_q_goal(capsys, out)
    assert zipfile.is_zipfile(out)
    with np.load(out, allow_pickle=False) as data:
        assert str(data["kind"]) == "q-goal"
        assert json.loads(str(data["document"]))["training"]["task"] == "q-goal"
    status, out_text, err = run_cli(capsys, "run", "example-goal", "--model", str(out), "--json")
    assert status == 0, err
    assert json.loads(out_text)["controller"] == "q-goal"


def test_json_and_npz_hold_the_same_document(capsys, tmp_path):
    train_q_goal(capsys, tmp_path / "q.json")
    train_q_goal(capsys, tmp_path / "q.npz")
    assert storage.read_document(tmp_path / "q.npz") == json.loads((tmp_path / "q.json").read_text())


@pytest.mark.parametrize("name", ["q.txt", "q", "q.pkl"])
def test_other_extensions_are_refused_before_training(capsys, tmp_path, name):
    status, _, err = run_cli(capsys, "train", "q-goal", "--episodes", "10", "--quiet", "--out", str(tmp_path / name))
    assert status == 2
    assert "--out" in err and ".json or .npz" in err and "Traceback" not in err
    assert not list(tmp_path.iterdir())  # nothing trained, no checkpoint written


def test_misnamed_files_still_load(capsys, tmp_path):
    train_q_goal(capsys, tmp_path / "q.json")
    train_q_goal(capsys, tmp_path / "q.npz")
    json_named_npz, npz_named_json = tmp_path / "json-inside.npz", tmp_path / "npz-inside.json"
    json_named_npz.write_bytes((tmp_path / "q.json").read_bytes())
    npz_named_json.write_bytes((tmp_path / "q.npz").read_bytes())
    for path in (json_named_npz, npz_named_json):
        status, out_text, err = run_cli(capsys, "run", "example-goal", "--model", str(path), "--json")
        assert status == 0, err
        assert json.loads(out_text)["outcome"] == json.loads(
            run_cli(capsys, "run", "example-goal", "--model", str(tmp_path / "q.json"), "--json")[1])["outcome"]


@pytest.mark.parametrize("content", [b"not a model at all", b"PK\x03\x04 broken archive", b"\x93NUMPY pickled?"])
@pytest.mark.parametrize("name", ["m.npz", "m.json"])
def test_unreadable_model_names_the_file_without_numpy_hints(capsys, tmp_path, content, name):
    path = tmp_path / name
    path.write_bytes(content)
    status, _, err = run_cli(capsys, "run", "example-goal", "--model", str(path))
    assert status == 2
    assert f"{path}: cannot read model file" in err
    assert "pickle" not in err and "Traceback" not in err
    if content == b"not a model at all":  # an .npz that is not one is not called a JSON document alone
        assert ("neither an .npz archive" in err) == (name == "m.npz")


def test_an_archive_of_python_objects_is_refused_without_numpy_hints(capsys, tmp_path):
    path = tmp_path / "objects.npz"
    with path.open("wb") as handle:
        np.savez(handle, kind=np.array("q-goal"), q=np.array([{"a": 1}], dtype=object))
    status, _, err = run_cli(capsys, "run", "example-goal", "--model", str(path))
    assert status == 2
    assert f"{path}: cannot read model file" in err and "Python objects" in err
    assert "pickle" not in err and "Traceback" not in err


def test_save_document_refuses_an_unknown_extension(tmp_path):
    with pytest.raises(InputError, match="must end in .json or .npz"):
        storage.save_document(tmp_path / "m.yaml", {"kind": "x"})
    assert not list(tmp_path.iterdir())


def test_a_tracker_model_is_refused_where_the_task_is_a_goal(capsys, tmp_path):
    from fuzzynav.learn.tasks.trackers import default_document

    path = tmp_path / "anfis.json"
    storage.save_document(path, default_document("anfis-tracker"))
    for argv in (["run", "example-goal", "--model", str(path)],
                 ["evaluate", "--model", str(path), "--worlds", "mixed", "--n", "1"],
                 ["bench", "mixed:1", "--controllers", str(path), "--out", str(tmp_path / "campaign")]):
        status, out, err = run_cli(capsys, *argv)
        assert status == 2 and out == "", argv
        assert f"{path}: --model: this anfis-tracker model cannot do a goal task (it does: path, target)" in err
    assert not (tmp_path / "campaign").exists()
    status, out, _ = run_cli(capsys, "run", "path-n", "--model", str(path), "--json")
    assert status == 0 and json.loads(out)["outcome"] == "reached"
