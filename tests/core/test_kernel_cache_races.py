"""Two processes compiling one kernel at once leave a cache every later process can trust.

numba's cache file (``IndexDataCacheFile.save``) reads the kernel's index, picks the first free
data file name, writes the index, then the data, with no lock (numba/numba#4807 on GitHub). Two processes
that compile two signatures of one kernel at once (forked workers of ``evaluate`` or ``bench`` on a
cold cache) can both pick ``kernel.1.nbc``: the index keeps one signature, and the data file may
hold the other's machine code, which a later run loads and calls with the wrong argument types.
:mod:`fuzzynav.jit` holds a lock on the cache folder around each save and load. Here both
processes are made to reach the index write together, which without the lock they always do."""

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

KERNEL = """
from fuzzynav.jit import jit


@jit
def next_one(x):
    return x + 1
"""

# Each writer stops before writing the index until the other has got there too (or 3 s passed):
# unlocked, both have read the empty index by then and both pick data file 1.
WRITER = """
import os, sys, time
from pathlib import Path
from numba.core import caching

meet = Path(sys.argv[1])
write_index = caching.IndexDataCacheFile._save_index


def save_index_together(self, overloads):
    (meet / str(os.getpid())).touch()
    deadline = time.monotonic() + 3
    while len(list(meet.iterdir())) < 2 and time.monotonic() < deadline:
        time.sleep(0.01)
    write_index(self, overloads)


caching.IndexDataCacheFile._save_index = save_index_together
import racing
print(racing.next_one(int(sys.argv[2])) if sys.argv[2].isdigit() else racing.next_one(float(sys.argv[2])))
"""

READER = """
import racing
stats = racing.next_one.stats
print(racing.next_one(7), racing.next_one(7.0), sum(stats.cache_hits.values()), sum(stats.cache_misses.values()))
"""


@pytest.mark.skipif(sys.platform == "win32", reason="the lock needs fcntl; Windows keeps numba's own guard")
def test_two_signatures_compiled_at_once_are_both_cached_intact(tmp_path):
    (tmp_path / "racing.py").write_text(textwrap.dedent(KERNEL))
    (tmp_path / "meet").mkdir()
    source = str(Path(__file__).resolve().parents[2] / "src")
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(tmp_path), source])}
    env.pop("NUMBA_CACHE_DIR", None)  # the cache beside racing.py, in tmp_path
    writers = [subprocess.Popen([sys.executable, "-c", WRITER, str(tmp_path / "meet"), argument], env=env,
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
               for argument in ("7", "7.0")]
    outputs = [writer.communicate(timeout=120) for writer in writers]
    assert [writer.returncode for writer in writers] == [0, 0], outputs
    assert [out.strip() for out, _ in outputs] == ["8", "8.0"]
    data_files = sorted(path.name for path in (tmp_path / "__pycache__").glob("racing.next_one-*.nbc"))
    assert len(data_files) == 2, data_files  # one per signature

    reader = subprocess.run([sys.executable, "-c", READER], env=env, capture_output=True, text=True, timeout=120)
    assert reader.returncode == 0, reader.stderr
    # each signature's own machine code, loaded (two hits, no compilation)
    assert reader.stdout.split() == ["8", "8.0", "2", "0"], reader.stdout


def test_a_kernels_cache_file_is_locked_and_still_answers_as_numbas():
    from fuzzynav.jit import LockedCacheFile
    from fuzzynav.kernels import motion

    cache_file = motion.turn_remainder._cache._cache_file
    assert isinstance(cache_file, LockedCacheFile)
    assert cache_file._index_path.endswith(".nbi")  # numba's own attributes pass through
