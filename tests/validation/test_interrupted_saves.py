"""Saving never corrupts the previous file and leaves no temporary file behind: a save that fails
(an exception in the middle of writing, a full disk) removes its temporary file at once; a save
killed with SIGKILL (nothing can clean up) leaves the previous file intact, and its temporary
file is removed by the next save of that file."""

import errno
import json
import os
import signal
import subprocess
import sys
import time

import pytest

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
