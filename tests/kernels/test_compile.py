"""Kernels still run where no cache directory is writable (a read-only install with no user
cache): :func:`fuzzynav.jit.jit` then compiles in memory."""

import os
import subprocess
import sys

import pytest

SCRIPT = """
from fuzzynav.kernels import motion
from fuzzynav.robot.tricycle import DEFAULT_PARAMS
x, y, theta = motion.advance(1.0, 2.0, 0.0, 0.0, 1.0, DEFAULT_PARAMS.array().copy())
print(round(x, 12), y, theta, type(motion.advance._cache).__name__)
"""


@pytest.mark.slow
def test_kernels_compile_in_memory_without_a_cache_locator():
    # numba's only locator left is the one for IPython cells: none applies to an installed module
    env = {**os.environ, "NUMBA_CACHE_LOCATOR_CLASSES": "IPythonCacheLocator"}
    env.pop("NUMBA_CACHE_DIR", None)
    done = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True, env=env, timeout=600)
    assert done.returncode == 0, done.stderr
    assert done.stdout.split() == ["1.1", "2.0", "0.0", "NullCache"]
