"""The shared plumbing: model files are written atomically and read safely; registries name errors."""

import json

import numpy as np
import pytest

from fuzzynav import storage
from fuzzynav.catalog import controllers as registry, tasks as training
from fuzzynav.cli import main
from fuzzynav.control.base import Observation, thesis_angle_error
from fuzzynav.errors import InputError
from fuzzynav.world.geometry import wrap_angle


def test_save_json_atomic_replaces_and_leaves_no_temporary(tmp_path):
    path = tmp_path / "model.json"
    storage.save_json_atomic(path, {"kind": "a", "value": 1})
    storage.save_json_atomic(path, {"kind": "a", "value": 2})
    assert json.loads(path.read_text())["value"] == 2
    assert [p.name for p in tmp_path.iterdir()] == ["model.json"]


def test_failed_save_keeps_previous_model(tmp_path):
    path = tmp_path / "model.json"
    storage.save_json_atomic(path, {"kind": "a", "value": 1})
    with pytest.raises(TypeError):
        storage.save_json_atomic(path, {"kind": "a", "value": object()})
    assert json.loads(path.read_text())["value"] == 1
    assert [p.name for p in tmp_path.iterdir()] == ["model.json"]


def test_npz_round_trip_without_pickle(tmp_path):
    path = tmp_path / "model.npz"
    storage.save_npz_atomic(path, kind=np.array("toy"), q=np.arange(6.0).reshape(2, 3))
    document = storage.read_document(path)
    assert document["kind"] == "toy"
    np.testing.assert_array_equal(document["q"], np.arange(6.0).reshape(2, 3))


@pytest.mark.parametrize(
    "content, field",
    [("not json", None), ('{"no_kind": 1}', "kind"), ('{"kind": "no-such-kind"}', "kind")],
)
def test_bad_model_files_name_the_file(tmp_path, content, field):
    path = tmp_path / "bad.json"
    path.write_text(content)
    with pytest.raises(InputError) as error:
        training.load_controller(path)
    assert str(path) in str(error.value)
    if field:
        assert field in str(error.value)


def test_unknown_names_suggest_close_matches():
    with pytest.raises(InputError, match="did you mean goal-seeking"):
        registry.make_controller("goal-seeking2")
    with pytest.raises(InputError, match="unknown training task"):
        training.trainer("no-such-task")


def test_cli_reports_bad_input_with_exit_2(capsys):
    assert main(["train", "no-such-task"]) == 2
    assert "unknown training task" in capsys.readouterr().err


def test_wrap_angle_range():
    angles = np.linspace(-10, 10, 1001)
    wrapped = wrap_angle(angles)
    assert np.all(wrapped > -np.pi) and np.all(wrapped <= np.pi)
    np.testing.assert_allclose(np.cos(wrapped), np.cos(angles), atol=1e-12)
    assert wrap_angle(-np.pi) == pytest.approx(np.pi)


def test_thesis_angle_error_is_the_negated_bearing():
    obs = Observation(t=0, dt=0.1, pose=np.array([0.0, 0.0, 0.0]), speed=0, steering=0,
                      target=np.array([0.0, 5.0]))
    assert obs.target_bearing == pytest.approx(np.pi / 2)  # goal on the left
    assert obs.target_distance == pytest.approx(5.0)
    assert thesis_angle_error(obs.target_bearing) == pytest.approx(-np.pi / 2)
