"""An output path that is not a file to replace: a link is kept and its target written, a device
or a pipe is written in place (``-o /dev/stdout``, ``--plot /dev/null``), never replaced by a
file; a figure name the file system refuses is a one-line error; reading a named pipe does not
wait for ever."""

import os
import stat
import sys
import threading

import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.storage import atomic_write, write_text_atomic
from fuzzynav.validation import read_bytes


def test_a_link_is_kept_and_the_file_it_points_to_is_written(tmp_path):
    target = tmp_path / "real.txt"
    target.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(target)
    write_text_atomic(link, "new")
    assert link.is_symlink() and target.read_text() == "new"


def test_a_link_to_a_device_is_written_through_not_replaced(tmp_path):
    link = tmp_path / "null"
    link.symlink_to(os.devnull)
    write_text_atomic(link, "x" * 1000)
    assert link.is_symlink() and stat.S_ISCHR(os.stat(link).st_mode)


@pytest.mark.skipif(sys.platform == "win32", reason="named pipes are POSIX")
def test_a_named_pipe_is_written_in_place(tmp_path):
    pipe = tmp_path / "pipe"
    os.mkfifo(pipe)
    received = []
    reader = threading.Thread(target=lambda: received.append(pipe.read_bytes()), daemon=True)
    reader.start()
    atomic_write(pipe, lambda handle: handle.write(b"through the pipe"))
    reader.join(10)
    assert received == [b"through the pipe"] and stat.S_ISFIFO(os.stat(pipe).st_mode)


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="needs /dev/full")
def test_a_full_device_is_an_input_error_naming_it(tmp_path):
    link = tmp_path / "full"
    link.symlink_to("/dev/full")
    with pytest.raises(InputError, match="full: cannot write"):
        write_text_atomic(link, "x" * 100_000)
    assert link.is_symlink()


@pytest.mark.skipif(sys.platform == "win32", reason="named pipes are POSIX")
def test_reading_a_named_pipe_is_refused_at_once(tmp_path):
    pipe = tmp_path / "system.fll"
    os.mkfifo(pipe)
    with pytest.raises(InputError, match="named pipe"):
        read_bytes(pipe)


def test_a_figure_name_too_long_for_the_file_system_is_one_line(capsys):
    with pytest.raises(SystemExit) as stop:
        main(["fis", "plot", "goal-seeking", "-o", "a" * 300 + ".png"])
    assert stop.value.code == 2
    error = capsys.readouterr().err
    assert "not a usable file name" in error and "Traceback" not in error
