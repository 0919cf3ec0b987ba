"""More hostile inputs for the readers: a closed standard input."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest


@pytest.mark.skipif(sys.platform == "win32", reason="a child started without a standard input: POSIX fds")
def test_a_csv_read_from_a_closed_standard_input_says_so():
    # ``fuzzynav fis eval goal-seeking --csv - <&-``: Python makes sys.stdin None
    process = subprocess.run([sys.executable, "-m", "fuzzynav", "fis", "eval", "goal-seeking", "--csv", "-"],
                             capture_output=True, preexec_fn=lambda: os.close(0), timeout=120)
    assert process.returncode == 2, process.stderr
    assert process.stderr.decode().strip() == "fuzzynav fis: error: -: cannot read file (standard input is closed)"
