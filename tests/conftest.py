"""Test-suite configuration.

The pyfuzzylite cross-checks (``tests/fll``) need pyfuzzylite, which pins numpy < 2 and is GPL,
so they run in their own virtual environment (``.ci/run`` step 2: ``pytest -m fll tests/fll``).
Where pyfuzzylite is not installed they are not collected at all (rather than reported skipped).
"""

import importlib.util
import os
import sys

# NumPy chooses its SIMD code by the CPU when it is imported, and its AVX-512 (X86_V4) exp, log,
# arctan and tan differ from its AVX2 ones in the last bits. The traces the tests compare with, bit
# for bit (tests/sim/static_hashes.json, tests/control/default_episodes.json), were recorded with
# AVX2, so the suite runs NumPy's AVX2 code on any machine that has more (names of NumPy ≥ 2.4 and of
# earlier versions; a name a version does not know is ignored). Set before NumPy is imported.
NUMPY_AVX2 = "X86_V4 AVX512_ICL AVX512_SPR AVX512F AVX512CD AVX512_SKX AVX512_CLX AVX512_CNL"
os.environ.setdefault("NPY_DISABLE_CPU_FEATURES", NUMPY_AVX2)
if "numpy" in sys.modules:  # a plugin imported it first: the recorded traces may then not match
    sys.stderr.write("tests/conftest.py: numpy was imported before its SIMD level could be set\n")

from hypothesis import settings  # noqa: E402 - after the environment above

collect_ignore = [] if importlib.util.find_spec("fuzzylite") else ["fll"]

# Property tests: no per-example deadline (the CI machine is shared and its timing varies), and in CI
# (CI=true) a derandomized search, so a run is reproducible; locally the search stays random.
settings.register_profile("default", deadline=None)
settings.register_profile("ci", deadline=None, derandomize=True)
settings.load_profile("ci" if os.environ.get("CI") else "default")
