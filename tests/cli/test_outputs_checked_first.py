"""A long command refuses an output it could not write before it starts working: ``train`` and
``tune`` check ``--out`` and ``--curve`` (a folder, a missing folder, a folder it may not write in)
before the first episode, ``evaluate`` its ``--save-failures`` folder before the first world and
``reproduce`` its ``--out`` folder before the first experiment (they ran every world, or the
first experiment, then failed to write), with a one-line error naming the option (exit status 2)."""

import os

import pytest

from fuzzynav.cli import main

TRAIN = ["train", "q-goal", "--episodes", "200", "--quiet"]
TUNE = ["tune", "goal-seeking:gsb", "--budget", "400", "--worlds", "mixed:4", "--quiet", "--validation", "none"]


def _refused(argv, capsys):
    assert main(argv) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    return err


def test_tune_refuses_an_output_in_a_missing_folder_before_any_work(tmp_path, capsys):
    err = _refused([*TUNE, "--out", str(tmp_path / "missing" / "t.yaml")], capsys)
    assert "--out" in err and "no folder" in err and "missing" in err
    assert not any(tmp_path.iterdir())


@pytest.mark.parametrize("command", [TRAIN, TUNE], ids=["train", "tune"])
@pytest.mark.parametrize("flag", ["--out", "--curve"])
def test_a_missing_folder_under_one_it_may_not_write_in_is_refused(tmp_path, capsys, monkeypatch, command, flag):
    locked = tmp_path / "locked"
    locked.mkdir()
    real = os.access
    monkeypatch.setattr(os, "access", lambda path, mode, **kw: False if str(path) == str(locked) else real(path, mode, **kw))
    outputs = {"--out": tmp_path / ("m.json" if command is TRAIN else "t.yaml"), "--curve": tmp_path / "c.png"}
    if command is TUNE and flag == "--out":
        outputs[flag] = locked / outputs[flag].name  # tune: its folder must exist
    else:
        outputs[flag] = locked / "new" / outputs[flag].name  # made by the save, but not inside locked
    err = _refused([*command, "--out", str(outputs["--out"]), "--curve", str(outputs["--curve"])], capsys)
    assert flag in err and "cannot write in the folder" in err and str(locked) in err
    assert not any(locked.iterdir()) and not outputs["--out"].exists()


@pytest.mark.parametrize("command", [TRAIN, TUNE], ids=["train", "tune"])
def test_an_output_that_is_a_folder_or_in_a_read_only_folder_is_refused(tmp_path, capsys, monkeypatch, command):
    out = tmp_path / ("m.json" if command is TRAIN else "t.yaml")
    folder = tmp_path / f"folder{out.suffix}"
    folder.mkdir()
    err = _refused([*command, "--out", str(folder)], capsys)  # (--curve's own type refuses a folder)
    assert "--out" in err and "is a directory" in err
    locked = tmp_path / "locked"
    locked.mkdir()
    real = os.access
    monkeypatch.setattr(os, "access", lambda path, mode, **kw: False if str(path) == str(locked) else real(path, mode, **kw))
    err = _refused([*command, "--out", str(locked / out.name)], capsys)
    assert "--out" in err and "cannot write in the folder" in err
    assert not out.exists() and not any(locked.iterdir())
    err = _refused([*command, "--out", str(out), "--curve", str(locked / "c.png")], capsys)
    assert "--curve" in err and "cannot write in the folder" in err and not out.exists()


@pytest.mark.parametrize("command, flag", [
    (["evaluate", "--controller", "goal-seeking", "--worlds", "circles", "--n", "2", "--quiet"], "--save-failures"),
    (["reproduce", "fig-V-7", "--quick", "--quiet"], "--out")], ids=["evaluate", "reproduce"])
def test_an_output_folder_it_may_not_write_in_is_refused_before_the_runs(tmp_path, capsys, monkeypatch, command, flag):
    locked = tmp_path / "locked"
    locked.mkdir()
    real = os.access
    monkeypatch.setattr(os, "access", lambda path, mode, **kw: False if str(path) == str(locked) else real(path, mode, **kw))
    err = _refused([*command, flag, str(locked)], capsys)
    assert flag in err and "cannot write in the folder" in err and str(locked) in err
    assert not any(locked.iterdir())
