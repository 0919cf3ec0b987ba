"""Damaged tracker model files (``fuzzynav run SCEN --model FILE``): exit 2 with the file
and the field named, no traceback."""

import json

import pytest

from fuzzynav.cli import main


@pytest.fixture(scope="module")
def models(tmp_path_factory):
    folder = tmp_path_factory.mktemp("trackers")
    files = {}
    for kind in ("neural-tracker", "anfis-tracker"):
        files[kind] = folder / f"{kind}.json"
        assert main(["train", kind, "--quiet", "--out", str(files[kind])]) == 0
    return {kind: json.loads(path.read_text()) for kind, path in files.items()}


@pytest.mark.parametrize("kind", ["neural-tracker", "anfis-tracker"])
@pytest.mark.parametrize("key, value, message", [
    ("speed", "fast", "speed: must be a number, got 'fast'"),
    ("speed", True, "speed: must be a number, got True"),
    ("lookahead", -1.0, "lookahead: must be > 0, got -1.0"),
    ("corner_radius", -1.0, "corner_radius: must be >= 0, got -1.0"),
])
def test_bad_tracker_option_names_file_and_field(models, tmp_path, capsys, kind, key, value, message):
    path = tmp_path / "model.json"
    path.write_text(json.dumps({**models[kind], key: value}))
    assert main(["run", "path-v", "--model", str(path)]) == 2
    assert f"{path}: {message}" in capsys.readouterr().err
