"""The campaign lock's write errors, which carry no file name, name the lock file (a full disk)."""

import errno
import os
import sys
from pathlib import Path

import pytest

from fuzzynav.bench import lock
from fuzzynav.errors import InputError

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="no fcntl lock on Windows")


@pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="needs /proc to tell the lock file's descriptor")
def test_a_full_disk_names_the_lock_file(tmp_path, monkeypatch):
    write = os.write

    def full(fd, data):
        if os.readlink(f"/proc/self/fd/{fd}").endswith(lock.LOCK_FILE):
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return write(fd, data)

    monkeypatch.setattr(os, "write", full)
    with pytest.raises(InputError, match=r"\.bench\.lock: --out: cannot write the campaign's lock file \(No space"):
        with lock.campaign_lock(tmp_path / "o"):
            pass
