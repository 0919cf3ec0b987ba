"""Ctrl-C or SIGTERM that a library swallows, then fails in its place, ends the command as the signal
does: one line, exit 130 or 143, no traceback. numba's compiler does it when Ctrl-C lands in
llvmlite's ctypes callback during a cold compile (``RuntimeError: no compiled object yet``); the
probe below does the same on purpose inside the ``scenarios`` command, run as the process' own
command (``fuzzynav.cli.main()`` with no argv, which installs the handlers)."""

from __future__ import annotations

import signal
import subprocess
import sys

import pytest

PROBE = """
import os, signal, sys
import fuzzynav.cli.scenarios as command

signal.signal(signal.SIGINT, signal.default_int_handler)  # as in a terminal: a test runner in the background ignores it

import ctypes

def swallowed_then_failed(args):
    if {signum} != 0:  # the handler raises inside a ctypes callback, which reports it as "Exception ignored"
        ctypes.CFUNCTYPE(None)(lambda: os.kill(os.getpid(), {signum}))()
    raise RuntimeError("no compiled object yet")  # ... and the library fails in its place

command.run = swallowed_then_failed
sys.argv = ["fuzzynav", "scenarios"]
from fuzzynav.cli import main
sys.exit(main())
"""


def _run(signum: int) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", PROBE.format(signum=int(signum))], capture_output=True, text=True,
                          timeout=120)


@pytest.mark.parametrize("signum, status, line", [(signal.SIGINT, 130, "interrupted"),
                                                  (signal.SIGTERM, 143, "terminated")])
def test_a_failure_after_the_signal_ends_as_the_signal(signum, status, line):
    done = _run(signum)
    assert (done.returncode, done.stderr.strip()) == (status, line)


def test_the_same_failure_without_a_signal_is_not_hidden():
    done = _run(0)
    assert done.returncode == 1 and "RuntimeError: no compiled object yet" in done.stderr
