"""Saving never corrupts the previous file and leaves no temporary file behind: a save that fails
(an exception in the middle of writing, a full disk, a read-only folder) removes its temporary file
at once; a save
killed with SIGKILL (nothing can clean up) leaves the previous file intact, and its temporary
file is removed by the next save of that file."""

import errno
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.storage import atomic_write, save_json_atomic

PREVIOUS = {"kind": "x", "weights": [1, 2, 3]}


def _leftovers(folder):
    return sorted(p.name for p in folder.iterdir() if p.name != "m.json")


def test_exception_while_writing_keeps_the_previous_file_and_no_temporary(tmp_path):
    path = tmp_path / "m.json"
    save_json_atomic(path, PREVIOUS)

    def half_then_fail(handle):
        handle.write(b'{"kind": "x", "wei')
        raise KeyboardInterrupt  # Ctrl-C in the middle of writing

    with pytest.raises(KeyboardInterrupt):
        atomic_write(path, half_then_fail)
    assert json.loads(path.read_text()) == PREVIOUS and _leftovers(tmp_path) == []


def test_full_disk_is_an_input_error_naming_the_file_and_keeps_the_previous_file(tmp_path):
    path = tmp_path / "m.json"
    save_json_atomic(path, PREVIOUS)

    def disk_full(handle):
        handle.write(b"{")
        raise OSError(errno.ENOSPC, "No space left on device")

    with pytest.raises(InputError, match=r"m\.json: cannot write \(No space left on device\)"):
        atomic_write(path, disk_full)
    assert json.loads(path.read_text()) == PREVIOUS and _leftovers(tmp_path) == []


def _read_only(monkeypatch, folder, fail):
    """Simulate a read-only ``folder`` (root ignores permissions): creating a file in it
    (``fail="create"``) or renaming one onto a file in it (``fail="replace"``) raises EROFS."""
    folder = Path(folder).resolve()
    real_mkstemp, real_replace = tempfile.mkstemp, os.replace

    def refuse(where):
        if Path(where).resolve().parent == folder:
            raise OSError(errno.EROFS, os.strerror(errno.EROFS), str(where))

    def mkstemp(*args, **options):
        if fail == "create":
            refuse(Path(options.get("dir") or ".") / "new")
        return real_mkstemp(*args, **options)

    def replace(source, target, **options):
        if fail == "replace":
            refuse(target)
        return real_replace(source, target, **options)

    monkeypatch.setattr(tempfile, "mkstemp", mkstemp)
    monkeypatch.setattr(os, "replace", replace)


@pytest.mark.parametrize("fail", ["create", "replace"])
def test_read_only_folder_is_an_input_error_naming_the_file_and_keeps_the_previous_file(tmp_path, monkeypatch, fail):
    path = tmp_path / "m.json"
    save_json_atomic(path, PREVIOUS)
    _read_only(monkeypatch, tmp_path, fail)
    with pytest.raises(InputError, match=r"m\.json: cannot write \(Read-only file system\)"):
        save_json_atomic(path, {"kind": "x", "weights": [4]})
    assert json.loads(path.read_text()) == PREVIOUS and _leftovers(tmp_path) == []


def test_cli_into_a_read_only_out_is_one_line_and_exit_2(tmp_path, monkeypatch, capsys):
    out = tmp_path / "ro" / "m.json"
    out.parent.mkdir()
    _read_only(monkeypatch, out.parent, "create")
    assert main(["train", "q-goal", "--episodes", "2", "--out", str(out), "--quiet"]) == 2
    captured = capsys.readouterr()
    assert captured.err.count("\n") == 1 and "Traceback" not in captured.err
    assert captured.err.startswith("fuzzynav train: error: " + str(out))  # the model or its checkpoint
    assert captured.err.endswith(": cannot write (Read-only file system)\n")
    assert list(out.parent.iterdir()) == []


KILLED_SAVE = """
import sys, time
from fuzzynav.storage import atomic_write
def half_then_hang(handle):
    handle.write(b'{"kind": "x", "wei')
    handle.flush()
    print("writing", flush=True)
    time.sleep(60)
atomic_write(sys.argv[1], half_then_hang)
"""


def test_save_killed_with_sigkill_keeps_the_previous_file_and_the_next_save_cleans_up(tmp_path):
    path = tmp_path / "m.json"
    save_json_atomic(path, PREVIOUS)
    process = subprocess.Popen([sys.executable, "-c", KILLED_SAVE, str(path)], stdout=subprocess.PIPE, text=True)
    assert process.stdout.readline().strip() == "writing"  # the temporary file is half written
    os.kill(process.pid, signal.SIGKILL)
    process.wait(timeout=30)
    assert process.returncode == -signal.SIGKILL
    stray = _leftovers(tmp_path)
    assert len(stray) == 1 and stray[0].startswith(".m.json.") and stray[0].endswith(".tmp")
    assert json.loads(path.read_text()) == PREVIOUS
    time.sleep(1.1)  # the next save removes temporaries older than itself (not a concurrent save's)
    save_json_atomic(path, {"kind": "x", "weights": [4]})
    assert json.loads(path.read_text()) == {"kind": "x", "weights": [4]} and _leftovers(tmp_path) == []
