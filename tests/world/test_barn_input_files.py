"""``fuzzynav import barn`` refuses hostile path and world files with an InputError naming them."""

import os
import shutil
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from fuzzynav.cli import main
from fuzzynav.errors import InputError
from fuzzynav.world.barn import optimal_path_length, read_posts

DATA = Path(__file__).resolve().parents[1] / "data" / "barn"


def _huge_header(path: Path) -> None:
    """An .npy whose header declares (10**11, 2) doubles (1.6 TB) followed by 64 bytes."""
    with open(path, "wb") as handle:
        np.lib.format.write_array_header_1_0(handle, {"descr": "<f8", "fortran_order": False, "shape": (10**11, 2)})
        handle.write(b"\0" * 64)


def _npz_as_npy(path: Path) -> None:
    with open(path, "wb") as handle:
        np.savez(handle, cells=np.array([[1, 2], [3, 4]]))


@pytest.mark.parametrize("write, expected", [
    (_npz_as_npy, r"path_0\.npy: must be one \.npy array.*NpzFile"),
    (_huge_header, r"path_0\.npy: unreadable path file"),
    (lambda path: path.write_bytes(b""), r"path_0\.npy: unreadable path file"),
    (lambda path: np.save(path, np.zeros((0, 2))), r"path_0\.npy: must be an \(n, 2\) array.*\(0, 2\)"),
    (lambda path: np.save(path, np.array([[1, None]], dtype=object)), r"path_0\.npy: unreadable path file"),
])
def test_bad_path_file_is_an_input_error_naming_it(tmp_path, capsys, write, expected):
    shutil.copy(DATA / "world_0.world", tmp_path / "world_0.world")
    write(tmp_path / "path_0.npy")
    with pytest.raises(InputError, match=expected):
        optimal_path_length(tmp_path / "path_0.npy")
    assert main(["import", "barn", str(tmp_path / "world_0.world"), "--out", str(tmp_path / "o")]) == 2
    assert "path_0.npy" in capsys.readouterr().err
    assert not (tmp_path / "o" / "world_0.yaml").exists()


def test_path_file_is_read_as_before(tmp_path):
    cells = np.load(DATA / "path_0.npy")
    np.save(tmp_path / "path_0.npy", cells.astype(np.float32))
    assert optimal_path_length(tmp_path / "path_0.npy") == pytest.approx(optimal_path_length(DATA / "path_0.npy"))
    np.save(tmp_path / "one.npy", np.array([[30, 0]]))
    assert optimal_path_length(tmp_path / "one.npy") > 10.0


def _unblock_later(fifo: Path, stop: threading.Event) -> None:
    """Open ``fifo`` for writing (then close it) after 3 s if a reader is waiting: a reader that
    hangs on it (the defect) then sees an empty file and the test fails instead of hanging."""
    def unblock():
        if stop.wait(3.0):
            return
        try:
            os.close(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
        except OSError:  # no reader waiting
            pass
    threading.Thread(target=unblock, daemon=True).start()


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="named pipes are POSIX")
def test_named_pipe_world_is_refused_not_read(tmp_path, capsys):
    """Opening a FIFO for reading waits for a writer: it must be refused without waiting."""
    os.mkfifo(tmp_path / "world_3.world")
    stop = threading.Event()
    _unblock_later(tmp_path / "world_3.world", stop)
    began = time.monotonic()
    try:
        with pytest.raises(InputError, match=r"world_3\.world: is a named pipe, not a regular file"):
            read_posts(tmp_path / "world_3.world")
    finally:
        stop.set()
    assert time.monotonic() - began < 2.0
    assert main(["import", "barn", str(tmp_path / "world_3.world"), "--out", str(tmp_path / "o")]) == 2
    assert "world_3.world" in capsys.readouterr().err
    os.mkfifo(tmp_path / "path_3.npy")
    with pytest.raises(InputError, match=r"path_3\.npy: is a named pipe"):
        optimal_path_length(tmp_path / "path_3.npy")


def test_folder_as_world_is_refused(tmp_path):
    (tmp_path / "world_4.world").mkdir()
    with pytest.raises(InputError, match=r"world_4\.world: is a folder, not a regular file"):
        read_posts(tmp_path / "world_4.world")
